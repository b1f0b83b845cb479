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
    assert implied == F.implied_names(n)
    assert implied == {f"p_3(t_{k})" for k in range(1, 2 * n)} | {f"p_1(t_{k})" for k in range(2 * n + 1, 4 * n)}
    assert F.reduced_names(n) <= set(engine) | {"x"}


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


# ------------------------------------------------------------------ the quadrant proposition
def _in_quadrant(q):
    return q[0] < 0 < q[1]


@pytest.mark.parametrize("m", range(1, 9))
def test_quadrant_proposition_at_rational_points(m):
    """Q_0..Q_m in the open quadrant ⟺ Q_0, Q_m in it and r < ρ_m, exactly at rational r and
    Q_0 (a grid through both sides of ρ_m and of r* = 7 − 4√3)."""
    rho = F.turning_bound(m)
    seen = set()
    for k in range(1, 200):
        r0 = flint.fmpq(k, 400) if k < 100 else flint.fmpq(7, 100) + flint.fmpq(k - 100, 2000)
        s = F.chebyshev(m, r0)
        assert all(e > 0 for e in s[1:]) == (rho is None or rho.compare_rational(r0) > 0), (m, r0)
        for u in (flint.fmpq(1, 50), flint.fmpq(1, 3), flint.fmpq(2), flint.fmpq(9)):
            Q = [(flint.fmpq(-1), u)]
            K = F.block_K(r0)
            for _ in range(m):
                q = Q[-1]
                Q.append((K[0][0] * q[0] + K[0][1] * q[1], K[1][0] * q[0] + K[1][1] * q[1]))
            every = all(_in_quadrant(q) for q in Q)
            ends = _in_quadrant(Q[0]) and _in_quadrant(Q[-1]) and all(e > 0 for e in s[1:])
            assert every == ends, (m, r0, u)
            seen.add(every)
    assert seen == {True, False} or m == 1           # both cases met: the test can fail


def test_turning_bound_is_where_m_theta_is_pi():
    """ρ_m is the root of r² − (6 + 8 cos(π/m)) r + 1 in ]0, 1[ (balls); ρ_2 = 3 − 2√2."""
    from certify.algebra.algebraic import Algebraic
    assert F.turning_bound(1) is None
    assert F.turning_bound(2) == Algebraic.roots(flint.fmpq_poly([1, -6, 1]), 0, 1)[0]
    from certify.algebra.balls import precision
    for m in (3, 7, 20):
        with precision(200):
            a = 3 + 4 * (flint.arb.pi() / m).cos()
            ball = a - (a * a - 1).sqrt()
            assert abs(F.turning_bound(m).arb(200) - ball) < flint.arb(10) ** -40


# ------------------------------------------------------------------ the route of certify pattern
def _generic(word, monkeypatch):
    from certify.patterns import pattern as P
    with monkeypatch.context() as mp:
        mp.setattr(F, "family_n", lambda w: None)
        return P.analyse(word)


def _pieces(sets: list) -> tuple[dict, set]:
    """The intervals per (branch, fixed point), and the points as (branch, fixed point, r)."""
    intervals, points = {}, set()
    for e in sets:
        key = (e["branch"], e["fixed_point"])
        intervals[key] = [p for p in e["pieces"] if p["kind"] == "interval"]
        points |= {(*key, float(p["at"]["digits"])) for p in e["pieces"] if p["kind"] == "point"}
    return {k: v for k, v in intervals.items() if v}, points


def _undecided_at(undecided: list) -> set:
    """(branch, fixed point, r) of each undecided point ("middle x₊ at ≈0.0841870277: ...")."""
    out = set()
    for u in undecided:
        head, _, rest = u.partition(" at ≈")
        branch, fixed_point = head.split()
        out.add((branch, fixed_point, float(rest.split(":")[0])))
    return out


def _near(p, points) -> bool:
    return any(p[:2] == q[:2] and abs(p[2] - q[2]) < 1e-9 for q in points)


@pytest.mark.parametrize("n", [2, 3, 4, *(pytest.param(n, marks=pytest.mark.slow) for n in (5, 6))])
def test_family_route_gives_the_generic_sets(n, monkeypatch):     # n = 5, 6: minutes each
    """`certify pattern (ab)^n(cb)^n` through the family route: the same JSON as the generic route
    (every interval, condition, formula), except points the generic route left undecided: at
    r ≥ ρ_{n−1} the quadrant proposition proves the word infeasible, and at a multiple eigenvalue the
    eigenspace route, asked for the family's 11 conditions instead of 8n, may find a datum where the
    generic route found none (a point the family route adds is one the generic route left undecided)."""
    from certify.patterns import pattern as P
    w = F.family_word(n)
    ours, theirs = P.analyse(w), _generic(w, monkeypatch)
    a, b = ours.to_json(), theirs.to_json()
    assert {k for k in a if a[k] != b[k]} <= {"undecided", "verdict", "exists", "feasible", "stable"}
    assert set(a["undecided"]) <= set(b["undecided"])
    left = _undecided_at(b["undecided"])
    for stage in ("exists", "feasible", "stable"):
        (ia, pa), (ib, pb) = _pieces(a[stage]), _pieces(b[stage])
        assert ia == ib, stage
        assert pb <= pa and all(_near(p, left) for p in pa - pb), stage
    rho = F.turning_bound(n - 1)
    for u in set(b["undecided"]) - set(a["undecided"]):
        r = float(u.split("≈")[1].split(":")[0])
        assert r >= float(rho) - 1e-9 or _near(_undecided_at([u]).pop(), _pieces(a["feasible"])[1]), u
    if n <= 2:
        assert ours.json_text() == theirs.json_text() and ours.markdown() == theirs.markdown()


@pytest.mark.parametrize("n", [4, 5])
def test_family_route_mutants_fail(n, monkeypatch):
    """Without the cut at ρ_{n−1} the reduced conditions give a larger feasible set; with the cut
    at ρ_{2n} the stable window is cut: the route's sets are then not the generic ones."""
    from certify.patterns import pattern as P
    w = F.family_word(n)
    theirs = _generic(w, monkeypatch).to_json()
    bound = F.turning_bound
    monkeypatch.setattr(F, "turning_bound", lambda m: None)
    assert P.analyse(w).to_json()["feasible"] != theirs["feasible"]
    monkeypatch.setattr(F, "turning_bound", lambda m: bound(2 * m + 2))
    assert P.analyse(w).to_json()["stable"] != theirs["stable"]
