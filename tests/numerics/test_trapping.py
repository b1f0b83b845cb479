"""Certified trapping ellipses of attracting periodic orbits of the reduction
(certify/numerics/trapping.py): the certificate holds where the orbit attracts, is
refused where it does not (or for a U too large, or a perturbed map), and agrees with
the exact reduction map of certify/dynamics/reduction.py on rational normals of U."""
import flint
import pytest

from certify import cli
from certify.dynamics import reduction as R
from certify.errors import UsageError
from certify.numerics import trapping
from certify.numerics.trapping import Trap, attempt, check, products, trap

COMPLEX = "abacbabcbcabcb"           # complex in-plane pair, attracting on ]0.22007…, 1[
REAL = "ababcbcb"                    # (ab)^2(cb)^2, real pair
Q = flint.fmpq
NEAR_EDGE = Q(999, 1000)            # sample points at this fraction of the radius


@pytest.fixture(scope="module")
def complex_trap():
    return trap(COMPLEX, Q(3, 10))


@pytest.fixture(scope="module")
def real_trap():
    return trap(REAL, Q(3, 20))


def test_complex_pair_orbit_has_a_certified_trap(complex_trap):
    T = complex_trap
    assert isinstance(T, Trap) and T.pair == "complex"
    assert 0 < T.image < 1 and 0 < T.contraction < 1 and T.radius > 0
    assert 0 < T.inner <= T.outer and T.distance < T.radius
    assert T.contains(T.centre) and T.centre[2] == 1
    assert "follows abacbabcbcabcb for ever" in T.summary()


def test_real_pair_orbit_has_a_certified_trap(real_trap):
    assert isinstance(real_trap, Trap) and real_trap.pair == "real"
    assert real_trap.image < 1 and real_trap.contraction < 1


def test_refused_outside_the_attracting_window():
    """At r = 1/10 the word's attracting orbit does not exist (the window is ]0.22007…, 1[)."""
    assert trap(COMPLEX, Q(1, 10)) is None
    assert "does not realise" in attempt(COMPLEX, Q(1, 10))


def test_refused_for_a_too_large_ellipse(complex_trap):
    T = complex_trap
    why = check(COMPLEX, T.r, T.centre, T.frame, 4 * T.radius)
    assert isinstance(why, str) and "wall" in why


def test_refused_for_a_perturbed_map(complex_trap):
    """The ellipse certified at 3/10, checked against the return map at 31/100 (a perturbed
    matrix): its centre is no longer nearly fixed, and a small ellipse is refused."""
    T = complex_trap
    why = check(COMPLEX, Q(31, 100), T.centre, T.frame, T.radius / 1000)
    assert isinstance(why, str) and "F(U) ⊂ U" in why
    assert isinstance(check(COMPLEX, T.r, T.centre, T.frame, T.radius / 1000), Trap)


def test_refused_for_a_perturbed_word(complex_trap):
    """The same ellipse for another word (two letters swapped) violates a wall."""
    T = complex_trap
    other = "abacbabcbacbcb"
    assert sorted(other) == sorted(COMPLEX) and other != COMPLEX
    assert isinstance(check(other, T.r, T.centre, T.frame, T.radius / 1000), str)


def test_dropping_the_face_walls_breaks_the_exact_check(monkeypatch):
    """Mutation: without the face walls the certificate accepts, for (ab)^2(cb)^2 at 3/20, an
    ellipse from whose points the exact reduction leaves the word: the walls carry the proof."""
    honest = trap(REAL, Q(3, 20))
    assert all(_follows(honest, u, 1) for u in _boundary(honest, 16))
    walls = trapping.walls
    monkeypatch.setattr(trapping, "walls", lambda word, P: [w for w in walls(word, P) if not w.name.startswith("face")])
    big = trap(REAL, Q(3, 20))
    assert big.radius > honest.radius
    assert not all(_follows(big, u, 1) for u in _boundary(big, 16))


def _boundary(T: Trap, count: int, shrink=NEAR_EDGE) -> list:
    """Rational points u of the circle |u| = shrink·ρ: ((1-s²)/(1+s²), 2s/(1+s²))."""
    out = []
    for k in range(count):
        s = Q(4 * k - 2 * count, count)
        out.append((T.radius * shrink * (1 - s * s) / (1 + s * s), T.radius * shrink * 2 * s / (1 + s * s)))
    return out


