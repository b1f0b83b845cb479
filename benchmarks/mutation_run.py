"""The mutation run of issue 25 over carry_bound, trapping and reduction_orbits, of issue 34 over
the independent kernel (certify_kernel/), and of issue 38 over the island's membership test.

Each mutant is a textual replacement in one source file (it must match exactly once).  The
tree (certify/, tests/, pyproject.toml) is copied once to a temporary directory; for each
mutant the file is rewritten there, the targeted tests run with PYTHONPATH set to the copy
(``pytest -x``: the first failure kills), and the original is put back.  A mutant is
*killed* when the tests fail, *survived* when they pass.  Every mutant the issue lists must
be killed; a survivor outside the list must be one docs/developing.md explains.

    nice python benchmarks/mutation_run.py              # all (about 10 minutes on a loaded machine)
    python benchmarks/mutation_run.py --only carry      # one group: carry, trapping, orbits, kernel, island
    python benchmarks/mutation_run.py --list

Exit code 1 when a listed mutant survives or an expected survivor is killed (update the docs).
The kernel's mutants are small wrong changes to certify_kernel/ (a bounding polynomial dropped,
a sample outside its cell, "every piece" weakened to "some piece", a sign, Sturm's count off by
one, the modulus or the circles ignored, digits read loosely, a status or a verdict not
compared, ...); tests/kernel/ must kill each (its default suite, the fast files first).  The
island's mutants decide a ball of states at its midpoint, in the membership test or in one of
its callers (issue 38); the tests on a ball across the boundary ellipse must kill each.
"""
from __future__ import annotations

import argparse
import os
import re
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
ISLAND, POINTS, IDENTIFY = ("certify/dynamics/island.py", "certify/run/figure_points.py",
                            "certify/run/identify.py")
CELLS, STURM, EVAL, VALUES, SIGNS, INIT, MAIN, LANG = (f"certify_kernel/{name}.py" for name in (
    "cells", "sturm", "evaluate", "values", "signs", "__init__", "__main__", "language"))
