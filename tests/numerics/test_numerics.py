"""The numerical engines of Section 5 (certify.numerics): one map, one set of break
rules, three number systems.

Each break code is triggered; the three engines give the same collision words where
all decide; the float64 kernel steps exactly like ``reduction.step`` on rational data
(dyadic r, small integer normals: no rounding at all); φ agrees with
``reduction.angles``; the npz schema; the CLI's usage errors.
"""
import math
import subprocess
import sys
from fractions import Fraction
from pathlib import Path

import flint
import numpy as np
import pytest

from certify import numerics
from certify.dynamics import reduction
from certify.numerics import engines, kernel, rules

ROOT = Path(__file__).resolve().parents[2]
ENGINES = ("float64", "mp", "ball")
THETA, PHI = numerics.paper_grid()


def orbit(engine, r, theta, phi, n, **kw):
    return engines.run_orbit(engine, r, theta, phi, n, **kw)


# --- the grid and the initial data ------------------------------------------------

def test_paper_grid_is_2_theta_by_4_phi_interior():
    assert len(THETA) == len(PHI) == 8
    assert len(set(THETA)) == 2 and len(set(PHI)) == 4
    assert all(0 < t < math.pi / 2 for t in THETA) and all(0 < p < math.pi and abs(math.cos(p)) > 0.1 for p in PHI)
    t, p = numerics.grid(1)
    assert (t[0], p[0]) == (THETA[0], PHI[0])
    assert len(numerics.grid(12)[0]) == 12


def test_initial_normal_is_the_papers_u_at_b():
    t, p = 0.7, 1.1
    n = rules.initial_normal(t, p)
    expected = (-math.cos(t) * math.sin(p), math.cos(p), math.sin(t) * math.sin(p))
    assert np.allclose(n, expected, rtol=0, atol=1e-15)
    assert rules.phi_of(1, n) == pytest.approx(p, abs=1e-14)
    assert rules.theta_of(1, n) == pytest.approx(t, abs=1e-14)


@pytest.mark.parametrize("letter, n", [("b", (-3, 5, 4)), ("a", (2, 1, -7)), ("c", (5, -1, 3)), ("b", (-1, -9, 2))])
def test_float_angles_agree_with_reduction_angles(letter, n):
    P = reduction.canonical(letter, n)
    A = reduction.angles(P, 128)
    i = reduction.INDEX[letter]
    phi = rules.phi_of(i, [float(z) for z in P.n])
    assert math.cos(phi) == pytest.approx(float(A.cp.mid()), abs=1e-15)
    assert math.sin(phi) == pytest.approx(float(A.sp.mid()), abs=1e-15)
    theta = rules.theta_of(i, [float(z) for z in P.n])
    assert math.cos(theta) == pytest.approx(float(A.ct.mid()), abs=1e-15)


# --- one map --------------------------------------------------------------------

R_DYADIC = flint.fmpq(3, 8)                 # r, the cofactors and small normals exact in floats
CONSTANTS = (rules.TOL64, rules.G64, rules.K64, rules.TINY64)


def exact_orbit(letter, n, steps):
    return reduction.orbit(reduction.canonical(letter, n), R_DYADIC, steps)


def test_rules_step_is_reduction_step_on_rationals():
    rows = rules.integer_rows(R_DYADIC)
    planes = exact_orbit("b", (-3, 5, 4), 40)
    i, n = 1, tuple(flint.fmpz(z) for z in planes[0].n)
    for P in planes[1:]:
        code, j = rules.classify(i, n, (0, 0, 0))
        assert code == 0 and rules.LETTERS[j] == P.letter
        n = rules.advance(j, n, rows)
        assert reduction.canonical(P.letter, n) == P
        i = j


