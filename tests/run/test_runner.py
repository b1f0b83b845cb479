"""The runner: the verdict rule, units of certificates that share a quantity, and the
run on several processes, which must give what the serial run gives."""
from __future__ import annotations

import pytest

from certify.run import report, runner
from certify.run.runner import ERRATUM, FAIL, PASS, Certificate, Check, Quantity, conclude

# --------------------------------------------------------------------------
# conclude: the verdict rests on checks that could fail

def test_pass_erratum_fail():
    assert conclude([Check("a", True)]).status == PASS
    wrong = Check("x > 0", False)
    assert conclude([wrong], corrected=[Check("x < 0", True, corrects=wrong)]).status == ERRATUM
    assert conclude([wrong], corrected=[Check("x < 0", False, corrects=wrong)]).status == FAIL
    assert conclude([wrong]).status == FAIL


def test_a_consistency_check_is_not_evidence():
    tautology = Check("cp(0) = -det M", True, counts=False)
    assert conclude([tautology]).status == FAIL                 # nothing that could fail was checked
    assert conclude([tautology, Check("a", True)]).status == PASS
    broken = Check("the engine applied the word it was given", False, counts=False)
    assert conclude([broken, Check("a", True)]).status == FAIL  # an inconsistent engine proves nothing


def test_an_erratum_names_what_it_corrects():
    wrong, other = Check("x > 0", False), Check("y > 0", False)
    fix = Check("x < 0", True, corrects=wrong)
    assert conclude([wrong, other], corrected=[fix]).status == FAIL     # y > 0 is false and uncorrected
    assert conclude([wrong, other], corrected=[fix, Check("y < 0", True, corrects="y > 0")]).status == ERRATUM


# --------------------------------------------------------------------------
# Units and the parallel run, on a fake registry

CALLS = []


def quantity(name, needs=()):
    def compute(**args):
        CALLS.append(name)
        with open(LOG, "a") as f:
            f.write(name + "\n")
        return len(name) + sum(args.values())
    return Quantity(name, compute, tuple(needs), "")


def make(cid, needs=(), value=True):
    def claim(**args):
        return conclude([Check(f"{cid} with {sorted(args.items())}", value)])
    return Certificate(cid, "l. 1", f"claim {cid}", claim, tuple(needs), {}, "tests.test_runner")


@pytest.fixture
def registry(monkeypatch, tmp_path):
    global LOG
    LOG = tmp_path / "calls"
    quantities = {"A": quantity("A"), "B": quantity("B", ["A"]), "C": quantity("C")}
    certs = {c.id: c for c in [make("M1"), make("M2", ["B"]), make("T1", ["A"]), make("T2", ["C"]),
                               make("T3", value=False), make("S1", ["C"]), make("S2")]}
    monkeypatch.setattr(runner, "QUANTITIES", quantities)
    monkeypatch.setattr(runner, "load_all", lambda: certs)
    return certs


def test_units_join_certificates_that_share_a_quantity(registry):
    units = [[c.id for c in unit] for unit in runner.units(runner.select())]
    assert sorted(units) == sorted([["M1"], ["M2", "T1"], ["T2", "S1"], ["T3"], ["S2"]])


@pytest.mark.parametrize("jobs", [2, 3, 8])
def test_parallel_run_equals_serial_run_and_computes_each_quantity_once(registry, jobs):
    serial, _ = runner.run_selected(jobs=1)
    LOG.unlink()
    parallel, timings = runner.run_selected(jobs=jobs, estimates={"T2": 5.0})
    assert [c.id for c, _ in parallel] == ["M1", "M2", "T1", "T2", "T3", "S1", "S2"]
    assert report.render_markdown(parallel) == report.render_markdown(serial)
    assert sorted(LOG.read_text().split()) == ["A", "B", "C"]       # once each, across the workers
    assert set(timings["certificates"]) == set(registry) and set(timings["shared"]) == {"A", "B", "C"}


def test_progress_counts_every_certificate(registry):
    seen = []
    runner.run_selected(jobs=2, progress=lambda k, n, cid: seen.append((k, n)))
    assert seen[0] == (0, 7) and sorted(k for k, _ in seen[1:]) == list(range(1, 8))


def test_outcomes_cross_processes_as_plain_data(registry):
    class Relation:                     # e.g. a SymPy relation that decides itself
        def __bool__(self):
            return True
    outcome = runner.plain(conclude([Check("x", Relation(), [1])]))
    assert outcome.printed[0].holds is True and outcome.printed[0].evidence == ["1"]


def test_an_unread_printed_text_is_a_fail_that_says_so():
    from certify.algebra import statements

    def claim(text):
        statements.relation(text, {})
        return conclude([Check("read", True)])
    cert = Certificate("X9", "l. 1", "x", claim, (), {"text": "c is rather big"}, "tests.test_runner")
    outcome = runner.run_certificate(cert)
    assert outcome.status == FAIL
    assert outcome.printed[0].statement == "the printed text was read"
    assert "c is rather big" in outcome.printed[0].evidence[0]


def test_a_dead_worker_is_an_error_not_a_hang(registry):
    import os

    def dies():
        os._exit(3)                 # as a crash in C code would
    registry["T9"] = Certificate("T9", "l. 1", "x", dies, (), {}, "tests.test_runner")
    with pytest.raises(runner.WorkerDied, match="--jobs 1"):
        runner.run_selected(jobs=2)


# ---------------------------------------------------------------- checks several proofs make alike
def test_digit_count_and_eliminant_checks_can_fail():
    from certify.algebra import Algebraic, lam, parse
    from certify.run import count_check, digits_check, eliminant_check
    root = Algebraic.surd(5, -2, 6)                                   # 0.101020514...
    assert digits_check("r1", root, "0.10102").holds and not digits_check("r1", root, "0.10103").holds
    assert count_check("P", [root], (1, 1), 1).holds
    assert not count_check("P", [root], (1, 2), 1).holds and not count_check("P", [root], (1, 1), 2).holds
    cp = parse("λ^2 - r")                                             # λ = r eliminates to r^2 - r
    good, agree = eliminant_check("λ - r", lam - parse("r"), cp, "r*(r - 1)")
    assert good.holds and agree.holds
    assert not eliminant_check("λ - r", lam - parse("r"), cp, "r*(r - 2)")[0].holds


def test_the_float64_engine_starts_in_one_unit():
    """numba's start-up (about 0.5 s a process) is a shared quantity: the certificates that run
    the float64 engine (N2-N7's preview runs, N4's probe) are one unit, so one worker pays it."""
    with_engine = [unit for unit in runner.units(runner.select())
                   if any("float64_engine" in c.needs or "section5_preview" in c.needs for c in unit)]
    assert len(with_engine) == 1
    assert {"N2", "N4"} <= {c.id for c in with_engine[0]}
