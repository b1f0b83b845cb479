"""The island theorem (certify/patterns/island_theorem.py): every step at rational r and for
the symbol r, each against an independent computation, and a mutant of each step refused."""
from __future__ import annotations

import math
from fractions import Fraction

import flint
import mpmath
import numpy as np
import pytest
import sympy as sp

from certify.algebra import Algebraic
from certify.dynamics import island, reduction
from certify.dynamics.model import collide
from certify.patterns import island_theorem as it

ELLIPTIC = [flint.fmpq(3, 10), flint.fmpq(1, 2), flint.fmpq(9, 10), flint.fmpq(18, 100)]


@pytest.mark.parametrize("r", ELLIPTIC)
def test_every_step_holds_inside_the_interval(r):
    T = it.theorem(r)
    assert [s.name[:4] for s in T.steps] == ["(a) ", "(b) ", "(c) ", "(c′)", "(d) ", "(e) ", "(f) "]
    assert all(s.holds for s in T.steps), [s.evidence for s in T.steps if not s.holds]
    assert T.elliptic and T.quasi_periodic
    assert T.c_max == 1 - (1 - r) ** 2 / (4 * r)


@pytest.mark.parametrize("r", [flint.fmpq(1, 10), flint.fmpq(17, 100), flint.fmpq(1, 1000)])
def test_outside_the_interval_the_theorem_says_not_elliptic(r):
    T = it.theorem(r)
    assert T.holds and not T.elliptic and not T.quasi_periodic and T.c_max is None
    assert "not elliptic" in T.steps[-1].name


def test_elliptic_exactly_above_three_minus_two_root_two():
    """The boundary of the elliptic range against an independent computation: the eigenvalues
    of the matrix of the b-to-b map in mpmath, from the exact orbit of reduction.step."""
    for r in (flint.fmpq(171, 1000), flint.fmpq(172, 1000)):
        A = _observed_matrix(r)
        ev = mpmath.eig(mpmath.matrix(A))[0]
        elliptic = all(abs(mpmath.im(z)) > 1e-20 for z in ev)
        assert it.theorem(r).elliptic == elliptic


def _observed_matrix(r) -> list:
    """The b-to-b map in the chart, read off the exact orbit of reduction.step at two states
    (it is linear: col2 = 10·A(0, 1/10), col1 = 10·(A(1/10, 1/10) − A(0, 1/10)))."""
    def image(x, y):
        P = reduction.canonical("b", island.normal(x, y))
        while True:
            P = reduction.step(P, r)
            if P.letter == "b":
                return island.chart(P.n)
    t = flint.fmpq(1, 10)
    a, b = image(t, t), image(flint.fmpq(0), t)
    col1, col2 = [10 * (x - y) for x, y in zip(a, b)], [10 * y for y in b]
    return [[mpmath.mpf(int(z.p)) / int(z.q) for z in (col1[i], col2[i])] for i in (0, 1)]


def test_the_symbolic_theorem_holds_on_the_interval():
    T = it.symbolic_theorem()
    assert T.holds, [s.evidence for s in T.steps if not s.holds]
    assert sp.simplify(T.c_max - (1 - (1 - it.R_SYMBOL) ** 2 / (4 * it.R_SYMBOL))) == 0


def test_the_region_is_read_from_the_reduction_rules():
    """The leaves through R are exactly the two words, on the two sides of v = 0, and the
    region they cover agrees with reduction.step on a grid of exact states."""
    r = flint.fmpq(3, 10)
    rs = sp.Rational(3, 10)
    cofs = {L: it.cof(it.matrix(collide, L, rs)) for L in "abc"}
    leaves = it.explore(island.normal(it.u, it.v), cofs, False)
    assert sorted(w for _, w in leaves if w in it.WORDS) == ["acb", "cab"]
    h = (1 + r) / 2
    for a in range(-9, 10, 2):
        for b in range(-9, 10, 2):
            x, y = flint.fmpq(a, 10), flint.fmpq(b, 4)
            P = reduction.canonical("b", island.normal(x, y))
            letters = ""
            try:
                while len(letters) < 3:
                    P = reduction.step(P, r)
                    letters += P.letter
                    if P.letter == "b":
                        break
            except reduction.Corner:
                letters += "|corner"
            assert (letters in it.WORDS) == (abs(x - h * y) < 1), (x, y, letters)


