"""The command line.

In-process tests run ``cli.main`` on a small fake set of certificates (the
runner's ``load_all`` is replaced, so the real proofs are not run).  Subprocess
tests check the exit codes and one-line errors of ``python -m certify`` on
commands whose outcome does not depend on the real certificates.
"""
from __future__ import annotations

import io
import os
import subprocess
import sys
from pathlib import Path

import matplotlib.pyplot as plt
import pytest

from certify import cli
from certify.run import progress, report, runner
from certify.run import saving as figures
from certify.run.runner import OBSERVED, Certificate, Check, Outcome, conclude

ROOT = Path(__file__).resolve().parents[2]


# --------------------------------------------------------------------------
# A fake set of certificates

def passing():
    return conclude([Check("holds as printed", True, ["`1 = 1`"])])


def erratum():
    wrong = Check("x > 0 as printed", False, ["off by a sign"])
    return conclude([wrong], corrected=[Check("x < 0 with the sign corrected", True, corrects=wrong)],
                    kind="misprint", misprint="l. 2: > printed for <")


def disagreeing():
    return runner.observe([Check("seen as printed", False)], reason="not seen: the engine shows otherwise")


def observed():
    fig, ax = plt.subplots(figsize=(2, 2))
    ax.plot([0, 1], [1, 0])
    return Outcome(OBSERVED, [Check("seen", True)], figures=[figures.save_figure(fig, "seen.png")])


def broken():
    raise ZeroDivisionError("division by zero")


def interrupted():
    raise KeyboardInterrupt


@pytest.fixture
def fake(monkeypatch):
    """Replace the registry by X1 (PASS), X2 (ERRATUM), X3 (OBSERVED, one figure);
    returns a function that adds more."""
    registry = {}

    def add(cid, func):
        registry[cid] = Certificate(cid, f"l. {len(registry) + 1}", f"claim {cid} |x|",
                                    func, (), {}, "tests.test_cli")
    for cid, func in (("X1", passing), ("X2", erratum), ("X3", observed)):
        add(cid, func)
    monkeypatch.setattr(runner, "load_all", lambda: registry)
    yield add
    assert figures.get_output_dir() is None     # the CLI always restores the setting


def lines(text: str) -> list[str]:
    return text.strip().splitlines()


# --------------------------------------------------------------------------
# all

def test_all_writes_report_json_timings_and_figures(fake, tmp_path, capsys):
    out = tmp_path / "reports"
    assert cli.main(["all", "--out", str(out)]) == 0
    for name in ("REPORT.md", "report.json", "timings.json", "figures/seen.png"):
        assert (out / name).is_file(), name
    assert "![X3: seen](figures/seen.png)" in (out / "REPORT.md").read_text(encoding="utf-8")
    std = capsys.readouterr()
    assert lines(std.out)[-4:] == ["3 certificates: 1 PASS, 1 ERRATUM, 0 FAIL, 1 OBSERVED",
                                   "errata (the paper is wrong, a correction is certified): 1 distinct error of "
                                   "the paper, in 1 certificate: 1 misprint (in 1 certificate)",
                                   "  X2: misprint: l. 2: > printed for <",
                                   f"wrote {out / 'REPORT.md'}, report.json, figures/ (1 file)"]
    assert std.err == ""                        # stderr is not a terminal: no progress


def test_all_is_reproducible(fake, tmp_path):
    cli.main(["all", "--out", str(tmp_path / "a")])
    cli.main(["all", "--out", str(tmp_path / "b")])
    for name in ("REPORT.md", "report.json", "figures/seen.png"):
        assert (tmp_path / "a" / name).read_bytes() == (tmp_path / "b" / name).read_bytes()


def test_all_check_fails_on_missing_then_stale_report(fake, tmp_path, capsys):
    out = tmp_path / "reports"
    assert cli.main(["all", "--check", "--out", str(out)]) == 1
    assert "REPORT.md was missing" in capsys.readouterr().err
    assert cli.main(["all", "--check", "--out", str(out)]) == 0
    assert capsys.readouterr().err == ""

    fresh = (out / "REPORT.md").read_text(encoding="utf-8")
    (out / "REPORT.md").write_text(fresh.replace("claim X2", "claim X2 (edited)"), encoding="utf-8")
    assert cli.main(["all", "--check", "--out", str(out)]) == 1
    err = lines(capsys.readouterr().err)
    assert len(err) == 1 and "was stale (changed: summary, X2)" in err[0]
    assert (out / "REPORT.md").read_text(encoding="utf-8") == fresh     # rewritten anyway


