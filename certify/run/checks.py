"""Checks that the proofs of several claims make alike: printed digits against an
algebraic number, a printed number of roots counted by both routes, a printed eliminant
against both eliminations, identities and signs of :mod:`certify.algebra.trig` as checks,
a lemma of a lower layer read as a check, and a conclusion whose corrections replace
the printed checks one for one.
"""
from __future__ import annotations

import flint
import sympy as sp

from certify import obligations
from certify.algebra import (
    Algebraic,
    eliminate,
    facts,
    from_flint,
    parse,
    rational_between,
    same_up_to_constant,
    show_factored_int,
    to_fmpq_poly,
    to_fmpz_poly,
)
from certify.algebra import trig as T

from .runner import Check, conclude


def digits_check(name: str, root: Algebraic, printed: str) -> Check:
    """The printed decimal is the root correctly rounded (exact comparison with the rounding interval)."""
    return Check(f"{name} ≈ {printed}", root.in_rounding_interval(printed), [f"{name} is {root.describe()}"])


def count_check(name: str, roots: list, counts: tuple[int, int], expected: int) -> Check:
    """The printed number of roots in ]0,1[, counted by both routes (``counts``: the Sturm
    count and python-flint's, as :func:`certify.algebra.roots_in_unit_interval` gives
    them), and as many isolated."""
    sturm, flint_count = counts
    own = None
    if roots:        # for the kernel: the count on ]0, 1] and whether 1 is a root (same p: distinct roots)
        p = roots[0].p
        at_one = 1 if p(1) == 0 else 0
        sign_one = int(p(1) > 0) - int(p(1) < 0)
        own = obligations.take([i for i in (obligations.emit(facts.root_count(sturm + at_one, p, 0, 1)),
                                            obligations.emit(facts.sign_at(sign_one, p, 1))) if i])
    return Check(f"{name} has exactly {expected} root(s) in ]0,1[ (Sturm and python-flint)",
                 sturm == expected and flint_count == expected and len(roots) == expected,
                 [f"Sturm count {sturm}, python-flint count {flint_count}"], obligations=own)


def eliminant_check(name: str, g, cp, printed_product: str) -> list[Check]:
    """The λ-free element of the lex Gröbner basis of {g, cp} equals the printed
    product up to a constant; the resultant route has the same factors.  For the kernel,
    the Gröbner check names the identity (Gröbner eliminant)·k = printed product and the
    resultant route's fact; the second check names the latter."""
    E = eliminate(g, cp)
    printed = parse(printed_product)
    Pq = to_fmpq_poly(printed)
    P = to_fmpz_poly(Pq)
    same = same_up_to_constant(E.groebner, P)
    res = fact_ids(lambda: facts.resultant(E.agree and same, g, cp, printed, "same_factors"))
    lc = Pq.coeffs()[-1]                     # the constant, leading terms
    k = sp.Rational(int(lc.p), int(lc.q)) / sp.Integer(int(E.groebner.coeffs()[-1]))
    eliminant = identity_facts((same, k * from_flint(E.groebner), printed))
    groebner = Check(f"Gröbner basis of {{{name}, cp(M)}} (lex λ > r) eliminates to the printed polynomial", same,
                     E.evidence() + [f"printed: `{show_factored_int(P)}`"], obligations=eliminant + res)
    return [groebner, Check("the resultant route agrees factor by factor", E.agree, obligations=res)]


def fact_ids(*builders) -> list[str]:
    """Record, for the independent kernel, the obligations the ``builders`` (functions of no
    argument) make; one that fails records an ``unsupported`` obligation with the reason."""
    ids = []
    for build in builders:
        try:
            ob = build()
        except Exception as exc:   # not in the obligation language
            ob = {"kind": "unsupported", "reason": f"{type(exc).__name__}: {exc}"[:200]}
        ids.append(obligations.emit(ob))
    return obligations.take([i for i in ids if i])


def check_of(lemma) -> Check:
    """A lemma proven in a lower layer (statement, holds, evidence), as a check (with the facts
    it kept, if any: ``lemma.facts``, obligations as data)."""
    kept = getattr(lemma, "facts", None)
    return Check(lemma.statement, lemma.holds, list(lemma.evidence), obligations=kept_facts(kept) if kept else None)


def result_check(statement: str, res: T.Result) -> Check:
    """A proven or refuted statement of :mod:`certify.algebra.trig` as a check (with the
    facts the result carries, for the independent kernel)."""
    return Check(statement, res.holds, res.evidence, obligations=obligations.take(obligations.facts_of(res)))


def combined(statement: str, parts: list[T.Result]) -> Check:
    """One check that holds when every part holds; the parts' evidence in order."""
    own = obligations.facts_of(*parts)
    if own and not all(getattr(p_, "facts", None) for p_ in parts):    # a part without recorded facts
        own.append(obligations.emit({"kind": "unsupported", "reason": "a part of the check carries no fact"})
                   or "")
    return Check(statement, all(parts), [e for p_ in parts for e in p_.evidence],
                 obligations=obligations.take([i for i in own if i]))


def identity(statement: str, lhs, rhs) -> Check:
    """The check lhs ≡ rhs, with the evidence of both routes."""
    return result_check(statement, T.equal(lhs, rhs))


