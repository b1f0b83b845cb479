"""The certified horizon of the floating engines and the ball engine without wrapping.

* ``rules.carry_bound`` is an upper bound of the accumulated error of the float64
  normal, checked against the exact orbit (rationals) collision by collision; the
  kernel computes it bit for bit as the Python transcription does.
* On random data between the windows (0.075 < r < 0.13), where float64 orbits leave
  the certified word silently, every certified prefix (float64, mp) is the ball
  engine's word, and the departures happen after the certified horizon; ``strict``
  stops there with break 5.
* The ball engine gives the exact word (rational data), and keeps its precision.
* ``simulate`` and its CLI: ``certified``, ``--strict``, ``--words``,
  ``--theta0``/``--phi0``, their usage errors.
"""
import math
import random
from fractions import Fraction

import flint
import numpy as np
import pytest

from certify import numerics
from certify.dynamics import reduction
from certify.numerics import engines, kernel, rules
from certify.numerics.stress import departure

CONSTANTS = (rules.TOL64, rules.G64, rules.K64, rules.TINY64)


def exact_scaled_rows(r):
    """The exact matrices of which rules.float_rows(r) are the roundings."""
    out = []
    for rows in rules.integer_rows(r):
        shift = max(abs(int(z)) for row in rows for z in row).bit_length() - 1
        out.append([[Fraction(int(z), 1 << shift) for z in row] for row in rows])
    return out


def traced(r, n0, collisions, strict=False, tol=rules.TOL64):
    """kernel.trace; ``tol`` = 0 for an exact datum (no initial error: only the
    roundings along the orbit feed the bound)."""
    rows = np.array(rules.float_rows(r))
    letters, normals, errs = np.zeros(collisions, np.int8), np.zeros((collisions, 3)), np.zeros((collisions, 3))
    code, done, cert = kernel.trace(1, np.array(n0, dtype=float), rows.reshape(27), tol, *CONSTANTS[1:], collisions,
                                    strict, letters, normals, errs)
    return code, done, cert, letters, normals, errs, rows


@pytest.mark.parametrize("r", [0.1, 0.5, 0.9])
def test_the_accumulated_bound_bounds_the_error_of_the_float_normal(r):
    """|n̂_k − x_k| ≤ err_k componentwise, x_k the exact orbit of the same datum with
    the float64 engine's orientations and rescalings, for 80 collisions (beyond the
    certified horizon too).  The datum is exact in floats, its initial bound 0: the
    bound is fed only by the γ terms, and fails without them."""
    n0 = (-3, 5, 4)
    code, done, cert, letters, normals, errs, rows = traced(r, n0, 80, tol=0.0)
    assert code == 0 and done == 80 and 0 < cert < 80
    exact = exact_scaled_rows(r)
    x = [Fraction(z) for z in n0]
    prev = np.array(n0, dtype=float)
    worst = 0.0
    for k in range(done):
        C = exact[letters[k]]
        y = [sum(C[m][c] * x[c] for c in range(3)) for m in range(3)]
        approx = rows[letters[k]] @ prev                      # sign and power of 2 of the engine's step
        s = 1 if float(np.dot(approx, normals[k])) > 0 else -1
        f = 2.0 ** round(math.log2(np.max(np.abs(normals[k])) / np.max(np.abs(approx))))
        x = [s * Fraction(f) * z for z in y]
        for m in range(3):
            gap = abs(Fraction(normals[k, m]) - x[m])
            assert gap <= Fraction(errs[k, m]), (k, m)
            worst = max(worst, float(gap))
        prev = normals[k]
    assert worst > 0                                          # the orbit was rounded: the check is not empty


def test_the_kernel_computes_the_bound_as_the_rules_do():
    """kernel._advance carries rules.carry_bound exactly (same floats) when no rescaling happens."""
    r = 0.11
    n0 = rules.initial_normal(0.4, 1.3)
    code, done, cert, letters, normals, errs, rows = traced(r, n0, 30)
    absrows = np.abs(rows).tolist()
    err = (rules.TOL64 * max(abs(z) for z in n0),) * 3
    n = tuple(n0)
    for k in range(done):
        err = rules.carry_bound(int(letters[k]), n, err, absrows, rules.G64, rules.K64, rules.TINY64)
        assert tuple(errs[k]) == err
        n = tuple(normals[k])


