"""tools/five_particle_scan.py: the tails it reports are orbits of the exact map, and its
certification step is certify pattern's JSON (or says it ran out of time)."""
import importlib.util
import json
import subprocess
import sys
from pathlib import Path

import flint

from certify.numerics import five_reduction as five
from certify.numerics import rules

ROOT = Path(__file__).resolve().parents[1]
spec = importlib.util.spec_from_file_location("five_particle_scan", ROOT / "tools" / "five_particle_scan.py")
scan = importlib.util.module_from_spec(spec)
spec.loader.exec_module(scan)


def test_a_reported_tail_is_followed_by_the_exact_map():
    """At r = 1/4 every orbit's tail, continued from its last state read exactly, is spelt again by
    the exact map (four periods): the tail is the word of a true orbit of the reduction nearby."""
    tails, _ = scan.scan([0.25], 4, 5000, 0, 200)
    assert sum(n for w, n in tails[0.25].items() if w) == 4
    p0, q0 = five.random_data(4, 0)
    run = five.iterate([0.25], p0, q0, collisions=5000)
    for b in range(4):
        w = [flint.fmpq(*float(z).as_integer_ratio()) for z in run.omega[0, b]]
        word, code = five.exact_orbit(int(run.face[0, b]), w, rules.exact_r(0.25), 400)
        assert code == 0 and five.periodic_tail(word, 100, 4) in tails[0.25]


def test_grid_excludes_the_ends():
    assert scan.grid(0.2, 0.3, 3) == [0.225, 0.25, 0.275]


def test_certify_word_is_the_pattern_json_or_a_timeout():
    res = scan.certify_word("abcd", "1/10", "3/10", 600)
    doc = json.loads(subprocess.run([sys.executable, "-m", "certify", "pattern", "abcd", "--json", "--r-range",
                                     "1/10", "3/10"], capture_output=True, text=True, cwd=ROOT).stdout)
    assert res["status"] == "analysed" and res["stable"] == doc["stable"] and res["feasible"] == doc["feasible"]
    assert scan.certify_word("abcd", "1/10", "3/10", 0.01)["status"].startswith("not finished")


def test_a_symmetric_tail_is_certified_by_the_half_route(monkeypatch):
    """A tail X·m(X) goes to certify pattern with --half, another without (the command line checked)."""
    seen = []

    class Done:
        returncode, stdout, stderr = 0, "{}", ""
    monkeypatch.setattr(scan.subprocess, "run", lambda cmd, **k: seen.append(cmd) or Done())
    scan.certify_word("abacbacbdcbcdcdbcdbcabcb", "1/5", "1/4", 60)
    scan.certify_word("abadcbcabc", "1/5", "1/4", 60)
    assert seen[0][-1] == "--half" and "--half" not in seen[1]


def test_an_analysed_word_prints_its_windows(monkeypatch, capsys):
    """A clean exit of certify pattern is "analysed" (with or without a stable window), and the
    scan prints its windows and undecided points; a timeout prints its status."""
    import collections
    monkeypatch.setattr(scan, "scan", lambda *a: ({0.25: collections.Counter(["abcd", "abdc"])}, 0.0))
    results = {"abcd": {"word": "abcd", "status": "analysed", "seconds": 1.0, "stable": [], "feasible": [],
                        "undecided": 0},
               "abdc": {"word": "abdc", "status": "not finished in 1 s"}}
    monkeypatch.setattr(scan, "certify_word", lambda w, *a: results[w])
    assert scan.main(["--certify", "--r-range", "0.2", "0.3", "1", "--below", "0.1", "0.2", "1"]) == 0
    out = capsys.readouterr().out
    assert "abcd: stable on none; feasible on none; 0 undecided point(s)" in out
    assert "abdc: not finished in 1 s" in out


def test_the_certified_stable_word_is_observed_attracting_in_float64():
    """certify pattern: abadcbcabc stable on ]≈0.25012, 2 − √3[.  At r = 0.26 its self-similar plane
    (the float datum of tools/five_particle_search.py, observed) perturbed by 10⁻⁶ stays on the
    word for 3000 float64 collisions of the reduction, and perturbed by 10⁻² it does not: the orbit is
    observed to attract, with a small basin (random starts at r = 0.26 all settle on another word)."""
    import numpy as np
    search_spec = importlib.util.spec_from_file_location("search", ROOT / "tools" / "five_particle_search.py")
    search = importlib.util.module_from_spec(search_spec)
    search_spec.loader.exec_module(search)
    word, r = "abadcbcabc", 0.26
    M = search.period_matrix(word, 4, r)
    ev, V = np.linalg.eig(M)
    order = np.argsort(-abs(ev))
    q0, e = V[:, order[0]].real, V[:, order[1]].real          # λ > μ > |ν|: the two largest
    Y = five.LETTERS.index(word[-1])
    p0 = e[Y] * q0 - q0[Y] * e
    p0[Y] = 0
    p0 = p0 if p0[(Y + 1) % 4] > 0 else -p0
    q0 = q0 if search.follows(word, p0, q0, r, five.LETTERS) else -q0
    assert search.follows(word, p0, q0, r, five.LETTERS)
    rng = np.random.default_rng(0)
    tails = {}
    for eps in (1e-6, 1e-2):
        p, q = p0 + eps * np.abs(rng.standard_normal(4)), q0 + eps * rng.standard_normal(4)
        p[Y] = 0
        run = five.iterate([r], [p], [q], collisions=3000, words=True, face=word[-1])
        tails[eps] = five.periodic_tail(str(run.word[0, 0]))
    assert tails[1e-6] == word and tails[1e-2] != word