def _claims(**kw):
    return it.Claims(**kw)


def perturbed_c(letter, q, rr):
    x = collide(letter, q, rr)
    return (x[0] + q[2] / 100, x[1], x[2]) if letter == "c" else x


MUTANTS = {
    "K_c perturbed: K_a K_c ≠ K_c K_a": (_claims(law=perturbed_c), "(a)"),
    "A perturbed": (_claims(A=lambda r: ((1, -(1 + r) / 2),
                                         ((1 + r) / r, -(1 + r * r) / (2 * r) + sp.Rational(1, 999)))), "(c)"),
    "Q perturbed": (_claims(Q=lambda u, v, r: 2 * u * u - (1 + r) * u * v + r * v * v + u * v / 1000), "(d)"),
    "c_max wrong": (_claims(c_max=lambda r: island.c_max(r) * sp.Rational(101, 100)), "(e)"),
    "R perturbed": (_claims(walls=lambda r: [1 - it.u, 1 + it.u, 1 - it.u + r * it.v, 1 + it.u - r * it.v]), "(b)"),
    "R widened": (_claims(walls=lambda r: [2 - it.u, 2 + it.u, 1 - it.u + (1 + r) * it.v / 2,
                                           1 + it.u - (1 + r) * it.v / 2]), "(b)"),
    "a word perturbed": (_claims(words=("acb", "cb")), "(b)"),
    "words swapped": (_claims(words=("cab", "acb")), "(b)"),
}


@pytest.mark.parametrize("name", sorted(MUTANTS))
def test_a_mutant_of_each_step_is_refused(name):
    claims, step = MUTANTS[name]
    T = it.theorem(flint.fmpq(3, 10), claims)
    assert not T.holds and not T.quasi_periodic
    assert any(s.name.startswith(step) and not s.holds for s in T.steps), [(s.name, s.holds) for s in T.steps]


def test_a_perturbed_map_is_refused_by_the_reduction_route():
    """A law whose b-to-b map is not the reduction's: step (c) compares with reduction.step."""
    A = sp.Matrix([[1, sp.Rational(-13, 20)], [sp.Rational(13, 3), sp.Rational(-109, 60)]])
    assert it._matches_reduction(A, sp.Rational(3, 10))
    assert not it._matches_reduction(A + sp.Matrix([[0, 0], [sp.Rational(1, 100), 0]]), sp.Rational(3, 10))


# --- independent computations -----------------------------------------------------------

def _mp_orbit(r, x, returns: int, dps: int = 60):
    """The b-returns of the orbit from the chart point x, by the paper's vector formula
    (reduction.vectorial_step) in mpmath, normalised each step: (chart points, words)."""
    with mpmath.workdps(dps):
        rr = mpmath.mpf(int(r.p)) / int(r.q)
        n = tuple(mpmath.mpf(int(z.p)) / int(z.q) for z in island.normal(*x))
        letter, points, words, w = "b", [], [], ""
        while len(points) < returns:
            letter, n = reduction.vectorial_step(letter, n, rr)
            n = tuple(z / mpmath.norm(n) for z in n)
            w += letter
            if letter == "b":
                d = n[2] - n[0]
                points.append(((n[0] + n[2]) / d, 2 * n[1] / d))
                words.append(w)
                w = ""
        return points, words


@pytest.mark.parametrize("r", [flint.fmpq(3, 10), flint.fmpq(4, 5)])
def test_mpmath_orbits_stay_on_their_ellipse(r):
    x = (flint.fmpq(1, 5), flint.fmpq(1, 7))
    Q0 = island.quadratic_form(*x, r)
    assert Q0 < island.c_max(r)
    points, words = _mp_orbit(r, x, 200)
    assert set(words) <= {"acb", "cab"} and len(set(words)) == 2
    with mpmath.workdps(60):
        rr = mpmath.mpf(int(r.p)) / int(r.q)
        q0 = mpmath.mpf(int(Q0.p)) / int(Q0.q)
        drift = max(abs(2 * a * a - (1 + rr) * a * b + rr * b * b - q0) for a, b in points)
    assert drift < mpmath.mpf(10) ** -45
    exact = [tuple(flint.fmpq(Fraction(mpmath.nstr(z, 40)).numerator, Fraction(mpmath.nstr(z, 40)).denominator)
                   for z in x) for x in points[:20]]
    assert all(island.island_sign(island.normal(*x), r) == 1 for x in exact)