TESTS = {"orbits": ["tests/patterns/test_reduction_orbits.py"],
         "carry": ["tests/numerics/test_horizon.py", "-k", "not stress"],
         "trapping": ["tests/numerics/test_trapping.py"],
         "kernel": [f"tests/kernel/test_kernel_{name}.py" for name in (
             "language", "values", "cells", "evaluate", "statements", "signs", "verify", "forgeries",
             "every_statement")]
         + ["-m", "not slow"],
         "island": ["tests/dynamics/test_island.py", "tests/run/test_figure_points.py", "tests/run/test_identify.py",
                    "-k", "across"]}


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
           "t = [err[c] + g * abs(n[c]) for c in range(len(n))]", "t = [err[c] for c in range(len(n))]"),
    Mutant("g |n| dropped in the kernel", "carry", KERNEL,
           "t0 = err[0] + g * a0 ", "t0 = err[0] "),
    Mutant("γ: 4u → 3u", "carry", RULES, "return L * u * (1 + 2 * L * u)",
           "return 3 * L // 4 * u * (1 + 2 * L * u)"),
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
    # ---- the independent kernel (issue 34): the decomposition (cells.py)
    Mutant("the discriminant dropped from a condition's bounding polynomials", "kernel", CELLS,
           "out = [resultant_in(self.cp, d_lambda(self.cp)), in_lambda(self.cp)[-1]]",
           "out = [in_lambda(self.cp)[-1]]"),
    Mutant("the leading coefficient of cp dropped from the bounding polynomials", "kernel", CELLS,
           "out = [resultant_in(self.cp, d_lambda(self.cp)), in_lambda(self.cp)[-1]]",
           "out = [resultant_in(self.cp, d_lambda(self.cp))]", survives=True),
    Mutant("the zeros of a condition on a branch not cut (its resultant with cp dropped)", "kernel", CELLS,
           "out.append(R)", "pass"),
    Mutant("Δ dropped from the bounding polynomials (x real or not: no cut)", "kernel", CELLS,
           '([p["delta"]] if p["delta"] else [])', "[]"),
    Mutant("a sample outside its cell (the isolating intervals' outer ends)", "kernel", CELLS,
           "lo, hi = (a.hi, b.lo) if not (a.rational and b.rational) else (a.lo, b.lo)", "lo, hi = (a.lo, b.hi)"),
    Mutant("condition_sign: the denominator's sign ignored", "kernel", CELLS,
           'return _surd_sign(at["N0"], at.get("N1") or [], delta, sg, mul_, sub_) * sden',
           'return _surd_sign(at["N0"], at.get("N1") or [], delta, sg, mul_, sub_) * abs(sden)'),
    Mutant("condition_sign: P₀ + P₁√Δ of the sign of P₁ when the signs differ", "kernel", CELLS,
           "return s0 * sg(sub_(mul_(p0, p0), mul_(mul_(p1, p1), delta)))",
           "return s1 * sg(sub_(mul_(p0, p0), mul_(mul_(p1, p1), delta)))"),
    Mutant("condition_sign: Δ < 0 read as a real x", "kernel", CELLS, "        if sd < 0:\n            return None\n",
           "        if sd < 0:\n            pass\n"),
    # ---- Sturm and the algebraic numbers (sturm.py, values.py)
    Mutant("Sturm's count off by one", "kernel", STURM,
           'return variations(seq, "-inf" if a is None else a) - variations(seq, b)',
           'return variations(seq, "-inf" if a is None else a) - variations(seq, b) + 1'),
    Mutant("two algebraic numbers equal when their polynomials share a factor (the root not located)", "kernel",
           STURM, "if deg(g) > 0 and count(g, lo, hi) == 1:", "if deg(g) > 0:"),
    Mutant("the circle relation ignored in identities", "kernel", VALUES,
           "diff = reduce_circles(madd(mmul(self.num, o.den), mmul(o.num, self.den), -1), CIRCLES)",
           "diff = reduce_circles(madd(mmul(self.num, o.den), mmul(o.num, self.den), -1), [])"),
    Mutant("the modulus ignored in identities (… mod P)", "kernel", EVAL,
           "return a.same(b, MODULUS[-1] if MODULUS else None)", "return a.same(b, None)"),
    Mutant("reduction modulo a monic polynomial stops one degree early", "kernel", VALUES,
           "        if top < d:\n            return p", "        if top <= d:\n            return p"),
    # ---- what formulas mean (evaluate.py)
    Mutant("≈ with a rounding interval twice as wide", "kernel", EVAL,
           'h = Fraction(1, 2 * 10 ** len(printed[1].split(".")[1]))',
           'h = Fraction(1, 10 ** len(printed[1].split(".")[1]))'),
    Mutant("≈ of a set: a set of several intervals read as its first", "kernel", EVAL,
           "if len(s.parts) != 1 or s.parts[0][0] is s.parts[0][1]:", "if s.parts[0][0] is s.parts[0][1]:"),
    Mutant("forall: 'every piece true' weakened to 'some piece true'", "kernel", EVAL,
           "    if false:\n        ctx.counterexample = false[0]",
           "    if len(false) == len(found):\n        ctx.counterexample = false[0]"),
    Mutant("forall: an undecided piece taken as true", "kernel", EVAL, "    if undecided:\n", "    if False:\n"),
    Mutant("{r in I : F}: an undecided piece taken as false", "kernel", EVAL,
           '            raise NotVerified(f"undecided at r = {p}")\n        if v:',
           '            continue\n        if v:'),
    Mutant("every branch and fixed point → some branch or fixed point", "kernel", EVAL,
           "return all(_truth_at(body, p, k, s, B, ctx, conds) for k in ks for s in sigmas)",
           "return any(_truth_at(body, p, k, s, B, ctx, conds) for k in ks for s in sigmas)"),
    Mutant("r < r₀ decided by the sign of r₀'s polynomial (the fault the tests found)", "kernel", EVAL,
           "g = number(p.r0).compare(value(t[2][j + 1], ctx))", "g = p.sign(conds[(id(t), j, s)], k)"),
    Mutant("changes(): one side compared with itself", "kernel", EVAL,
           "left, right = p.left.sign(c, k), p.right.sign(c, k)", "left, right = p.left.sign(c, k), p.left.sign(c, k)"),
    Mutant("the closed ends of an interval of r not decided", "kernel", EVAL,
           "pts = cells.pieces(list(conds.values()), lo, hi, iv.lo_closed, iv.hi_closed)",
           "pts = cells.pieces(list(conds.values()), lo, hi, False, False)"),
    Mutant("the collision law with the wrong sign of r (v_i' − v_j' = +r(v_i − v_j))", "kernel", EVAL,
           "v[pair], v[pair + 1] = half * (s - r * d), half * (s + r * d)",
           "v[pair], v[pair + 1] = half * (s + r * d), half * (s - r * d)"),
    Mutant("a word's matrices multiplied in reading order (K_c1 ··· K_cn)", "kernel", EVAL,
           'M = collision("abc".index(letter)) * M', 'M = M * collision("abc".index(letter))'),
    Mutant("the discriminant without its sign (−1)^(n(n−1)/2)", "kernel", EVAL,
           "return RF.const((-1) ** (n * (n - 1) // 2)) * resultant(", "return RF.const(1) * resultant("),
    # ---- strict signs over several variables (signs.py)
    Mutant("signs: a form of non-strict terms taken as strict", "kernel", SIGNS,
           "return signs.pop() if len(signs) == 1 and strict else 0", "return signs.pop() if len(signs) == 1 else 0"),
    Mutant("signs: a variable of unknown sign to an odd power accepted", "kernel", SIGNS,
           "                if e % 2:\n                    return 0\n",
           "                if e % 2:\n                    pass\n"),
    Mutant("signs: the factors not multiplied out against the form", "kernel", SIGNS,
           "    if madd(product, form, -1):\n", "    if False:\n"),
    Mutant("signs: the form not compared with the expression modulo the circles", "kernel", SIGNS,
           "    if reduce_circles(madd(given, form, -1), CIRCLES):\n", "    if False:\n"),
    Mutant("signs: a factor in r not checked for roots in ]0, 1[", "kernel", SIGNS,
           "if not u or count(u, Fraction(0), Fraction(1)) - (1 if not sum(u) else 0):", "if not u:"),
    Mutant("signs: cos θ > 0 for θ in ]π/2, π[ (a wrong quadrant)", "kernel", SIGNS,
           "(Fraction(1, 2), Fraction(1)): (-1, 1)", "(Fraction(1, 2), Fraction(1)): (1, 1)"),
    # ---- the certificate and the command (__init__.py, __main__.py, language.py)
    Mutant("status: a refuted statement makes no ERRATUM", "kernel", INIT,
           'return "ERRATUM" if any(s.verdict == "refuted" for s in statements) else "PASS"', 'return "PASS"'),
    Mutant("status: OBSERVED when some statement is an observation", "kernel", INIT,
           'if statements and all(s.verdict == "observed" for s in statements):',
           'if statements and any(s.verdict == "observed" for s in statements):'),
    Mutant("the run's status not compared", "kernel", INIT,
           'if engine.get("status") != out["status"]:', "if False:"),
    Mutant("the run's verdicts not compared", "kernel", INIT,
           'if not isinstance(rec, dict) or rec.get("verdict") != verdict:', "if not isinstance(rec, dict):"),
    Mutant("a statement the run adds accepted (the sets of statements not compared both ways)", "kernel", INIT,
           "if mine != theirs:", "if mine - theirs:"),
    Mutant("a refuted statement found true accepted (only 'holds' compared)", "kernel", INIT,
           "if got != want:", "if got != want and want:"),
    Mutant("an undecided statement counted as verified", "kernel", INIT,
           "    except NotVerified as exc:\n        return False, str(exc)",
           "    except NotVerified as exc:\n        return True, ''"),
    Mutant("the command exits 0 when a certificate fails", "kernel", MAIN, "return 1 if failed else 0", "return 0"),
    Mutant("fields of the run that the kernel does not read accepted (an object, a modulus, a cover)", "kernel", INIT,
           'extra = sorted(set(engine) - {"id", "status", "statements"})', "extra = []"),
    Mutant("a witness of any kind accepted", "kernel", INIT,
           'x.get("kind") not in WITNESSES for x in w', 'x.get("kind") is None for x in w'),
    Mutant("* binds like + (precedence)", "kernel", LANG, '"*": 30,', '"*": 20,'),
    Mutant("^ left-associative", "kernel", LANG,
           "right = self.formula(bp - 1 if op in (\"^\", \"implies\") else bp, brackets)",
           "right = self.formula(bp, brackets)"),
    # ---- the island's membership test and its callers (issue 38): a ball decided at its midpoint
    Mutant("island.inside: a ball of states decided at its midpoint", "island", ISLAND,
           "        return island_sign(n, r) == 1\n",
           "        return island_sign(tuple(z.mid() if hasattr(z, 'mid') else z for z in n), r) == 1\n"),
    Mutant("figure_points.island_intervals: the state at b decided at its midpoint", "island", POINTS,
           "if not island.inside(z0_state, r):", "if not island.inside(tuple(z.mid() for z in z0_state), r):"),
    Mutant("identify: the scan's state at b decided at its midpoint", "island", IDENTIFY,
           "and island.inside(n, r):", "and island.inside(tuple(z.mid() for z in n), r):"),
    Mutant("identify.verify: the second route's state decided at its midpoint", "island", IDENTIFY,
           "inside = island.inside(n, r)\n", "inside = island.inside(tuple(z.mid() for z in n), r)\n"),
]


