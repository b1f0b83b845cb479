"""`certify pattern WORD`: reading, rejections, normal forms, thresholds against
independently built surds, the JSON schema, the command line."""
import json
import os
import subprocess
import sys
from pathlib import Path

import flint
import pytest

from certify import cli
from certify.algebra.algebraic import Algebraic
from certify.errors import UsageError
from certify.patterns import SCHEMA_PATH, analyse, normal_form, parse, primitive_root, read
from certify.patterns.pattern import dominance_requirements

ROOT = Path(__file__).resolve().parents[2]


# ------------------------------------------------------------------ rejections: one per rule
@pytest.mark.parametrize("word, says", [
    ("abx", "unexpected 'x'"),                                  # another letter
    ("ab s", "unexpected 's'"),                                 # the internal letter is not for users
    ("", "empty"),                                              # an empty word
    ("   ", "empty"),
    ("aab", "adjacent"),                                        # two equal letters adjacent
    ("abca", "adjacent"),                                       # ... cyclically (a ... a)
    ("a", "adjacent"),
    ("[ac]ab", "symmetric system"),                             # [ac] mixed with a single a
    ("acab", "Proposition 4.4"),                                # aca
    ("acbc", "Proposition 4.4"),                                # c|ac: cac cyclically
    ("abab", "proper power of 'ab'"),                           # a proper power, root named
    ("(abcb)^2", "proper power of 'abcb'"),
    ("(ab)^0cb", "power"),
    ("(ab)^-1cb", "negative power -1; a power is a whole number n ≥ 1"),     # one reason, not the characters
    ("(ab)^1000000cb", "the power 1000000 is too large (a word has at most 400 letters)"),
    ("(ab)^cb", "'^' must be followed by a whole number"),
    ("(ab)cb", "the group (ab) has no power"),
    ("((ab)^2cb", "unbalanced parentheses"),
    ("(((ab)^20cb)^20)^20", "more than 400 collisions (a word has at most 400 letters)"),   # refused as it grows
])
def test_rejections_are_one_line_exit_2_nothing_written(word, says, tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    assert cli.main(["pattern", word]) == 2
    out, err = capsys.readouterr()
    assert out == "" and err.count("\n") == 1 and says in err, err
    assert list(tmp_path.iterdir()) == []
    with pytest.raises(UsageError):
        read(word)


def test_a_without_c_is_read_as_three_particles():
    assert read("ba")[:2] == ("ab", "three")
    assert read("cb")[:2] == ("ab", "three")            # the mirror: particles numbered from the right


def test_r_range_is_validated(capsys):
    for rng in (["1/2", "1/3"], ["-1", "1/2"], ["0", "2"], ["x", "1"]):
        assert cli.main(["pattern", "ab", "--r-range", *rng]) == 2
        assert "--r-range" in capsys.readouterr().err


# ------------------------------------------------------------------ normal forms
@pytest.mark.parametrize("written, normal", [
    ("ababcb", "ababcb"), ("bcbaba", "ababcb"), ("cbcbab", "ababcb"),     # rotation; mirror
    ("(ab)^3(cb)^3", "abababcbcbcb"), ("(cb)^2(ab)^2", "ababcbcb"),
    ("bcba", "abcb"), ("cbacb", "abcab"), ("b[ac]", "sb"), ("[ca]b", "sb"),
])
def test_normal_forms(written, normal):
    assert read(written)[0] == normal
    assert normal_form(parse(written))[0] == normal


def test_normal_form_explains():
    n, why = normal_form(parse("cbabcb"))
    assert n == "ababcb" and "mirror" in why and "rotated" in why


def test_primitive_root():
    assert primitive_root("abababab") == ("ab", 4)
    assert primitive_root("ababcb") == ("ababcb", 1)


# ------------------------------------------------------------------ thresholds, exact
def _top(res, stage, branch=None):
    ends = [(p.lo if p.is_point else p.hi) for R in res.regions[stage] if branch is None or R.branch == branch
            for p in R.pieces]
    return max(ends)


def test_three_particles_threshold_7_minus_4_sqrt3():
    res = analyse("ab")
    assert res.system == "three"
    t = Algebraic.surd(7, -4, 3)
    assert _top(res, "exists") == t
    assert [(b, lo, hi) for b, _, lo, hi in res.intervals("stable")] == [(0, 0, t)]
    assert not res.undecided


def test_symmetric_threshold_3_minus_2_sqrt2():
    res = analyse("[ac]b")
    assert res.system == "symmetric" and res.written == "[ac]b"
    t = Algebraic.surd(3, -2, 2)
    assert _top(res, "exists") == t
    assert [(lo, hi) for _, _, lo, hi in res.intervals("stable")] == [(0, t)]


def test_ababcb_feasible_below_5_minus_2_sqrt6_never_stable():
    res = analyse("ababcb")
    assert _top(res, "feasible") == Algebraic.surd(5, -2, 6)
    assert not res.stable and res.feasible


def test_ab2cb2_window():
    res = analyse("(ab)^2(cb)^2")
    (st,) = res.intervals("stable")
    assert st[0] == 0 and not res.points("stable")
    assert st[3] == Algebraic.surd(3, -2, 2)
    assert st[2].in_rounding_interval("0.12754")


def test_abcb_r_exist_is_the_root_of_P():
    P = flint.fmpz_poly([17, -138, 831, -3148, 831, -138, 17])
    (r_exist,) = Algebraic.roots(P, 0, 1)
    res = analyse("abcb")
    assert _top(res, "feasible") == r_exist
    assert not res.stable


def test_abcab_diagnosis():
    res = analyse("abcab")
    assert not res.feasible and res.exists
    d = res.diagnosis
    assert d["collision"] == 3 and d["expected"] == "c" and [i["letter"] for i in d["instead"]] == ["a"]
    assert d["complete"] and "after ab comes a, strictly before c" in res.verdict


def test_r_range_restricts():
    res = analyse("ab", "1/20", "1/10")
    assert res.to_json()["r_range"] == ["1/20", "1/10"]
    (s,) = res.stable
    assert s["pieces"][0]["lo"]["exact"] == "1/20"
    assert s["pieces"][0]["hi"]["minimal_polynomial"] == "r^2 - 14r + 1"


def test_dominance_is_the_jury_criterion():
    """At r = 1/2, λ = 1 for cp = (λ-1)(λ²+pλ+q): dominant iff |q| < 1 and |p| < 1 + q."""
    import sympy as sp

    from certify.algebra.poly import lam
    for p, q, dominant in ((0, sp.Rational(1, 2), True), (sp.Rational(-3, 2), sp.Rational(1, 2), False),
                           (0, sp.Rational(-3, 2), False), (sp.Rational(1, 5), sp.Rational(-1, 2), True)):
        cp = sp.expand((lam - 1) * (lam ** 2 + p * lam + q))
        values = [q_.G[0].as_expr().subs(lam, 1) for q_ in dominance_requirements(cp)]
        assert all(v > 0 for v in values) == dominant, (p, q, values)


# ------------------------------------------------------------------ output
def _validate(doc):
    schema = json.loads(SCHEMA_PATH.read_text())
    jsonschema = pytest.importorskip("jsonschema")
    jsonschema.validate(doc, schema)


@pytest.mark.parametrize("word", ["ab", "[ac]b", "abcab", "abcb"])
def test_json_follows_the_schema(word):
    doc = analyse(word).to_json()
    _validate(doc)
    assert json.loads(json.dumps(doc)) == doc
    for s in doc["exists"] + doc["feasible"] + doc["stable"]:
        for p in s["pieces"]:
            for e in ([p["lo"], p["hi"]] if p["kind"] == "interval" else [p["at"]]):
                assert e["exact"] is not None or len(e["digits"].replace("0.", "").lstrip("0")) >= 10


def test_json_is_deterministic():
    assert analyse("ab").json_text() == analyse("ab").json_text()
    a, b = analyse("abcb").to_json(), analyse("bcba").to_json()
    assert a["normal_form"] == b["normal_form"] == "abcb"
    for key in ("exists", "feasible", "stable", "matrix", "characteristic_polynomial", "verdict"):
        assert a[key] == b[key]


def test_markdown_sections():
    md = analyse("abcab").markdown()
    for head in ("# Pattern abcab", "## Period matrix", "## Self-similar data exist", "## Feasible",
                 "## Stable", "## The datum", "## First collision that goes wrong", "## Verdict"):
        assert head in md


def test_cli_smoke(tmp_path):
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    out = subprocess.run([sys.executable, "-m", "certify", "pattern", "b[ac]", "--json"], cwd=tmp_path, env=env,
                         capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, out.stderr
    doc = json.loads(out.stdout)
    _validate(doc)
    assert doc["normal_form"] == "[ac]b" and doc["system"] == "symmetric"
    md = subprocess.run([sys.executable, "-m", "certify", "pattern", "ab"], cwd=tmp_path, env=env,
                        capture_output=True, text=True, timeout=300)
    assert md.returncode == 0 and md.stdout.startswith("# Pattern ab")
    assert list(tmp_path.iterdir()) == []


def test_the_engine_certifies_what_the_committed_digests_record():
    """`certify pattern WORD --json` for every census word up to 7 collisions hashes to the
    committed digest (reports/pattern-json-digests.txt, all words up to 12: `python
    benchmarks/same_results.py check`; their JSON equals that of the engine of commit
    cb9d573, before the fast exact core, but for a reworded diagnosis): the same sets."""
    import hashlib
    from pathlib import Path

    from certify.patterns import census
    path = Path(__file__).resolve().parents[2] / "reports" / "pattern-json-digests.txt"
    recorded = dict(line.split() for line in path.read_text(encoding="utf-8").splitlines() if not line.startswith("#"))
    words = census.words(7)
    assert words and all(w in recorded for w in words)
    for w in words:
        assert hashlib.sha256(analyse(w).json_text().encode("utf-8")).hexdigest() == recorded[w], w


def test_ababcb_names_the_fixed_points_both_ways_and_t10_certifies_the_factor(certificates):
    from certify.patterns.pattern import PAPER_NORMALISATION
    from certify.run.runner import run_certificate
    t10 = run_certificate(certificates["T10"])
    factor = next(c for c in t10.printed if c.statement.startswith("the factor printed/computed"))
    assert factor.holds and "-1024" in factor.statement
    assert "divided by −1024" in PAPER_NORMALISATION["ababcb"]
    text = analyse("ababcb").markdown()
    assert "lower branch, x₋ (the paper's x₊)" in text and "this x₋ is the paper's x₊" in text
    assert "(the paper's" not in analyse("abcb").markdown()


def test_a_candidate_that_misses_the_first_collision_says_so_plainly():
    text = analyse("acb").markdown()
    assert "(nothing)" not in text and "1..0" not in text and "never realises the first collision" in text


@pytest.mark.parametrize("word", ["ababcb", "abacbc", "ab", "[ac]b"])
def test_discriminant_by_flint_is_sympys(word):
    """The report's disc_λ cp (python-flint, :func:`pattern.discriminant`) is SymPy's
    discriminant of cp as a polynomial in λ, for four- and three-particle words."""
    import sympy as sp

    from certify.algebra.poly import from_flint, lam
    from certify.dynamics.systems import candidate_in
    from certify.patterns.pattern import discriminant
    normal, system, _ = read(word)
    cand = candidate_in(system, normal)
    assert sp.expand(from_flint(discriminant(cand.spectrum)) - sp.discriminant(sp.Poly(cand.cp, lam)).as_expr()) == 0
