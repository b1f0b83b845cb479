"""Bounded input and honest words (issue 25, items 3, 7, 14): what cannot finish is refused
with its reason and its limit; an option is honoured or refused, never ignored; a command
says what it wrote and nothing else."""
from __future__ import annotations

import json

import pytest

from certify import cli
from certify.cli import exact


def run(capsys, *argv):
    code = cli.main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


@pytest.mark.parametrize("length", ["60", "1000", "21"])
def test_a_census_that_cannot_finish_is_refused_with_the_limit_and_the_reason(length, tmp_path, capsys):
    code, out, err = run(capsys, "census", "--max-length", length, "--out", str(tmp_path))
    assert code == 2 and out == "" and err.count("\n") == 1
    assert f"at most {exact.MAX_CENSUS_LENGTH}" in err and "5618 words" in err and "about an hour" in err
    assert list(tmp_path.iterdir()) == []


def test_the_census_limit_is_in_the_help_and_the_docs(capsys):
    assert cli.main(["census", "--help"]) == 0
    out = " ".join(capsys.readouterr().out.split())
    assert f"(at most {exact.MAX_CENSUS_LENGTH}; with --scheduler at most {exact.MAX_CLUSTER_LENGTH})" in out
    assert "Every periodic collision word" in out


def test_beyond_20_only_on_a_cluster_and_never_beyond_32(tmp_path, capsys, monkeypatch):
    """With --scheduler the local cap does not apply: the census to 21 gets as far as the
    scheduler (unreachable here); 33 is refused even then."""
    from certify.run import executors
    monkeypatch.setattr(executors, "CONNECT_TIMEOUT", 1)
    code, out, err = run(capsys, "census", "--max-length", "21", "--out", str(tmp_path), "--scheduler",
                         "tcp://127.0.0.1:9")
    assert code == 2 and "9423 words" in err and "cannot reach the scheduler" in err
    code, out, err = run(capsys, "census", "--max-length", "21", "--out", str(tmp_path))
    assert code == 2 and "--scheduler" in err and "docs/census.md" in err
    code, out, err = run(capsys, "census", "--max-length", "33", "--out", str(tmp_path), "--scheduler",
                         "tcp://127.0.0.1:9")
    assert code == 2 and f"at most {exact.MAX_CLUSTER_LENGTH}, even on a cluster" in err and err.count("\n") == 1


def test_a_census_without_windows_says_it_drew_no_figure(tmp_path, capsys):
    code, out, _ = run(capsys, "census", "--max-length", "1", "--out", str(tmp_path), "--jobs", "1")
    assert code == 0 and out.startswith("0 words up to length 1:")
    assert "census-windows.png" not in out and not (tmp_path / "census-windows.png").exists()
    assert "no figure" in out and (tmp_path / "CENSUS.md").is_file()


def test_a_census_of_one_word_says_word(tmp_path, capsys):
    code, out, _ = run(capsys, "census", "--max-length", "2", "--out", str(tmp_path), "--jobs", "1")
    assert code == 0 and out.startswith("1 word up to length 2:") and "0 errors" in out
    assert ("census-windows.png" in out) == (tmp_path / "census-windows.png").is_file()


@pytest.mark.parametrize("command", ["census", "all", "run", "list", "bench", "particles", "pattern", "orbit",
                                     "identify", "simulate", "stress", "figures"])
def test_every_command_has_a_description(command, capsys):
    """`certify COMMAND --help` says what the command does, beyond the usage line."""
    parser = cli.build_parser()
    sub = next(a for a in parser._actions if a.dest == "command").choices[command]
    assert sub.description and len(sub.description) > 40, command


# ------------------------------------------------------------------ orbit --trap: honoured or refused
def test_trap_prints_json_with_json(capsys):
    code, out, err = run(capsys, "orbit", "abacbabcbcabcb", "--trap", "3/10", "--json")
    assert code == 0, err
    doc = json.loads(out)
    assert doc["word"] == "abacbabcbcabcb" and doc["r"] == "3/10" and doc["trapped"] is True
    assert doc["radius"]["exact"] and doc["lines"]


def test_trap_json_when_none_is_found(capsys):
    code, out, _ = run(capsys, "orbit", "abcb", "--trap", "1/10", "--json")
    doc = json.loads(out)
    assert code == 1 and doc["trapped"] is False and doc["why"]


def test_trap_with_r_range_is_refused(capsys):
    code, out, err = run(capsys, "orbit", "abcb", "--trap", "3/10", "--r-range", "0.2", "0.4")
    assert code == 2 and out == "" and "--trap R certifies one r: not with --r-range" in err


def test_a_census_of_hours_says_so_before_it_starts(tmp_path, capsys, monkeypatch):
    from certify.run import census_report

    def stop(*args, **kwargs):
        raise KeyboardInterrupt
    monkeypatch.setattr(census_report, "run_census", stop)
    code, _, err = run(capsys, "census", "--max-length", "18", "--out", str(tmp_path), "--jobs", "1")
    assert code == 130 and "census up to length 18: 2015 words; the census to 20 (5618 words) took about an hour" in err
