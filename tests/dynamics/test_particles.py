"""certify.dynamics.particles: four particles in absolute coordinates, exactly; the particles command."""
import doctest
import os
import subprocess
import sys
from fractions import Fraction
from pathlib import Path

import flint
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from certify import cli
from certify.dynamics import particles
from certify.dynamics import simulate as sim
from certify.dynamics.model import INDEX, collide, collide_particles
from certify.dynamics.particles import History, evolve
from certify.errors import UsageError

Q = flint.fmpq
ROOT = Path(__file__).resolve().parents[2]


def fmpq_of(f: Fraction) -> flint.fmpq:
    return Q(f.numerator, f.denominator)


rationals = st.fractions(min_value=-5, max_value=5, max_denominator=30).map(fmpq_of)
restitution = st.fractions(min_value=0, max_value=1, max_denominator=40).filter(
    lambda f: 0 < f < 1).map(fmpq_of)
positions = st.lists(rationals, min_size=4, max_size=4).map(sorted)
velocities = st.lists(rationals, min_size=4, max_size=4)
# mirror-symmetric data x = (-b, -a, a, b), v = (w, u, -u, -w): a and c come together
symmetric = st.tuples(rationals, rationals, rationals, rationals).map(
    lambda z: ((-max(abs(z[0]), abs(z[1])), -min(abs(z[0]), abs(z[1])),
                min(abs(z[0]), abs(z[1])), max(abs(z[0]), abs(z[1]))), (z[2], z[3], -z[3], -z[2])))
data = st.one_of(st.tuples(positions, velocities), symmetric)


def pairs(letters: str) -> list[int]:
    """The left particles (0-based) of the colliding pairs."""
    return [INDEX[L] for L in letters]


def test_doctest():
    assert doctest.testmod(particles).failed == 0


# --------------------------------------------------------------------------
# The law

@pytest.mark.parametrize("letter", "abc")
def test_differences_of_the_law_are_the_collision_matrices(letter):
    """diff(v') = K diff(v) for K = A, B, C, as an identity in r, v1..v4: the printed
    matrices (l. 208-232) follow from the law (l. 158-163)."""
    r = sp.Symbol("r")
    v = sp.symbols("v1:5")
    w = collide_particles(letter, v, r)
    diff = particles.differences
    assert all(sp.expand(a - b) == 0 for a, b in zip(diff(w), collide(letter, diff(v), r)))


@pytest.mark.parametrize("letter", "abc")
def test_the_law_conserves_momentum_and_scales_the_relative_velocity(letter):
    """l. 160-162, symbolically: v_i + v_{i+1} kept, v_{i+1} - v_i times -r, others kept."""
    r = sp.Symbol("r")
    v = sp.symbols("v1:5")
    w = collide_particles(letter, v, r)
    i = INDEX[letter]
    assert sp.expand(w[i] + w[i + 1] - v[i] - v[i + 1]) == 0
    assert sp.expand(w[i + 1] - w[i] + r * (v[i + 1] - v[i])) == 0
    assert all(w[k] == v[k] for k in range(4) if k not in (i, i + 1))


def test_unknown_letter():
    with pytest.raises(ValueError):
        collide_particles("d", (1, 2, 3, 4), Q(1, 2))


# --------------------------------------------------------------------------
# Properties of the orbits

def check_collision(before: tuple, c, r) -> None:
    """One collision from the state ``before`` = (t, x, v): free motion up to c.t,
    contact of the colliding pairs, order kept, then the law on each pair."""
    t0, x0, v0 = before
    assert c.t > t0 or (c.t == 0 == t0)                 # times increase (t_1 may be 0)
    assert c.x == tuple(x + (c.t - t0) * v for x, v in zip(x0, v0))   # l. 155-156
    assert all(c.x[i] <= c.x[i + 1] for i in range(3))  # the order never changes
    assert sum(c.v) == sum(v0)                          # momentum
    moved = set()
    for i in pairs(c.letters):
        assert c.x[i] == c.x[i + 1]                     # the pair is exactly in contact
        assert c.v[i + 1] - c.v[i] == -r * (v0[i + 1] - v0[i])
        assert c.v[i + 1] - c.v[i] > 0                  # and separates (l. 177)
        moved |= {i, i + 1}
    assert all(c.v[k] == v0[k] for k in range(4) if k not in moved)


