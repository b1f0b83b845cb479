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
