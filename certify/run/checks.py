"""Checks that the proofs of several claims make alike: printed digits against an
algebraic number, a printed number of roots counted by both routes, a printed eliminant
against both eliminations, identities and signs of :mod:`certify.algebra.trig` as checks
(with the witnesses of their signs), a lemma of a lower layer read as a check, and a
conclusion whose corrections replace the printed checks one for one.
"""
from __future__ import annotations

from certify import witnesses
from certify.algebra import (
    Algebraic,
    eliminate,
    parse,
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
    return Check(f"{name} has exactly {expected} root(s) in ]0,1[ (Sturm and python-flint)",
                 sturm == expected and flint_count == expected and len(roots) == expected,
                 [f"Sturm count {sturm}, python-flint count {flint_count}"])


def eliminant_check(name: str, g, cp, printed_product: str) -> list[Check]:
    """The λ-free element of the lex Gröbner basis of {g, cp} equals the printed
    product up to a constant; the resultant route has the same factors."""
    E = eliminate(g, cp)
    P = to_fmpz_poly(to_fmpq_poly(parse(printed_product)))
    same = same_up_to_constant(E.groebner, P)
    groebner = Check(f"Gröbner basis of {{{name}, cp(M)}} (lex λ > r) eliminates to the printed polynomial", same,
                     E.evidence() + [f"printed: `{show_factored_int(P)}`"])
    return [groebner, Check("the resultant route agrees factor by factor", E.agree)]


def check_of(lemma) -> Check:
    """A lemma proven in a lower layer (statement, holds, evidence), as a check (with the
    witnesses it kept, if any: ``lemma.witnesses``, as data)."""
    kept = getattr(lemma, "witnesses", None)
    return Check(lemma.statement, lemma.holds, list(lemma.evidence), witnesses=kept_witnesses(kept) if kept else None)


def result_check(statement: str, res: T.Result) -> Check:
    """A proven or refuted statement of :mod:`certify.algebra.trig` as a check (with the
    witnesses the result carries, for the independent kernel)."""
    return Check(statement, res.holds, res.evidence, witnesses=witnesses.witnesses_of(res))


def combined(statement: str, parts: list[T.Result]) -> Check:
    """One check that holds when every part holds; the parts' evidence in order, their witnesses."""
    return Check(statement, all(parts), [e for p_ in parts for e in p_.evidence],
                 witnesses=witnesses.witnesses_of(*parts))


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


def kept_witnesses(data: list) -> list[str]:
    """Record again, for a check, the witnesses ``data`` (dicts) that a computation kept
    (:func:`certify.witnesses.captured`: a lemma of a shared quantity, computed once); the ids."""
    ids = []
    for ob in data:
        i = witnesses.record(ob)
        if i and i not in ids:
            ids.append(i)
    return ids


def witness(kind: str, **data) -> list[str]:
    """Record a witness for the kernel (certificates.json: data of a kind it reads, such as
    ``factors``, certify_kernel/pattern.py), for the check that names it: its id in a list
    (none outside a recording)."""
    oid = witnesses.record({"kind": kind, **data})
    return [oid] if oid else []