def test_float64_kernel_steps_exactly_like_reduction_step():
    """While the exact normals fit in 53 bits the kernel's normals are positive
    multiples of reduction.step's (no rounding happens); the words agree for longer."""
    planes = exact_orbit("b", (-3, 5, 4), 400)
    rows = np.array(rules.float_rows(R_DYADIC))
    assert all(float(Fraction(x)) == x for x in rows.ravel())
    letters, normals, errs = np.zeros(400, np.int8), np.zeros((400, 3)), np.zeros((400, 3))
    code, done, _ = kernel.trace(1, np.array(planes[0].n, dtype=float), rows.reshape(27), *CONSTANTS, 400, False,
                                 letters, normals, errs)
    assert code == 0 and done == 400
    exact_steps, irows, n = 0, rules.integer_rows(R_DYADIC), planes[0].n
    for k, P in enumerate(planes[1:]):
        assert rules.LETTERS[letters[k]] == P.letter, k
        n = rules.advance(letters[k], n, irows)         # the unreduced integer normal
        if max(abs(int(z)) for z in n).bit_length() <= 53:   # the float one is exact: a multiple
            m = [Fraction(x) for x in normals[k]]
            e = [Fraction(int(z)) for z in P.n]
            assert reduction.cross(m, e) == (0, 0, 0) and reduction.dot(m, e) > 0, k
            exact_steps += 1
    assert exact_steps >= 5


def test_float64_word_is_the_exact_word():
    start = reduction.canonical("b", (-3, 5, 4))
    for r in (flint.fmpq(3, 20), flint.fmpq(1, 2)):
        word, _ = reduction.word_of(start, r, 300)
        res = engines.run_orbit("float64", r, 0, 0, 300, word=True, normal=[float(z) for z in start.n])
        assert res.code == 0 and res.word == word


@pytest.mark.parametrize("r", [0.15, 0.5, 0.9])
def test_engines_agree_where_they_decide(r):
    words = {e: orbit(e, r, THETA[1], PHI[1], 600, word=True, keep=50) for e in ENGINES}
    assert all(w.code == 0 and w.collisions == 600 for w in words.values())
    assert words["float64"].word == words["mp"].word == words["ball"].word
    assert np.allclose(words["float64"].phi, words["ball"].phi, atol=1e-9)
    assert np.allclose(words["mp"].phi, words["ball"].phi, atol=1e-12)


def test_ring_buffer_keeps_the_last_b_angles_in_order():
    full = orbit("float64", 0.3, THETA[0], PHI[0], 500, word=True, keep=10_000)
    b = full.phi[np.isfinite(full.phi)]
    assert len(b) == full.word.count("b")
    last = orbit("float64", 0.3, THETA[0], PHI[0], 500, keep=7)
    assert np.array_equal(last.phi, b[-7:])
    short = orbit("float64", 0.3, THETA[0], PHI[0], 4, keep=7)      # fewer b than keep: NaN in front
    assert np.isnan(short.phi[0]) and np.isfinite(short.phi[-1])
    assert np.sum(np.isfinite(short.phi)) == orbit("float64", 0.3, THETA[0], PHI[0], 4, word=True).word.count("b")


# --- the break codes ----------------------------------------------------------------

def test_break_names():
    assert set(numerics.BREAKS) == {0, 1, 2, 3, 4, 5}
    assert (numerics.UNDECIDED, numerics.SHORT_STEP, numerics.CORNER, numerics.NONFINITE, numerics.HORIZON) == \
        (1, 2, 3, 4, 5)


@pytest.mark.parametrize("engine", ENGINES)
def test_break_1_undecided_contact(engine):
    # cos φ = 0 exactly (a rational datum): no engine may choose the next contact
    res = orbit(engine, 0.5, 0, 0, 10, normal=(-1, 0, 1), dps=20)
    assert (res.code, res.collisions) == (numerics.UNDECIDED, 0)


def test_break_1_float64_at_cos_phi_below_precision():
    res = orbit("float64", 0.5, 0.6, math.pi / 2, 10)       # |cos φ0| ≈ 6e-17
    assert (res.code, res.collisions) == (numerics.UNDECIDED, 0)
    res = orbit("float64", 0.5, 0.6, math.pi / 2 + 1e-13, 10)   # 1e-13: decided
    assert res.code == 0


@pytest.mark.parametrize("engine", ENGINES)
def test_break_2_short_step(engine):
    # θ0 = 0: the position is the vertex where the gaps b and a vanish together
    res = orbit(engine, 0.5, 0.0, 1.0, 10, dps=20)
    assert (res.code, res.collisions) == (numerics.SHORT_STEP, 0)


def test_break_2_float64_near_a_vertex():
    assert orbit("float64", 0.5, 1e-16, 1.0, 10).code == numerics.SHORT_STEP
    assert orbit("float64", 0.5, math.pi / 2, 1.0, 10).code == numerics.SHORT_STEP     # cos θ0 ≈ 6e-17