def copy_tree(dest: Path) -> None:
    ignore = shutil.ignore_patterns("__pycache__", "*.pyc", ".hypothesis")
    for name in ("certify", "certify_kernel", "proofs", "tests", "statements"):    # conftest loads proofs; the kernel
        if (ROOT / name).exists():
            shutil.copytree(ROOT / name, dest / name, ignore=ignore)
    for name in ("pyproject.toml", "conftest.py"):
        if (ROOT / name).exists():
            shutil.copy2(ROOT / name, dest / name)


def run(m: Mutant, tree: Path, timeout: int) -> tuple[str, float, str]:
    """('killed' | 'survived' | 'timeout', seconds, the test that failed first (pytest's FAILED line))."""
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
        last = next((re.match(r"\S+ (?:\S*/)?([^/\s]+?::[A-Za-z_0-9]+)", line).group(1)
                     for line in out.stdout.splitlines() if re.match(r"(FAILED|ERROR) \S+::", line)), "")
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
            print(f"{verdict:8} {seconds:6.1f} s  [{m.group}] {m.name}{' (issue 25)' if m.listed else ''}{flag}"
                  + (f"  (by {last})" if last else ""), flush=True)
            if verdict != expected:
                bad.append(m.name)
    killed = len(chosen) - sum(m.survives for m in chosen)
    print(f"{len(chosen)} mutants: {killed} expected killed, {len(chosen) - killed} expected survivors; "
          f"{len(bad)} unexpected")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
