"""certify pattern on five-particle words (the κ route, certify/patterns/five.py): abadcbcabc's exact
stable window against the float search (tools/five_particle_search.py), an exact five-particle run
from the certified datum, and mutants (a dropped condition, a moved end) caught."""
import importlib.util
import json
import subprocess
import sys
from pathlib import Path

import flint
import pytest

from certify.dynamics.particles import evolve
from certify.patterns import five

ROOT = Path(__file__).resolve().parents[2]
spec = importlib.util.spec_from_file_location("five_particle_search", ROOT / "tools" / "five_particle_search.py")
search = importlib.util.module_from_spec(spec)
spec.loader.exec_module(search)
WORD = "abadcbcabc"


@pytest.fixture(scope="module")
def result():
    return five.analyse_five(WORD)


def _window(result):
    (w,) = result.intervals("stable")
    return w


def test_the_stable_window_has_exact_ends(result):
    """One window; its upper end is 2 - √3 (r² - 4r + 1, checked by SymPy), its lower end a root of
    an exhibited polynomial where the float search's stability changes (bisected in floats)."""
    import sympy as sp
    w = _window(result)
    r = sp.Symbol("r")
    hi = [int(c) for c in w.hi.minimal_polynomial().coeffs()]
    assert sp.Poly(list(reversed(hi)), r) == sp.Poly(r ** 2 - 4 * r + 1, r)
    assert abs(float(w.hi.digits(15)) - float(2 - sp.sqrt(3))) < 1e-12
    lo = float(w.lo.digits(15))
    stable = lambda x: any(s for *_, s in search.data(WORD, x, 5))   # noqa: E731
    assert abs(search.bisect(stable, 0.249, 0.252) - lo) < 1e-9
    assert w.lo.minimal_polynomial().degree() > 2


@pytest.mark.parametrize("k", range(1, 20))
def test_the_window_against_the_float_search(result, k):
    """Stable at r exactly where the exact window says so, on a grid over [0.2, 0.3] (away from the ends)."""
    w = _window(result)
    r = 0.2 + k * 0.005
    a, b = float(w.lo.digits(15)), float(w.hi.digits(15))
    if min(abs(r - a), abs(r - b)) < 1e-4:
        return
    assert (a < r < b) == any(s for *_, s in search.data(WORD, r, 5))


def test_a_moved_end_is_caught(result):
    """The floats are stable just above the certified lower end and not just below it: an end moved by
    1e-7 either way would contradict them."""
    lo = float(_window(result).lo.digits(15))
    stable = lambda x: any(s for *_, s in search.data(WORD, x, 5))   # noqa: E731
    assert stable(lo + 1e-7) and not stable(lo - 1e-7)


def test_a_dropped_condition_is_caught(result):
    """Without Jury's condition μ² - p > 0 (the other pair inside the disc of radius μ) the stable set is
    strictly larger: the condition is not idle."""
    from certify.patterns.feasibility import Analysis
    cand = five.five_candidate(WORD)
    reqs = five.requirements(cand)
    an = Analysis(cand, flint.fmpq(1, 5), flint.fmpq(3, 10))
    for q in reqs["exists"] + [q for g in reqs["feasible"] for q in g] + \
            [q for q in reqs["stable"] if q.name != "μ² - p"]:
        an.impose(q)
    spans = [s for R in an.regions for s in R.merged()[0]]
    assert any(a < _window(result).lo for a, _ in spans)         # below the certified end, compared exactly


WINDOW_RANGE = (flint.fmpq(1, 4), flint.fmpq(27, 100))       # abadcbcabc's r-range of the datum tests


