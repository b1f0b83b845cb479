"""The five-particle reduction map (certify.numerics.five_reduction): exact map against the exact
five-particle simulator collision by collision, the float64 engine against the exact map on
its certified collisions (and its bound against the exact error), the chart of S² × S²."""
import math
import random

import flint
import numpy as np
import pytest

from certify.dynamics import particles
from certify.numerics import five_reduction as five
from certify.numerics import rules

Q = flint.fmpq


def particle_start(seed: int):
    """Random exact data of five particles, converging (v decreasing)."""
    rng = random.Random(seed)
    x = [Q(0)]
    for _ in range(4):
        x.append(x[-1] + Q(rng.randint(1, 40), rng.randint(1, 9)))
    v = sorted((Q(rng.randint(-60, 60), rng.randint(1, 9)) for _ in range(5)), reverse=True)
    return x, v


def gaps(z):
    return tuple(z[k + 1] - z[k] for k in range(len(z) - 1))


def after_first(history):
    """(face, p, q) right after the first collision of a particle history."""
    c = history.collisions[0]
    return five.LETTERS.index(c.letters), gaps(c.x), gaps(c.v)


@pytest.mark.parametrize("r", [Q(1, 4), Q(13, 50), Q(1, 5), Q(7, 10)])
def test_exact_map_spells_the_particle_words(r):
    """From the state after the first collision of an exact five-particle run, the exact map
    on the plane p ∧ q spells the particles' next collisions, letter by letter, as long as the
    particles collide (a run that separates is cut there: the plane does not see q ≥ 0)."""
    checked = 0
    for seed in range(60):
        h = particles.evolve(*particle_start(seed), r, 40, particles=5)
        events = [c.letters for c in h.collisions]
        if len(events) < 3 or any(len(e) > 1 for e in events):
            continue
        i, p, q = after_first(h)
        word, code = five.exact_orbit(i, five.bivector(p, q), r, len(events) - 1)
        assert code == 0
        assert word == "".join(events[1:]), seed
        checked += len(word)
    assert checked >= 150


def plane_state(w, i):
    """Exact gaps p and velocities q with p ∧ q = ω on the face i (ω a plane): q_i = 1,
    p_k = −ω_ik, q_k0 = 0 and q_m = ω_k0m / p_k0 for a k0 ≠ i."""
    p = [-five.entry(w, i, k)[0] if k != i else Q(0) for k in range(4)]
    k0 = next(k for k in range(4) if k != i)
    q = [Q(1) if m == i else (Q(0) if m == k0 else five.entry(w, k0, m)[0] / p[k0]) for m in range(4)]
    return p, q


def test_exact_map_spells_a_long_collapse():
    """On the attractor of the reduction at r = 13/50 (a float orbit's last plane, read
    exactly) with an inward radial velocity, the particles collide 60 times and the exact map
    spells all 60."""
    r = Q(13, 50)
    p0, q0 = five.random_data(1, seed=3)
    orbit = five.iterate([float(r)], p0, q0, collisions=3000)
    i = int(orbit.face[0, 0])
    p, q = plane_state([Q(*float(z).as_integer_ratio()) for z in orbit.omega[0, 0]], i)
    top = max(abs(z) for z in q)
    q = [z - 4 * top * pk / max(p) for z, pk in zip(q, p)]     # q − c p, c > 0: the same plane
    assert five.bivector(p, q) == five.bivector(*plane_state(five.bivector(p, q), i))
    x, v = [Q(0)], [Q(0)]
    for pk, qk in zip(p, q):
        x.append(x[-1] + pk)
        v.append(v[-1] + qk)
    h = particles.evolve(x, v, r, 60, particles=5)
    events = "".join(c.letters for c in h.collisions)
    assert len(events) == 60
    word, code = five.exact_orbit(i, five.bivector(p, q), r, 60)
    assert code == 0 and word == events


@pytest.mark.parametrize("r", [0.25, 0.2, 0.26, 0.5, 0.9])
def test_float64_engine_certified_collisions_are_exact(r):
    """Every collision the float64 engine certifies is the exact map's (the exact orbit of
    its datum (p0, q0) read exactly), and the engine certifies a few dozen."""
    p0, q0 = five.random_data(6, seed=11)
    orbits = five.iterate([r], p0, q0, collisions=400, words=True)
    rr = rules.exact_r(r)
    for b in range(len(p0)):
        cert = int(orbits.certified[0, b])
        assert cert >= 20
        p = [Q(*float(z).as_integer_ratio()) for z in p0[b]]
        q = [Q(*float(z).as_integer_ratio()) for z in q0[b]]
        word, code = five.exact_orbit(1, five.bivector(p, q), rr, cert + 10)
        assert orbits.word[0, b][:cert] == word[:cert]