def _normal(T: Trap, u) -> tuple:
    return tuple(T.centre[k] + T.frame[0][k] * u[0] + T.frame[1][k] * u[1] for k in range(3))


def _follows(T: Trap, u, periods: int) -> bool:
    P = R.canonical(T.word[-1], _normal(T, u))
    for _ in range(periods):
        w, P = R.word_of(P, T.r, len(T.word))
        if w != T.word or not T.contains(P.n):
            return False
    return True


@pytest.mark.parametrize("which", ["complex", "real"])
def test_points_of_u_follow_the_word_exactly_and_stay_in_u(which, complex_trap, real_trap):
    """Consistency with the exact route: rational normals near the boundary of U and at its
    centre, followed by the exact reduction for three periods, realise w each period, come
    back inside image·U after one period, and inside U after each."""
    T = complex_trap if which == "complex" else real_trap
    for u in _boundary(T, 12) + [(Q(0), Q(0))]:
        P = R.canonical(T.word[-1], _normal(T, u))
        w, P1 = R.word_of(P, T.r, len(T.word))
        assert w == T.word
        v = T.coordinates(P1.n)
        assert v[0] ** 2 + v[1] ** 2 <= (T.image * T.radius) ** 2
        assert _follows(T, u, 3)


def test_the_trap_shrinks_towards_n_star(complex_trap):
    """Three periods contract |u - u*| by κ³ at least: |u_3| ≤ κ³(ρ + d) + d."""
    T = complex_trap
    u = _boundary(T, 4)[1]
    P = R.canonical("b", _normal(T, u))
    _w, P3 = R.word_of(P, T.r, 3 * len(T.word))
    v = T.coordinates(P3.n)
    bound = T.contraction ** 3 * (T.radius + T.distance) + T.distance
    assert v[0] ** 2 + v[1] ** 2 <= bound ** 2


def test_products_are_positive_multiples_of_cof_m(complex_trap):
    """N = P_L fixes the centre's direction up to a positive factor, to the centre's precision."""
    T = complex_trap
    N = products(COMPLEX, T.r)[-1]
    n = [sum(Q(N[i, j]) * T.centre[j] for j in range(3)) for i in range(3)]
    assert n[2] > 0
    assert all(abs(n[k] / n[2] - T.centre[k]) < Q(1, 2 ** 150) for k in range(2))


@pytest.mark.parametrize("word, r", [("abab", Q(1, 2)), ("abacbabcbcabcb", 2), ("abcc", Q(1, 3)), ("ab", "x")])
def test_bad_input_raises_usage_error(word, r):
    with pytest.raises(UsageError):
        attempt(word, r)


def test_cli_trap(capsys):
    assert cli.main(["orbit", "abacbabcbcabcb", "--trap", "3/10"]) == 0
    out = capsys.readouterr().out
    assert "certified trapping ellipse" in out and "radius ρ =" in out
    assert cli.main(["orbit", "(ab)^2(cb)^2", "--trap", "0.15"]) == 0
    assert "real frame" in capsys.readouterr().out
    assert cli.main(["orbit", "abacbabcbcabcb", "--trap", "1/10"]) == 1
    out = capsys.readouterr().out
    assert len(out.strip().splitlines()) == 1 and "no certified trapping neighbourhood" in out


@pytest.mark.parametrize("argv", [["orbit", "abacbabcbcabcb", "--trap", "2"], ["orbit", "ab", "--trap", "1/2"],
                                  ["orbit", "abacbabcbcabcb", "--trap", "x"]])
def test_cli_trap_bad_input_exit_2(argv, capsys):
    assert cli.main(argv) == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1


