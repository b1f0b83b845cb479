"""The horseshoe of ``certify chaos`` (certify/numerics/horseshoe.py): the proof refuses a perturbed
box or covering relation; each box's word and image are the exact reduction map's (an independent
route: certify.dynamics.reduction); the branch forms agree with the reduction's rules on a grid;
Collatz–Wielandt and the entropy bound are lower bounds."""
from __future__ import annotations

import dataclasses
import itertools
from fractions import Fraction

import mpmath
import numpy as np
import pytest

from certify.dynamics import island, reduction
from certify.numerics import horseshoe as hs

R = Fraction(11, 100)
RQ = hs.to_fmpq(R)                  # the reduction's own functions take python-flint's rationals


@pytest.fixture(scope="module")
def found():
    H = hs.find(R)
    assert H.proof is not None and H.proof.holds
    return H


def test_a_horseshoe_is_proved_at_11_100_with_positive_entropy(found):
    P = found.proof
    assert float(P.beta) > 1 and float(P.entropy) > 0
    assert all(h for h, _ in P.in_branch.values()) and all(h for h, _ in P.covers.values()) and P.disjoint[0]
    # T has the loop at N0 and the homoclinic cycle: ρ(T) > 1 numerically too, β below it
    rho = max(abs(np.linalg.eigvals(np.array(P.T, dtype=float))))
    assert 1 < float(P.beta) <= rho + 1e-12


def test_mirror_saddles_are_ordered_by_their_word_not_by_the_last_bits_of_floats(found):
    """abacb and cbcab are mirror images with the same multipliers; floats tell them apart only in
    their last bits, and which came first changed with numpy's version (the report's N2.7 then
    named abacb).  Rounded to 9 digits they tie, and the later word, cbcab, comes first."""
    ss = hs.saddles(hs.FloatMap(R))
    weak = {s.word: -min(np.log(abs(s.lam)), -np.log(abs(s.mu))) for s in ss}
    assert {"abacb", "cbcab"} <= set(weak) and abs(weak["abacb"] - weak["cbcab"]) < 1e-9
    order = [s.word for s in ss]
    assert order.index("cbcab") < order.index("abacb") and found.saddle == "cbcab"


def interior_points(box):
    """Rational points inside the box: its centre and convex combinations of its vertices."""
    yield box.c
    for s, t in itertools.product((Fraction(-9, 10), Fraction(1, 3)), repeat=2):
        yield box.point(hs.to_fmpq(s), hs.to_fmpq(t))


def test_each_box_follows_its_word_by_the_exact_reduction_map(found):
    """From rational points inside each box, reduction.word_of (the engine's own rules on the exact
    normal) gives the box's word, and reduction.orbit's last plane is the projective image."""
    for box in found.proof.boxes:
        for z in interior_points(box):
            P = reduction.canonical("b", island.normal(*z))
            letters, last = reduction.word_of(P, RQ, len(box.word))
            assert letters == box.word, (box.name, letters)
            assert last.letter == "b" and island.chart(last.n) == hs.image(box.word, z, R)


def test_the_branch_forms_are_the_reduction_rules_on_a_grid():
    """follows(w, z) holds exactly when the reduction from z goes along w and returns to b."""
    for k, j in itertools.product(range(-9, 10, 2), range(-12, 13, 3)):
        z = (hs.to_fmpq(Fraction(k, 10)), hs.to_fmpq(Fraction(j, 4) + Fraction(1, 7)))
        P = reduction.canonical("b", island.normal(*z))
        letters, last = reduction.word_of(P, RQ, 3)
        word = letters[:letters.index("b") + 1] if "b" in letters else None
        for w in hs.BRANCHES:
            assert hs.follows(w, z, R) == (w == word), (z, w, letters)


def moved(box, **changes):
    return dataclasses.replace(box, **changes)


