"""tools/five_particle_scan.py: the tails it reports are orbits of the exact map, and its
certification step is certify pattern's JSON (or says it ran out of time)."""
import importlib.util
import json
import subprocess
import sys
from pathlib import Path

import flint

from certify.numerics import five, rules

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
    assert res["status"] == "certified" and res["stable"] == doc["stable"] and res["feasible"] == doc["feasible"]
    assert scan.certify_word("abcd", "1/10", "3/10", 0.01)["status"].startswith("not finished")