def test_accumulated_bound_contains_the_exact_bivector():
    """The engine's err (rules.carry_bound at length 6) bounds |ω − ω_exact| entrywise along
    an orbit, ω_exact the exact map through the engine's faces, scaled as its matrices are
    (no power-of-2 rescaling in 80 collisions at r = 1/4 without the kernel)."""
    r = 0.25
    rows = five.float_rows(r)
    exact_rows = [[[Q(z) for z in row] for row in K] for K in five.integer_rows(r)]
    scale = [Q(max(abs(int(z)) for row in K for z in row).bit_length() - 1) for K in five.integer_rows(r)]
    p0, q0 = five.random_data(1, seed=5)
    w, err = five.start(p0[0], q0[0])
    x = five.bivector([Q(*float(z).as_integer_ratio()) for z in p0[0]],
                      [Q(*float(z).as_integer_ratio()) for z in q0[0]])
    absrows = [[[abs(z) for z in row] for row in K] for K in rows]
    i = 1
    for _ in range(80):                 # the faces of the floats (past the horizon too: the bound still holds)
        code, j = five.classify(i, w, (0.0,) * 6)
        assert code == 0
        err = rules.carry_bound(j, w, err, absrows, five.G64_6, rules.K64, rules.TINY64)
        w = five.advance(j, w, rows)
        x = tuple(z / Q(2) ** int(scale[j]) for z in five.advance(j, x, exact_rows))
        for a, b, e in zip(w, x, err):
            assert abs(Q(*a.as_integer_ratio()) - b) <= Q(*e.as_integer_ratio())
        i = j


def test_a_broken_bound_is_caught():
    """Mutant: the bound without its rounding term g (g = 0) no longer contains the exact
    bivector within 80 collisions: the check above can fail."""
    r = 0.25
    rows = five.float_rows(r)
    exact_rows = [[[Q(z) for z in row] for row in K] for K in five.integer_rows(r)]
    scale = [max(abs(int(z)) for row in K for z in row).bit_length() - 1 for K in five.integer_rows(r)]
    p0, q0 = five.random_data(1, seed=5)
    w, _ = five.start(p0[0], q0[0])
    err = (0.0,) * 6
    x = five.bivector([Q(*float(z).as_integer_ratio()) for z in p0[0]],
                      [Q(*float(z).as_integer_ratio()) for z in q0[0]])
    absrows = [[[abs(z) for z in row] for row in K] for K in rows]
    i, escaped = 1, False
    for _ in range(80):
        _, j = five.classify(i, w, (0.0,) * 6)
        err = rules.carry_bound(j, w, err, absrows, 0.0, 1.0, 0.0)
        w = five.advance(j, w, rows)
        x = tuple(z / Q(2) ** scale[j] for z in five.advance(j, x, exact_rows))
        escaped |= any(abs(Q(*a.as_integer_ratio()) - b) > Q(*e.as_integer_ratio()) for a, b, e in zip(w, x, err))
        i = j
    assert escaped


def test_kernel_is_the_python_map():
    """The numba kernel spells the word of five.classify/five.advance in floats (margins
    TOL · |Ĉ||ω|), 300 collisions, before any rescaling differs."""
    r = 0.3
    rows = five.float_rows(r)
    absrows = [[[abs(z) for z in row] for row in K] for K in rows]
    p0, q0 = five.random_data(3, seed=2)
    orbits = five.iterate([r], p0, q0, collisions=300, words=True)
    for b in range(3):
        w, bnd = five.start(p0[b], q0[b])
        i, word = 1, []
        for _ in range(300):
            code, j = five.classify(i, w, bnd)
            if code:
                break
            bnd = rules.step_bounds(j, w, absrows, rules.TOL64)
            w = five.advance(j, w, rows)
            top = max(abs(z) for z in w)
            if top > 2.0 ** 256 or top < 2.0 ** -256:
                f = math.ldexp(1.0, -math.frexp(top)[1])
                w, bnd = tuple(z * f for z in w), tuple(z * f for z in bnd)
            i = j
            word.append(five.LETTERS[j])
        assert orbits.word[0, b] == "".join(word)


def test_classify_decides_the_tournament_and_the_face():
    """The next face is the j with ω_jk > 0 for the two other k; a state outside its face is a
    corner, an undecided sign a break."""
    p, q = (0, 1, 2, 3), (1, -1, -1, -1)        # face a; times 1, 2, 3: b first
    w = five.bivector(p, q)
    assert five.classify(0, w, (0,) * 6) == (0, 1)
    assert five.classify(0, w, (10,) * 6)[0] == rules.SHORT_STEP
    assert five.classify(0, five.bivector((0, 1, 2, 3), (-1, -1, -1, -1)), (0,) * 6)[0] == rules.CORNER
    assert five.classify(0, five.bivector((0, 1, 2, 4), (1, -1, -2, -1)), (0,) * 6)[0] == rules.UNDECIDED
    assert five.classify(0, (0,) * 6, (0,) * 6)[0] == rules.CORNER
    assert five.classify(0, (math.nan,) * 6, (0,) * 6)[0] == rules.NONFINITE