@pytest.mark.parametrize("engine", ENGINES)
def test_break_3_corner(engine):
    # θ0 = 2 > π/2: cos θ0 < 0, the position lies outside the face
    assert orbit(engine, 0.5, 2.0, 1.0, 10, dps=20).code == numerics.CORNER
    assert orbit(engine, 0.5, 0, 0, 10, normal=(0, 0, 0), dps=20).code == numerics.CORNER


@pytest.mark.parametrize("engine", ENGINES)
def test_break_4_nonfinite(engine):
    assert orbit(engine, 0.5, float("nan"), 1.0, 10, dps=20).code == numerics.NONFINITE


def test_a_break_after_some_collisions_keeps_what_was_done():
    # a datum close to cos φ = 0 at a later collision: every engine stops, none goes on
    start = reduction.canonical("b", (-3, 5, 4))
    planes = reduction.orbit(start, flint.fmpq(1, 2), 5)
    P = planes[3]
    # a plane with exactly cos φ = 0 after 3 collisions cannot be built generically; instead
    # check that a float run stopped by the margin reports the collisions it did
    res = engines.run_orbit("float64", 0.5, 0, 0, 5, normal=[float(z) for z in start.n], word=True)
    assert res.code == 0 and res.word == reduction.word(planes)
    assert P.letter == res.word[2]


def test_simulate_reports_breaks_per_orbit():
    out = numerics.iterate([0.5], [0.6, 0.6, 2.0, float("nan")], [1.0, math.pi / 2, 1.0, 1.0], collisions=50, keep=5)
    assert out.breaks.tolist() == [[0, 1, 3, 4]]
    assert out.collisions.tolist() == [[50, 0, 0, 0]]
    assert np.isnan(out.phi[0, 1:]).all()


# --- the interface ---------------------------------------------------------------

def test_npz_schema(tmp_path):
    out = numerics.iterate([0.15, 0.5], THETA[:3], PHI[:3], collisions=200, keep=20)
    path = tmp_path / "o.npz"
    out.save(path)
    data = np.load(path)
    assert sorted(data.files) == sorted(["r", "theta0", "phi0", "phi", "breaks", "collisions", "certified"])
    assert data["r"].shape == (2,) and data["theta0"].shape == data["phi0"].shape == (3,)
    assert data["phi"].shape == (2, 3, 20) and data["breaks"].shape == data["collisions"].shape == (2, 3)
    assert data["collisions"].tolist() == [[200] * 3] * 2
    back = numerics.Orbits.load(path)
    assert np.array_equal(back.phi, out.phi)


@pytest.mark.parametrize("engine", ["mp", "ball"])
def test_simulate_on_an_executor(engine):
    from concurrent.futures import ThreadPoolExecutor
    with ThreadPoolExecutor(2) as ex:
        a = numerics.iterate([0.3, 0.6], THETA[:2], PHI[:2], collisions=100, keep=10, engine=engine, executor=ex)
    b = numerics.iterate([0.3, 0.6], THETA[:2], PHI[:2], collisions=100, keep=10, engine="float64")
    assert np.array_equal(a.breaks, b.breaks) and np.allclose(a.phi, b.phi, atol=1e-9)


def test_an_mp_sweep_on_a_dask_cluster_equals_the_serial_one():
    """The sweep's Executor can be a Dask cluster (`--scheduler`): the same arrays, to the bit."""
    distributed = pytest.importorskip("distributed")
    from certify.run.executors import executor
    serial = numerics.iterate([0.3, 0.6], THETA[:2], PHI[:2], collisions=100, keep=10, engine="mp", dps=20)
    with distributed.LocalCluster(processes=False, n_workers=1, threads_per_worker=2,
                                  dashboard_address=None) as cluster:
        with executor(scheduler=cluster.scheduler_address) as ex:
            on_cluster = numerics.iterate([0.3, 0.6], THETA[:2], PHI[:2], collisions=100, keep=10, engine="mp",
                                           dps=20, executor=ex)
    assert np.array_equal(on_cluster.breaks, serial.breaks)
    assert np.array_equal(on_cluster.collisions, serial.collisions)
    assert np.array_equal(on_cluster.phi, serial.phi, equal_nan=True)