def _datum(r0: flint.fmpq, prec: int = 400, word: str = WORD, rng=WINDOW_RANGE, half: bool = False):
    """p(0), q(0) (gaps, balls) of the stable datum at a rational r0 inside the window, from the candidate's
    exact formulas: κ the certified branch, λ the root of x² - t x + κ of the stable region (``half``: the
    half route's candidate, ν = κ's square root and β = λ's, of N = J·M_X)."""
    X = five.half_of(word) if half else None
    cand = five.five_candidate(X, sextic=five.half_sextic(X), face=word[-1]) if half else five.five_candidate(word)
    (R,) = [R for R in five.analyse_five(word, *rng, half=half).regions["stable"] if R.pieces]
    kappa = cand.spectrum.real_eigenvalues(r0)[R.branch].arb(prec)
    flint.ctx.prec = prec
    rr = flint.arb(r0)

    def ev(F):
        def poly(P):
            return sum((flint.arb(int(c)) * kappa ** e[0] * rr ** e[1] for e, c in zip(P.monoms(), P.coeffs())),
                       flint.arb(0))
        return poly(F.num) / poly(F.den)
    T, D = ev(cand.T), ev(cand.D)
    sigma = 1 if R.fixed_point == "x₊" else -1
    y = (T + sigma * (T * T - 4 * kappa * D * D).sqrt()) / 2
    p = [ev(e) for e in cand.p0]
    q = [ev(a) + y * ev(b) for a, b in cand.q0]
    i1 = "abcd".index(word[0])
    s = -1 if q[i1] > 0 else 1
    j0 = next(j for j in range(4) if j != cand.face and p[j] != 0)
    t = 1 if p[j0] > 0 else -1
    return [t * e for e in p], [s * e for e in q]


def test_an_exact_particle_run_from_the_certified_datum():
    """At r = 13/50 (inside the window) the datum, rounded to rationals after half the first flight, is run
    exactly with five particles (simulate's evolve): three periods of the word, collision by collision."""
    _particle_run(flint.fmpq(13, 50), WORD)


def _particle_run(r0: flint.fmpq, word: str, **datum) -> None:
    """The datum of :func:`_datum` at r0 run exactly with five particles: three periods of ``word``."""
    p, q = _datum(r0, word=word, **datum)
    i1 = "abcd".index(word[0])
    tau = -p[i1] / q[i1] / 2
    gaps = [p[j] + tau * q[j] for j in range(4)]
    def rational(b):
        return flint.fmpq(int((b * 2 ** 200).mid().floor().unique_fmpz()), 2 ** 200)
    x = [flint.fmpq(0)]
    v = [flint.fmpq(0)]
    for g, u in zip(gaps, q):
        x.append(x[-1] + rational(g))
        v.append(v[-1] + rational(u))
    history = evolve(x, v, r0, 3 * len(word), particles=5)
    assert history.word == word * 3


def test_the_cli_json_follows_the_pattern_schema():
    import jsonschema
    out = subprocess.run([sys.executable, "-m", "certify", "pattern", WORD, "--json", "--r-range", "1/4", "27/100"],
                         cwd=ROOT, capture_output=True, text=True, check=True).stdout
    doc = json.loads(out)
    schema = json.loads((ROOT / "certify" / "patterns" / "pattern.schema.json").read_text())
    jsonschema.validate(doc, schema)
    assert doc["system"] == "five" and doc["stable"]


def test_bad_five_particle_words_are_one_line_errors():
    """Another letter, a pair twice in a row (cyclically), a pair never used, a proper power."""
    for word in ("abadcbcabe", "abcdd", "abad", "abdcabdc"):
        res = subprocess.run([sys.executable, "-m", "certify", "pattern", word], cwd=ROOT, capture_output=True,
                             text=True)
        assert res.returncode == 2 and "Traceback" not in res.stderr and len(res.stderr.strip().splitlines()) == 1