def test_chart_round_trip_and_plucker():
    """The chart of S² × S²: |u| = |v| on planes, and from_chart inverts chart up to a factor."""
    rng = np.random.default_rng(0)
    for _ in range(50):
        p, q = rng.standard_normal(4), rng.standard_normal(4)
        w = five.bivector(p, q)
        u, v = five.self_dual_parts(w)
        assert math.isclose(math.hypot(*u), math.hypot(*v), rel_tol=1e-12)
        back = np.array(five.from_chart(*five.chart(w)))
        ratio = np.array(w) / back
        assert np.allclose(ratio, ratio[0], rtol=1e-9) and ratio[0] > 0


def test_periodic_tail_and_canonical():
    assert five.periodic_tail("dd" + "abadcbcabc" * 8) == five.canonical("abadcbcabc")
    assert five.canonical("bdcbdcdabc") == "abadcbcabc"        # the mirror (a ↔ d, b ↔ c), rotated
    assert five.periodic_tail("abcdabdcbacdbadc") is None


@pytest.mark.parametrize("bad", [math.nan, math.inf])
def test_a_nonfinite_bound_certifies_nothing(bad):
    """rules: an inf or nan bound decides nothing.  A state whose face and next face are decided
    with the bound 0 is not certified when the bounds of its in-face entries (or of the
    tournament's) are nan or inf: the kernel's certification says so; the one-orbit count (its bound
    starts at the bad value, so the margins already stop it) checks the margin classification."""
    from certify.numerics import five_kernel
    p, q = (0.0, 1.0, 2.0, 3.0), (1.0, -1.0, -1.0, -1.0)      # face a, b first (test above)
    w = np.array(five.bivector(p, q))
    assert five_kernel._certifies(0, w, np.zeros(6), 1)
    inface = [five.SLOT[0, k] for k in (1, 2, 3)]
    for slots in (inface, [m for m in range(6) if m not in inface]):
        err = np.zeros(6)
        err[slots] = bad
        assert not five_kernel._certifies(0, w, err, 1)
        rows = np.array(five.float_rows(0.25)).reshape(-1)
        out = np.empty(6)
        _, _, certified, _ = five_kernel.orbit(0, w, err, rows, rules.TOL64, five.G64_6, rules.K64, rules.TINY64,
                                               1, False, False, np.zeros(1, np.int8), out)
        assert certified == 0


def replay(r, p, q, collisions):
    """The float64 engine's orbit from the datum (p, q) on face b, replayed in Python: the margins
    TOL · |Ĉ||ω| decide each step (five.classify), rules.carry_bound carries err, the power-of-2
    rescaling as in the kernel; (certified horizon, collisions done, rescalings)."""
    rows = five.float_rows(r)
    absrows = [[[abs(z) for z in row] for row in K] for K in rows]
    w, err = five.start(p, q)
    bnd, i, horizon, rescaled = err, 1, None, 0
    for done in range(collisions):
        code, j = five.classify(i, w, bnd)
        if code:
            break
        if horizon is None and five.classify(i, w, err) != (0, j):
            horizon = done
        bnd = rules.step_bounds(j, w, absrows, rules.TOL64)
        err = rules.carry_bound(j, w, err, absrows, five.G64_6, rules.K64, rules.TINY64)
        w = five.advance(j, w, rows)
        top = max(abs(z) for z in w)
        if top > 2.0 ** 256 or 0 < top < 2.0 ** -256:
            f = math.ldexp(1.0, -math.frexp(top)[1])
            w, bnd, err = (tuple(z * f for z in w), tuple(z * f for z in bnd),
                           tuple(e * f + rules.TINY64 for e in err))
            rescaled += 1
        i = j
    else:
        done = collisions
    return (done if horizon is None else horizon), done, rescaled


@pytest.mark.parametrize("r", [0.2, 0.26, 0.5, 0.9])
def test_engine_certified_count_is_the_replayed_horizon(r):
    """The count the engine reports as certified is exactly the horizon of the Python replay
    (classify at the margins, rules.carry_bound, the rescaling), for random data and for the
    same data scaled by 2^±150 (the bivector then rescaled at its first collision)."""
    p0, q0 = five.random_data(3, seed=7)
    scale = np.array([1.0, 2.0 ** 150, 2.0 ** -150])[:, None]
    p0, q0 = p0 * scale, q0 * scale
    orbits = five.iterate([r], p0, q0, collisions=300)
    reached = 0
    for b in range(len(p0)):
        horizon, done, rescaled = replay(r, p0[b], q0[b], 300)
        assert int(orbits.certified[0, b]) == horizon and int(orbits.collisions[0, b]) == done
        assert rescaled or b == 0
        reached += horizon < done
    assert reached