@pytest.mark.parametrize("kwargs", [dict(r=[1.2]), dict(r=[0.0]), dict(collisions=-1), dict(engine="quad")])
def test_simulate_rejects_bad_arguments(kwargs):
    args = dict(r=[0.5], theta0=THETA[:1], phi0=PHI[:1], collisions=10, keep=5) | kwargs
    with pytest.raises(ValueError):
        numerics.iterate(**args)


def cli(*args):
    env = {"PYTHONPATH": str(ROOT), "PATH": "/usr/bin:/bin"}
    return subprocess.run([sys.executable, "-m", "certify", *args], cwd=ROOT, env=env, capture_output=True, text=True)


@pytest.mark.parametrize("args", [
    ["--r", "1.5"], ["--r", "0"], ["--r-range", "0.1", "1.0", "5"], ["--r", "0.5", "--collisions", "-3"],
    ["--r", "0.5", "--keep", "x"], ["--r", "0.5", "--engine", "quad"], ["--r", "0.5", "--out", "/dev/null/x.npz"],
    ["--r-range", "0.1", "0.2", "2.5"], [], ["--r", "0.5", "--dps", "30"], ["--r-range", "0.2", "0.1", "5"],
])
def test_cli_usage_errors(args, capsys):
    from certify.cli import main
    assert main(["simulate", *args]) == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1 and err.startswith("certify: error:"), err


def test_cli_writes_the_npz(tmp_path):
    path = tmp_path / "sweep.npz"
    res = cli("simulate", "--r-range", "0.14", "0.16", "3", "--orbits", "2", "--collisions", "10^3", "--keep", "7",
              "--out", str(path))
    assert res.returncode == 0, res.stderr
    data = np.load(path)
    assert data["phi"].shape == (3, 2, 7) and data["breaks"].tolist() == [[0, 0]] * 3
    assert not [p for p in tmp_path.iterdir() if p.name.startswith(".")]       # no temporary left

def test_cli_summary(capsys):
    from certify.cli import main
    assert main(["simulate", "--r", "3/20", "--orbits", "1", "--collisions", "100", "--engine", "mp"]) == 0
    out = capsys.readouterr().out
    assert "mp: 1 value(s) of r × 1 orbit(s)" in out and "1 completed (break 0)" in out


@pytest.mark.slow
def test_paper_resolution_figure_5_1_in_float64():
    r = np.linspace(0.072, 0.999, 3709)
    out = numerics.iterate(r, THETA, PHI)
    assert out.phi.shape == (3709, 8, 500)
    assert (out.breaks == 0).mean() > 0.99


def test_the_grid_beyond_eight_is_a_superset_of_the_eight_without_corners():
    """Issue 25 item 6: --orbits N > 8 keeps the tool's eight and adds finer φ0, never
    φ0 = π/2 (cos φ0 = 0: a corner, the orbit stops at once)."""
    for n in (9, 16, 40):
        t, p = numerics.grid(n)
        assert len(t) == n and list(t[:8]) == list(THETA) and list(p[:8]) == list(PHI)
        assert len(set(zip(t, p))) == n and all(abs(math.cos(x)) > 1e-6 for x in p)


def test_load_float64_imports_the_engine():
    from certify.numerics import load_float64
    load_float64()
    assert "certify.numerics.kernel" in sys.modules and "numba" in sys.modules


@pytest.mark.parametrize("r, datum, collisions, strict", [
    (Fraction(3, 10), (0.5235987755982988, 0.6283185307179586), 20_000, False),
    (Fraction(93271, 100000), (0.6872233929727672, 2.55981623625835), 200_000, False),
    (Fraction(3, 10), (0.5235987755982988, 0.6283185307179586), 20_000, True),      # stops at its horizon
    (Fraction(1, 10), (0.0, 0.0), 5_000, False)])                                    # a break at once
def test_the_word_alone_is_the_word_of_the_full_trace(r, datum, collisions, strict):
    """float64_orbit's word alone (``trace`` keeping no state) gives the word, break and horizons
    of ``trace`` (every state kept, asked with a checkpoint), letter for letter."""
    q = flint.fmpq(r.numerator, r.denominator)
    alone = engines.float64_orbit(q, *datum, collisions, word=True, strict=strict)
    full = engines.float64_orbit(q, *datum, collisions, word=True, strict=strict, checkpoints=(1,))
    assert (alone.code, alone.collisions, alone.certified, alone.word) == \
        (full.code, full.collisions, full.certified, full.word)
    assert len(alone.word) == alone.collisions and set(alone.word) <= set("abc")