def chaotic_data(count, seed=19):
    rng = random.Random(seed)
    return [(rng.uniform(0.075, 0.13), rng.uniform(0, math.pi / 2), rng.uniform(0, math.pi)) for _ in range(count)]


def test_float64_and_mp_certified_prefixes_are_the_certified_word_and_departures_come_after():
    """The issue's silent wrong collisions: float64 leaves the ball word while going on;
    its certified horizon is always before the departure, and the certified prefix is
    the ball word.  The same for mp at 16 digits."""
    departed = 0
    for r, t, p in chaotic_data(12):
        ball = engines.ball_orbit(r, t, p, 600, word=True)
        assert ball.code == 0 and ball.collisions == ball.certified == 600
        for engine, dps in (("float64", None), ("mp", 16)):
            res = engines.run_orbit(engine, r, t, p, 600, dps=dps, word=True)
            k = departure(res.word, ball.word)
            assert res.word[:res.certified] == ball.word[:res.certified]
            assert k == 0 or k > res.certified, (engine, r, t, p, k, res.certified)
            departed += bool(k) and engine == "float64"
    assert departed >= 3                     # the bound has something to catch


@pytest.mark.parametrize("engine", ["float64", "mp"])
def test_break_5_strict_stops_at_the_certified_horizon(engine):
    r, t, p = chaotic_data(1)[0]
    free = engines.run_orbit(engine, r, t, p, 600, dps=20, word=True)
    strict = engines.run_orbit(engine, r, t, p, 600, dps=20, word=True, strict=True)
    assert free.code == 0 and free.collisions == 600 and 0 < free.certified < 600
    assert (strict.code, strict.collisions, strict.certified) == (numerics.HORIZON, free.certified, free.certified)
    assert strict.word == free.word[:free.certified]


def test_strict_does_not_stop_the_ball_engine():
    res = engines.run_orbit("ball", 0.1, 0.5, 1.0, 300, strict=True)
    assert (res.code, res.collisions, res.certified) == (0, 300, 300)


def test_a_break_before_the_horizon_keeps_its_code():
    """cos φ0 below the rounding: break 1 at collision 0, with or without strict."""
    for strict in (False, True):
        res = engines.float64_orbit(0.5, 0.6, math.pi / 2, 10, strict=strict)
        assert (res.code, res.collisions, res.certified) == (numerics.UNDECIDED, 0, 0)


def test_mp_horizon_grows_with_its_precision():
    r, t, p = chaotic_data(1)[0]
    h = [engines.mp_orbit(r, t, p, 2000, dps=d).certified for d in (16, 30, 60)]
    assert h[0] < h[1] < h[2]


# --- the ball engine ----------------------------------------------------------------

@pytest.mark.parametrize("r", [flint.fmpq(1, 10), flint.fmpq(3, 20), flint.fmpq(1, 2)])
def test_ball_engine_gives_the_exact_word(r):
    start = reduction.canonical("b", (-3, 5, 4))
    word, _ = reduction.word_of(start, r, 1200)
    res = engines.ball_orbit(r, 0, 0, 1200, word=True, normal=(-3, 5, 4))
    assert res.code == 0 and res.word == word                # 1200 > 512: across a re-centring


def test_ball_engine_keeps_its_precision():
    """2000 collisions of the paper's first orbit at r = 0.15 and 0.5 need no more than
    the starting 64 bits (the engine with wrapping needed 2048), and the radius of the
    normal after 1500 collisions at 256 bits is still below 2^-200 of its size."""
    for r in (0.15, 0.5):
        res = engines.ball_orbit(r, math.pi / 6, math.pi / 5, 2000)
        assert res.code == 0 and res.collisions == 2000 and res.bits == engines.BALL_START
        res = engines.ball_orbit(r, math.pi / 6, math.pi / 5, 1500, start_bits=256, dps=77, checkpoints=(1500,))
        n = res.checkpoints[1500][1]
        with flint.ctx.workprec(res.bits):
            rel = max(z.rad() for z in n) / max(abs(z.mid()) for z in n)
        assert rel < flint.arb(2) ** -200