def test_a_disagreement_is_said_up_front_with_its_reason(fake, tmp_path, capsys):
    """An observation that does not agree with the paper: OBSERVED, disagrees, with its
    one-line reason, under its line, in the last lines of `all`, and in the report's
    summary, contents, table and heading."""
    fake("X5", disagreeing)
    assert cli.main(["run", "X5"]) == 0
    out = lines(capsys.readouterr().out)
    assert out[0].split()[:3] == ["X5", "OBSERVED,", "disagrees"]
    assert out[1].strip() == "≠ does not agree with the paper: not seen: the engine shows otherwise"
    assert out[-2:] == ["disagree with the paper (numerical observations):",
                        "  X5: not seen: the engine shows otherwise"]
    assert out[-3].endswith("1 OBSERVED (1 of them disagrees with the paper)")
    assert cli.main(["all", "--out", str(tmp_path)]) == 0
    assert "  X5: not seen: the engine shows otherwise" in lines(capsys.readouterr().out)
    text = (tmp_path / "REPORT.md").read_text(encoding="utf-8")
    summary = text.split("## All certificates")[0]
    assert "| of which disagree with the paper | 1 |" in summary
    assert "[X5](#cert-x5) OBSERVED, disagrees" in summary
    assert "- OBSERVED, disagrees: [X5](#cert-x5) (l. 4): not seen: the engine shows otherwise" in summary
    assert "| OBSERVED, disagrees |" in text.split("## All certificates")[1]
    assert "**Does not agree with the paper:** not seen: the engine shows otherwise" in text


def test_a_fail_gives_exit_code_1(fake, tmp_path, capsys):
    fake("X4", broken)
    assert cli.main(["all", "--out", str(tmp_path)]) == 1
    std = capsys.readouterr()
    assert "1 FAIL" in lines(std.out)[-4]
    assert lines(std.err) == ["certify: FAIL: X4"]


def test_all_removes_figures_no_certificate_made(fake, tmp_path):
    (tmp_path / "figures").mkdir()
    (tmp_path / "figures" / "gone.png").write_bytes(b"old")
    cli.main(["all", "--out", str(tmp_path)])
    assert sorted(p.name for p in (tmp_path / "figures").iterdir()) == ["seen.png"]


# --------------------------------------------------------------------------
# run, list, bench