def test_a_wider_target_box_breaks_the_covering(found):
    """N_i ⇒ N_j fails when N_j is widened 50 times along its unstable side: the exit edges' images
    fall inside it (the proof refuses it, and prove() no longer holds)."""
    P = found.proof
    (i, j) = next(e for e in P.covers if e[0] != e[1])
    a, b = P.boxes[i], P.boxes[j]
    wide = moved(b, U=tuple(50 * z for z in b.U))
    holds, why = hs.covering(a, wide, R)
    assert not holds and "exit edges" in why
    boxes = list(P.boxes)
    boxes[j] = wide
    assert not hs.prove(R, boxes, list(P.covers), P.k).holds


def test_a_target_box_moved_along_its_stable_side_breaks_the_covering(found):
    P = found.proof
    (i, j) = next(e for e in P.covers if e[0] != e[1])
    a, b = P.boxes[i], P.boxes[j]
    shifted = moved(b, c=(b.c[0] + 3 * b.S[0], b.c[1] + 3 * b.S[1]))
    holds, why = hs.covering(a, shifted, R)
    assert not holds and "|y| ≥ 1" in why


def test_a_box_stretched_out_of_its_branch_is_refused(found):
    P = found.proof
    box = P.boxes[0]
    big = moved(box, U=tuple(10**4 * z for z in box.U))
    holds, why = hs.in_branch(big, R)
    assert not holds and "not > 0" in why
    assert not hs.prove(R, [big] + list(P.boxes[1:]), list(P.covers), P.k).holds


def test_overlapping_boxes_are_not_called_disjoint(found):
    b = found.proof.boxes[1]
    assert hs.separated(b, moved(b, name="far", c=(b.c[0] + 5 * b.U[0], b.c[1] + 5 * b.U[1])))
    assert not hs.separated(b, moved(b, name="near", c=(b.c[0] + b.U[0], b.c[1] + b.U[1])))


def test_collatz_wielandt_and_the_entropy_bound_are_lower_bounds():
    assert hs.collatz_wielandt([[1, 1], [1, 1]], [Fraction(1), Fraction(1)]) == 2
    T = [[1, 1, 0], [0, 0, 1], [1, 0, 0]]          # ρ is the root of x³ = x² + 1
    beta = hs.collatz_wielandt(T, [Fraction(146, 100), Fraction(68, 100), Fraction(1)])
    rho = max(abs(np.linalg.eigvals(np.array(T, dtype=float))))
    assert 1 < beta <= rho
    mpmath.mp.dps = 40
    for b, k in ((Fraction(2), 1), (Fraction(30458698429, 24261704268), 2), (Fraction(3, 2), 7)):
        text = hs.entropy_bound(b, k)
        exact = mpmath.log(mpmath.mpf(b.numerator) / b.denominator) / k
        assert mpmath.mpf(text) <= exact < mpmath.mpf(text) + mpmath.mpf("1e-6")


def test_no_horseshoe_is_claimed_without_a_proof():
    """At r = 9/10 the search finds no saddle of at most 2 returns: nothing is claimed."""
    H = hs.find(Fraction(9, 10))
    assert H.proof is None
    doc = hs.as_json(H)
    assert doc["certified"] is False and "nothing is claimed" in doc["why"]


def test_visits_counts_orbits_that_enter_a_box(found):
    """A box covering the whole strip |u| < 1, |v| < 10^4 is visited by every orbit; the proof's
    boxes are visited by few (observed)."""
    whole = hs.Box("all", "ab", (hs.to_fmpq(0), hs.to_fmpq(0)), (hs.to_fmpq(1), hs.to_fmpq(0)),
                   (hs.to_fmpq(0), hs.to_fmpq(10**4)))
    v = hs.visits(R, [whole], orbits=3, returns=50)
    assert v["visiting"] == 3 and v["share_of_returns"] > 0.99
    few = hs.visits(R, found.proof.boxes, orbits=3, returns=50)
    assert 0 <= few["visiting"] <= 3 and "observed" in few["kind"]
