"""Run time against error of the numerical engines (certify.numerics), and the
float64 kernel against a plain C loop of the same map.

    python benchmarks/bench_numerics.py [--quick]
    python -m certify bench --numerics [--quick]

Measured in one run:

* the float64 kernel, one core: map steps per CPU second (both sides measure their
  process's CPU time, best of 3: a per-core rate that a loaded machine does not
  distort as much as wall time) on a stable-window orbit
  (r = 0.15, the (ab)^2(cb)^2 window), a chaotic one (r = 0.5) and one between the
  windows (r = 0.1), against ``benchmarks/loop.c`` compiled with ``cc -O2`` (same
  matrices, same checks, the same accumulated error bound, same word and certified
  horizon: the checksums must agree); the ratio;
* Figure 5.1 at the paper's resolution (3709 r × 8 orbits × 10^4 collisions) with
  ``simulate`` on every core (numba threads), and on one;
* for every engine and precision (float64; mp at 16, 30, 60, 120 digits; ball): the
  time per collision and the error after 10^2, 10^3, 10^4 collisions against the
  certified ball orbit (the sine of the angle between the normals; "word" when the
  collision word already departed);
* the horizon of trust, per regime, for the 8 orbits of the paper's grid: as
  certified (the accumulated error bound of float64, mp 16 and mp 30 digits) and as
  measured (the first collision where the word departs from the certified ball word);
* the ball engine (benchmarks/bench_ball.py): bits lost and µs per collision at a
  fixed precision, and the certified horizon reached in 10 s, for this checkout and
  for the engine before the exact products (``BEFORE``, a ``git archive`` of that
  commit measured by the same script in a subprocess).

Without --quick the tables go to reports/BENCH.md (section "numerics") and the plot
to reports/figures/bench_numerics.png.
"""
from __future__ import annotations

import argparse
import math
import os
import platform
import shutil
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ProcessPoolExecutor
from datetime import date
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
if str(ROOT) not in sys.path:  # run as a script from a source checkout
    sys.path.insert(0, str(ROOT))

import flint  # noqa: E402
import mpmath  # noqa: E402
import numba  # noqa: E402
import numpy as np  # noqa: E402

from certify.numerics import engines, iterate, kernel, paper_grid, rules  # noqa: E402
from certify.run import files  # noqa: E402

BENCH = ROOT / "reports" / "BENCH.md"
PLOT = ROOT / "reports" / "figures" / "bench_numerics.png"
ORBITS = {"stable": 0.15, "chaotic": 0.5, "between the windows": 0.1}
BEFORE = "cb9d573"             # the last commit whose ball engine wrapped (one ball through every matrix)
CONSTANTS = (rules.TOL64, rules.G64, rules.K64, rules.TINY64)
MP_DPS = (16, 30, 60, 120)
THETA, PHI = paper_grid()


# --- speed ---------------------------------------------------------------------

def kernel_input(r, orbit=0):
    rows = np.array(rules.float_rows(r)).reshape(27)      # the kernel's flat layout, as loop.c's
    n0 = np.array(rules.initial_normal(THETA[orbit], PHI[orbit]))
    return rows, n0


def float64_rate(r, steps, repeat=3):
    """(steps per second, (code, done, certified, checksum)) of the numba kernel, one
    core, best of ``repeat``."""
    rows, n0 = kernel_input(r)
    kernel.count_steps(1, n0, rows, *CONSTANTS, 10)
    best, out = float("inf"), None
    for _ in range(repeat):
        start = time.process_time()          # CPU time, as loop.c measures: per core, robust to load
        out = kernel.count_steps(1, n0, rows, *CONSTANTS, steps)
        best = min(best, time.process_time() - start)
    return out[1] / best, out


def c_rate(r, steps, repeat=3):
    """(steps per second, (code, done, certified, checksum)) of benchmarks/loop.c, or
    None without a compiler."""
    cc = shutil.which("cc") or shutil.which("gcc")
    if cc is None:
        return None
    rows, n0 = kernel_input(r)
    with tempfile.TemporaryDirectory() as tmp:
        exe = Path(tmp) / "loop"
        subprocess.run([cc, "-O2", "-o", str(exe), str(ROOT / "benchmarks" / "loop.c"), "-lm"], check=True)
        numbers = [float(x).hex() for x in CONSTANTS] + ["1"] + [float(x).hex() for x in [*n0, *rows.ravel()]]
        text = f"{steps} {repeat} " + " ".join(numbers)
        out = subprocess.run([str(exe)], input=text, capture_output=True, text=True, check=True).stdout.split()
    code, done, cert, check, seconds = int(out[0]), int(out[1]), int(out[2]), int(out[3]), float(out[4])
    return done / seconds, (code, done, cert, check)