def test_run_prints_verdicts_and_writes_nothing(fake, tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    fake("X4", broken)
    assert cli.main(["run", "X2", "X4", "X3"]) == 1
    out = lines(capsys.readouterr().out)
    assert out[0].split()[:2] == ["X2", "ERRATUM"] and out[0].endswith("claim X2 |x|")
    assert out[1].split() == ["misprint:", "l.", "2:", ">", "printed", "for", "<"]
    assert out[2].split() == ["✗", "as", "printed:", "x", ">", "0", "as", "printed"]
    assert out[3].split() == ["✓", "corrected:", "x", "<", "0", "with", "the", "sign", "corrected"]
    assert out[4].split() == ["changed:", ">", "→", "<;", "as", "printed", "→", "with", "the", "sign", "corrected"]
    assert out[5].split()[:2] == ["X3", "OBSERVED"]
    assert out[6].split()[:2] == ["X4", "FAIL"]
    assert "✗ the certificate ran to completion: `ZeroDivisionError: division by zero`" in out[7]
    assert out[-3] == "3 certificates: 0 PASS, 1 ERRATUM, 1 FAIL, 1 OBSERVED"
    assert out[-2] == ("errata (the paper is wrong, a correction is certified): 1 distinct error of the paper, "
                       "in 1 certificate: 1 misprint (in 1 certificate)")
    assert out[-1] == "  X2: misprint: l. 2: > printed for <"
    assert list(tmp_path.iterdir()) == []       # no report, no figure


def test_run_with_out_writes_a_report(fake, tmp_path):
    assert cli.main(["run", "X3", "--out", str(tmp_path)]) == 0
    assert (tmp_path / "figures" / "seen.png").is_file()
    assert "X1" not in (tmp_path / "REPORT.md").read_text(encoding="utf-8")


def test_run_unknown_id_is_a_usage_error(fake, capsys):
    assert cli.main(["run", "X1", "Y9"]) == 2
    assert lines(capsys.readouterr().err) == [
        "certify: error: unknown claim id 'Y9' (see 'python -m certify list')"]


def test_list(fake, capsys):
    assert cli.main(["list"]) == 0
    out = lines(capsys.readouterr().out)
    assert [line.split()[:3] for line in out] == [["X1", "l.", "1"], ["X2", "l.", "2"],
                                                  ["X3", "l.", "3"]]


@pytest.mark.parametrize("jobs", ["1", "2"])
def test_bench(fake, capsys, jobs):
    assert cli.main(["bench", "--repeat", "2", "--jobs", jobs]) == 0
    out = capsys.readouterr().out
    assert f"run(jobs={jobs}): 2 runs of 3 certificates" in out and "heaviest certificates" in out


# --------------------------------------------------------------------------
# Errors never end in a traceback

def test_internal_error_is_one_line(fake, tmp_path, monkeypatch, capsys):
    def crash(*args, **kwargs):
        raise RuntimeError("boom")
    monkeypatch.setattr(report, "write_report", crash)
    assert cli.main(["all", "--out", str(tmp_path)]) == 3        # its own code: not a FAIL (1), not usage (2)
    err = [line for line in lines(capsys.readouterr().err)]
    assert len(err) == 1 and err[0].startswith("certify: internal error: RuntimeError: boom")


def test_undecided_is_one_line_with_the_code_of_an_internal_error(fake, tmp_path, monkeypatch, capsys):
    from certify.errors import Undecided

    def undecided(*args, **kwargs):
        raise Undecided("sign of x undecided at r = 1/3")
    monkeypatch.setattr(report, "write_report", undecided)
    assert cli.main(["all", "--out", str(tmp_path)]) == 3
    err = lines(capsys.readouterr().err)
    assert len(err) == 1 and err[0].startswith("certify: undecided: sign of x undecided at r = 1/3")
    assert "nothing is claimed" in err[0]


def test_the_exit_codes_are_in_the_help_and_the_docs(capsys):
    assert cli.main(["--help"]) == 0
    out = " ".join(capsys.readouterr().out.split())
    commands = " ".join((ROOT / "docs" / "commands.md").read_text(encoding="utf-8").split())
    for code, meaning in cli.EXIT_CODES.items():
        assert f"{code} {meaning}" in out
        assert f"| {code} |" in commands, code


def test_interrupt_exits_130(fake, tmp_path, capsys):
    fake("X4", interrupted)
    assert cli.main(["all", "--out", str(tmp_path)]) == 130
    assert lines(capsys.readouterr().err) == ["certify: interrupted"]
    assert not (tmp_path / "REPORT.md").exists()


def test_help_exits_0(capsys):
    assert cli.main(["--help"]) == 0
    assert "exit codes" in capsys.readouterr().out


def test_the_table_of_commands_is_what_the_topics_register():
    """Each command runs with its topic's module alone (cli.COMMANDS): the table names every
    command of the whole parser with the topic that registers it, and the parser built for one
    command holds its topic's commands."""
    import argparse

    def names(parser):
        sub = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
        return {name: p.get_default("func").__module__.rsplit(".", 1)[1] for name, p in sub.choices.items()}
    everything = names(cli.build_parser())
    assert everything == cli.COMMANDS
    for command, topic in cli.COMMANDS.items():
        assert names(cli.build_parser(command)) == {c: t for c, t in everything.items() if t == topic}


def test_pattern_loads_neither_the_runner_nor_numpy():
    """`certify pattern` imports what it needs (SymPy, python-flint, the exact layers), not
    certify.run, numpy or matplotlib (a fresh interpreter)."""
    code = ("import sys; from certify.cli import main; code = main(['pattern', 'abcab', '--json']); "
            "print(code, sorted(m for m in ('certify.run', 'numpy', 'matplotlib', 'tqdm') if m in sys.modules))")
    done = subprocess.run([sys.executable, "-c", code], cwd=ROOT, env={**os.environ, "PYTHONPATH": str(ROOT)},
                          capture_output=True, text=True, timeout=120)
    assert done.stdout.splitlines()[-1] == "0 []", done.stderr


# --------------------------------------------------------------------------
# Progress

class Terminal(io.StringIO):
    def isatty(self):
        return True


def test_progress_on_a_terminal_only():
    tty, pipe = Terminal(), io.StringIO()
    for stream in (tty, pipe):
        bar = progress.Bar("certificate", stream)
        bar(0, 2, "")
        bar(1, 2, "T1")
        bar(2, 2, "T2")
    assert pipe.getvalue() == ""
    shown = tty.getvalue()
    assert "1/2" in shown and "T1" in shown and "2/2" in shown and "certificate" in shown
    assert progress._OPEN == []                   # the bar closed itself at 2/2


# --------------------------------------------------------------------------
# The real program, as a user runs it

def certify(*args: str) -> subprocess.CompletedProcess:
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    env.pop("CERTIFY_DEBUG", None)
    return subprocess.run([sys.executable, "-m", "certify", *args], cwd=ROOT, env=env,
                          capture_output=True, text=True, timeout=120)


def test_a_usage_error_of_the_real_program_exits_2_with_one_line():
    done = certify("frobnicate")
    assert done.returncode == 2, done.stderr
    assert len(lines(done.stderr)) == 1 and done.stderr.startswith("certify: error: ")
    assert "Traceback" not in done.stderr + done.stdout


@pytest.mark.parametrize("args", [
    ["run", "NOPE"],
    ["frobnicate"],
    [],
    ["all", "--bogus"],
    ["all", "--out", "/proc/forbidden"],
    ["bench", "--repeat", "0"],
])
def test_usage_errors_exit_2_with_one_line(args, capsys):
    """The same ``main`` as the real program above, in this interpreter (a new one costs
    a second and a half of imports per case)."""
    assert cli.main(args) == 2
    std = capsys.readouterr()
    assert len(lines(std.err)) == 1 and std.err.startswith("certify: error: "), std.err
    assert "Traceback" not in std.err + std.out


def test_output_under_a_file_is_a_usage_error(tmp_path, capsys):
    (tmp_path / "file").write_text("")
    assert cli.main(["all", "--out", str(tmp_path / "file" / "reports")]) == 2
    assert lines(capsys.readouterr().err) == [f"certify: error: cannot write to output directory "
                                              f"{str(tmp_path / 'file' / 'reports')!r}: not a directory "
                                              f"({str(tmp_path / 'file')!r} is a file)"]


def test_list_runs():
    done = certify("list")
    assert done.returncode == 0, done.stderr
    assert "Traceback" not in done.stderr


def test_all_check_fails_on_a_stale_certificates_file(fake, tmp_path, capsys):
    """certificates.json is part of the staleness check of `all --check`."""
    out = tmp_path / "reports"
    cli.main(["all", "--out", str(out)])
    capsys.readouterr()
    fresh = (out / "certificates.json").read_text(encoding="utf-8")
    (out / "certificates.json").write_text(fresh.replace('"format"', '"format" ', 1), encoding="utf-8")
    assert cli.main(["all", "--check", "--out", str(out)]) == 1
    assert "certificates.json" in capsys.readouterr().err
    assert (out / "certificates.json").read_text(encoding="utf-8") == fresh     # rewritten anyway


def test_verify_check_finds_a_stale_kernel_json(tmp_path, capsys):
    """`certify verify --check` decides the statements again and compares with kernel.json beside the file."""
    assert cli.main(["run", "T1", "T5", "--out", str(tmp_path), "--jobs", "1"]) == 0
    capsys.readouterr()
    path = str(tmp_path / "certificates.json")
    assert cli.main(["verify", path, "--check", "--jobs", "1"]) == 0
    assert "13/13 statements verified" in capsys.readouterr().out
    kernel = tmp_path / "kernel.json"
    kernel.write_text(kernel.read_text(encoding="utf-8").replace('"verified": 13', '"verified": 12'), encoding="utf-8")
    assert cli.main(["verify", path, "--check", "--jobs", "1"]) == 1
    assert "kernel.json is stale" in capsys.readouterr().err
