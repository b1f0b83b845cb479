"""certify/patterns/five_orbits.py: the periodic orbits of the five-particle reduction (`certify orbit WORD`
for a word over a, b, c, d), against the exact run of the plane and an independent float route."""
from fractions import Fraction

import flint
import pytest

from certify.algebra.poly import LR_LAMBDA
from certify.patterns import five, five_orbits
from tests.patterns import five_float_orbits as floats


@pytest.mark.parametrize("word", ["abadcbcabc", "abcdcb", "abcbdcb", "abadcb"])
def test_the_plane_returns_as_kappa_times_itself(word):
    """Exactly, modulo the sextic: the run of Π through the word (Λ²K of each letter) ends at κΠ, so the
    orbit closes with its orientation where κ > 0."""
    cand = five.five_candidate(word)
    P = list(cand.plane)
    for letter in cand.word:
        P = five.wedge_collide(letter, P, cand.ext.red)
    assert all(cand.ext.red(p - LR_LAMBDA * q).is_zero() for p, q in zip(P, cand.plane))


def _inside(result, stage: str, r: float, margin: float) -> bool | None:
    """Whether r lies in the stage's sets (None: within ``margin`` of an end, not compared)."""
    inside = False
    for d in result.sets[stage]:
        for piece in d["pieces"]:
            if piece["kind"] != "interval":
                continue
            lo, hi = float(piece["lo"]["digits"]), float(piece["hi"]["digits"])
            if abs(r - lo) < margin or abs(r - hi) < margin:
                return None
            inside = inside or lo < r < hi
    return inside


def _agree(word: str, rs) -> int:
    """Compare the certified sets with the float route at the rationals rs (away from every end, and
    where floats resolve the spectrum of Λ²M_w: :func:`five_float_orbits.resolved`) and return how
    many r were compared."""
    result = five_orbits.analyse(word)
    compared = 0
    for r in rs:
        if not floats.resolved(word, r):
            continue
        found = floats.orbits(word, r)
        x = float(Fraction(int(r.p), int(r.q)))
        want = {"orbit": bool(found), "feasible": any(ok for _k, ok, _t in found),
                "attracting (real pair)": any(t == "real" for *_, t in found),
                "attracting (complex pair)": any(t == "complex" for *_, t in found)}
        got = {stage: _inside(result, stage, x, 2e-3) for stage in five_orbits.STAGES}
        if None in got.values():
            continue
        assert got == want, (word, x)
        compared += 1
    return compared


@pytest.mark.parametrize("word", ["abadcbcabc", "abcdcb", "abcbdcb", "abadcb", "acbcbd"])
def test_the_sets_agree_with_the_float_route(word):
    """At r = k/97 (away from the sets' ends), r lies in the certified sets exactly where numpy finds a real
    κ > 0 of Λ²M whose eigenvector is in the face, follows the word, and dominates (real or complex pair)."""
    assert _agree(word, [flint.fmpq(k, 97) for k in range(1, 97)]) > 80


def test_abadcbcabc_attracts_where_it_collapses_stably():
    """The ten-letter word's attracting orbit has a real pair, on its stable window ]≈0.2501215574, 2 − √3[."""
    result = five_orbits.analyse("abadcbcabc")
    assert [d["set"] for d in result.sets["attracting (real pair)"]] == ["]≈0.2501215574, ≈0.2679491924["]
    assert result.sets["attracting (complex pair)"] == []


@pytest.mark.slow
def test_the_nineteen_letter_word_attracts_with_a_complex_pair_above_its_window():
    """ababcbcdcdbcdbcbabc (about 30 s): a real pair on its stable window ]≈0.2251551606, ≈0.2592407154[, then
    a complex pair up to 2 − √3 (not a collapse: the attractor `simulate --particles 5` meets at r = 0.26)."""
    word = "ababcbcdcdbcdbcbabc"
    result = five_orbits.analyse(word)
    assert [d["set"] for d in result.sets["attracting (real pair)"]] == ["]≈0.2251551606, ≈0.2592407154["]
    assert [d["set"] for d in result.sets["attracting (complex pair)"]] == ["]≈0.2592407154, ≈0.2679491924["]
    assert _agree(word, [flint.fmpq(k, 400) for k in range(20, 140)]) > 80       # 26 r below 0.115 not resolved


def test_a_requirement_dropped_or_turned_is_seen_by_the_float_route():
    """Without the tournament of the third collision (abadcbcabc, abadcb: most single tournaments are implied
    by the others), or with the real pair's ordering λ² > μ² reversed (abadcbcabc), the certified sets no
    longer agree with the float route."""
    original = five_orbits.orbit_requirements

    def no_third(cand):
        reqs = original(cand)
        reqs["feasible"][2] = []
        return reqs

    def real_reversed(cand):
        reqs = original(cand)
        reqs["real"][1] = five.Requirement(reqs["real"][1].name, reqs["real"][1].G, -1)
        return reqs

    rs = [flint.fmpq(k, 97) for k in range(1, 97)]
    for word, mutant in (("abadcbcabc", no_third), ("abadcb", no_third), ("abadcbcabc", real_reversed)):
        five_orbits.orbit_requirements = mutant
        try:
            with pytest.raises(AssertionError):
                _agree(word, rs)
        finally:
            five_orbits.orbit_requirements = original


