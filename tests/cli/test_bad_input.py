"""Issue 38, item 3: input that escaped the one-line contract (one line on stderr, exit 2):
certificates files of the wrong shape (the kernel and `certify verify`), numbers of thousands
of digits (one reader of numbers, certify.cli.options.exact; an echo is clipped), and output
paths that are files or cannot be written (one report, certify.run.files.ensure_writable)."""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from certify import cli
from certify_kernel.__main__ import main as kernel_main

WRONG_SHAPES = {
    "a list": [1, 2, 3],
    "a string": "certificates",
    "no certificates": {"format": "certify-certificates/2"},
    "a certificate without statements": {"format": "certify-certificates/2", "certificates": [{"id": "L1"}]},
    "a certificate that is a number": {"format": "certify-certificates/2", "certificates": [3]},
    "statements as a list": {"format": "certify-certificates/2", "certificates": [{"id": "L1", "statements": []}]},
}


def one_line(err: str) -> bool:
    return err.count("\n") == 1 and "Traceback" not in err and len(err) < 300


@pytest.mark.parametrize("shape", WRONG_SHAPES)
def test_a_certificates_file_of_the_wrong_shape_is_one_line_exit_2(shape, tmp_path, capsys):
    path = tmp_path / "certificates.json"
    path.write_text(json.dumps(WRONG_SHAPES[shape]))
    assert kernel_main([str(path), "--jobs", "1"]) == 2
    assert one_line(capsys.readouterr().err)
    assert cli.main(["verify", str(path), "--jobs", "1"]) == 2
    assert one_line(capsys.readouterr().err)


@pytest.mark.parametrize("argv", [["--jobs", "x"], ["--jobs", "0"], ["--only"], ["--bogus"], ["a", "b"]])
def test_a_bad_option_of_the_kernel_is_one_line_exit_2(argv, capsys):
    assert kernel_main(argv) == 2
    assert one_line(capsys.readouterr().err)


LONG = "1" * 5000 + "/3" + "0" * 5000           # a rational r in ]0, 1[ with a 5000-digit numerator


@pytest.mark.parametrize("argv", [
    ["identify", "--r", LONG, "--orbits", "1"],
    ["orbit", "abcb", "--trap", LONG],
    ["island", "--r", LONG],
    ["island", "--r-range", "1/3", "1/2", LONG],
    ["pattern", "abcb", "--r-range", LONG, "1"],
    ["particles", "--x", "0", "1", "2", LONG, "--v", "1", "0", "0", "-1", "--r", "1/2"],
    ["simulate", "--r", LONG],
    ["census", "--max-length", "1" * 5000],
    ["pattern", "ab" * 5000 + "x"],
])
def test_a_number_of_thousands_of_digits_is_one_short_line_exit_2(argv, capsys):
    assert cli.main(argv) == 2
    err = capsys.readouterr().err
    assert one_line(err) and len(err) < 300, err[:400]


def test_an_echo_is_clipped_and_says_how_long_it_was():
    from certify.cli.options import clip
    assert clip("got '" + "7" * 1000 + "'") == "got '" + "7" * 99 + "…(1002 characters)"
    assert clip("a short message") == "a short message"


def test_an_output_directory_that_is_a_file_is_not_a_directory(tmp_path, capsys):
    afile = tmp_path / "afile"
    afile.write_text("x")
    for out, said in ((afile, "not a directory"), (afile / "sub", f"not a directory ('{afile}' is a file)")):
        for argv in (["census", "--max-length", "2"], ["family", "--n-max", "2"], ["run", "L1"]):
            assert cli.main([*argv, "--out", str(out)]) == 2
            err = capsys.readouterr().err
            assert one_line(err) and err.endswith(f"{said}\n"), err


@pytest.mark.skipif(not Path("/proc/self").is_dir(), reason="no /proc")
def test_an_output_directory_that_cannot_be_written_says_so(capsys):
    assert cli.main(["census", "--max-length", "2", "--out", "/proc/self"]) == 2
    err = capsys.readouterr().err
    assert one_line(err) and "'/proc/self': not writable" in err, err


def test_an_output_file_that_is_a_directory_is_refused_by_every_command(tmp_path, capsys):
    for argv, option in ((["stress", "--quick", "--out"], "--out"),
                         (["simulate", "--r", "1/2", "--collisions", "1", "--out"], "--out"),
                         (["island", "--r", "1/2", "--figure"], "--figure"),
                         (["census", "--max-length", "2", "--out", str(tmp_path / "c"), "--state"], "--state")):
        assert cli.main([*argv, str(tmp_path)]) == 2
        err = capsys.readouterr().err
        assert one_line(err) and f"{option} '{tmp_path}' is a directory, not a file" in err, err


@pytest.mark.parametrize("argv", [["census", "--max-length=--"], ["family", "--n-max=--"], ["island", "--r=--"]])
def test_an_option_given_the_value_dashdash_is_refused(argv, capsys):
    """argparse (3.11) drops a "--" given as ``--opt=--`` and hands the option an empty list:
    exit 3 (census, family, island) before cli.options.Parser refused it."""
    assert cli.main(argv) == 2
    err = capsys.readouterr().err
    assert one_line(err) and "expected a value, got '--'" in err, err