def test_ball_sign_agrees_with_the_exact_membership_and_refuses_straddling_balls(complex_trap):
    """Trap.ball_sign (identify's check that a rigorous state lies in U): +1 on small balls
    around rational points just inside U, −1 just outside, 0 for a ball straddling the
    boundary; a positive multiple of the normal changes nothing, a negative one is refused."""
    from certify.algebra.balls import precision
    T = complex_trap
    with precision(256):
        for inside, shrink in ((True, Q(99, 100)), (False, Q(101, 100))):
            for u in _boundary(T, 6, shrink):
                n = _normal(T, u)
                assert T.contains(n) == inside
                ball = tuple(flint.arb(3 * z, Q(1, 10 ** 30)) for z in n)
                assert T.ball_sign(ball) == (1 if inside else -1)
                assert T.ball_sign(tuple(-z for z in ball)) == 0
        u = _boundary(T, 1, Q(1))[0]
        wide = tuple(flint.arb(z, T.radius / 100) for z in _normal(T, u))
        assert T.ball_sign(wide) == 0


# ------------------------------------------------------------------ the bounds of check() against the map itself
def _g(T: Trap, u) -> tuple:
    """The return map in the frame, by the exact reduction (one period from c + T u)."""
    w, P = R.word_of(R.canonical(T.word[-1], _normal(T, u)), T.r, len(T.word))
    assert w == T.word
    return T.coordinates(P.n)


def _dg_norm(T: Trap, u, h) -> flint.arb:
    """‖Dg(u)‖₂ by exact central differences of the exact return map (step h), in arb."""
    cols = []
    for d in ((h, 0), (0, h)):
        plus, minus = _g(T, (u[0] + d[0], u[1] + d[1])), _g(T, (u[0] - d[0], u[1] - d[1]))
        cols.append([(a - b) / (2 * h) for a, b in zip(plus, minus)])
    return trapping._spectral(((cols[0][0], cols[1][0]), (cols[0][1], cols[1][1])))


@pytest.mark.parametrize("which", ["complex", "real"])
def test_the_jacobian_of_the_exact_return_map_is_below_kappa_on_u(which, complex_trap, real_trap):
    """‖Dg‖ ≤ κ at points of U near its boundary and at its centre, Dg from the exact reduction
    map (differences of step ρ·2^-40), not from the formula of check().  The term R|β|/(α - |β|ρ)
    of κ is needed: without it κ is below ‖Dg‖ on U (0.19 against 0.22 for the real trap)."""
    T = complex_trap if which == "complex" else real_trap
    h = T.radius / 2 ** 40
    with trapping.precision(128):
        for u in _boundary(T, 12, shrink=Q(1) - Q(1, 2 ** 20)) + [(Q(0), Q(0))]:
            assert _dg_norm(T, u, h) < T.contraction, u


def _lower_fixed_radius(T: Trap, bits: int = 2048) -> flint.arb:
    """ρ₀, the smaller root of |β|ρ² - (α - ‖A‖)ρ + |g_0| = 0: R(ρ) = ρ there (R < ρ just above it)."""
    g0, A, alpha, beta = trapping._return_map(products(T.word, T.r)[-1], T.centre, T.frame, T.chart)
    with trapping.precision(bits):
        b, a, n = trapping._norm(beta), flint.arb(alpha) - trapping._spectral(A), trapping._norm(g0)
        return (a - (a * a - 4 * b * n).sqrt()) / (2 * b)


def test_a_radius_at_the_boundary_of_r_below_rho_is_refused(real_trap, monkeypatch):
    """ρ just below ρ₀ (F(U) ⊄ U: R > ρ by a relative 2^-200), checked with balls of 20 to 59
    bits: R's ball then contains ρ, and check() must refuse at every precision; a check at the
    ball's midpoint accepts at some of them (verified below: the test reaches the boundary)."""
    T = real_trap
    with trapping.precision(2048):
        rho0 = _lower_fixed_radius(T)
        rho = trapping._dyadic(rho0 * (1 - flint.arb(2) ** -200), 400)
    g0, A, alpha, beta = trapping._return_map(products(T.word, T.r)[-1], T.centre, T.frame, T.chart)
    below_mid = 0
    for bits in range(20, 60):
        monkeypatch.setattr(trapping, "PREC", bits)
        why = check(T.word, T.r, T.centre, T.frame, rho)
        assert isinstance(why, str) and "F(U) ⊂ U" in why, (bits, why)
        with trapping.precision(bits):
            Rb = (trapping._norm(g0) + trapping._spectral(A) * rho) / (flint.arb(alpha) - rho * trapping._norm(beta))
            below_mid += bool(Rb.mid() < rho)
    assert below_mid > 0
    monkeypatch.setattr(trapping, "PREC", 256)
    assert isinstance(check(T.word, T.r, T.centre, T.frame, 2 * rho), Trap)          # above ρ₀: certified