def test_an_orbit_outside_the_island_leaves_its_level():
    """Control: the same measure on a state outside U_r whose orbit leaves R changes level."""
    r = flint.fmpq(3, 10)
    x = (flint.fmpq(-9, 10), flint.fmpq(-1, 1))
    assert island.quadratic_form(*x, r) > island.c_max(r)
    _, words = _mp_orbit(r, x, 30)
    assert set(words) - {"acb", "cab"}


@pytest.mark.parametrize("r", [flint.fmpq(3, 10), flint.fmpq(7, 10)])
def test_rotation_number_measured_along_an_exact_orbit(r):
    """ρ(r) against the exact orbit of reduction.step: the angle advance per b-return in the
    coordinates where Q is Euclidean, and the count of turns."""
    P = reduction.canonical("b", island.normal(flint.fmpq(1, 5), flint.fmpq(1, 7)))
    rf = float(r)
    k = math.sqrt(rf - (1 + rf) ** 2 / 8)
    angles = []
    while len(angles) < 300:
        P = reduction.step(P, r)
        if P.letter == "b":
            a, b = (float(z) for z in island.chart(P.n))
            angles.append(math.atan2(k * b, math.sqrt(2) * (a - (1 + rf) * b / 4)))
    steps = [(y - x) % (2 * math.pi) for x, y in zip(angles, angles[1:])]
    measured = sum(steps) / len(steps) / (2 * math.pi)
    turns = sum(1 for x, y in zip(angles, angles[1:]) if (y - x) % (2 * math.pi) > 0 and y < x)
    rho = float(it.rotation_number(r, 20))
    assert abs(measured - rho) < 1e-9
    assert abs(turns / len(steps) - rho) < 2 / len(steps)
    assert 0.25 < rho < 0.5


def test_rotation_number_digits_against_mpmath():
    for r in (flint.fmpq(3, 10), flint.fmpq(99, 100), flint.fmpq(172, 1000)):
        text = it.rotation_number(r, 20)
        with mpmath.workdps(60):
            rr = mpmath.mpf(int(r.p)) / int(r.q)
            exact = mpmath.acos(-(1 - rr) ** 2 / (4 * rr)) / (2 * mpmath.pi)
            assert abs(mpmath.mpf(text) - exact) < mpmath.mpf(10) ** -20
        assert len(text.replace("0.", "", 1).lstrip("0")) >= 15


def test_resonances_are_the_fractions_between_a_quarter_and_a_half():
    Q = 12
    found = it.resonances(Q)
    farey = sorted({Fraction(p, q) for q in range(2, Q + 1) for p in range(1, q)
                    if Fraction(1, 4) < Fraction(p, q) < Fraction(1, 2)})
    assert sorted(Fraction(s.p, s.q) for s in found) == farey
    with mpmath.workdps(40):
        for s in found:
            x = mpmath.mpf(s.r.digits(30))
            rho = mpmath.acos(-(1 - x) ** 2 / (4 * x)) / (2 * mpmath.pi)
            assert abs(rho - mpmath.mpf(int(s.p)) / int(s.q)) < 1e-25
    rs = [s.r for s in found]
    assert all(a < b for a, b in zip(rs, rs[1:]))                 # ρ decreasing in r: p/q decreasing
    assert [Fraction(s.p, s.q) for s in found] == sorted(farey, reverse=True)