@settings(max_examples=60, deadline=None)
@given(data, restitution)
def test_orbit_properties(xv, r):
    x, v = xv
    h = evolve(x, v, r, 30)
    state = (Q(0), tuple(x), tuple(v))
    for c in h.collisions:
        check_collision(state, c, r)
        state = (c.t, c.x, c.v)
    if h.stop == "separate":                            # nothing approaches any more
        assert all(state[2][i] <= state[2][i + 1] for i in range(3))
    if h.stop == "triple":                              # the particles meet at one point
        m = h.triple
        assert len(m.particles) >= 3 and len({m.x[k - 1] for k in m.particles}) == 1
        assert m.t >= state[0] and m.v == state[2]
    assert (h.stop == "n") == (len(h.collisions) == 30)


@settings(max_examples=60, deadline=None)
@given(data, restitution)
def test_agrees_with_the_relative_simulator(xv, r):
    """The same word, the same times, diff(x) = p and diff(v) = q at every collision:
    the relative run moves p, q with the printed matrices, this one x, v with the law."""
    x, v = xv
    diff = particles.differences
    h = evolve(x, v, r, 30)
    run = sim.follow(diff(x), diff(v), r, 30)
    assert run.events == [c.letters for c in h.collisions]
    assert {"n": "n", "free": "separate", "multiple": "triple"}[run.stop] == h.stop
    for s, c in zip(run.states[1:], h.collisions):
        assert (s.t, s.p, s.q) == (c.t, diff(c.x), diff(c.v))


# --------------------------------------------------------------------------
# Hand-computed orbits (r = 1/2, so h = (1 + r)/2 = 3/4)

def times(h: History) -> list[str]:
    return [str(c.t) for c in h.collisions]


def test_a_then_c_then_b():
    """x = (0, 1, 3, 5), v = (1, 0, 0, -1).  Gap a closes at speed 1: a at t = 1,
    x = (1, 1, 3, 4), v -> (1 - 3/4, 3/4, 0, -1) = (1/4, 3/4, 0, -1).  Gap c (1 left)
    closes at speed 1: c at t = 2, x = (5/4, 7/4, 3, 3), v -> (1/4, 3/4, -3/4, -1/4).
    Gap b = 3 - 7/4 = 5/4 closes at speed 3/2: b at t = 2 + 5/6 = 17/6."""
    h = evolve([0, 1, 3, 5], [1, 0, 0, -1], "1/2", 3)
    assert h.word == "acb" and times(h) == ["1", "2", "17/6"]
    assert h.collisions[0].v == (Q(1, 4), Q(3, 4), Q(0), Q(-1))
    assert h.collisions[1].x == (Q(5, 4), Q(7, 4), Q(3), Q(3))
    assert h.collisions[1].v == (Q(1, 4), Q(3, 4), Q(-3, 4), Q(-1, 4))


def test_simultaneous_a_and_c_then_separation():
    """x = (0, 1, 3, 4), v = (1, 0, 0, -1): both outer gaps close at speed 1, a and c
    at t = 1, both applied: v = (1/4, 3/4, -3/4, -1/4).  b: gap 2 at speed 3/2, t = 7/3,
    x2 = x3 = 2, v -> (1/4, -3/8, 3/8, -1/4).  The gaps a, c (2/3 each) close at 5/8:
    ac at t = 7/3 + 16/15 = 17/5, v -> (-7/32, 3/32, -3/32, 7/32).  Gap b = 4/5 at
    speed 3/16: b at t = 17/5 + 64/15 = 23/3, v -> (-7/32, -3/64, 3/64, 7/32), and now
    q = (11/64, 3/32, 11/64) > 0: the particles separate after 4 collisions."""
    h = evolve([0, 1, 3, 4], [1, 0, 0, -1], "1/2", 10)
    assert h.word == "[ac]b[ac]b" and times(h) == ["1", "7/3", "17/5", "23/3"]
    assert h.collisions[0].letters == "ac" and h.collisions[0].x == (1, 1, 3, 3)
    assert h.collisions[3].v == (Q(-7, 32), Q(-3, 64), Q(3, 64), Q(7, 32))
    assert h.stop == "separate" and h.triple is None


def test_triple_collision():
    """x = (-1, 0, 1, 10), v = (1, 0, -1, 0): particles 1 and 3 reach particle 2 at
    x = 0 at t = 1 (a and b at the same time): a triple collision, nothing applied."""
    h = evolve([-1, 0, 1, 10], [1, 0, -1, 0], "1/3", 5)
    assert h.stop == "triple" and h.collisions == []
    assert h.triple.particles == (1, 2, 3) and h.triple.t == 1
    assert h.triple.x == (0, 0, 0, 10) and h.triple.v == (1, 0, -1, 0)
    assert "triple collision of particles 1, 2, 3 at t = 1" in list(particles.report_lines(h))[-1]


