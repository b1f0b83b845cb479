"""The mutation run of issue 25 over carry_bound, trapping and reduction_orbits.

Each mutant is a textual replacement in one source file (it must match exactly once).  The
tree (certify/, tests/, pyproject.toml) is copied once to a temporary directory; for each
mutant the file is rewritten there, the targeted tests run with PYTHONPATH set to the copy
(``pytest -x``: the first failure kills), and the original is put back.  A mutant is
*killed* when the tests fail, *survived* when they pass.  Every mutant the issue lists must
be killed; a survivor outside the list must be one docs/developing.md explains.

    nice python benchmarks/mutation_run.py              # all (about 10 minutes on a loaded machine)
    python benchmarks/mutation_run.py --only carry      # one group: carry, trapping, orbits
    python benchmarks/mutation_run.py --list

Exit code 1 when a listed mutant survives or an expected survivor is killed (update the docs).
"""
from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
ORBITS, RULES, KERNEL, TRAP = ("certify/patterns/reduction_orbits.py", "certify/numerics/rules.py",
                               "certify/numerics/kernel.py", "certify/numerics/trapping.py")
TESTS = {"orbits": ["tests/patterns/test_reduction_orbits.py"],
         "carry": ["tests/numerics/test_horizon.py", "-k", "not stress"],
         "trapping": ["tests/numerics/test_trapping.py"]}


@dataclass(frozen=True)
class Mutant:
    name: str
    group: str
    path: str
    old: str
    new: str
    listed: bool = False          # listed in issue 25: must be killed
    survives: bool = False        # an expected survivor (docs/developing.md says why it changes no result)


