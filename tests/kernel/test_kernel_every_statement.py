"""Every formal statement of the repository's statements/ (docs/verify.md: "tests/kernel/ alter
every statement's constants one at a time"):

- its verdict flipped (holds ↔ refuted) is never verified: the kernel decides the statement, and
  the opposite verdict contradicts it (or the statement is undecided, never verified);
- its constants matter: one numeric literal altered by one unit of its last digit (5-2√6 →
  5-2√7, 0.11384 → 0.11385, a coefficient 646 → 647, an index, an exponent), the kernel no
  longer verifies it.  The literals are tried in order: those of the formula (+1, then −1 unit),
  then those of the definitions it uses, each let once (+1), until one alteration is not
  verified; the statement fails the test when none is.  Not every literal can change the truth
  (]0, 1[ → ]0, 2[ in "det M > 0 on ]0, 1[": det M = r⁶; "the datum follows ababcb for 20
  periods" holds for 21; a strict sign with a margin at a point), so the search goes on past
  them; SKIP lists the statements none of whose literals can change the truth, with the reason.
  A refuted statement stays false under most changes (a false claim changed a little is false
  too): its verdict flip is its test.

Deciding every statement takes about as long as the kernel's whole run (a minute on 2 cores):
the test over all of them is slow; the default suite runs it on the fast certificates FAST."""
from __future__ import annotations

import copy
import signal
from fractions import Fraction

import pytest

from certify_kernel import check_statement, prepare
from certify_kernel.evaluate import Context, NotVerified, truth
from certify_kernel.language import _TOKEN, parse
from tests.kernel.kernel_support import declared, repository_statements

FAST = {"T1", "T2", "T3", "T5", "T7", "S7", "S8", "B1"}
SECONDS = 30                    # per decision: an altered statement may cost more than the printed one
TRIES = 40                      # alterations per statement at most

# Statements none of whose numeric literals can change the truth (the reason), checked by their
# verdict flip alone.  A statement without any literal (in its formula or the definitions it uses)
# is skipped without being listed here.
SKIP = {
    "T25.2.7": "the datum perturbed by 10^-30 leaves the unstable pattern within 200 periods: so it does for any "
               "other n past its exit, any other small ε, r or digit of the datum (a robust property of an unstable "
               "orbit; its verdict flip is decided)",
    "T25.2.8": "as T25.2.7, on the lower branch",
    "L6.6.5": "its one literal is the N of n ≥ N, and the statement holds from n = 7 on (n ≥ 7 and n ≥ 9 are true "
              "too); its verdict flip is decided, and tests/kernel/test_kernel_family.py checks that n ≥ 6 and other "
              "thresholds (nθ = 2π, π/2) are not verified",
    "B1.4": "Λ²M (u ∧ v) = Mu ∧ Mv holds for every square matrix M (Cauchy-Binet for the 2×2 minors): no entry "
            "of K_i can change its truth (it checks the kernel's compound; its verdict flip is decided)",
}


def formal(paper):
    return [(c.id, s) for c in paper.certificates for s in c.statements
            if s.verdict != "observed" and not s.unformalised and s.formula]


PAPER = repository_statements()
STATEMENTS = formal(PAPER)


def cases(slow_too: bool = True):
    return [pytest.param(s, id=s.id, marks=() if cid in FAST else pytest.mark.slow) for cid, s in STATEMENTS]


class _Timeout(Exception):
    pass


def _alarm(*_):
    raise _Timeout


def decide(s, lets: dict) -> str:
    """"verified", "not verified: WHY", "failed: WHY" or "timeout"."""
    declared()
    prepare(PAPER)
    old = signal.signal(signal.SIGALRM, _alarm)
    signal.alarm(SECONDS)
    try:
        ok, why = check_statement(s, lets)
        return "verified" if ok else f"not verified: {why}"
    except ValueError as exc:
        return f"failed: {exc}"
    except _Timeout:
        return "timeout"
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, old)


def literals(text: str) -> list[tuple[int, int]]:
    """The spans of the numeric literals of a text, as the kernel's tokenizer reads it (the 6 of
    √6 and of r^6, never the 0 of P0 or the 1 of r1: those are names)."""
    out, at = [], 0
    while at < len(text):
        m = _TOKEN.match(text, at)
        if m is None:
            break
        if m.lastgroup == "num":
            out.append((m.start(), m.end()))
        at = m.end()
    return out