def test_collision_next_to_particles_in_contact():
    """x = (0, 1, 1, 2), v = (1, 0, 0, -1): 2 and 3 rest in contact at x = 1 (no time
    for b, q2 = 0); 1 and 4 reach them at t = 1, a and c at once: all four meet."""
    h = evolve([0, 1, 1, 2], [1, 0, 0, -1], "1/2", 5)
    assert h.stop == "triple" and h.triple.particles == (1, 2, 3, 4) and h.triple.t == 1
    with pytest.raises(sim.MultipleCollision, match="quadruple collision of particles 1, 2, 3, 4"):
        sim.next_collision(particles.differences(h.x), particles.differences(h.v))


def test_contact_that_opens_is_not_a_meeting():
    """x = (0, 1, 1, 5), v = (1, 0, 1, 1): 2 and 3 touch at t = 0 but separate (q2 = 1),
    so at the a collision (t = 1) particle 3 is at 2: a binary collision."""
    h = evolve([0, 1, 1, 5], [1, 0, 1, 1], "1/2", 5)
    assert h.collisions[0].letters == "a" and h.collisions[0].t == 1


def test_collapse_at_small_r():
    """r = 1/20, the symmetric datum: ([ac]b)^500, 1000 exact collisions.  The
    collisions accumulate: the durations of the periods decrease, the times stay
    below 4 and the four particles end within 2^-1000 of each other."""
    h = evolve([0, 1, 3, 4], [1, 0, 0, -1], "1/20", 1000)
    assert h.stop == "n" and h.word == "[ac]b" * 500
    t = [Q(0)] + [c.t for c in h.collisions]
    periods = [t[k + 2] - t[k] for k in range(0, 1000, 2)]
    assert all(b < a for a, b in zip(periods, periods[1:])) and t[-1] < 4
    x = h.collisions[-1].x
    assert 0 < x[3] - x[0] < Q(1, 2 ** 1000)
    assert sum(h.collisions[-1].v) == 0


def test_progress_is_reported_and_cleared():
    calls = []
    evolve([0, 1, 3, 4], [1, 0, 0, -1], "1/20", 400, progress=lambda *a: calls.append(a))
    assert calls[0] == (0, 400, "collisions") and calls[-1] == (400, 400, "")
    assert [k for k, _, _ in calls[:-1]] == list(range(0, 400, 2))      # every 400/200


# --------------------------------------------------------------------------
# Input

@pytest.mark.parametrize("text, value", [("3", Q(3)), ("-3/7", Q(-3, 7)), ("0.25", Q(1, 4)),
                                         ("-.5", Q(-1, 2)), (" 2. ", Q(2)), ("6/4", Q(3, 2))])
def test_numbers_are_exact(text, value):
    assert particles.rational(text, "x1") == value


@pytest.mark.parametrize("text", ["abc", "1e3", "0.1.2", "", "1/-2", "nan", "inf", 0.5])
def test_not_a_number(text):
    with pytest.raises(UsageError, match="not an exact number"):
        particles.rational(text, "x1")


@pytest.mark.parametrize("x, v, r, n, message", [
    ([0, 1, 2], [0, 0, 0, 0], "1/2", 1, "expected four values x1 x2 x3 x4, got 3"),
    ([0, 1, 2, 3], [0, 0, 0, 0, 0], "1/2", 1, "expected four values v1 v2 v3 v4, got 5"),
    ([0, 2, 1, 3], [0, 0, 0, 0], "1/2", 1, "x2 = 2 > x3 = 1"),
    ([0, 1, 2, 3], [0, 0, 0, 0], "1", 1, "r = 1 is outside ]0,1["),
    ([0, 1, 2, 3], [0, 0, 0, 0], "0", 1, "r = 0 is outside ]0,1["),
    ([0, 1, 2, 3], [0, 0, 0, 0], "1/2", 0, "positive integer, got 0"),
    ([0, 1, 2, 3], [0, 0, 0, 0], "1/2", 2.0, "positive integer, got 2.0"),
    ([0, 1, 2, 3], [0, 0, "1/0", 0], "1/2", 1, "v3 = '1/0' divides by zero"),
])
def test_invalid_data(x, v, r, n, message):
    with pytest.raises(UsageError, match=message.replace("[", r"\[").replace("]", r"\]")):
        evolve(x, v, r, n)


def test_decimal_digits_are_correctly_rounded():
    assert particles.decimal_digits(Q(2, 3), 5) == ("0.66667", False)
    assert particles.decimal_digits(Q(-3, 2), 5) == ("-1.5", True)
    assert particles.decimal_digits(Q(1, 3 * 10 ** 20), 3) == ("3.33e-21", False)


