"""`certify orbit WORD`: the periodic orbits of the reduction, certified
(certify/patterns/reduction_orbits.py).  Checked against independent routes: the
stable windows of `certify pattern` for (ab)^n(cb)^n (L4), the exact reduction map of
certify/dynamics/reduction.py (the word followed from n*, the multipliers against a
finite-difference Jacobian), the ball engine of certify/numerics; the schema; the CLI."""
import json
import re
from fractions import Fraction

import flint
import pytest

from certify import cli
from certify.algebra import Q
from certify.algebra.algebraic import Algebraic
from certify.algebra.balls import precision
from certify.dynamics import reduction as R
from certify.dynamics.systems import candidate_in
from certify.errors import UsageError
from certify.numerics.engines import ball_orbit
from certify.patterns import SCHEMA_PATH as PATTERN_SCHEMA
from certify.patterns import analyse as analyse_pattern
from certify.patterns import reduction_orbits as ro
from certify.patterns.reduction_orbits import SCHEMA_PATH, analyse, normal_at

COMPLEX = "abacbabcbcabcb"           # the attractor at r = 0.3 (period 14)


@pytest.fixture(scope="module")
def complex_orbit():
    return analyse(COMPLEX)


def _windows(intervals):
    """{(lo, hi)} of (branch, fixed point, lo, hi) or of the JSON intervals, as exact keys."""
    return sorted((a.key(), b.key()) for a, b in intervals)


def _attracting(res):
    return [(a, b) for R_ in res.regions["attracting"] for a, b in R_.merged()[0]]


# ------------------------------------------------------------------ two routes agree: L4
@pytest.mark.parametrize("n", [2, 3, 4])
def test_ab_cb_attracting_windows_are_the_stable_windows_of_pattern(n):
    """The attracting windows of the reduction for (ab)^n(cb)^n are exactly the stable
    self-similar windows of `certify pattern` (L4-L5): the same algebraic end points,
    obtained from different conditions (the smallest eigenvalue of M_w in modulus at a
    left eigenvector, against the dominant eigenvalue and |f'(x)| < 1 at a right one)."""
    word = f"(ab)^{n}(cb)^{n}"
    orbit, pattern = analyse(word), analyse_pattern(word)
    stable = [(lo, hi) for _b, _x, lo, hi in pattern.intervals("stable")]
    assert stable, "pattern certifies a stable window for n = 2..4"
    assert _windows(_attracting(orbit)) == _windows(stable)
    assert [a["pair"] for a in orbit.attracting()] == ["real"] * len(stable)
    assert "attracting periodic orbit of the reduction" in orbit.verdict
    # one window, two eigenvalues: the orbit's branch is λ of its normal n* (the smallest, lower),
    # the datum's that of its velocity q(0) in the plane n*^⊥ (upper); the physics line says so
    assert {a["branch"] for a in orbit.attracting()} == {"lower"}
    assert {s["branch"] for s in pattern.stable} == {"upper"}
    assert ro.BRANCH_WORDS in orbit.physics and "eigenvalue of q(0)" in ro.BRANCH_WORDS


def test_a_flipped_modulus_condition_breaks_the_agreement(monkeypatch):
    """Mutation: with λ (λ³ - det M) > 0 in place of λ (det M - λ³) > 0 (λ the largest
    in modulus instead of the smallest), the attracting set is no longer the stable
    window, so the test above can fail."""
    word = "(ab)^2(cb)^2"
    stable = [(lo, hi) for _b, _x, lo, hi in analyse_pattern(word).intervals("stable")]
    real = ro.type_requirements

    def flipped(cp):
        out = real(cp)
        out["attracting"] = out["attracting"][:2] + out["repelling"][2:]
        return out
    monkeypatch.setattr(ro, "type_requirements", flipped)
    assert _windows(_attracting(analyse(word))) != _windows(stable)


# ------------------------------------------------------------------ the complex-pair attractor
def test_complex_pair_orbit_is_attracting_at_three_tenths(complex_orbit):
    res = complex_orbit
    r0 = Algebraic.rational(Q(3, 10))
    hits = [a for a in res.attracting() if a["branch"] == "upper"]
    assert len(hits) == 1 and hits[0]["pair"] == "complex"
    (lo, hi), = [(a, b) for R_ in res.regions["attracting"] if R_.branch == 0 for a, b in R_.merged()[0]]
    assert lo < r0 < hi
    assert hits[0]["lo"]["minimal_polynomial"] == "r^4 - 6r^3 - 2r^2 - 22r + 5"
    # the pair is complex on the whole window: the only real eigenvalue there is λ_x
    assert len(candidate_in("four", COMPLEX).spectrum.real_eigenvalues(Q(3, 10))) == 1
    assert "complex pair" in res.verdict
    assert "not a collapse" in res.physics and "leave the word within a period or two" in res.physics
    assert not res.sets("saddle") or all(s["branch"] != "upper" for s in res.sets("saddle"))