def test_resonance_of_two_minus_root_three_and_the_end():
    assert it.resonance_of(Algebraic.surd(2, -1, 3), 6) == (1, 3)
    assert it.resonance_of(Algebraic.surd(2, -1, 3), 2) is None            # q = 3 > 2
    assert it.resonance_of(Algebraic.surd(3, -2, 2), 20) is None            # ρ = 1/2 at the end, not inside
    assert it.resonance_of(Algebraic.rational(flint.fmpq(3, 10)), 20) is None
    assert it.resonance_of(Algebraic.surd(2, -1, 3).refine(flint.fmpq(1, 10 ** 9)), 6) == (1, 3)
    assert it.cos_minimal_polynomial(2).degree() == 1
    assert it.resonance_polynomial(2)(Algebraic.surd(3, -2, 2).arb(64)).contains(0)   # c = −1 at 3−2√2


def test_island_fraction_against_monte_carlo():
    r = flint.fmpq(3, 10)
    lo, hi = it.island_fraction(r, depth=8)
    rng = np.random.default_rng(7)
    N = 200_000
    th, ph = rng.uniform(0, np.pi / 2, N), rng.uniform(0, np.pi, N)
    n = np.array([-np.cos(th) * np.sin(ph), np.cos(ph), np.sin(th) * np.sin(ph)])   # p ∧ q at b
    U, V = (n[0] + n[2]) / (n[2] - n[0]), 2 * n[1] / (n[2] - n[0])
    rf = float(r)
    share = np.mean(2 * U * U - (1 + rf) * U * V + rf * V * V < float(island.c_max(r)))
    sigma = math.sqrt(share * (1 - share) / N)
    assert float(lo) - 4 * sigma < share < float(hi) + 4 * sigma
    assert hi - lo < flint.fmpq(1, 10)
    lo2, hi2 = it.island_fraction(r, depth=5)
    assert lo2 <= lo and hi <= hi2
    assert it.island_fraction(flint.fmpq(1, 10)) == (0, 0)


@pytest.mark.slow
def test_many_rationals_and_long_orbits():
    """30 random rationals: the theorem holds, elliptic exactly above 3−2√2 (compared with the
    algebraic number), and a long mpmath orbit keeps its level."""
    rng = np.random.default_rng(11)
    for _ in range(30):
        r = flint.fmpq(int(rng.integers(1, 999)), 1000)
        T = it.theorem(r)
        assert T.holds
        assert T.elliptic == (Algebraic.rational(r) > it.LOWER_END)
        if T.elliptic:
            x = (flint.fmpq(1, 9), flint.fmpq(-1, 11))
            if island.quadratic_form(*x, r) < island.c_max(r):
                points, words = _mp_orbit(r, x, 2000, dps=80)
                assert set(words) <= {"acb", "cab"}


@pytest.mark.parametrize("r", [flint.fmpq(3, 10), flint.fmpq(19, 100)])
def test_the_two_box_classifications_never_contradict(r):
    """box_sign (monotone enclosure of the chart) against box_sign_balls (plain balls through
    reduction.Angles): never inside for one and outside for the other; the first decides more."""
    decided = [0, 0]
    with it.precision(64):
        for i in range(16):
            for j in range(16):
                box = (flint.fmpq(i, 16), flint.fmpq(i + 1, 16), flint.fmpq(j, 16), flint.fmpq(j + 1, 16))
                a, b = it.box_sign(box, r), it.box_sign_balls(box, r)
                assert a * b >= 0, box
                decided[0] += a != 0
                decided[1] += b != 0
    assert decided[0] >= decided[1] > 0


def _end(x: Algebraic) -> dict:
    x.refine(flint.fmpq(1, 10 ** 12))
    return {"exact": None, "minimal_polynomial": it.show(x.minimal_polynomial()),
            "interval": [str(Fraction(int(x.lo.p), int(x.lo.q))), str(Fraction(int(x.hi.p), int(x.hi.q)))],
            "digits": x.digits(12)}


def test_window_ends_that_are_resonances():
    """Ends written as the census writes them (minimal polynomial as printed, interval) are read
    back exactly; 2 − √3 is ρ = 1/3, 3 − 2√2 the end ρ = 1/2, r = 1 the end ρ = 1/4, 1/5 none."""
    windows = {"w1": [{"lo": _end(Algebraic.rational(flint.fmpq(1, 5))), "hi": _end(Algebraic.surd(2, -1, 3))}],
               "w2": [{"lo": {"exact": "1/10", "digits": "0.1"}, "hi": _end(Algebraic.surd(3, -2, 2))}],
               "w3": [{"lo": _end(Algebraic.surd(5, -2, 6)), "hi": {"exact": "1", "digits": "1"}}]}
    found = {(w, side): pq for w, side, _d, pq in it.window_resonances(windows, 12)}
    assert found == {("w1", "hi"): (1, 3), ("w2", "hi"): (1, 2), ("w3", "hi"): (1, 4)}
    assert it.algebraic_of(windows["w1"][0]["hi"]) == Algebraic.surd(2, -1, 3)