def exponent(f: Fraction) -> int:
    """floor(log10 |f|), f != 0, by exact comparisons."""
    e = 0
    while Fraction(10) ** (e + 1) <= abs(f):
        e += 1
    while Fraction(10) ** e > abs(f):
        e -= 1
    return e


@given(st.fractions(min_value=-10 ** 6, max_value=10 ** 6, max_denominator=10 ** 12)
       .filter(lambda f: f != 0), st.integers(1, 30))
def test_decimal_digits_within_half_a_unit(f, digits):
    """|printed - z| <= 1/2 unit in the digits-th significant digit of z (exact)."""
    text, exact = particles.decimal_digits(fmpq_of(f), digits)
    printed = Fraction(text)
    unit = Fraction(10) ** (exponent(f) - digits + 1)
    assert abs(printed - f) <= unit / 2 and exact == (printed == f)


# --------------------------------------------------------------------------
# The command

def test_command_output(capsys):
    """The ac/b orbit of test_simultaneous_a_and_c_then_separation, as printed."""
    argv = ["particles", "--x", "0", "1", "3", "4", "--v", "1", "0", "0", "-1", "--r", "0.5"]
    assert cli.main(argv) == 0
    out, err = capsys.readouterr()
    assert out.splitlines() == [
        "1  ac  t = 1",
        "2  b   t ≈ 2.3333333333333333333   = 7/3",
        "3  ac  t = 3.4   = 17/5",
        "4  b   t ≈ 7.6666666666666666667   = 23/3",
        "word: [ac]b[ac]b",
        "the particles separate after 4 collisions: no pair approaches"]
    assert err == ""                                    # no progress off a terminal


def test_command_negative_fractions_and_limits(capsys):
    argv = ["particles", "--x", "-3/2", "-1", "0", "1", "--v", "-1/2", "-3/4", "-.5", "-0.5",
            "--r", "1/20", "--collisions", "1", "--digits", "3"]
    assert cli.main(argv) == 0
    assert capsys.readouterr().out.splitlines() == [   # a: gap 1/2 at speed 1/4, t = 2
        "1  a   t = 2", "word: a", "1 collision done"]


@pytest.mark.parametrize("args, message", [
    (["--r", "1"], "argument --r: r must lie in ]0,1[, got 1"),
    (["--r", "0"], "argument --r: r must lie in ]0,1[, got 0"),
    (["--r", "-1/2"], "argument --r: r must lie in ]0,1[, got -1/2"),
    (["--r", "half"], "argument --r: expected an exact number (3/10, 0.3, 1e-1 or 10^-1), got 'half'"),
    (["--r", "1/2", "--collisions", "0"], "argument --collisions: expected a positive integer"),
    (["--r", "1/2", "--x", "0", "1", "2"], "argument --x: expected 4 arguments"),
    (["--r", "1/2", "--x", "0", "2", "1", "3"], "x2 = 2 > x3 = 1"),
    (["--r", "1/2", "--v", "1", "0", "z", "-1"], "argument --v: expected an exact number (3/10, 0.3, 1e-1 or 10^-1), "
                                                  "got 'z'"),
    (["--r", "1/2", "--digits", "100000"], "--digits is at most 1000"),
])
def test_command_usage_errors(args, message, capsys):
    base = {"--x": ["0", "1", "3", "4"], "--v": ["1", "0", "0", "-1"]}
    defaults = [a for k, vals in base.items() if k not in args for a in [k, *vals]]
    argv = ["particles", *defaults, *args]
    assert cli.main(argv) == 2
    out, err = capsys.readouterr()
    assert out == "" and err.count("\n") == 1 and message in err
    assert err.startswith("certify: error: ")


def run_certify(*args: str) -> subprocess.CompletedProcess:
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    env.pop("CERTIFY_DEBUG", None)
    return subprocess.run([sys.executable, "-m", "certify", *args], cwd=ROOT, env=env,
                          capture_output=True, text=True, timeout=120)


def test_the_real_command():
    ok = run_certify("particles", "--x", "0", "1", "3", "5", "--v", "1", "0", "0", "-1",
                     "--r", "1/2", "--collisions", "3")
    assert ok.returncode == 0 and ok.stderr == ""
    assert ok.stdout.splitlines()[-2:] == ["word: acb", "3 collisions done"]
    bad = run_certify("particles", "--x", "0", "1", "3", "5", "--v", "1", "0", "0", "-1",
                      "--r", "2")
    assert bad.returncode == 2 and "Traceback" not in bad.stderr + bad.stdout
    assert bad.stderr.splitlines() == [
        "certify: error: argument --r: r must lie in ]0,1[, got 2"]
