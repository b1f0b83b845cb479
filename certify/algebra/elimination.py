"""Elimination of λ by two independent routes.

Route 1: a reduced lex Gröbner basis of the ideal (g, cp) with λ > r (SymPy);
its elements free of λ generate the elimination ideal ⟨g, cp⟩ ∩ Q[r].
Route 2: the resultant Res_λ(g, cp) (python-flint, fmpz_mpoly).
Both vanish at r exactly when g and cp have a common root λ (cp is monic in λ),
so their irreducible factors must agree; they may differ in multiplicity.
Disagreement is reported, and certificates turn it into a FAIL.
"""
from __future__ import annotations

from dataclasses import dataclass

import flint
import sympy as sp

from .poly import expr, irreducible_factors, lam, primitive, r, resultant_lambda, show, to_fmpz_poly


@dataclass
class Elimination:
    """The eliminant of {g = 0, cp = 0} in r, computed twice."""

    groebner: flint.fmpz_poly
    resultant: flint.fmpz_poly

    @property
    def factors(self) -> list[tuple[flint.fmpz_poly, int]]:
        """Irreducible factors of the Gröbner eliminant, with multiplicities."""
        return irreducible_factors(self.groebner)

    @property
    def agree(self) -> bool:
        """Same irreducible factors on both routes (multiplicities aside)."""
        a = {str(f) for f, _ in irreducible_factors(self.groebner)}
        b = {str(f) for f, _ in irreducible_factors(self.resultant)}
        return a == b

    def evidence(self) -> list[str]:
        return [f"Gröbner eliminant (lex λ > r, SymPy): `{show_factored_int(self.groebner)}`",
                f"Res_λ (python-flint): `{show_factored_int(self.resultant)}`",
                f"irreducible factors agree on both routes: {'yes' if self.agree else 'NO'}"]


def show_factored_int(p: flint.fmpz_poly) -> str:
    """A factored integer polynomial, factors in a fixed order (deterministic)."""
    c, facs = p.factor()
    parts = []
    for f, m in sorted(facs, key=lambda fm: (fm[0].degree(), str(fm[0]))):
        f = primitive(f)
        body = show(f)
        body = body if f.degree() == 1 and len(f.coeffs()) == 2 and f.coeffs()[0] == 0 else f"({body})"
        parts.append(body + (f"^{m}" if m > 1 else ""))
    const = "" if c == 1 else f"{c}·"
    return const + "·".join(parts)


def groebner_eliminant(g, cp) -> flint.fmpz_poly:
    """The generator of ⟨g, cp⟩ ∩ Q[r] from a reduced lex Gröbner basis (λ > r); by SymPy's
    F5B (the reduced basis is unique: Buchberger's algorithm gives the same, slower)."""
    G = sp.groebner([sp.expand(expr(g)), sp.expand(expr(cp))], lam, r, order="lex", method="f5b")
    free = [p for p in G.exprs if not p.has(lam)]
    if len(free) != 1:
        raise ArithmeticError(f"expected one λ-free basis element, found {len(free)}")
    return to_fmpz_poly(free[0], r)


def eliminate(g, cp) -> Elimination:
    """Eliminate λ from g = cp = 0 by both routes."""
    return Elimination(groebner_eliminant(g, cp), primitive(resultant_lambda(g, cp)))