def test_the_two_stability_criteria_agree():
    """For λ > μ > 0 real and two other eigenvalues (a real pair or a complex pair): λ > μ > |ν| for both
    iff κ = λμ strictly dominates the five other products of two eigenvalues (the module's argument),
    on random spectra and on the word's at r on a grid."""
    import random

    import numpy as np
    rng = random.Random(5)

    def agree(ev):
        lam, mu, *rest = ev
        direct = lam > mu > max(abs(v) for v in rest)
        products = [ev[i] * ev[j] for i in range(4) for j in range(i + 1, 4) if (i, j) != (0, 1)]
        return direct == all(abs(lam * mu) > abs(p) for p in products)
    for _ in range(2000):
        mu = rng.uniform(0.01, 2)
        lam = mu + rng.uniform(0.001, 2)
        if rng.random() < 0.5:
            rest = [rng.uniform(-3, 3), rng.uniform(-3, 3)]
        else:
            z = complex(rng.uniform(-2, 2), rng.uniform(0.01, 2))
            rest = [z, z.conjugate()]
        assert agree([lam, mu, *rest])
    for k in range(1, 60):
        ev = sorted(np.linalg.eigvals(search.period_matrix(WORD, 4, k / 60)), key=lambda z: -abs(z))
        real = sorted((z.real for z in ev if abs(z.imag) < 1e-12 and z.real > 0), reverse=True)
        if len(real) >= 2:
            rest = list(ev)
            for v in real[:2]:
                rest.pop(int(np.argmin([abs(z - v) for z in rest])))
            assert agree([real[0], real[1], *rest])


def test_a_repeated_factor_is_analysed_on_its_planes(monkeypatch):
    """abcacd: cp(Λ²M) has the repeated factor κ + r³ (κ = λμ < 0: λ, μ > 0 nowhere).  REPEATED_ROUTE
    analyses it (nothing exists on it) and nothing is left not analysed; where the route does not apply (a
    repeated_candidate that raises), the factor is named not analysed, never stable, with no traceback."""
    assert [m for _, m in five.sextic_factors("abcacd")].count(2) == 1
    res = five.analyse_five("abcacd")
    assert res.not_analysed == [] and not any("not analysed" in u for u in res.undecided)
    assert "REPEATED_ROUTE" in res.datum["t"]

    def refuse(*a, **k):
        raise ArithmeticError("refused")
    monkeypatch.setattr(five, "repeated_candidate", refuse)
    res = five.analyse_five("abcacd")
    assert [n["multiplicity"] for n in res.not_analysed] == [2] and res.not_analysed[0]["stable"] == "none (proved)"
    assert any("multiplicity 2" in u and "not analysed: refused" in u for u in res.undecided)


REPEATED_WORDS = ["abcd", "abdc", "abcacd", "acadbc", "abacbdcd", "abcacacd", "abdbcacd", "abdbdbdc"]


@pytest.mark.parametrize("word", REPEATED_WORDS)
def test_the_plane_of_a_repeated_factor_is_exact(word):
    """REPEATED_ROUTE's datum, exactly modulo Q(t) and y² = t y - κ₀: p̂ = ι_Y Π is not zero, lies on the
    face (p̂_Y = 0) and M has trace t on its plane (M²p̂ - t M p̂ + κ₀ p̂ = 0), and q̄ = A + yB is an
    eigenvector for λ = y (M A = -κ₀ B, M B = A + t B).  With the other root t' = -c₁ - t in place of t
    the trace identity fails: the plane is the one of t, not of t'."""
    S = five.Sextic.of(word)
    (f,) = [f for f, m in five.sextic_factors(word, S) if m > 1]
    cand = five.repeated_candidate(word, f, S)
    red, t, kappa = cand.ext.red, cand.T, cand.ext.D2k
    assert cand.repeated and cand.D == five.Frac.of(1) and not kappa.num.degrees()[0]
    p = cand.p0
    assert any(not e.is_zero() for e in p) and p[cand.face].is_zero()
    Mp = five.matvec(cand.Mq, p, red)
    MMp = five.matvec(cand.Mq, Mp, red)
    assert all(red(MMp[k] - t * Mp[k] + kappa * p[k]).is_zero() for k in range(4))
    other = red(five.Frac.of(0) - cand.cp4[0] - t)
    assert not all(red(MMp[k] - other * Mp[k] + kappa * p[k]).is_zero() for k in range(4))
    A, B = [a for a, _ in cand.q0], [b for _, b in cand.q0]
    MA, MB = five.matvec(cand.Mq, A, red), five.matvec(cand.Mq, B, red)
    assert all(red(MA[k] + kappa * B[k]).is_zero() and red(MB[k] - A[k] - t * B[k]).is_zero() for k in range(4))