def test_complex_pair_orbit_stays_on_its_word_exactly_and_in_balls():
    """From a rational approximation of n* at r = 3/10 (inside the certified window), the
    exact reduction map follows the word for 10 periods, and the ball engine certifies
    the true orbit of that rational datum for 200 periods (2800 collisions)."""
    r = Q(3, 10)
    n = normal_at(COMPLEX, r, 0)
    word, _ = R.word_of(R.canonical("b", n), r, 10 * len(COMPLEX))
    assert word == COMPLEX * 10
    res = ball_orbit(r, 0.0, 0.0, 200 * len(COMPLEX), word=True, letter="b", normal=n)
    assert res.code == 0 and res.collisions == 200 * len(COMPLEX) and res.word == COMPLEX * 200
    # a saddle leaves its word: ababcb at r = 1/20 (saddle on ]0, 0.101[), from the same kind of datum
    m = normal_at("ababcb", Q(1, 20), 1, bits=64)
    w, _ = R.word_of(R.canonical("b", m), Q(1, 20), 40 * 6)
    assert w[:12] == "ababcb" * 2 and w != ("ababcb" * 40)[:len(w)]


# ------------------------------------------------------------------ the multipliers
def _return_map(word, r, n1, n2):
    """The exact reduction (contacts decided, normals re-oriented) over one period from
    (b, (n1, n2, 1)), in the chart n_z = 1."""
    planes = R.orbit(R.canonical("b", (n1, n2, Q(1))), r, len(word))
    assert R.word(planes) == word
    m = planes[-1].n
    return Q(m[0], m[2]), Q(m[1], m[2])


@pytest.mark.parametrize("word, r, branch", [(COMPLEX, Q(3, 10), 0), ("ababcbcb", Q(3, 20), 2),
                                             ("ababcb", Q(1, 20), 1)])
def test_multipliers_are_the_eigenvalue_ratios(word, r, branch):
    """The Jacobian of the exact return map at n* (central differences, step 2^-80, n*
    to 2^-400) has trace λ/λ_y + λ/λ_z = λ²(tr M - λ)/det M and determinant
    λ²/(λ_y λ_z) = λ³/det M (λ = λ_x): attracting (complex pair), attracting (real
    pair), saddle."""
    n1, n2, _ = normal_at(word, r, branch, bits=400)
    h = Q(1, 2 ** 80)
    cols = []
    for d1, d2 in ((h, 0), (0, h)):
        plus, minus = _return_map(word, r, n1 + d1, n2 + d2), _return_map(word, r, n1 - d1, n2 - d2)
        cols.append([(p - m) / (2 * h) for p, m in zip(plus, minus)])
    J = [[cols[0][0], cols[1][0]], [cols[0][1], cols[1][1]]]
    trace, det = J[0][0] + J[1][1], J[0][0] * J[1][1] - J[0][1] * J[1][0]
    M = flint.fmpq_mat([[c(r) for c in row] for row in candidate_in("four", word).Mq])
    trM, detM = M[0, 0] + M[1, 1] + M[2, 2], M.det()
    with precision(300):
        lam = candidate_in("four", word).spectrum.real_eigenvalues(r)[branch].arb(300)
        expect_trace, expect_det = lam ** 2 * (trM - lam) / detM, lam ** 3 / detM
        for got, want in ((trace, expect_trace), (det, expect_det)):
            assert abs(flint.arb(got) - want) < 1e-20 * (1 + abs(want))
    # the type the analysis certifies at r is the one the multipliers show
    inside = abs(expect_det) < 1 and abs(expect_trace) < 1 + expect_det
    assert inside == (word != "ababcb")