def test_box_sign_with_the_sides_of_a_run_is_box_sign_alone():
    """island_fraction's shared Sides (the balls at the boxes' sides, computed once a side) give
    every box the sign box_sign gives it computing them; a Sides of another r is not used."""
    r = flint.fmpq(3, 10)
    with it.precision(64):
        sides, other = it.Sides(r), it.Sides(flint.fmpq(1, 2))
        for i in range(32):
            for j in range(1, 31):
                box = (flint.fmpq(i, 32), flint.fmpq(i + 1, 32), flint.fmpq(j, 32), flint.fmpq(j + 1, 32))
                alone = it.box_sign(box, r)
                assert it.box_sign(box, r, sides) == alone == it.box_sign(box, r, other)


def test_the_theorem_is_proved_once_a_run():
    """theorem(r) with the default claims is kept until the caches are emptied
    (caches.for_a_run), then proved again with the same verdicts; other claims never kept."""
    from certify import caches
    r = flint.fmpq(2, 5)
    T = it.theorem(r)
    assert it.theorem(r) is T and it.theorem(r, it.Claims()) is not T
    caches.reset()
    U = it.theorem(r)
    assert U is not T and [(s.name, s.holds, s.evidence) for s in U.steps] == \
        [(s.name, s.holds, s.evidence) for s in T.steps]


def test_signs_on_the_interval_from_the_field_and_from_sympy():
    """The sign of an element of Q(r) on ]3−2√2, 1[ (Coefficients, from its numerator and
    denominator) is interval_sign's of the same rational function; a change of sign inside
    is refused by both."""
    F = it.Coefficients(True)
    rs = it.R_SYMBOL
    for e in ((1 + rs) / (2 * rs), -(rs ** 2 - 6 * rs + 1) / (4 * rs), (rs - 2) * (rs + 3) / (rs ** 2 + 1), rs / 7):
        assert F.sign(F.of(e)) == it.interval_sign(e)
    for e in (rs - sp.Rational(1, 2), (rs - sp.Rational(1, 3)) / (rs + 1)):
        with pytest.raises(ValueError):
            F.sign(F.of(e))
        with pytest.raises(ValueError):
            it.interval_sign(e)


def test_a_theorem_crosses_process_boundaries_with_its_evidence():
    """A Theorem pickles (a worker may return one) with every step's evidence written."""
    import pickle
    T = it.prove(flint.fmpq(7, 10), it.Claims())
    U = pickle.loads(pickle.dumps(T))
    assert [(s.name, s.holds, s.evidence) for s in U.steps] == [(s.name, s.holds, s.evidence) for s in T.steps]
    assert U.quasi_periodic and U.c_max == T.c_max


def test_a_key_hashes_as_its_rationals_and_equals_as_its_tuple():
    """Key (the branching's dict key) hashed from its coefficients' numerators and
    denominators: equal keys hash alike, whatever the fmpq were made from; unequal keys
    differ; over Q(r) it is the tuple's hash."""
    q = flint.fmpq
    a, b = it.Key((q(1), q(2, 4), q(-3, 6))), it.Key((q(1), q(1, 2), q(-1, 2)))
    assert a == b and hash(a) == hash(b) and {a: 1}[b] == 1
    assert it.Key((q(1), q(1, 3), q(0))) != a and (q(1), q(1, 2), q(-1, 2)) == a
    F = it.Coefficients(True)
    x, y = it.form_key(it.u + it.R_SYMBOL * it.v, True)[1], it.form_key(2 * it.u + 2 * it.R_SYMBOL * it.v, True)[1]
    assert x == y and hash(x) == hash(y) and hash(x) == tuple.__hash__(x) and F.symbolic