def ball_tables(quick):
    """The rows of bench_ball.table() for this checkout, and for BEFORE (None when git
    or the commit is missing)."""
    import importlib.util
    spec = importlib.util.spec_from_file_location("bench_ball", ROOT / "benchmarks" / "bench_ball.py")
    bench_ball = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(bench_ball)
    kw = dict(prec=512, marks=(100, 300), seconds=1.0) if quick else {}
    now = bench_ball.table(**kw)
    before = None
    with tempfile.TemporaryDirectory() as tmp:
        archive = subprocess.run(["git", "-C", str(ROOT), "archive", BEFORE], capture_output=True)
        if archive.returncode == 0:
            subprocess.run(["tar", "-x", "-C", tmp], input=archive.stdout, check=True)
            code = ("import sys; sys.path.insert(0, sys.argv[1]); import runpy; "
                    "m = runpy.run_path(sys.argv[2]); print('\\n'.join(m['table'](**eval(sys.argv[3]))))")
            script = str(ROOT / "benchmarks" / "bench_ball.py")
            res = subprocess.run([sys.executable, "-c", code, tmp, script, repr(kw)],
                                 capture_output=True, text=True, env={**os.environ, "PYTHONPATH": tmp})
            before = res.stdout.strip().splitlines() if res.returncode == 0 else [f"(failed: {res.stderr[-300:]})"]
    return now, before


def paper_sweep(threads, n_r=3709, collisions=10_000):
    """Seconds of iterate() over n_r values of r in [0.072, 0.999] × the 8 grid orbits."""
    numba.set_num_threads(threads)
    r = np.linspace(0.072, 0.999, n_r)
    iterate(r[:2], THETA, PHI, collisions=10, keep=5)
    start = time.perf_counter()
    out = iterate(r, THETA, PHI, collisions=collisions, keep=500)
    seconds = time.perf_counter() - start
    numba.set_num_threads(numba.config.NUMBA_NUM_THREADS)
    return seconds, out


# --- error -------------------------------------------------------------------

def as_arb(z):
    """An engine's number as an arb: a float or an mpf exactly, an fmpq at the working
    precision, a ball by its midpoint."""
    if isinstance(z, flint.arb):
        return z.mid()
    if isinstance(z, float):
        return flint.arb(float(z))
    if isinstance(z, flint.fmpq):
        return flint.arb(z)
    sign, man, exp, _ = z._mpf_
    return (-1) ** sign * flint.arb(int(man)) * flint.arb(2) ** int(exp)