def test_certify_orbit_takes_a_five_particle_word(capsys):
    """`certify orbit abcdcb` prints the Markdown (its feasible set ]0, 3 − 2√2[), --json the sets; a bad
    word, --trap or --self-similar with a five-particle word: one line on stderr, exit 2."""
    from certify import cli
    assert cli.main(["orbit", "abcdcb"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("# Periodic orbits of the five-particle reduction: abcdcb")
    assert "## Feasible (the orbit follows the word)\n- κ3: ]0, ≈0.1715728753[" in out
    assert cli.main(["orbit", "abcdcb", "--json"]) == 0
    import json
    doc = json.loads(capsys.readouterr().out)
    assert doc["schema"] == "certify-five-orbit" and doc["sets"]["attracting (complex pair)"] == []
    for argv in (["orbit", "abcddcb"], ["orbit", "abcdcb", "--trap", "1/3"], ["orbit", "abcdcb", "--self-similar"]):
        assert cli.main(argv) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and "Traceback" not in err


def test_the_census_part_of_abadcbcabc():
    """five_orbits.census_part, the five-particle census's second way: the sets as texts, the largest r of
    the attracting real pair exact (2 − √3, the root of r² − 4r + 1), none with a complex pair."""
    part = five_orbits.census_part("abadcbcabc")
    assert part["attracting_real"] == ["upper: ]≈0.2501215574, ≈0.2679491924["]
    assert part["attracting_complex"] == [] and part["top"]["attracting_complex"] is None
    top = part["top"]["attracting_real"]
    assert top["minimal_polynomial"] == "r^2 - 4r + 1" and top["digits"] == "0.267949192431"
    assert "κ3: ]≈0.04607447305, ≈0.07295006984[" in part["feasible"]


def test_a_repeated_factor_is_not_analysed_unless_its_root_is_negative():
    """abcd: κ = r² twice (its eigenplanes not unique): listed as not analysed, never attracting; abcacd:
    κ = −r³ twice, negative on ]0, 1[ (decided exactly): no periodic orbit, nothing left out."""
    assert [n.split(" (")[0] for n in five_orbits.analyse("abcd").not_analysed] == ["-r^2 + κ"]
    assert five_orbits.analyse("abcacd").not_analysed == []


def _signs(word: str, r: Fraction, stage: str) -> list[int]:
    """The signs of the stage's requirements (G₀ only: no y) at r on the plane that numpy finds feasible and
    attracting there: κ the root of the sextic at r nearest numpy's (python-flint's certified complex roots
    at 300 bits), the requirements' polynomials in (κ, r) evaluated by SymPy at 50 digits."""
    import sympy as sp
    cand = five.five_candidate(word)
    reqs = five_orbits.orbit_requirements(cand)[stage]
    [kappa_float] = [k for k, ok, kind in floats.orbits(word, flint.fmpq(r.numerator, r.denominator)) if kind]
    lam, rr = sp.symbols("λ r")
    cp = sp.Poly(five.Sextic.of(word).cp.as_expr().subs(rr, sp.Rational(r.numerator, r.denominator)), lam)
    coeffs = [flint.fmpq(int(c.p), int(c.q)) for c in reversed(cp.all_coeffs())]
    old, flint.ctx.prec = flint.ctx.prec, 300
    try:
        roots = [z.real for z, _m in flint.fmpq_poly(coeffs).complex_roots() if z.imag.contains(0)]
    finally:
        flint.ctx.prec = old
    kappa = sp.Float(min((z.mid() for z in roots), key=lambda z: abs(float(z) - kappa_float)).str(70, radius=False), 60)
    out = []
    for q in reqs:
        value = sp.sympify(q.G[0].as_expr()).subs({lam: kappa, rr: sp.Rational(r.numerator, r.denominator)})
        out.append(int(sp.sign(sp.N(value, 50))))
    return out


def test_the_complex_pair_conditions_at_one_r_of_the_nineteen_letter_word():
    """At r = 263/1000 numpy finds ababcbcdcdbcdbcbabc's plane feasible and attracting with a complex pair:
    there −Δ, κ − p, κ + p and (κ + p)² − s²κ are all positive at 60 digits on its κ; at r = 6/25 (a real
    pair, its stable window) −Δ is negative.  The requirements are the engine's (orbit_requirements)."""
    word = "ababcbcdcdbcdbcbabc"
    assert [kind for *_, kind in floats.orbits(word, flint.fmpq(263, 1000)) if kind] == ["complex"]
    assert _signs(word, Fraction(263, 1000), "complex") == [1, 1, 1, 1]
    assert _signs(word, Fraction(6, 25), "complex")[0] == -1