def test_ball_engine_raises_the_precision_when_a_choice_is_undecided():
    """cos φ0 = 2^-300 exactly (a rational normal): the first images mix 1 and 2^-300,
    64 bits cannot decide them; the engine raises its precision and gives the exact word."""
    eps = flint.fmpq(1, 2 ** 300)
    res = engines.ball_orbit(flint.fmpq(1, 2), 0, 0, 50, normal=(-1, eps, 1), word=True)
    word, _ = reduction.word_of(reduction.canonical("b", (-(2 ** 300), 1, 2 ** 300)), flint.fmpq(1, 2), 50)
    assert res.code == 0 and res.collisions == 50 and res.bits > engines.BALL_START
    assert res.word == word


# --- simulate and the CLI -------------------------------------------------------------

def test_simulate_reports_certified_and_words():
    data = chaotic_data(2)
    r = [data[0][0]]
    theta0, phi0 = [d[1] for d in data], [d[2] for d in data]
    out = numerics.iterate(r, theta0, phi0, collisions=400, keep=5, words=True)
    ball = numerics.iterate(r, theta0, phi0, collisions=400, keep=5, engine="ball", words=True)
    assert out.word.shape == (1, 2) and all(len(w) == 400 for w in out.word.ravel())
    assert np.array_equal(ball.certified, ball.collisions)
    for b in range(2):
        one = engines.float64_orbit(r[0], theta0[b], phi0[b], 400, word=True)
        assert out.word[0, b] == one.word and out.certified[0, b] == one.certified < 400
    strict = numerics.iterate(r, theta0, phi0, collisions=400, keep=5, strict=True)
    assert (strict.breaks == numerics.HORIZON).all() and np.array_equal(strict.collisions, out.certified)
    assert 0 < out.certified_fraction() < 1 and "certified:" in out.summary()


def test_npz_keeps_the_words(tmp_path):
    out = numerics.iterate([0.3], [0.5], [1.0], collisions=50, keep=5, words=True)
    out.save(tmp_path / "w.npz")
    back = numerics.Orbits.load(tmp_path / "w.npz")
    assert back.word[0, 0] == out.word[0, 0] and len(back.word[0, 0]) == 50
    assert np.array_equal(back.certified, out.certified)


def test_cli_explicit_data_words_strict(tmp_path):
    from certify.cli import main
    path = tmp_path / "one.npz"
    assert main(["simulate", "--r", "0.1", "--theta0", "0.5", "1.2", "--phi0", "1", "2.5", "--collisions", "300",
                 "--words", "--out", str(path)]) == 0
    data = np.load(path)
    assert data["theta0"].tolist() == [0.5, 1.2] and data["phi0"].tolist() == [1.0, 2.5]
    assert data["word"][0, 1] == engines.float64_orbit(0.1, 1.2, 2.5, 300, word=True).word
    assert (data["certified"] < 300).all()
    assert main(["simulate", "--r", "0.1", "--theta0", "0.5", "--phi0", "1", "--collisions", "300", "--strict",
                 "--out", str(path)]) == 0
    data = np.load(path)
    assert data["breaks"].tolist() == [[numerics.HORIZON]] and data["collisions"].tolist() == data["certified"].tolist()
    assert "word" not in data.files


@pytest.mark.parametrize("args", [
    ["--r", "0.5", "--theta0", "0.5", "1", "--phi0", "1"],          # lengths differ
    ["--r", "0.5", "--theta0", "1.6", "--phi0", "1"],                 # θ0 > π/2
    ["--r", "0.5", "--theta0", "-0.1", "--phi0", "1"],                # θ0 < 0
    ["--r", "0.5", "--theta0", "1", "--phi0", "3.2"],                 # φ0 > π
    ["--r", "0.5", "--theta0", "1"],                                  # θ0 without φ0
    ["--r", "0.5", "--phi0", "1"],                                    # φ0 without θ0
    ["--r", "0.5", "--orbits", "2", "--theta0", "1", "--phi0", "1"],  # the grid and explicit data
    ["--r", "0.5", "--words"],                                        # words without --out
    ["--r-range", "0.2", "0.1", "3"],                                 # reversed
    ["--r", "0.5", "--theta0", "x", "--phi0", "1"],
])
def test_cli_usage_errors_of_the_new_options(args, capsys):
    from certify.cli import main
    assert main(["simulate", *args]) == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1 and err.startswith("certify: error:"), err