def _repeated_data(word: str, r: float, kappa: float) -> list:
    """Float (numpy): the pairs of real eigenvalues λ, μ of M_w(r) with λμ = κ₀ (relative 1e-7), each with
    whether λ, μ > 0 and p(0) = the plane's vector on the face has every other gap of one sign."""
    import itertools

    import numpy as np

    from certify.dynamics.systems import of_particles, system_matrix_flint
    q = flint.fmpq(round(r * 10 ** 6), 10 ** 6)
    M = np.array([[float(e(q)) for e in row] for row in system_matrix_flint(of_particles(5), word)])
    ev, V = np.linalg.eig(M)
    Y, out = "abcd".index(word[-1]), []
    for i, j in itertools.combinations(range(4), 2):
        real = abs(ev[i].imag) < 1e-12 and abs(ev[j].imag) < 1e-12
        if not real or abs(ev[i].real * ev[j].real - kappa) > 1e-7 * abs(kappa):
            continue
        vi, vj = V[:, i].real, V[:, j].real
        p = vj[Y] * vi - vi[Y] * vj
        o = [p[m] / (1e-6 * max(abs(p))) for m in range(4) if m != Y]
        out.append(ev[i].real > 0 and ev[j].real > 0 and (all(x > 1 for x in o) or all(x < -1 for x in o)))
    return out