# ------------------------------------------------------------------ claims of the docstring
@pytest.mark.parametrize("word", [COMPLEX, "ababcbcb"])
def test_implied_orientation_and_face_conditions_hold_on_the_feasible_set(word):
    """No re-orientation along a realised orbit, and every state inside its face: the
    conditions the analysis does not impose hold wherever it certifies the orbit."""
    res = analyse(word)
    cand = candidate_in("four", res.normal)
    an = ro._fork(ro.Analysis(ro.replace(cand, abcd=None, abcd_ring=None), 0, 1))
    an.regions = ro._copy(res.regions["feasible"])
    for q in ro.implied_requirements(res.normal, cand.Mq, cand.spectrum.lrq_cp):
        assert [v for v in an.violations(q) if v[1].is_point is False] == [], q.name


def test_types_are_disjoint_and_cover_the_feasible_set(complex_orbit):
    for res in (complex_orbit, analyse("ababcbcb")):
        spans = {t: [(R_.branch, a, b) for R_ in res.regions[t] for a, b in R_.merged()[0]] for t in ro.TYPES}
        for s, t in ((0, 1), (0, 2), (1, 2)):
            for k, a, b in spans[ro.TYPES[s]]:
                assert not any(k == k2 and a < b2 and a2 < b for k2, a2, b2 in spans[ro.TYPES[t]])
        feas = [(R_.branch, a, b) for R_ in res.regions["feasible"] for a, b in R_.merged()[0]]
        for k, a, b in feas:            # covered up to finitely many points
            inner = sorted((a2, b2) for t in ro.TYPES for k2, a2, b2 in spans[t] if k2 == k and a <= a2 and b2 <= b)
            assert inner and inner[0][0] == a and inner[-1][1] == b
            assert all(x[1] == y[0] for x, y in zip(inner, inner[1:]))


# ------------------------------------------------------------------ JSON and the command line
def test_json_follows_the_schema(complex_orbit):
    jsonschema = pytest.importorskip("jsonschema")
    referencing = pytest.importorskip("referencing")
    schema = json.loads(SCHEMA_PATH.read_text())
    registry = referencing.Registry().with_resource(
        "certify/patterns/pattern.schema.json",
        referencing.Resource.from_contents(json.loads(PATTERN_SCHEMA.read_text())))
    doc = json.loads(complex_orbit.json_text())
    jsonschema.Draft202012Validator(schema, registry=registry).validate(doc)
    (a,) = doc["attracting"]
    assert a["pair"] == "complex" and a["hi"]["exact"] == "1"
    # the lower end by the other route: the point check at rationals just outside its interval
    lo, hi = (Fraction(x) for x in a["lo"]["interval"])
    below, above = (lo - Fraction(1, 10 ** 6), hi + Fraction(1, 10 ** 6))
    assert not any(o.feasible for o in ro.orbit_at(COMPLEX, Q(below.numerator, below.denominator)))
    assert [o.kind for o in ro.orbit_at(COMPLEX, Q(above.numerator, above.denominator))] == ["attracting"]
    bad = dict(doc, attracting=[{"branch": "upper", "lo": a["lo"], "hi": {"digits": "1"}, "pair": "complex"}])
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.Draft202012Validator(schema, registry=registry).validate(bad)


@pytest.mark.parametrize("argv, says", [
    (["orbit", "abx"], "unexpected 'x'"),
    (["orbit", "abab"], "proper power"),
    (["orbit", "acab"], "Proposition 4.4"),
    (["orbit", "ab"], "four-particle"),
    (["orbit", "[ac]b"], "four-particle"),
    (["orbit", "ababcb", "--r-range", "1/2", "1/3"], "--r-range"),
    (["orbit", "ababcb", "--r-range", "x", "1"], "--r-range"),
    (["orbit", "(ab)^61(cb)^61"], f"more than {ro.MAX_ORBIT_LENGTH}"),     # 244 letters: refused before any work
])
def test_bad_input_is_one_line_and_exit_2(argv, says, capsys):
    assert cli.main(argv) == 2
    out, err = capsys.readouterr()
    assert out == "" and err.count("\n") == 1 and says in err, err
    if argv[1] in ("ab", "[ac]b"):
        with pytest.raises(UsageError):
            analyse(argv[1])


