"""The closed form of (ab)^n(cb)^n (certify/patterns/family.py) against the engine: the product of
the collision matrices, its characteristic polynomial, and the run of the word (positions and
velocities, with the collision times the engine defines), n ≤ 12."""
import flint
import pytest

from certify.algebra.poly import LR_LAMBDA, LR_R, Frac, field_to_frac
from certify.dynamics.model import charpoly_coefficients, word_matrix_flint
from certify.dynamics.words import candidate, run_lr
from certify.patterns import family as F
from certify.patterns.feasibility import prefix_requirements


@pytest.mark.parametrize("n", range(1, 13))
def test_matrices_are_the_engines_products(n):
    """M_n, every prefix matrix (k = 1..4n) and cp_n equal the engine's product of A, B, C."""
    w = F.family_word(n)
    assert F.period_matrix(n) == word_matrix_flint(w)
    for k in range(1, 4 * n + 1):
        assert F.prefix_matrix(n, k) == word_matrix_flint(w[:k]), k
    assert F.charpoly(n) == charpoly_coefficients(word_matrix_flint(w))


@pytest.mark.parametrize("n", [1, 2, 3, 7, 12, 40])
def test_doubling_is_the_recurrence(n):
    R = F.r_poly()
    s = F.chebyshev(max(n, 2), R)
    assert F.chebyshev_pair(n, R) == (s[n], s[n - 1])
    assert s[:3] == [0, 1, F.trace(R)]


def test_the_family_is_recognised():
    assert F.family_n("ababcbcb") == 2 and F.family_word(2) == "ababcbcb"
    assert F.family_n("ababcb") is None and F.family_n("abcbcb") is None


def _at(pair, x):
    return pair[0] + pair[1] * x


@pytest.mark.parametrize("n", range(1, 7))
def test_positions_are_the_engines_run(n):
    """p(t_2n), p(t_4n), q(t_4n) in closed form = the engine's run, for a generic q(0) (symbolic r)."""
    w = F.family_word(n)
    q0 = (Frac.of(-1), Frac.of(flint.fmpq(3, 7)), Frac.of(flint.fmpq(-2, 5)))
    run = run_lr(w, q0)
    for x in (Frac.of(0), Frac.of(flint.fmpq(5, 3))):
        pos = F.positions(n, q0, x, LR_R)
        assert list(pos["p(t_2n)"]) == [_at(e, x) for e in run[2 * n - 1][1]]
        assert list(pos["p(t_4n)"]) == [_at(e, x) for e in run[4 * n - 1][1]]
        assert list(pos["q(t_4n)"]) == list(run[-1][2])


@pytest.mark.parametrize("n", [2, 3])
def test_binding_conditions_are_the_engines(n):
    """Every binding condition is the engine's requirement of the same name (the same function of
    λ, r, x at the self-similar datum), and the engine's others are the implied p_3(t_k), p_1(t_k)."""
    w = F.family_word(n)
    cand = candidate(w)
    reqs, _ = prefix_requirements(w, 4 * n, cand.q0, cand.steps, cand.q0_other)
    for m in range(1, 4 * n):
        reqs += prefix_requirements(w, m, cand.q0, cand.steps, cand.q0_other)[0]
    engine = {q.name: q.G for q in reqs}
    q0 = tuple(field_to_frac(e) for e in cand.q0)
    ours = {x: {name: value for name, value, _ in F.binding_conditions(n, q0, Frac.of(x), LR_R)} for x in (0, 1)}
    for name in ours[0]:
        if name == "x":
            continue
        G0, G1 = (field_to_frac(e) for e in engine[name])
        assert ours[0][name] == G0 and ours[1][name] == G0 + G1, name
    implied = set(engine) - set(ours[0])
    assert implied == {f"p_3(t_{k})" for k in range(1, 2 * n)} | {f"p_1(t_{k})" for k in range(2 * n + 1, 4 * n)}


@pytest.mark.parametrize("n", [2, 3, 5])
def test_position_map_is_the_engines_up_to_a_factor(n):
    """(a, b, c, d) in closed form is proportional to the engine's, on every branch (modulo cp)."""
    from certify.algebra.poly import frac_to_field, ring_to_lrq
    from certify.dynamics.words import _lrq_to_frac, reduce_mod
    cand = candidate(F.family_word(n))
    q0 = tuple(field_to_frac(e) for e in cand.q0)
    ours = F.position_map(n, q0, LR_R)
    theirs = [_lrq_to_frac(ring_to_lrq(e)) for e in cand.abcd_ring]
    for i in range(4):
        for j in range(i + 1, 4):
            e = ours[i] * theirs[j] - ours[j] * theirs[i]
            assert reduce_mod(frac_to_field(e), cand.cp) == 0, (i, j)


@pytest.mark.parametrize("n", [2, 4])
def test_dominance_is_the_engines(n):
    """The dominance conditions in closed form are the engine's polynomials in (λ, r)."""
    from certify.algebra.poly import to_field
    from certify.patterns.pattern import dominance_requirements
    cand = candidate(F.family_word(n))
    ours = {name: value for name, value, _ in F.dominance(n, LR_LAMBDA, LR_R)}
    for q in dominance_requirements(cand.spectrum.ring_cp):
        assert ours[q.name] == field_to_frac(to_field(q.G[0])), q.name