# --- stress ---------------------------------------------------------------------------

def _columns(line):
    return len(line.replace("\\|", "")) - len(line.replace("\\|", "").replace("|", ""))


def test_stress_report_tables_keep_their_columns(monkeypatch):
    """Every row of every table of STRESS.md has its header's number of cells (a '|'
    inside a cell, as in '|cos φ0|', is escaped), and the quick run has no silent wrong
    collision."""
    from certify.numerics import stress
    monkeypatch.setattr(stress, "RANDOM_QUICK", dict(count=6, collisions=200, seed=3))
    text, wrong = stress.report(quick=True)
    assert wrong == 0 and "**Silent wrong collisions: 0.**" in text
    header = None
    rows = 0
    for line in text.splitlines():
        if not line.startswith("|"):
            header = None
            continue
        if header is None:
            header = _columns(line)
        assert _columns(line) == header, line
        rows += 1
    assert rows > 50 and "\\|cos φ0\\|" in text
    assert stress.cell("|cos φ0|") == "\\|cos φ0\\|"


def test_stress_counts_a_departure_at_a_certified_collision_as_silent_wrong():
    """silent(): a departure within the certified prefix is wrong, after it is not."""
    from certify.numerics import stress
    data = [(0.1, 0.5, 1.0), (0.1, 0.6, 1.0)]
    ball = (0, 2000, 64)
    fine = {"ball": ball, ("float64", None): (0, 2000, 40, 120), ("mp", 30): (0, 2000, 90, 0)}
    bad = {"ball": ball, ("float64", None): (0, 2000, 40, 30), ("mp", 30): (0, 2000, 90, 90)}
    _, wrong = stress.random_section([fine, fine], data, 2000)
    assert wrong == 0
    table, wrong = stress.random_section([fine, bad], data, 2000)
    assert wrong == 2 and any(line.endswith("| 1 |") for line in table)
    assert stress.verdict(bad[("float64", None)], ball).startswith("**WRONG at 30**")
    assert "departs at 120" in stress.verdict(fine[("float64", None)], ball)


def test_cli_stress_runs_its_random_orbits_on_jobs(tmp_path, monkeypatch, capsys):
    """`stress --quick --jobs 2 --out FILE`: the random orbits on two processes, the
    report written, exit 0; `--jobs 0` is a usage error."""
    from certify.cli import main
    from certify.numerics import stress
    monkeypatch.setattr(stress, "RANDOM_QUICK", dict(count=4, collisions=100, seed=5))
    monkeypatch.setattr(stress, "cases", lambda quick: [stress.Case("θ0 near 0", 0.5, 0.0, 1.0, 50)])
    out = tmp_path / "S.md"
    assert main(["stress", "--quick", "--jobs", "2", "--out", str(out)]) == 0
    text = out.read_text()
    assert "## 4 random orbits, 100 collisions each" in text and "**Silent wrong collisions: 0.**" in text
    assert "0 silent wrong collision(s)" in capsys.readouterr().out
    assert main(["stress", "--jobs", "0", "--out", str(out)]) == 2


# --- the bound's own proof, across a rescaling, and what certifies ------------------------

U, ETA = Fraction(1, 2 ** 53), Fraction(1, 2 ** 1074)
GAMMA3 = 3 * U / (1 - 3 * U)