def concluded(printed: list[Check], corrected: list[Check] | None = None, note: str = "", kind: str = "",
              misprint: str = ""):
    """:func:`conclude`, where the corrected computation is the printed one with the stated
    corrections applied, check for check: each failing printed check is corrected by the
    check in the same place (unless a correction already names it)."""
    corrected = corrected or []
    named = {id(c.corrects) for c in corrected if c.corrects is not None}
    if len(corrected) == len(printed):
        for wrong, fix in zip(printed, corrected):
            if not wrong.holds and id(wrong) not in named and fix.corrects is None and fix is not wrong:
                fix.corrects = wrong
    return conclude(printed, corrected, note=note, kind=kind, misprint=misprint)


def product_fact(holds: bool, factors: list, rhs, entry: int | None = None) -> list[str]:
    """Record, for the independent kernel, that the product of the matrices ``factors`` equals
    ``rhs`` (or its entry ``entry``), with the engine's verdict ``holds``; the ids, for
    ``Check(..., obligations=...)``."""
    try:
        ob = facts.product_identity(holds, factors, rhs, entry)
    except Exception as exc:   # not in the obligation language
        ob = {"kind": "unsupported", "reason": f"product identity: {exc}"[:200]}
    i = obligations.emit(ob)
    return obligations.take([i]) if i else []


def identity_modulo_facts(modulo, *triples, var=None) -> list[str]:
    """:func:`identity_facts` modulo a polynomial monic in λ (cp), or in ``var`` (r − r₀: the
    identity at r = r₀)."""
    return fact_ids(*[lambda h=h, a=a, b=b: facts.identity(h, a, b, modulo, var) for h, a, b in triples])


def identity_facts(*triples) -> list[str]:
    """Record, for the independent kernel, identities ``(holds, lhs, rhs)`` (scalars or matrices;
    ``lhs`` or ``rhs`` a list of matrices stands for their product) with the engine's verdicts;
    the ids, for ``Check(..., obligations=...)``."""
    ids = []
    for holds, lhs, rhs in triples:
        try:
            if isinstance(lhs, list) or isinstance(rhs, list):
                left = lhs if isinstance(lhs, list) else [lhs]
                right = rhs if isinstance(rhs, list) else [rhs]
                ob = facts.products_identity(holds, left, right)
            else:
                ob = facts.identity(holds, lhs, rhs)
        except Exception as exc:   # not in the obligation language
            ob = {"kind": "unsupported", "reason": f"identity: {exc}"[:200]}
        ids.append(obligations.emit(ob))
    return obligations.take([i for i in ids if i])


def resultant_fact(holds: bool, f, g, poly, relation: str) -> list[str]:
    """Record that Res_λ(f, g) (g "d/dλ": ∂f/∂λ) is "proportional" to, or has the "same_factors"
    as, the polynomial ``poly`` in r (the engine's verdict ``holds``); the ids."""
    return fact_ids(lambda: facts.resultant(holds, f, g, poly, relation))


def kept_facts(data: list) -> list[str]:
    """Record again, for a check, the obligations ``data`` (dicts) that a computation kept
    (:func:`certify.obligations.captured`: a lemma of a shared quantity, computed once); the ids."""
    ids = []
    for ob in data:
        i = obligations.emit(ob)
        if i and i not in ids:
            ids.append(i)
    return obligations.take(ids)


def sign_intervals_facts(poly, ivs) -> list[str]:
    """Record the facts :func:`certify.algebra.sign_intervals` decided ``ivs`` from (the
    intervals between the roots of ``poly`` in ]lo, hi[, lo and hi rational, with a sign
    each): the number of roots in ]lo, hi] and the sign at hi (Sturm), each inner end a
    root, and for each interval a rational sample inside it (two comparisons) with the sign
    there; the ids."""
    P = flint.fmpq_poly(poly) if not isinstance(poly, flint.fmpq_poly) else poly
    lo, hi = ivs[0][0], ivs[-1][1]
    inner = [b for _a, b, _s in ivs[:-1]]
    at_hi = P(hi.lo)

    def sign(q) -> int:
        return int(q > 0) - int(q < 0)
    builders = [lambda: facts.root_count(len(inner) + (at_hi == 0), P, lo.lo, hi.lo),
                lambda: facts.sign_at(sign(at_hi), P, hi.lo)]
    builders += [lambda z=z: facts.sign_at(0, P, z) for z in inner]
    for a, b, s in ivs:
        with obligations.quiet():        # the comparisons are recorded below
            t = rational_between(a, b)
        builders += [lambda a=a, t=t: facts.compare(-1, a, t), lambda b=b, t=t: facts.compare(-1, t, b),
                     lambda s=s, t=t: facts.sign_at(s, P, t)]
    return fact_ids(*builders)


def unsupported_fact(reason: str) -> list[str]:
    """Record that a check rests on something the kernel does not have, named by ``reason``
    (the exact simulator of the particles, ball arithmetic, ...); the ids."""
    return fact_ids(lambda: {"kind": "unsupported", "reason": reason})


def determinant_fact(holds: bool, matrix, rhs) -> list[str]:
    """Record that det(matrix) = rhs (the engine's verdict ``holds``); the ids."""
    return fact_ids(lambda: facts.determinant_identity(holds, matrix, rhs))


def witness(kind: str, **data) -> list[str]:
    """Record a witness for the kernel (certificates.json: data of a kind it reads, such as
    ``factors``, certify_kernel/pattern.py) and take it for the next check alone: its id in a list
    (none outside a recording)."""
    oid = obligations.record({"kind": kind, **data})
    return obligations.take([oid]) if oid else []
