"""L1-L6 through `certify pattern`: each passes, and each turns FAIL when its printed
text is altered (mutation tests).  L4-L6 share one quantity, `certify pattern (ab)^n(cb)^n`
for n = 2..6, computed once for this module (one Context)."""
import pytest

from certify.run.runner import CERTIFICATES, FAIL, PASS, Context, altered, load_all, run_certificate

load_all()
SHARED = Context()          # the quantities (ab_cb_patterns) computed once for all tests here


def run(id, **overrides):
    return run_certificate(CERTIFICATES[id], SHARED, overrides=overrides or None)


@pytest.mark.parametrize("id", ["L1", "L2", "L3"])
def test_passes(id):
    o = run(id)
    assert o.status == PASS, [(c.statement, c.evidence) for c in o.printed if not c.holds]


@pytest.mark.parametrize("id, name, old, new", [
    ("L1", "threshold", "7-4√3", "7-4√2"),
    ("L1", "digits", "0.07180", "0.07181"),
    ("L1", "word", "ab", "[ac]b"),
    ("L2", "threshold", "3-2√2", "3-2√3"),
    ("L2", "digits", "0.17157", "0.17158"),
    ("L3", "P", "831r^4", "832r^4"),
    ("L3", "r_exist", "0.19166", "0.19167"),
    ("L3", "stability", "unstable", "stable"),
])
def test_mutations_fail(id, name, old, new):
    assert run(id, **altered(id, name, old, new)).status == FAIL


def test_unread_radical_fails():
    o = run("L1", threshold="7-4√")
    assert o.status == FAIL


@pytest.mark.parametrize("id", ["L4", "L5", "L6"])
def test_windows_pass(id):
    o = run(id)
    assert o.status == PASS, [(c.statement, c.evidence) for c in o.printed if not c.holds]


@pytest.mark.parametrize("id, name, old, new", [
    ("L4", "n4", "4 + 3√2", "4 + 3√3"),
    ("L4", "n6", "0.07782", "0.07783"),
    ("L4", "n2", "3-2√2", "5-2√6"),
    ("L5", "n2", "0.12754", "0.12755"),
    ("L5", "n3", "0.10102", "0.10103"),
    ("L5", "order", "disjoint", "overlapping"),
    ("L5", "limit", "7-4√3", "3-2√2"),
    ("L6", "criterion", "q_2(0)", "q_3(0)"),
])
def test_window_mutations_fail(id, name, old, new):
    assert run(id, **altered(id, name, old, new)).status == FAIL