def test_each_contact_wall_is_a_wall_of_the_next_state(complex_trap):
    """Why dropping the contact walls cannot change a certificate (docs/developing.md,
    mutation run): cof(K_j)'s rows other than j are multiples of e_m, so the contact wall at
    state k is a positive multiple of the orientation or face wall at state k + 1 (k < L - 1),
    and the last one of the orientation at the return or of the face wall at state 0 applied
    to N n (implied by F(U) ⊂ U)."""
    for word in (COMPLEX, REAL, "abacb"):
        P = products(word, Q(3, 10))
        ws = trapping.walls(word, P) + [trapping.Wall("face at the return", tuple(
            -Q(P[-1][(R.ORIENTATION[word[-1]] + 1) % 3, j]) for j in range(3)))]
        for k, w in enumerate(x for x in ws if x.name.startswith("contact")):
            later = [v for v in ws if f"state {k + 1} " in v.name or (k == len(word) - 1 and "return" in v.name)]
            assert any(_positive_multiple(w.row, v.row) for v in later), (word, w.name)


def _positive_multiple(a, b) -> bool:
    i = next(m for m in range(3) if a[m] != 0)
    f = b[i] / a[i]
    return f > 0 and all(b[m] == f * a[m] for m in range(3))


def test_ball_sign_decides_the_centre_itself(complex_trap):
    """The centre of U, as balls at any precision, is proved inside (ρ² − |u|² with u = 0 ± ε):
    python-flint's x ** 2 of a ball 0 ± ε is nan, which once left the centre undecided."""
    from certify.algebra.balls import precision
    for bits in (53, 128, 256):
        with precision(bits):
            assert complex_trap.ball_sign(tuple(flint.arb(z) for z in complex_trap.centre)) == 1, bits


def test_a_shape_computed_once_serves_every_radius(complex_trap):
    """check with the Shape of (centre, frame) given, as attempt and the bisection pass it, says
    what check says computing it: the same Trap, the same refusal, at radii on both sides."""
    T = complex_trap
    P = products(COMPLEX, T.r)
    form = trapping.shape(COMPLEX, T.centre, T.frame, P)
    for rho in (T.radius / 7, T.radius, T.radius * Q(21, 20), 4 * T.radius):
        given = check(COMPLEX, T.r, T.centre, T.frame, rho, T.pair, P, form)
        fresh = check(COMPLEX, T.r, T.centre, T.frame, rho, T.pair)
        assert given == fresh
    assert isinstance(check(COMPLEX, T.r, T.centre, T.frame, T.radius, T.pair, P, form), Trap)


def test_the_walls_given_to_shape_and_the_exact_dot_are_the_computed_ones(complex_trap):
    """shape with the walls given (as attempt passes them) is shape computing them, and the
    three-term _dot is the sum over the pairs (exact: the order does not matter)."""
    T = complex_trap
    P = products(COMPLEX, T.r)
    forms = trapping.walls(COMPLEX, P)
    def exact(x):                 # a ball as its midpoint and radius (== on balls is "certainly equal")
        if isinstance(x, flint.arb):
            return x.mid().fmpq(), x.rad().fmpq()
        return tuple(exact(y) for y in x) if isinstance(x, tuple) else x
    given, fresh = trapping.shape(COMPLEX, T.centre, T.frame, P, forms), trapping.shape(COMPLEX, T.centre, T.frame, P)
    assert [exact(getattr(given, k)) for k in given.__dataclass_fields__] == \
        [exact(getattr(fresh, k)) for k in fresh.__dataclass_fields__]
    for w in forms:
        for v in (T.centre, *T.frame):
            assert trapping._dot(w.row, v) == sum((x * y for x, y in zip(w.row, v)), Q(0))