def distance(n, m) -> float:
    """sin of the angle between two normals (projective distance), at 4096 bits."""
    old = flint.ctx.prec
    flint.ctx.prec = 4096
    try:
        a, b = [as_arb(z) for z in n], [as_arb(z) for z in m]
        c = (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
        num2 = sum(z * z for z in c)                 # may straddle 0 when below the precision
        den2 = sum(z * z for z in a) * sum(z * z for z in b)
        ratio = num2.upper() / den2.lower()          # an upper bound of sin²
        return math.sqrt(max(float(ratio), 0.0))
    finally:
        flint.ctx.prec = old


def departure(word, ref_word) -> int:
    """The first collision (1-based) where ``word`` departs from ``ref_word``, or
    -1 when it does not within both."""
    for k, (x, y) in enumerate(zip(word, ref_word)):
        if x != y:
            return k + 1
    return -1


def errors(engine, dps, r, collisions, marks, ref):
    """(seconds per collision, {mark: error or 'word'}) of one engine on orbit 0."""
    code, done, bits, ref_word, ref_cps = ref
    start = time.perf_counter()
    res = engines.run_orbit(engine, r, THETA[0], PHI[0], collisions, dps=dps, word=True, checkpoints=marks)
    seconds = (time.perf_counter() - start) / max(res.collisions, 1)
    out = {}
    for k in marks:
        if k not in res.checkpoints or k not in ref_cps:
            out[k] = "break"
        elif departure(res.word[:k], ref_word[:k]) != -1:
            out[k] = "word"
        else:
            ref_n = [flint.fmpq(p, q) for p, q in ref_cps[k][1]]
            out[k] = distance(res.checkpoints[k][1], ref_n)
    return seconds, out, res


def fmt(e) -> str:
    return e if isinstance(e, str) else ("< 1e-300" if e == 0 else f"{e:.1e}")


# --- main --------------------------------------------------------------------

def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="bench --numerics", description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true", help="small sizes, nothing written")
    args = parser.parse_args(argv)
    quick = args.quick
    steps = 10**6 if quick else 2 * 10**7
    collisions = 1000 if quick else 10_000
    marks = tuple(k for k in (100, 1000, 10_000) if k <= collisions)
    lines = []

    def say(text=""):
        print(text, flush=True)
        lines.append(text)

    # 1. the kernel against C
    speed = []
    for name, r in ORBITS.items():
        f_rate, f_out = float64_rate(r, steps)
        c = c_rate(r, steps)
        same = c is not None and tuple(c[1]) == tuple(int(x) for x in f_out)
        speed.append((name, r, f_rate, c[0] if c else None, same))
    # 2. the paper's sweep
    cores = numba.config.NUMBA_NUM_THREADS
    n_r = 371 if quick else 3709
    t_all, sweep = paper_sweep(cores, n_r)
    t_one, _ = paper_sweep(1, n_r) if not quick else (None, None)
    # 3. references, horizons: certified (the bound) and measured (against the ball word)
    grid = range(2 if quick else 8)
    jobs = [(r, o) for r in ORBITS.values() for o in grid]
    with ProcessPoolExecutor(cores) as pool:
        futures = {job: pool.submit(engines.certified, job[0], THETA[job[1]], PHI[job[1]], collisions, marks,
                                    None, 1024) for job in jobs}
        refs = {job: f.result() for job, f in futures.items()}
    horizon = {}
    setups_h = (("float64", None), ("mp", 16), ("mp", 30))
    for (r, o), ref in refs.items():
        for engine, dps in setups_h:
            res = engines.run_orbit(engine, r, THETA[o], PHI[o], collisions, dps=dps, word=True)
            dep = departure(res.word, ref[3])
            horizon[(r, o, engine, dps)] = (dep, res.certified, min(res.collisions, ref[1]))
    # 4. run time against error, orbit 0 of the grid
    table = []
    setups = [("float64", None)] + [("mp", d) for d in MP_DPS] + [("ball", None)]
    for engine, dps in setups:
        row = [engine if dps is None else f"{engine} {dps} digits"]
        bits = []
        for r in ORBITS.values():
            ref = refs[(r, 0)]
            if engine == "float64":
                rate, _ = float64_rate(r, steps // 10, repeat=1)
                _, errs, res = errors(engine, dps, r, collisions, marks, ref)
                sec = 1 / rate
            else:
                sec, errs, res = errors(engine, dps, r, collisions, marks, ref)
            bits.append(str(res.bits))
            row += [sec * 1e6] + [errs[k] for k in marks]
        if engine == "ball":
            row[0] += " (" + "/".join(bits) + " bits)"
        table.append(row)
    # 5. the ball engine, now and before
    ball_now, ball_before = ball_tables(quick)

    say(f"float64 kernel (with the accumulated error bound) against benchmarks/loop.c (cc -O2, the same bound), "
        f"one core, {steps:.0e} steps:")
    ratios = []
    for name, r, f, c, same in speed:
        ratio = f"{f / c:.2f}" if c else "no C compiler"
        if c:
            ratios.append(f / c)
        say(f"  {name} r = {r}: float64 {f / 1e6:.1f} M steps/s, C {c / 1e6 if c else float('nan'):.1f} M steps/s, "
            f"ratio {ratio}, same word and certified horizon: {same}")
    if ratios:
        say(f"  median ratio float64 / C: {float(np.median(ratios)):.2f}")
    total = int(sweep.collisions.sum())
    say(f"Figure 5.1 sweep ({n_r} r × 8 orbits × {collisions} collisions = {total:.3g} collisions): "
        f"{t_all:.2f} s on {cores} threads" + (f", {t_one:.2f} s on one" if t_one else "")
        + f"; breaks: {dict((int(k), int(v)) for k, v in zip(*np.unique(sweep.breaks, return_counts=True)))}; "
        f"certified: {sweep.certified_fraction():.2%} of the collisions")
    say("")
    say("Horizon of trust over the orbits of the paper's grid (min / median / max): certified = the collisions the "
        "accumulated error bound proves; measured = the first collision where the word departs from the certified "
        "ball word ('>N': none within the N compared):")
    for name, r in ORBITS.items():
        for engine, dps in setups_h:
            cert = sorted(horizon[(r, o, engine, dps)][1] for o in grid)
            deps = [horizon[(r, o, engine, dps)] for o in grid]
            meas = sorted(d if d > 0 else float("inf") for d, _, _ in deps)
            shown = [str(x) if x != float("inf") else f">{min(n for _, _, n in deps)}" for x in
                     (meas[0], meas[len(meas) // 2], meas[-1])]
            label = engine if dps is None else f"{engine} {dps} digits"
            say(f"  {name} r = {r}, {label}: certified {cert[0]} / {cert[len(cert) // 2]} / {cert[-1]}; "
                f"measured {' / '.join(shown)}")
    head = "| engine | " + " | ".join(f"µs/coll. r={r} | " + " | ".join(f"err {k}" for k in marks)
                                       for r in ORBITS.values()) + " |"
    say("")
    say(head)
    say("|" + "---|" * (1 + len(ORBITS) * (1 + len(marks))))
    for row in table:
        cells = [row[0]] + [f"{x:.3g}" if isinstance(x, float) and i % (1 + len(marks)) == 0 else fmt(x)
                            for i, x in enumerate(row[1:])]
        say("| " + " | ".join(cells) + " |")
    say("")
    say("Ball engine, now (exact products of the cofactor matrices, re-centred every "
        f"{engines.SEGMENT} collisions), the paper's first orbit:")
    say("")
    for line in ball_now:
        say(line)
    say("")
    say(f"Ball engine before ({BEFORE}: one ball pushed through every matrix), the same script:")
    say("")
    for line in ball_before or ["(not measured: no git checkout)"]:
        say(line)
    if not quick:
        plot(table, marks)
        machine = (f"{date.today().isoformat()}, {os.cpu_count()} cores, {platform.machine()}, Python "
                   f"{platform.python_version()}, numba {numba.__version__}, mpmath {mpmath.__version__} "
                   f"(backend {mpmath.libmp.BACKEND}), python-flint {flint.__version__}")
        body = (f"Measured by `python -m certify bench --numerics` on {machine}, in one run.  Errors: the sine of "
                "the angle between the engine's normal and the certified ball normal after k collisions of the orbit "
                f"(θ0, φ0) = ({THETA[0]:.4f}, {PHI[0]:.4f}) from b; 'word': the collision word had already "
                "departed.  Plot: reports/figures/bench_numerics.png.\n\n" + markdown(lines))
        files.write_section(BENCH, "numerics", body)
        print(f"\nwrote {BENCH.relative_to(ROOT)} (section 'numerics') and {PLOT.relative_to(ROOT)}")
    return 0


def markdown(lines) -> str:
    """The printed lines as Markdown: tables as tables, the rest in code blocks."""
    out, text = [], []
    for line in lines + [""]:
        if line.startswith("|"):
            if text and any(t.strip() for t in text):
                out.append("```\n" + "\n".join(text).strip("\n") + "\n```")
            text = []
            out.append(line)
        else:
            if out and out[-1].startswith("|"):
                out.append("")
            text.append(line)
    if text and any(t.strip() for t in text):
        out.append("```\n" + "\n".join(text).strip("\n") + "\n```")
    return "\n".join(out) + "\n"


def plot(table, marks, path=None):
    """Each engine's error after the last mark against its time per collision, one panel per orbit,
    into ``path`` (default reports/figures/bench_numerics.png; certify.run.saving.write_figure: the
    same bytes for the same table)."""
    from certify.run import saving
    plt = saving.pyplot()
    fig, axes = plt.subplots(1, len(ORBITS), figsize=(5 * len(ORBITS), 4.2), sharey=True)
    width = 1 + len(marks)
    for a, (ax, (name, r)) in enumerate(zip(axes, ORBITS.items())):
        for row in table:
            sec = row[1 + a * width]
            err = row[1 + a * width + len(marks)]
            if isinstance(err, float):
                ax.loglog(sec, max(err, 1e-300), "o")
                ax.annotate(row[0].split(" (")[0], (sec, max(err, 1e-300)), xytext=(4, -3),
                            textcoords="offset points", fontsize=7)
        ax.margins(x=0.25)                      # room for the engines' names at the right
        ax.set_title(f"{name} orbit, r = {r}:\nerror after {marks[-1]} collisions", fontsize=9)
        ax.set_xlabel("µs per collision")
        ax.tick_params(labelleft=True)
    axes[0].set_ylabel("sin(angle to the certified normal)")
    fig.tight_layout()
    saving.write_figure(fig, path or PLOT, dpi=100)

if __name__ == "__main__":
    raise SystemExit(main())