MUTANTS = [
    # ---- reduction_orbits (issue 25's list first)
    Mutant("analyse: λ(det M − λ³) → λ(det M + λ³) (Jury, attracting)", "orbits", ORBITS,
           'R("λ (det M - λ³)", L * (det - L ** 3))', 'R("λ (det M - λ³)", L * (det + L ** 3))', listed=True),
    Mutant("orbit_at: λ(det M − λ³) → λ(det M + λ³)", "orbits", ORBITS,
           '"attracting": [d, -L * minus, L * (det - L ** 3)]', '"attracting": [d, -L * minus, L * (det + L ** 3)]',
           listed=True),
    Mutant("orbit_at: −λ cp(−λ) > 0 dropped (attracting)", "orbits", ORBITS,
           '"attracting": [d, -L * minus, L * (det - L ** 3)]', '"attracting": [d, L * (det - L ** 3)]', listed=True),
    Mutant("analyse: −λ cp(−λ) > 0 dropped (attracting and repelling)", "orbits", ORBITS,
           'common = [R("cp\'(λ)", d), R("-λ cp(-λ)", -L * minus)]', 'common = [R("cp\'(λ)", d)]'),
    Mutant("orbit_at: −λ cp(−λ) > 0 dropped (repelling)", "orbits", ORBITS,
           '"repelling": [d, -L * minus, L * (L ** 3 - det)]', '"repelling": [d, L * (L ** 3 - det)]', survives=True),
    Mutant("analyse: saddle sign flipped", "orbits", ORBITS,
           '"saddle": [R("λ cp\'(λ) cp(-λ)", L * d * minus)]', '"saddle": [R("λ cp\'(λ) cp(-λ)", -L * d * minus)]'),
    Mutant("analyse: det M / λ > 0 → < 0", "orbits", ORBITS,
           'return Requirement("det M / λ", (to_field(det) / to_field(L), FIELD.zero), 1)',
           'return Requirement("det M / λ", (to_field(det) / to_field(L), FIELD.zero), -1)'),
    Mutant("analyse: direction σ flipped", "orbits", ORBITS,
           "sigma = 1 if j == (i + 1) % 3 else -1\n        feasible.append",
           "sigma = -1 if j == (i + 1) % 3 else 1\n        feasible.append"),
    Mutant("analyse: n*_x < 0 → > 0", "orbits", ORBITS,
           'exists = [req("n*_x (inside the face b)", 0, (i0 + 2) % 3, -1)]',
           'exists = [req("n*_x (inside the face b)", 0, (i0 + 2) % 3, 1)]'),
    Mutant("orbit_at: the last contact not checked (off by one)", "orbits", ORBITS,
           "for j in range(1, len(normal) + 1):", "for j in range(1, len(normal)):", survives=True),
    Mutant("orbit_at: n*_x = 0 accepted (>= → >)", "orbits", ORBITS,
           "if s(run[0][0]) * s3 >= 0:", "if s(run[0][0]) * s3 > 0:", survives=True),
    Mutant("orbit_at: complex pair when disc ≤ 0", "orbits", ORBITS,
           'pair = "complex" if disc < 0 else "real"', 'pair = "complex" if disc <= 0 else "real"', survives=True),
    Mutant("pair_requirement: complex ↔ real", "orbits", ORBITS,
           'for name, sign in (("complex", -1), ("real", 1)):', 'for name, sign in (("complex", 1), ("real", -1)):'),
    Mutant("_modulus: max → min", "orbits", ORBITS,
           "return max((abs(x / y) for y in ys), key=lambda m: m.mid())",
           "return min((abs(x / y) for y in ys), key=lambda m: m.mid())"),
    # ---- carry_bound (rules.py, its transcription in kernel.py)
    Mutant("K = 1 (the bound's own roundings uncovered)", "carry", RULES,
           "K64 = float(inflation(53))", "K64 = 1.0", listed=True),
    Mutant("the power-of-2 rescaling not applied to the bound", "carry", KERNEL,
           "        e0 = e0 * f + tiny\n        e1 = e1 * f + tiny\n        e2 = e2 * f + tiny\n", "", listed=True),
    Mutant("certification ignores the bound on the orientation and face entries (kernel)", "carry", KERNEL,
           "if not (n[a] > err[a] and n[b] < -err[b]):", "if not (n[a] > 0.0 and n[b] < 0.0):", listed=True),
    Mutant("certification ignores the bound on the orientation and face entries (rules)", "carry", RULES,
           "    return classify(i, n, err, sign, finite) == (COMPLETED, j)",
           "    return classify(i, n, (err[0] if i == 0 else 0, err[1] if i == 1 else 0, err[2] if i == 2 else 0),"
           " sign, finite) == (COMPLETED, j)", listed=True),
    Mutant("g |n| dropped from carry_bound", "carry", RULES,
           "t = [err[c] + g * abs(n[c]) for c in range(3)]", "t = [err[c] for c in range(3)]"),
    Mutant("g |n| dropped in the kernel", "carry", KERNEL,
           "t0 = err[0] + g * a0 ", "t0 = err[0] "),
    Mutant("γ: 4u → 3u", "carry", RULES, "return 4 * u * (1 + 8 * u)", "return 3 * u * (1 + 8 * u)"),
    Mutant("tiny dropped from carry_bound", "carry", RULES, "out.append(s * kappa + tiny)", "out.append(s * kappa)"),
    Mutant("tiny dropped from the rescaled bound", "carry", KERNEL,
           "        e0 = e0 * f + tiny\n        e1 = e1 * f + tiny\n        e2 = e2 * f + tiny\n",
           "        e0 = e0 * f\n        e1 = e1 * f\n        e2 = e2 * f\n"),
    Mutant("the rescaling threshold: > BIG → >= BIG", "carry", KERNEL,
           "if new_top > BIG or", "if new_top >= BIG or", survives=True),
    # ---- trapping
    Mutant("κ without its R|β| term", "trapping", TRAP,
           "kappa = norm_a / den + R * form.norm_beta / den", "kappa = norm_a / den", listed=True),
    Mutant("the contact walls dropped", "trapping", TRAP,
           ',\n                Wall(f"contact {k + 1} ({letters[k + 1]})", row(k, i, sigma))]', "]",
           listed=True, survives=True),
    Mutant("R < ρ tested at the ball's midpoint", "trapping", TRAP,
           "if not R < rho:", "if not R.mid() < rho:", listed=True),
    Mutant("the walls' ρ|Tᵀℓ| term with the wrong sign", "trapping", TRAP,
           "low = value - rho", "low = value + rho"),
    Mutant("the denominator α + |β|ρ", "trapping", TRAP,
           "den = form.alpha - rho * form.norm_beta", "den = form.alpha + rho * form.norm_beta"),
    Mutant("R without its ‖A‖ρ term", "trapping", TRAP,
           "R = (norm_g + norm_a * rho) / den", "R = norm_g / den"),
    Mutant("‖A‖ by half the Frobenius norm squared, no root term", "trapping", TRAP,
           "return ((f + abs(f * f - 4 * d * d).sqrt()) / 2).sqrt()", "return (f / 2).sqrt()"),
    Mutant("the face walls dropped", "trapping", TRAP,
           '                Wall(f"face at state {k} ({letters[k]})", row(k, (i + 2) % 3, -1)),\n', ""),
    Mutant("the orientation at the return dropped", "trapping", TRAP,
           '    out.append(Wall(f"orientation at the return ({letters[0]})", '
           'row(len(word), ORIENTATION[letters[0]], 1)))\n', ""),
    Mutant("κ < 1 → κ < 2", "trapping", TRAP, "if not kappa < 1:", "if not kappa < 2:"),
]


