"""certify/patterns/five_rule.py: the block A = abacbc turns by the island's rotation taken twice, and the
family members' certified windows lie where the rule puts them, between two resonances of the island."""
import cmath
import math

import flint
import numpy as np
import pytest

from certify.algebra import Algebraic
from certify.dynamics.systems import of_particles, system_matrix_flint
from certify.patterns import five_rule as R
from certify.patterns.five import FAMILY_CORES, family_word
from certify.patterns.island_theorem import rotation_ball
from certify.patterns.pattern import end_data

F1, F2 = FAMILY_CORES["F₁"], FAMILY_CORES["F₂"]


def test_the_block_identity_holds_for_abacbc_and_fails_for_other_blocks():
    """cp(M_A) = (x − r²)(x² − 2r² cos 2θ x + r⁴) exactly for A = abacbc and for abcabc = (abc)² (a and c
    commute: the same matrix); not for abacba, ababcb, acbacbc or abcb."""
    assert R.block_identity() and R.block_identity("abcabc")
    assert not any(R.block_identity(w) for w in ("abacba", "ababcb", "acbacbc", "abcb"))


@pytest.mark.parametrize("r", [0.172, 0.175, 0.19, 0.3, 0.7])
def test_the_block_turns_by_twice_the_island_rotation_in_floats(r):
    """An independent route: numpy's eigenvalues of M_A at r have a real one r² and a complex pair of
    modulus r² and argument 2π(1 − 2ρ), ρ the island's rotation number (arb)."""
    M = system_matrix_flint(of_particles(4), R.A_BLOCK)
    A = np.array([[float(sum(float(c) * r ** i for i, c in enumerate(e.coeffs()))) for e in row] for row in M])
    ev = np.linalg.eigvals(A)
    z = max(ev, key=lambda x: x.imag)
    rho = float(rotation_ball(flint.fmpq(round(r * 1000), 1000)).mid())
    assert min(abs(ev - r * r)) < 1e-12 and abs(abs(z) - r * r) < 1e-12
    assert cmath.phase(z) == pytest.approx(2 * math.pi * (1 - 2 * rho), rel=1e-9)


@pytest.mark.parametrize("core,k,j", [(F1, 2, 1), (F1, 4, 3), (F2, 1, 1), (F2, 3, 2), (F2, 5, 1)])
def test_q_read_off_a_members_length_is_the_families_closed_form(core, k, j):
    """q = (|W| − 2)/6 of the word family_word builds is 4k + 2j + 1 for F₁ and 4k + 2j + 3 for F₂ (the
    closed forms of docs/particles.md), and p = (q − 1)/2."""
    p, q = R.resonance(core, k, j)
    assert q == 4 * k + 2 * j + (1 if core == F1 else 3) and 2 * p + 1 == q


def test_the_rule_intervals_are_ordered_and_fall_to_three_minus_two_root_two():
    """F₂(k)·A, k = 1..6: each interval lies below the one of k − 1 and above 3 − 2√2 (exact); the upper
    end of k = 1 is r_{4/9}."""
    from certify.algebra import Algebraic
    L = Algebraic.roots(flint.fmpq_poly([1, -6, 1]), 0, 1)[0]
    previous = None
    for k in range(1, 7):
        a, b = R.rule_interval(F2, k)
        assert L < a < b
        if previous is not None:
            assert b < previous
        previous = a
    assert R.rule_interval(F2, 1)[1].digits(9) == "0.179226104"      # r_{4/9}


def _window(core, k, j=1):
    from tests.test_five_particle_figure import committed
    doc = committed()[family_word(core, k, j)]
    [piece] = [p for s in doc["stable"] for p in s["pieces"] if p["kind"] == "interval"]
    return piece["lo"], piece["hi"]


@pytest.mark.parametrize("k", [1, 2, 3, 4])
def test_the_certified_windows_of_f2_lie_in_their_rule_intervals(k):
    """The committed certified windows of F₂(k)·A (reports/five-patterns/) lie in ]r_{(2k+3)/(4k+7)},
    r_{(2k+2)/(4k+5)}[, decided exactly."""
    lo, hi = _window(F2, k)
    assert R.rule_problems(F2, k, 1, lo, hi) == []


def test_a_window_put_at_another_member_or_past_a_resonance_is_named():
    """Member 2's window given as member 3's, or as F₁(2)·A's, contradicts the rule; a window whose upper
    end is moved just above r_{6/13} (or its lower end below r_{7/15}) is named by the end it crosses."""
    lo, hi = _window(F2, 2)
    assert R.rule_problems(F2, 3, 1, lo, hi) == ["(3, 1): the window reaches above r_8/17 ≈ 0.173664541378"]
    assert R.rule_problems(F1, 2, 1, lo, hi) == ["(2, 1): the window reaches below r_6/13 ≈ 0.175174520939"]
    a, b = R.rule_interval(F2, 2)
    above = end_data(Algebraic.rational(flint.fmpq(b.floor_scaled(10 ** 15) + 2, 10 ** 15)))
    below = end_data(Algebraic.rational(flint.fmpq(a.floor_scaled(10 ** 15) - 1, 10 ** 15)))
    assert R.rule_problems(F2, 2, 1, lo, above) == ["(2, 1): the window reaches above r_6/13 ≈ 0.175174520939"]
    assert R.rule_problems(F2, 2, 1, below, hi) == ["(2, 1): the window reaches below r_7/15 ≈ 0.174266927309"]