def test_carry_bound_meets_its_proof_inequality_in_exact_rationals():
    """Step (iii) of rules.carry_bound's proof on computed values, exactly in rationals:
    err'_m ≥ Σ_c |Ĉ_mc| ((γ_3 + u/(1 − u)) |n_c| + err_c/(1 − u)) + 3η, γ_3 = 3u/(1 − 3u)
    written here (not rules.gamma_bound), on random states whose error ranges from 0 to far
    above |n| (past the horizon), at several r.  Without κ (K = 1) the five roundings of the
    bound are uncovered, with γ = 3u the rounding of the product, and the inequality fails."""
    rng = random.Random(7)
    for r in (0.013, 0.3, 0.77):
        absrows = np.abs(np.array(rules.float_rows(r))).tolist()
        for k in range(400):
            low = -1070 if k % 4 == 0 else -40                  # a quarter underflows: the 3η term and tiny
            n = [rng.uniform(-1, 1) * 2.0 ** rng.randint(low, 40) for _ in range(3)]
            err = [abs(z) * 2.0 ** rng.randint(-60, 8) * rng.random() for z in n]
            j = rng.randrange(3)
            out = rules.carry_bound(j, n, err, absrows, rules.G64, rules.K64, rules.TINY64)
            for m in range(3):
                C = [Fraction(absrows[j][m][c]) for c in range(3)]
                needed = sum(C[c] * ((GAMMA3 + U / (1 - U)) * abs(Fraction(n[c])) + Fraction(err[c]) / (1 - U))
                             for c in range(3)) + 3 * ETA
                assert Fraction(out[m]) >= needed, (r, j, m)


def _exact_check(r, n0, collisions):
    """The float64 orbit of the exact datum n0 (initial bound 0) against its exact orbit,
    with the engine's orientations and power-of-2 rescalings: |n̂_k − x_k| ≤ err_k.  Returns
    the rescaling factors met."""
    code, done, cert, letters, normals, errs, rows = traced(r, n0, collisions, tol=0.0)
    assert code == 0 and done == collisions
    exact = exact_scaled_rows(r)
    x = [Fraction(z) for z in n0]
    prev = np.array(n0, dtype=float)
    factors = []
    for k in range(done):
        C = exact[letters[k]]
        y = [sum(C[m][c] * x[c] for c in range(3)) for m in range(3)]
        approx = rows[letters[k]] @ prev
        s = 1 if float(np.dot(approx, normals[k])) > 0 else -1
        e = round(math.log2(np.max(np.abs(normals[k])) / np.max(np.abs(approx))))
        factors.append(e)
        x = [s * Fraction(2) ** e * z for z in y]
        for m in range(3):
            assert abs(Fraction(normals[k, m]) - x[m]) <= Fraction(errs[k, m]), (k, m, e)
        prev = normals[k]
    return factors


@pytest.mark.parametrize("scale", [-255, 255])
def test_the_bound_bounds_the_error_across_a_rescaling(scale):
    """A datum at the edge of the kernel's range [2^-256, 2^256]: the normal is rescaled by
    a power of 2 within a few collisions (up for 2^-255, down for 2^255), and the bound,
    rescaled with it (step (v)), still bounds the error of the exact orbit."""
    n0 = tuple(math.ldexp(z, scale) for z in (-3, 5, 4))
    factors = _exact_check(0.5, n0, 40)
    assert any(e != 0 for e in factors) and all((e > 0) == (scale < 0) for e in factors if e)


def test_the_kernel_rescales_the_bound_as_the_rules_say():
    """Bit for bit across rescalings: the kernel's err is rules.carry_bound, then, when the
    normal is multiplied by f = 2^e, fl(fl(err f) + tiny) (kernel._advance, step (v))."""
    r = 0.5
    for scale in (-255, 255):
        n0 = tuple(math.ldexp(z, scale) for z in (-3, 5, 4))
        code, done, cert, letters, normals, errs, rows = traced(r, n0, 40)
        absrows = np.abs(rows).tolist()
        err = (rules.TOL64 * max(abs(z) for z in n0),) * 3
        n, scaled = n0, 0
        for k in range(done):
            err = rules.carry_bound(int(letters[k]), n, err, absrows, rules.G64, rules.K64, rules.TINY64)
            m = rules.advance(int(letters[k]), n, rows.tolist())
            e = round(math.log2(np.max(np.abs(normals[k])) / max(abs(z) for z in m)))
            if e:
                f = 2.0 ** e
                err = tuple(z * f + rules.TINY64 for z in err)
                scaled += 1
            assert tuple(errs[k]) == err, (scale, k)
            n = tuple(normals[k])
        assert scaled