def copy_tree(dest: Path) -> None:
    ignore = shutil.ignore_patterns("__pycache__", "*.pyc", ".hypothesis")
    for name in ("certify", "certify_kernel", "proofs", "tests"):     # the tests' conftest loads proofs and the kernel
        if (ROOT / name).exists():
            shutil.copytree(ROOT / name, dest / name, ignore=ignore)
    for name in ("pyproject.toml", "conftest.py"):
        if (ROOT / name).exists():
            shutil.copy2(ROOT / name, dest / name)


def run(m: Mutant, tree: Path, timeout: int) -> tuple[str, float, str]:
    """('killed' | 'survived' | 'timeout', seconds, the last line of pytest)."""
    target = tree / m.path
    original = target.read_text()
    if original.count(m.old) != 1:
        raise SystemExit(f"mutant {m.name!r}: its text occurs {original.count(m.old)} times in {m.path}")
    target.write_text(original.replace(m.old, m.new))
    env = dict(os.environ, PYTHONPATH=str(tree), NUMBA_CACHE_DIR=str(tree / ".numba"))
    cmd = [sys.executable, "-m", "pytest", "-x", "-q", "-p", "no:cacheprovider", *TESTS[m.group]]
    start = time.perf_counter()
    try:
        out = subprocess.run(cmd, cwd=tree, env=env, capture_output=True, text=True, timeout=timeout)
        verdict = "survived" if out.returncode == 0 else "killed"
        last = (out.stdout.strip().splitlines() or [""])[-1]
    except subprocess.TimeoutExpired:
        verdict, last = "timeout", ""
    finally:
        shutil.copy2(ROOT / m.path, target)
    return verdict, time.perf_counter() - start, last


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--only", choices=sorted(TESTS), action="append")
    p.add_argument("--list", action="store_true")
    p.add_argument("--timeout", type=int, default=600)
    args = p.parse_args(argv)
    chosen = [m for m in MUTANTS if not args.only or m.group in args.only]
    if args.list:
        for m in chosen:
            print(f"{m.group:9} {'listed ' if m.listed else '       '}{m.name}")
        return 0
    bad = []
    with tempfile.TemporaryDirectory(prefix="mutation-") as tmp:
        tree = Path(tmp)
        copy_tree(tree)
        for m in chosen:
            verdict, seconds, last = run(m, tree, args.timeout)
            expected = "survived" if m.survives else "killed"
            flag = "" if verdict == expected else "   <-- UNEXPECTED"
            print(f"{verdict:8} {seconds:6.1f} s  [{m.group}] {m.name}{' (issue 25)' if m.listed else ''}{flag}",
                  flush=True)
            if verdict != expected:
                bad.append(m.name)
    killed = len(chosen) - sum(m.survives for m in chosen)
    print(f"{len(chosen)} mutants: {killed} expected killed, {len(chosen) - killed} expected survivors; "
          f"{len(bad)} unexpected")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