def moved(literal: str, step: int) -> str:
    """The literal moved by ``step`` units of its last digit (0.11384 → 0.11385, 646 → 647)."""
    if "." in literal:
        k = len(literal.split(".")[1])
        x = Fraction(literal) + Fraction(step, 10 ** k)
        sign, x = ("-" if x < 0 else ""), abs(x)
        whole, frac = divmod(x * 10 ** k, 10 ** k)
        return f"{sign}{whole}.{int(frac):0{k}d}"
    return str(int(literal) + step)


class _Recording(Context):
    """A context that records the definitions the kernel looks up (a word such as ab in
    concatenation(ab, cb) is read as letters, never as the let b)."""

    def __init__(self, lets: dict):
        super().__init__(lets)
        self.used: list = []

    def name(self, name: str):
        if name in self.lets and name not in self.used:
            self.used.append(name)
        return super().name(name)


def used_lets(s, lets: dict) -> list[str]:
    """The definitions the kernel looks up when it decides the statement, in the order of first use."""
    declared()
    prepare(PAPER)
    ctx = _Recording(lets)
    try:
        truth(parse(s.formula), ctx)
    except (NotVerified, ValueError, ZeroDivisionError):
        pass
    return ctx.used


def alterations(s, lets: dict):
    """(what, statement, lets) for each single-literal alteration, in the order tried."""
    for a, b in literals(s.formula):
        for step in (1, -1):
            t = copy.copy(s)
            t.formula = s.formula[:a] + moved(s.formula[a:b], step) + s.formula[b:]
            yield f"{s.formula[a:b]} → {moved(s.formula[a:b], step)} at {a} of the formula", t, lets
    for name in used_lets(s, lets):
        for a, b in literals(lets[name]):
            changed = dict(lets)
            changed[name] = lets[name][:a] + moved(lets[name][a:b], 1) + lets[name][b:]
            yield f"{lets[name][a:b]} → {moved(lets[name][a:b], 1)} at {a} of let {name}", s, changed


@pytest.mark.parametrize("s", cases())
def test_a_flipped_verdict_is_never_verified(s):
    flipped = copy.copy(s)
    flipped.verdict, flipped.other = ("refuted" if s.verdict != "refuted" else "holds"), ""
    got = decide(flipped, PAPER.lets)
    assert got != "verified", f"{s.id} is verified with the verdict {flipped.verdict} too"


@pytest.mark.parametrize("s", cases())
def test_altered_constants_are_not_verified(s):
    if s.verdict == "refuted":
        pytest.skip("a refuted statement: its verdict flip is its test")
    if s.id in SKIP:
        pytest.skip(SKIP[s.id])
    tried = []
    for what, t, lets in alterations(s, PAPER.lets):
        got = decide(t, lets)
        if got not in ("verified", "timeout"):
            return
        tried.append(f"{what}: {got}")
        if len(tried) >= TRIES:
            break
    if not tried:
        pytest.skip("no numeric literal in the formula or the definitions it uses (its verdict flip is its test)")
    pytest.fail(f"{s.id}: every alteration tried is still verified (list it in SKIP with the reason if no "
                "literal can change its truth):\n  " + "\n  ".join(tried))


def test_moved_literals():
    assert [moved(x, 1) for x in ("0", "9", "646", "0.11384", "0.99999", "0.5")] == \
        ["1", "10", "647", "0.11385", "1.00000", "0.6"]
    assert [moved(x, -1) for x in ("0", "1", "0.11384", "0.00000")] == ["-1", "0", "0.11383", "-0.00001"]
    assert literals("5-2√6 + P0*r1^2 ≈ 0.11384") == [(0, 1), (2, 3), (4, 5), (14, 15), (18, 25)]
    s = copy.copy(STATEMENTS[0][1])
    s.formula = "T = U*2"
    assert used_lets(s, {"T": "U*2", "U": "r", "V": "T"}) == ["T", "U"]
    s.formula = "concatenation(b, ab)"
    assert used_lets(s, {"b": "r", "ab": "r"}) == []
