"""A datum witnessed at a degenerate point (L3.3, l. 132): abcb at r₀ = 3 − 2√2, where two
eigenvalues meet with a plane of eigenvectors, so the candidate's q(0) (Cramer's rule) is 0/0 and
the kernel's cells leave the point undecided.  The engine's eigenspace route finds a datum of the
plane that realises abcb (``PatternResult.data``); the kernel re-runs the four particles from it
exactly in Q(r₀)(√Δ) (certify_kernel/particles.py, ``realised_at``).  Every forged part of the
witness is refused, and without the witness the point stays undecided."""
from __future__ import annotations

import copy
from fractions import Fraction

import pytest

from certify.patterns.pattern import analyse
from certify_kernel.particles import realised_at
from certify_kernel.statements import read
from certify_kernel.sturm import Algebraic
from tests.kernel.kernel_support import STATEMENTS, outcome

R0 = Algebraic([Fraction(1), Fraction(-6), Fraction(1)], Fraction(17, 100), Fraction(18, 100))   # 3 − 2√2


@pytest.fixture(scope="module")
def data() -> list:
    found = analyse("abcb", formulas=False).data
    assert found, "the engine found no datum at 3 − 2√2"
    return found


def test_the_engine_datum_is_realised_in_the_kernel(data):
    assert all(d["word"] == "abcb" for d in data)
    assert all(realised_at(d, R0) for d in data)


FORGERIES = {
    "another u": lambda d: d["q"][1].__setitem__(0, str(Fraction(d["q"][1][0]) + Fraction(1, 7))),
    "another x": lambda d: d["x"]["alpha"].__setitem__(0, str(Fraction(d["x"]["alpha"][0]) + Fraction(1, 9))),
    "another fixed point": lambda d: d["x"].__setitem__("beta", [str(-Fraction(c)) for c in d["x"]["beta"]]),
    "another λ": lambda d: d.__setitem__("lambda", ["0", "1", "1/1000"]),
    "another r": lambda d: d["r"].__setitem__("interval", ["5.8", "5.9"]),
    "a polynomial without r₀": lambda d: d["r"].__setitem__("polynomial", ["1", "-7", "1"]),
    "another word": lambda d: d.__setitem__("word", "acbc"),
    "q_1(0) not -1": lambda d: d["q"].__setitem__(0, ["-2"]),
    "a malformed number": lambda d: d["q"][1].__setitem__(0, "one half"),
    "two velocities": lambda d: d["q"].pop(),
}


@pytest.mark.parametrize("name", sorted(FORGERIES))
def test_a_forged_datum_is_refused(data, name):
    d = copy.deepcopy(data[0])
    FORGERIES[name](d)
    assert not realised_at(d, R0), name


def test_l3_3_is_verified_with_the_witness_and_undecided_without(data):
    paper = read(STATEMENTS)
    L3_3 = next(s for c in paper.certificates for s in c.statements if s.id == "L3.3").formula
    assert L3_3 == "forall r in ]0, rexist[: feasible(abcb)"
    witnesses = [{"kind": "datum", **d} for d in data]
    assert outcome(L3_3, lets=paper.lets, witnesses=witnesses) == "verified"
    assert outcome(L3_3, lets=paper.lets).startswith("not verified: undecided at r = ≈0.1715728")
    forged = copy.deepcopy(witnesses)
    for w in forged:
        FORGERIES["another x"](w)
    assert outcome(L3_3, lets=paper.lets, witnesses=forged).startswith("not verified: undecided")