@pytest.mark.parametrize("word", REPEATED_WORDS)
def test_a_repeated_factor_against_the_floats(word):
    """Nothing exists on the repeated factor (the route's sets are empty) and the float eigenvectors agree:
    at r = k/25 the pairs of real eigenvalues with λμ = κ₀ (there are such pairs) never give λ, μ > 0 with
    the gaps of p(0) of one sign."""
    res = five.analyse_five(word)
    S = five.Sextic.of(word)
    assert not res.not_analysed and not res.stable
    repeated = [d for d in res.exists if "t = λ + μ" in d["branch"]]
    assert repeated == [] and not [d for d in res.feasible if "t = λ + μ" in d["branch"]]
    (f,) = [f for f, m in five.sextic_factors(word, S) if m > 1]
    sign = 1 if len(word) % 4 == 0 else -1              # κ₀ = ±r^(n/2) (κ₀² = det M = r^n)
    assert f == f.ring.gens[0] - sign * f.ring.gens[1] ** (len(word) // 2)
    pairs = [ok for k in range(1, 25) for ok in _repeated_data(word, k / 25, sign * (k / 25) ** (len(word) // 2))]
    assert pairs and not any(pairs)


def test_the_word_classes_are_the_orbits_of_rotation_and_mirror():
    """word_classes against an independent count: every word over a, b, c, d of 4..7 letters (4^n of them,
    no shortcut), kept when every pair is used, no pair repeats cyclically and it is not a proper power; its
    orbit under rotations and the mirror (a<->d, b<->c) built as a set; each orbit holds exactly one listed
    word, and every listed word is in one."""
    import itertools
    listed = list(five.word_classes(7))
    assert len(listed) == len(set(listed))
    mirror = str.maketrans("abcd", "dcba")
    orbits = set()
    for n in range(4, 8):
        for t in itertools.product("abcd", repeat=n):
            w = "".join(t)
            if set(w) != set("abcd") or any(w[k] == w[(k + 1) % n] for k in range(n)):
                continue
            if any(w == w[:d] * (n // d) for d in range(1, n) if n % d == 0):
                continue
            orbits.add(frozenset(v[k:] + v[:k] for v in (w, w.translate(mirror)) for k in range(n)))
    assert len(orbits) == len(listed)
    assert all(len([w for w in listed if w in o]) == 1 for o in orbits)


@pytest.fixture(scope="module")
def census5():
    from certify.run import census5
    from certify.run.executors import executor
    with executor(1) as ex:
        return census5.document(census5.run(5, ex), 5)


def test_the_census_against_the_float_search(census5):
    """Every word of the census to 5: feasible at r on a grid (away from the ends) exactly where the float
    search finds a feasible datum, for the words whose every factor was analysed; the largest feasible r
    is 3 - 2√2 (SymPy), attained by one of its words."""
    import sympy as sp
    skip = {n["word"] for n in census5["census"]["not_analysed"]}
    for rec in census5["words"]:
        if rec["word"] in skip:
            continue
        res = five.analyse_five(rec["word"])
        spans = [(float(w.lo.digits(15)), float(w.hi.digits(15))) for w in res.intervals("feasible")]
        for k in range(1, 50):
            r = k / 50
            if any(min(abs(r - a), abs(r - b)) < 1e-3 for a, b in spans):
                continue
            assert any(a < r < b for a, b in spans) == bool(search.data(rec["word"], r, 5)), (rec["word"], r)
    best = census5["census"]["largest_feasible"]
    assert abs(float(best["r"]["digits"]) - float(3 - 2 * sp.sqrt(2))) < 1e-11
    assert best["r"]["minimal_polynomial"] == "r^2 - 6r + 1"


def test_the_census_command(tmp_path):
    """census --particles 5 writes CENSUS5.md and census5.json into --out and prints the summary; beyond its
    limit, another N, a cluster, or --check on the four-particle census: one line, exit 2."""
    run = lambda *a: subprocess.run([sys.executable, "-m", "certify", "census", *a], cwd=ROOT,  # noqa: E731
                                    capture_output=True, text=True)
    out = run("--particles", "5", "--max-length", "4", "--out", str(tmp_path), "--jobs", "1")
    assert out.returncode == 0 and "4 words up to length 4" in out.stdout, out.stderr
    assert (tmp_path / "CENSUS5.md").is_file() and (tmp_path / "census5.json").is_file()
    for bad in (["--particles", "5", "--max-length", "12"], ["--particles", "6", "--max-length", "4"],
                ["--particles", "5", "--max-length", "4", "--scheduler", "x:1"], ["--max-length", "4", "--check"]):
        res = run(*bad, "--out", str(tmp_path))
        assert res.returncode == 2 and len(res.stderr.strip().splitlines()) == 1 and "Traceback" not in res.stderr


def test_the_datum_is_exact():
    """Exact identities modulo the sextic (and y² = T y - κD²): Π is a κ-eigenvector of Λ²M, the plane's
    Cayley–Hamilton D M²p̂ - T M p̂ + κ D p̂ = 0, q̄ a λ-eigenvector (D M q̄ = y q̄), and each contraction
    p̂_k = ι P_k vanishes on the face of its collision; a wrong t (T + D) breaks the second."""
    from certify.algebra.poly import LR_LAMBDA, Frac
    from certify.dynamics.systems import of_particles, system_matrix_flint
    cand = five.five_candidate(WORD)
    red, ext = cand.ext.red, cand.ext
    M = system_matrix_flint(of_particles(5), WORD)
    W = five.second_compound(M)
    Pi = five.eigen_plane(W, red)
    assert all(red(e - LR_LAMBDA * p).is_zero() for e, p in zip(five.matvec(W, Pi, red), Pi))
    Mp = five.matvec(M, cand.p0, red)
    MMp = five.matvec(M, Mp, red)
    for T in (cand.T, cand.T + cand.D):
        ch = [red(cand.D * a - T * b + LR_LAMBDA * cand.D * c) for a, b, c in zip(MMp, Mp, cand.p0)]
        assert all(e.is_zero() for e in ch) == (T is cand.T)
    Mq = [five.matvec(M, [q[part] for q in cand.q0], red) for part in (0, 1)]
    y = (Frac.of(0), Frac.of(1))
    for k in range(4):
        lhs = (red(cand.D * Mq[0][k]), red(cand.D * Mq[1][k]))
        rhs = ext.mul(y, cand.q0[k])
        assert (lhs[0] - rhs[0]).is_zero() and (lhs[1] - rhs[1]).is_zero()


def _planes(cand, red):
    """{(letter, id(p̂_k)): P_k}: the run through the plane again, to pair each contraction with its plane."""
    P, out = list(five.eigen_plane(five.second_compound(cand.Mq), red)), {}
    P = [red(e * c) for e, c in zip(P, [_scale(cand, red, P)] * 6)]
    for letter, p, _, _ in cand.steps:
        P = five.wedge_collide(letter, P, red)
        out[letter, id(p)] = P
    return out


def _scale(cand, red, P):
    """The factor that makes the eigen-plane the candidate's Π (its p̂ = ι_Y Π)."""
    Y, j = cand.face, next(j for j in range(4) if not cand.p0[j].is_zero())
    return cand.p0[j] * five.contract(P, Y)[j].inverse()


def _wedge3(v, P):
    """v ∧ P in Λ³R⁴ (triples a < b < c): v_a P_bc - v_b P_ac + v_c P_ab; zero iff v lies in the plane P."""
    import itertools
    at = dict(zip(five.PAIRS, P))
    return [v[a] * at[b, c] - v[b] * at[a, c] + v[c] * at[a, b] for a, b, c in itertools.combinations(range(4), 3)]


def test_each_contraction_lies_in_its_plane():
    """p̂_k = ι_{i_k} P_k lies in the plane P_k (v ∧ P_k = 0 modulo the sextic, which holds only because P_k
    is decomposable and the contraction's signs are right): on the face, in the plane, so along p(t_k).
    A contraction with the sign of its lower part flipped is caught."""
    cand = five.five_candidate(WORD)
    red = cand.ext.red
    planes, caught = _planes(cand, red), 0
    for letter, p, _, _ in cand.steps:
        P = planes[letter, id(p)]
        assert all(red(e).is_zero() for e in _wedge3(p, P))
        i = "abcd".index(letter)
        flipped = [-e if m < i else e for m, e in enumerate(p)]
        if any(not e.is_zero() for e in flipped[:i]) and any(not e.is_zero() for e in flipped[i + 1:]):
            caught += not all(red(e).is_zero() for e in _wedge3(flipped, P))
    assert caught >= 3


def test_the_stable_requirements_are_the_criterion():
    """five.requirements' stable stage (λ - μ and Jury's three, with y = Dλ), evaluated at the word's true
    κ = λμ and λ (eigenvalues of M_w at r = k/40 in 60 digits), holds exactly where λ > μ > |ν| for the
    two largest positive eigenvalues λ > μ and the others ν; the points where a margin is below 1e-6 are
    skipped.  Both outcomes occur on the grid."""
    import mpmath
    import sympy as sp

    from certify.algebra.poly import frac_to_field
    from certify.dynamics.systems import of_particles, system_matrix_flint
    cand = five.five_candidate(WORD)
    reqs = five.requirements(cand)["stable"]
    lam, r = sp.symbols("λ r")          # the engine's field writes κ as λ
    mpmath.mp.dps = 60
    D = sp.lambdify((lam, r), frac_to_field(cand.D).as_expr(), "mpmath")
    forms = [(q.sign, sp.lambdify((lam, r), q.G[0].as_expr(), "mpmath"), sp.lambdify((lam, r), q.G[1].as_expr(),
              "mpmath")) for q in reqs]
    M = system_matrix_flint(of_particles(5), WORD)
    seen = set()
    for k in range(1, 40):
        r0 = flint.fmpq(k, 40)
        A = mpmath.matrix([[mpmath.mpf(int(e(r0).p)) / int(e(r0).q) for e in row] for row in M])
        ev = list(mpmath.eig(A, left=False, right=False))
        real = sorted((z.real for z in ev if abs(z.imag) < 1e-40 and z.real > 0), reverse=True)
        if len(real) < 2:
            continue
        lam0, mu0 = real[0], real[1]
        rest = list(ev)
        for v in (lam0, mu0):
            rest.pop(min(range(len(rest)), key=lambda i: abs(rest[i] - v)))
        margins = [lam0 - mu0] + [mu0 - abs(v) for v in rest]
        if min(abs(m) for m in margins) < 1e-6:
            continue
        direct = all(m > 0 for m in margins)
        y = D(lam0 * mu0, mpmath.mpf(k) / 40) * lam0
        values = [sign * (g0(lam0 * mu0, mpmath.mpf(k) / 40) + y * g1(lam0 * mu0, mpmath.mpf(k) / 40))
                  for sign, g0, g1 in forms]
        assert all(v > 0 for v in values) == direct, k
        seen.add(direct)
    assert seen == {True, False}



def test_a_repeated_factor_is_two_products_and_never_stable():
    """REPEATED_NOT_STABLE on the words to 6 with a repeated factor: at r = k/7 its root κ is the product of
    two different pairs of M's eigenvalues (60 digits), and the float search finds no stable datum; the
    census record says 'none (proved)' for that factor."""
    import itertools

    import mpmath

    from certify.dynamics.systems import of_particles, system_matrix_flint
    mpmath.mp.dps = 60
    words = [w for w in five.word_classes(6) if any(m > 1 for _, m in five.sextic_factors(w))]
    assert words
    for w in words:
        (f,) = [f for f, m in five.sextic_factors(w) if m > 1]
        assert f.degree(f.ring.gens[0]) == 1                       # κ = a polynomial in r
        M = system_matrix_flint(of_particles(5), w)
        for k in (2, 3, 5):
            r0 = flint.fmpq(k, 7)
            kappa = -mpmath.mpf(f.coeff_wrt(f.ring.gens[0], 0).as_expr().subs("r", sp_rational(r0)))
            A = mpmath.matrix([[mpmath.mpf(int(e(r0).p)) / int(e(r0).q) for e in row] for row in M])
            ev = list(mpmath.eig(A, left=False, right=False))
            pairs = [p for p in itertools.combinations(range(4), 2) if abs(ev[p[0]] * ev[p[1]] - kappa) < 1e-30]
            assert len(pairs) >= 2, (w, k)
            assert not any(s for *_, s in search.data(w, k / 7, 5))
        rec = five.census_record(w)
        assert rec["not_analysed"] == [] and rec["stable"] == []       # analysed by REPEATED_ROUTE, never stable


def sp_rational(q):
    import sympy as sp
    return sp.Rational(int(q.p), int(q.q))


HALF = "abacbacbdcbcdcdbcdbcabcb"                 # X·m(X), X = abacbacbdcbc (reports/five-patterns/)


def test_the_half_map_squares_to_the_period_matrix():
    """M_W = N² exactly for N = J·M_X (half_sextic's N), for every committed symmetric word; a word that
    is not X·m(X) has no half."""
    from certify.dynamics.systems import of_particles, system_matrix_flint
    words = [f.stem for f in (ROOT / "reports" / "five-patterns").glob("*.json")]
    symmetric = [w for w in words if five.half_of(w) is not None]
    assert len(symmetric) >= 5 and five.half_of(WORD) is None and five.half_of("abcdabcd") is None
    for w in symmetric:
        N = five.half_sextic(five.half_of(w)).M
        M = system_matrix_flint(of_particles(5), w)
        assert all(sum((N[i][k] * N[k][j] for k in range(4)), flint.fmpz_poly(0)) == M[i][j]
                   for i in range(4) for j in range(4))


def test_the_half_route_gives_the_committed_window():
    """The half route on the 24-letter word over the committed r-range: the stable, feasible and existence
    sets of reports/five-patterns/ (the ordinary route's), exact ends and minimal polynomials included."""
    doc = json.loads((ROOT / "reports" / "five-patterns" / f"{HALF}.json").read_text())
    res = five.analyse_five(HALF, *(flint.fmpq(*map(int, x.split("/"))) for x in doc["r_range"]), half=True)
    new = json.loads(res.json_text())
    assert new["stable"] == doc["stable"] and new["feasible"] == doc["feasible"] and new["exists"] == doc["exists"]
    assert res.half == "abacbacbdcbc" and "half route" in new["explanation"]


def test_an_exact_particle_run_from_the_half_datum():
    """The half route's datum (from N's eigenplane, a run over X only) at r = 1063/5000, inside the window:
    three periods of the whole word W, collision by collision, in an exact five-particle run."""
    _particle_run(flint.fmpq(1063, 5000), HALF, rng=(flint.fmpq(53, 250), flint.fmpq(107, 500)), half=True)


def test_the_ordinary_route_on_a_symmetric_word_names_the_half_route(monkeypatch, capsys):
    """certify pattern on X·m(X) without --half says on stderr that --half gives the same stable set; with
    --half, or on another word, it says nothing (the analysis itself stubbed: only the note is tested)."""
    from certify import cli

    class Stub:
        def markdown(self):
            return "stub"
    monkeypatch.setattr(five, "analyse_five", lambda *a, **k: Stub())
    for argv, note in (([HALF], True), ([HALF, "--half"], False), ([WORD], False)):
        assert cli.main(["pattern", *argv]) == 0
        out = capsys.readouterr()
        assert out.out == "stub\n" and ("--half gives the same stable set" in out.err) == note


def test_the_half_route_refuses_other_words():
    """--half on a word that is not X·m(X), or on a four-particle word: one line, exit 2."""
    for word in (WORD, "ababcb"):
        res = subprocess.run([sys.executable, "-m", "certify", "pattern", word, "--half"], cwd=ROOT,
                             capture_output=True, text=True)
        assert res.returncode == 2 and "Traceback" not in res.stderr and len(res.stderr.strip().splitlines()) == 1


@pytest.mark.parametrize("modulus", ["sextic", "3κ² + rκ - 5/7"])
def test_the_reduction_modulo_the_sextic_over_z_is_the_reduction_over_q(modulus):
    """five.Reducer reduces an integer polynomial in (κ, r) modulo cp by a pseudo-division over Z (cp scaled
    to integer coefficients, of leading coefficient L > 1 for both moduli: a power of 2 for a sextic, 3·7
    for the second): the remainder over Q (fmpq_mpoly's division) written P/d with d the lcm of its
    denominators, the same P and d, for κ-degrees below, at and far above deg cp."""
    import random

    import sympy as sp

    from certify.algebra.poly import LRCTX, LRQCTX, lam, r, ring_to_lrq, to_ring
    ring_cp = five.Sextic.of("abadcbcabc").cp if modulus == "sextic" else \
        to_ring(3 * lam ** 2 + r * lam - sp.Rational(5, 7))
    red, C = five.Reducer(ring_cp), ring_to_lrq(ring_cp)
    assert red.L > 1                                   # the scaling by L^k is exercised
    rng = random.Random(7)
    for _ in range(60):
        terms = {(rng.randint(0, 14), rng.randint(0, 20)): rng.randint(-10 ** 20, 10 ** 20) * 2 ** rng.randint(0, 30)
                 for _ in range(rng.randint(1, 12))}
        p = LRCTX.from_dict(terms)
        remainder = divmod(LRQCTX.from_dict({m: flint.fmpq(c) for m, c in terms.items()}), C)[1]
        d = flint.fmpz(1)
        for c in remainder.coeffs():
            d = d.lcm(c.q)
        P, scale = red.poly(p)
        assert scale == d and P == LRCTX.from_dict({m: int(c * d) for m, c in remainder.to_dict().items()})