def test_cli_prints_markdown_and_json(capsys):
    assert cli.main(["orbit", "cbcbabab", "--r-range", "1/10", "1/5"]) == 0     # a rotation and mirror
    out = capsys.readouterr().out
    assert "normal form analysed: `ababcbcb`" in out and "## Verdict" in out and "lower branch" in out
    assert cli.main(["orbit", "ababcbcb", "--json", "--r-range", "1/10", "1/5"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["r_range"] == ["1/10", "1/5"] and doc["attracting"][0]["branch"] == "lower"


# ------------------------------------------------------------------ the point check against the interval analysis
def _stage_at(res, r) -> dict:
    """{branch: the type of the interval analysis at the rational r, or 'feasible' / 'exists' / ''}."""
    x = Algebraic.rational(Q(r))
    out = {}
    for stage in ("exists", "feasible") + ro.TYPES:
        for R_ in res.regions[stage]:
            if any(lo < x < hi for lo, hi in R_.merged()[0]):
                out[R_.branch] = stage
    return out


@pytest.mark.parametrize("word, rs", [
    (COMPLEX, ["1/20", "1/5", "3/10", "1/2", "9/10"]),
    ("(ab)^2(cb)^2", ["1/10", "1/8", "1/6", "7/40", "1/2"]),
])
def test_orbit_at_agrees_with_the_interval_analysis(word, rs):
    """At rational points the exact point decision (M_w over Q, its real roots, every
    contact sign) gives, branch by branch, the stage the interval analysis certifies on
    the r-interval containing the point: attracting / saddle / repelling, feasible, exists."""
    res = analyse(word)
    for r in rs:
        interval = _stage_at(res, r)
        point = {}
        for o in ro.orbit_at(word, r):
            stage = o.kind or ("feasible" if o.feasible else "exists" if o.exists else "")
            if stage:
                point[o.branch] = stage
        assert point == interval, (word, r, point, interval)


def test_orbit_at_multiplier_modulus_and_pair():
    """At r = 3/10 the complex attractor has |ν|² = λ³ / det M_w exactly (a complex pair):
    the ball of the largest modulus contains the square root of that algebraic number."""
    (o,) = [x for x in ro.orbit_at(COMPLEX, "3/10") if x.feasible]
    assert o.kind == "attracting" and o.pair == "complex" and o.modulus < 1
    M = ro._matrix_at(read_normal(COMPLEX), Q("3/10"))
    square = o.lam.arb(128) ** 3 / flint.arb(M.det())
    assert o.modulus.overlaps(square.sqrt())


def read_normal(word):
    from certify.patterns import read
    return read(word)[0]


def test_orbit_at_refuses_bad_input():
    with pytest.raises(UsageError):
        ro.orbit_at(COMPLEX, "3/2")
    with pytest.raises(UsageError):
        ro.orbit_at("abab", "1/2")


# ------------------------------------------------------------------ the type against the multipliers themselves
def _type_from_multipliers(word, r, lam) -> tuple:
    """(type, largest multiplier modulus): attracting / saddle / repelling from the moduli of
    the multipliers λ/λ_y, λ/λ_z, the other roots of cp taken from python-flint's complex root
    finder (balls): a third route, without the Jury polynomials of analyse and orbit_at."""
    M = ro._matrix_at(read_normal(word), Q(r))
    roots = [z for z, _m in flint.fmpq_poly(M.charpoly()).complex_roots()]
    x = lam.arb(128)
    others = [z for z in roots if not (z.real.overlaps(x) and abs(z.imag) < 1e-30)]
    assert len(others) == 2
    inside = [bool(abs(x / z) < 1) for z in others]
    assert all(bool(abs(x / z) < 1) or bool(abs(x / z) > 1) for z in others)      # decided by the balls
    return {2: "attracting", 1: "saddle", 0: "repelling"}[sum(inside)], max((abs(x / z) for z in others),
                                                                          key=lambda m: m.mid())


@pytest.mark.parametrize("word, rs", [
    ("abcb", ["1/10", "1/2", "9/10"]),            # repelling with a complex pair on ]0.17, 1[, a saddle below
    ("abacb", ["1/10", "3/20"]),                  # a saddle with a real multiplier below -1 (-1.90 at 3/20)
    ("ababcbcb", ["3/20"]),                       # attracting, real pair
])
def test_types_are_those_of_the_multipliers_at_points_and_on_intervals(word, rs):
    """At rational r, the type orbit_at decides (the Jury polynomials at λ) is the one the
    multipliers' moduli show, and the one analyse certifies on the interval holding r.
    Kills a sign changed in λ (det M - λ³) and a dropped -λ cp(-λ) > 0 (abacb at 3/20:
    ν = -1.90 and -0.13, |ν_1 ν_2| < 1 and a(1) > 0: attracting without it)."""
    res = analyse(word)
    for r in rs:
        feasible = [o for o in ro.orbit_at(word, r) if o.feasible]
        assert feasible, (word, r)
        x = Algebraic.rational(Q(r))
        for o in feasible:
            kind, modulus = _type_from_multipliers(word, r, o.lam)
            assert o.kind == kind and o.modulus.overlaps(modulus), (word, r, o.branch, o.kind, o.modulus)
            types = {t for t in ro.TYPES for R_ in res.regions[t] if R_.branch == o.branch
                     and any(lo < x < hi for lo, hi in R_.merged()[0])}
            assert types == {o.kind}, (word, r, o.branch, types)


# ------------------------------------------------------------------ long words
ATTRACTOR_0173 = "(abacbc)^5a(bcabac)^4bc(ab)^2(cbcaba)^5c(bacbca)^4ba(cb)^2"    # 122 letters, r = 0.173


def test_long_words_are_refused_with_the_limit_and_a_progress_callback_is_told():
    assert len(ro.read("(ab)^60(cb)^60")[0]) == ro.MAX_ORBIT_LENGTH
    with pytest.raises(UsageError, match=str(ro.MAX_ORBIT_LENGTH)):
        ro.check_length("ab" * (ro.MAX_ORBIT_LENGTH // 2 + 1))
    calls = []
    res = analyse("ababcbcb", self_similar=False, progress=lambda k, n, label: calls.append((k, n, label)))
    assert [k for k, _n, _ in calls] == list(range(1, len(calls) + 1)) and calls[-1][0] == calls[-1][1]
    assert res.pattern is None


def test_beyond_the_limit_the_physics_line_says_the_self_similar_data_were_not_computed(monkeypatch, capsys):
    """Above SELF_SIMILAR_MAX_LENGTH letters (lowered here to 6) the physics line does not run
    `certify pattern` and says so, with how to get it; the orbit's own sets are the same;
    --self-similar (or self_similar=True) runs it anyway, and the JSON follows the schema."""
    jsonschema = pytest.importorskip("jsonschema")
    referencing = pytest.importorskip("referencing")
    word = "ababcbcb"
    full = analyse(word)
    assert full.pattern is not None and not full.not_computed
    monkeypatch.setattr(ro, "SELF_SIMILAR_MAX_LENGTH", 6)
    short = analyse(word)
    assert short.pattern is None and "not computed (8 letters, more than 6" in short.physics
    assert "--self-similar" in short.physics and "Self-similar collapse data of" in short.physics
    doc, whole = json.loads(short.json_text()), json.loads(full.json_text())
    assert doc["self_similar"] is None and whole["self_similar"] is not None
    assert {k: v for k, v in doc.items() if k not in ("self_similar", "physics")} == \
        {k: v for k, v in whole.items() if k not in ("self_similar", "physics")}
    schema = json.loads(SCHEMA_PATH.read_text())
    registry = referencing.Registry().with_resource(
        "certify/patterns/pattern.schema.json",
        referencing.Resource.from_contents(json.loads(PATTERN_SCHEMA.read_text())))
    jsonschema.Draft202012Validator(schema, registry=registry).validate(doc)
    monkeypatch.undo()
    assert f"longer than {ro.SELF_SIMILAR_MAX_LENGTH} letters" in schema["properties"]["self_similar"]["description"]
    assert analyse(word, self_similar=True).json_text() == full.json_text()
    monkeypatch.setattr(ro, "SELF_SIMILAR_MAX_LENGTH", 6)
    assert cli.main(["orbit", word, "--json", "--self-similar"]) == 0
    assert json.loads(capsys.readouterr().out)["self_similar"] == whole["self_similar"]


def test_without_the_physics_line_the_run_of_q0_is_not_computed_and_the_spectrum_is_shared():
    """self_similar=False reads only M_w, cp and the Spectrum (orbit_candidate): pattern's
    candidate (the run of q(0), most of a long word's candidate) is not built; built later, it
    shares the Spectrum (its sign tables), and the orbit's JSON is the same either way."""
    from certify.dynamics import words
    from certify.run import runner
    runner.reset_caches()
    light = analyse("ababcbcb", self_similar=False)
    assert words.candidate.cache_info().currsize == 0 and words.spectrum_of.cache_info().currsize == 1
    assert candidate_in("four", "ababcbcb").spectrum is ro.orbit_candidate("ababcbcb").spectrum
    runner.reset_caches()
    candidate_in("four", "ababcbcb")
    assert analyse("ababcbcb", self_similar=False).json_text() == light.json_text()


@pytest.mark.slow
def test_the_122_letter_attractor_of_0173_is_certified_and_agrees_with_the_point_check():
    """The word r = 0.173 settles on (identify): `orbit` crashed on it ("roots lost at higher
    precision"); now its attracting window on the upper branch (complex pair) contains 0.173,
    and the exact point decision at 173/1000 says attracting on the same branch."""
    res = analyse(ATTRACTOR_0173, self_similar=False)
    assert len(res.normal) == 122
    r0 = Algebraic.rational(Q(173, 1000))
    hits = [(R_.branch, a, b) for R_ in res.regions["attracting"] for a, b in R_.merged()[0] if a < r0 < b]
    assert [h[0] for h in hits] == [0]
    assert [a["pair"] for a in res.attracting() if a["branch"] == "upper"] == ["complex"]
    point = ro.orbit_at(ATTRACTOR_0173, Q(173, 1000))
    assert point[0].kind == "attracting" and point[0].pair == "complex"
    assert all(p.kind != "attracting" for p in point[1:])


def test_orbit_names_the_window_ends_that_are_resonances_of_the_island():
    """`certify orbit` says exactly which attracting window ends are resonances of the island
    (a(bac)^2bcb closes at 2 − √3, ρ = 1/3); a window moved off it is not named."""
    from certify.patterns import reduction_orbits as ro
    res = ro.analyse("abacbacbcb", self_similar=False)
    lines = ro.resonance_lines(res)
    assert any("upper end" in line and "ρ = 1/3" in line for line in lines), lines
    moved = [dict(a, hi={"exact": "27/100", "digits": "0.27"}) for a in res.attracting()]
    assert ro.resonance_lines(type("R", (), {"written": res.written, "attracting": lambda self: moved})()) == []


@pytest.mark.slow
def test_the_self_similar_line_of_the_122_letter_attractor_is_decided():
    """`orbit --self-similar` on r = 0.173's attractor (pattern's analysis of the word): a gcd
    in Q(rc)[λ] taken without its monic normalisation left a zero test undecided at the
    precision cap (exit 3, nothing claimed); made monic, the analysis ends: feasible data,
    never stable, with the same verdict as `certify pattern`."""
    from certify.patterns import analyse as analyse_pattern
    verdict = analyse_pattern(ATTRACTOR_0173).verdict
    assert "feasible self-similar data, never stable" in verdict


def test_a_period_longer_than_the_parser_reads_is_read_as_plain_letters():
    """read_plain: a 484-letter period ((abacbc)^40a(bcabac)^40bcb written out), which the parser
    refuses (over its 400 letters), is read as plain letters up to ``max_length``: a rotation
    and the mirror image give the same normal form, and orbit_at decides it at one r; over
    ``max_length``, written with powers, or not a period (two equal letters) it is refused in
    one line, as by read."""
    w = "abacbc" * 40 + "a" + "bcabac" * 40 + "bcb"
    with pytest.raises(UsageError, match="more than 400"):
        ro.read_plain(w)
    with pytest.raises(UsageError, match="more than 400"):
        ro.orbit_at(w, flint.fmpq(1, 5))
    normal, system = ro.read_plain(w, 1000)
    assert system == "four" and len(normal) == 484 and normal[0] == "a" and normal[-1] == "b"
    assert ro.read_plain(w[7:] + w[:7], 1000)[0] == normal == ro.read_plain(w.translate(str.maketrans("ac", "ca")),
                                                                              1000)[0]
    assert [o.feasible for o in ro.orbit_at(w, flint.fmpq(1, 5), 1000)] == [o.feasible for o in ro.orbit_at(
        w[7:] + w[:7], flint.fmpq(1, 5), 1000)]
    short = "abacbc" * 2 + "a" + "bcabac" * 2 + "bcb"
    assert ro.read_plain(short, 1000) == ro.read_plain(short) == ro.read(short)[:2]
    for bad, says in ((w, "484 letters, more than 480"), ("(abacbc)^40a(bcabac)^40bcb" + "ab" * 60, "more than 400"),
                      (w[:-1] + "a", "two equal letters")):
        with pytest.raises(UsageError, match=re.escape(says)):
            ro.read_plain(bad, 480 if bad == w else 1000)