@pytest.mark.parametrize("certifies", [rules.certifies, kernel._certifies], ids=["rules", "kernel"])
def test_a_contact_is_not_certified_when_an_in_face_entry_is_within_its_bound(certifies):
    """A state at b (i = 1) whose contact entry n_b is decided by its bound but whose
    orientation entry n_z or face entry n_x lies within its bound of 0: not certified (the
    true normal may be outside the face).  Decided by the margin rule (classify at a smaller
    bound), so only the accumulated bound can refuse it."""
    err = (1e-9, 1e-9, 1e-9)
    assert certifies(1, (-1.0, 0.5, 1.0), err, 2)                     # every entry decided: certified
    for n in ((-1.0, 0.5, 5e-10), (-5e-10, 0.5, 1.0), (-1.0, -0.5, 5e-10), (-5e-10, -0.5, 1.0)):
        j = 2 if n[1] > 0 else 0
        assert rules.classify(1, n, (1e-12,) * 3) == (0, j)
        assert not certifies(1, n, err, j), n


def test_float64_refuses_a_subnormal_r():
    """At r = 1e-310 (subnormal) the float matrices carry subnormal entries (no relative
    rounding; the kernel's rescaling overflowed to a non-finite break): refused, one line,
    exit 2 at the command line; the smallest normal r is accepted and completes its steps
    without a non-finite break."""
    from certify.errors import UsageError
    with pytest.raises(UsageError, match="too small for the float64 engine"):
        rules.float_rows(1e-310)
    with pytest.raises(UsageError):
        engines.float64_orbit(1e-310, 0.5, 1.0, 10)
    res = numerics.iterate([2.0 ** -1021], *numerics.grid(8), collisions=50, keep=1)
    assert numerics.NONFINITE not in res.breaks
    assert engines.mp_orbit(1e-310, 0.5, 1.0, 20).code == 0        # exact rows: no limit there


def test_cli_simulate_subnormal_r_is_one_line_exit_2(capsys):
    from certify.cli import main
    assert main(["simulate", "--r", "1e-310"]) == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1 and "2^-60" in err, err


def test_the_rescaled_bound_covers_an_underflowing_entry():
    """Step (v) of rules.carry_bound's proof on a crafted state of kernel._advance: the normal
    is scaled down (its largest entry passes 2^256, f = 2^-258) while the bound of its small
    entry, err'_2 f ≈ 2^-1028, is subnormal: the kernel's err''_2 = fl(fl(err'_2 f) + tiny) must
    exceed err'_2 f + η/2 exactly (the underflow of f n'_2).  Without tiny it does not."""
    rows = np.array(rules.float_rows(0.5)).reshape(27)
    n = (math.ldexp(-3.0, 255), math.ldexp(5.0, 255), math.ldexp(4.0, -720))
    err = (2.0 ** -1000,) * 3
    m, _bnd, out = kernel._advance(0, n, err, rows, *CONSTANTS)
    before = rules.carry_bound(0, n, err, np.abs(rows.reshape(3, 3, 3)).tolist(), *CONSTANTS[1:])
    unscaled = rules.advance(0, n, rows.reshape(3, 3, 3).tolist())
    f = Fraction(max(abs(z) for z in m)) / max(abs(Fraction(z)) for z in unscaled)
    assert f == Fraction(1, 2 ** 258)
    assert Fraction(before[2]) * f < Fraction(1, 2 ** 1022)              # the case the proof's tiny covers
    small = [k for k in range(3) if Fraction(before[k]) * f < Fraction(1, 2 ** 947)]
    assert small == [2]                  # (the others are exact, and (iv)'s slack covers them)
    assert Fraction(out[2]) >= Fraction(before[2]) * f + ETA / 2


@pytest.mark.parametrize("quick", [True, False])
def test_stress_runs_each_near_singular_datum_once(quick):
    """π/2 ± 1e-17 are one float64: the table once showed that datum twice (issue 25)."""
    from certify.numerics import stress
    data = [(c.r, c.theta0, c.phi0, c.collisions) for c in stress.cases(quick)]
    assert len(data) == len(set(data)) and len(data) > 30
