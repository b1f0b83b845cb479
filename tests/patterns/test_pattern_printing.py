"""The whole of `certify pattern WORD` (Markdown and JSON) is the same text whether its
formulas (period matrix, cp, discriminant, datum) are written directly from python-flint
(certify.algebra.printing, what the command does) or through SymPy's expressions and
printer (the route before, rebuilt here as the reference)."""
import dataclasses

import pytest
import sympy as sp

from certify.algebra.poly import lam, show
from certify.dynamics.model import factor_flint
from certify.dynamics.systems import candidate_in
from certify.patterns import analyse, census
from certify.patterns import pattern as P

WORDS = census.words(8) + [f"(ab)^{n}(cb)^{n}" for n in range(2, 7)] + ["[ac]b"]    # four, three and symmetric


def sympy_formulas(cand):
    """(matrix, discriminant, datum) by SymPy: factor, cancel, sstr (the route before)."""
    M = [[show(e) for e in row] for row in cand.M.tolist()]
    disc = show(factor_flint(P.discriminant(cand.spectrum)))
    out = {"q(0)": "(-1, u" + (", v)" if len(cand.q0) == 3 else ")"), "u": P._cap(P._fraction_text(cand.q0[1]))}
    if len(cand.q0) == 3:
        out["v"] = P._cap(P._fraction_text(cand.q0[2]))
        out["p(0)"] = "(1, 0, x), x = x± = (a - d ± √((a-d)² + 4bc))/(2c), f(x) = (ax + b)/(cx + d)"
        for k, e in zip("abcd", cand.abcd):                   # SymPy expressions
            out[k] = P._cap(show(e))
    else:
        out["p(0)"] = "(1, 0)"
    return M, disc, out


@pytest.mark.parametrize("word", sorted(set(WORDS)))
def test_pattern_prints_what_sympy_printed(word):
    res = analyse(word)
    cand = candidate_in(res.system, res.normal)
    ref = dataclasses.replace(res, cp_text=show(sp.collect(cand.cp, lam)), formulas=lambda: sympy_formulas(cand))
    assert res.markdown() == ref.markdown()
    assert res.json_text() == ref.json_text()
