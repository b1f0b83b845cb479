"""Issue 38, item 3: a fuzz test over every command's options.  Each example is a command
line built from the command's own parser (every option and positional argument, with the
number of values it takes), one value of it surely bad (a number of 5000 digits, 1/0, an
exponent beyond the bound, a word that is not one, an empty string...), the others good or
bad; paths point into a temporary directory (a directory, a file, a path under a file,
/proc/self).  Run in process through certify.cli.main, the contract: exit 0, 1 or 2, never
3 (an internal error) and never a traceback; on exit 2 one line on stderr, its echo clipped.
A command that starts working on such input instead of refusing it is stopped after
TIMEOUT seconds (as by Ctrl-C, exit 130) and fails the test; a benchmark (which writes the
checkout's reports/BENCH.md) fails it at once.

Left out: ``--scheduler`` (a Dask address: connecting is not input checking)."""
from __future__ import annotations

import argparse
import contextlib
import io
import signal
import tempfile
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from certify import cli
from certify.cli import claims

TIMEOUT = 20                               # seconds: refusing bad input takes a fraction of one
EXAMPLES = 30                              # per command
BAD = ["1" * 5000 + "/3", "1/0", "1e99999", "10^-99999", "abc", "", "nan", "inf", "1/3/4", "½", "0x1f", "--", "⅓"]
GOOD = ["1/2", "3", "0.3", "1", "2/7", "1e1", "10^1", "-1/3", "0", "ababcb", "L1", "5.2"]
PATHS = ("out", "state", "figure", "validate", "path")
SKIPPED = {"--scheduler"}


def subparsers() -> dict:
    parser = cli.build_parser()
    return next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction)).choices


def slots(parser) -> list:
    """The command's options and positional arguments, but --help and SKIPPED."""
    return [a for a in parser._actions
            if not isinstance(a, argparse._HelpAction) and not SKIPPED & set(a.option_strings)]


def count(action, draw) -> int:
    """How many values ``action`` takes in this example."""
    if isinstance(action.nargs, int):
        return action.nargs
    return {None: 1, "?": draw(st.integers(0, 1)), "+": draw(st.integers(1, 3)), "*": draw(st.integers(0, 2))}[
        action.nargs]


def paths(root: Path) -> list[str]:
    """Paths of every kind: a directory, a new one, a file, a path under a file, /proc/self."""
    (root / "afile").write_text("x")
    return [str(root / "dir"), str(root / "new" / "deeper"), str(root / "afile"), str(root / "afile" / "sub"),
            "/proc/self"]


@st.composite
def command_line(draw, name: str, parser, where: list[str]):
    """A command line of ``name`` with at least one bad value (or, for a command without
    values, its flags)."""
    actions = slots(parser)
    valued = [a for a in actions if a.nargs != 0 and a.dest not in PATHS]
    bad = draw(st.sampled_from(valued)) if valued else None
    argv: list[str] = [name]
    positional: list[str] = []
    for a in actions:
        path = a.dest in PATHS
        required = a.required or (not a.option_strings and a.nargs not in ("?", "*"))
        if a is not bad and not required and not draw(st.booleans()):
            continue
        if a.nargs == 0:
            argv.append(a.option_strings[0])
            continue
        n = max(count(a, draw), 1 if a is bad else 0)
        pool = where if path else (a.choices and list(a.choices) or GOOD) + BAD
        values = [draw(st.sampled_from(pool)) for _ in range(n)]
        if a is bad:
            values[draw(st.integers(0, n - 1))] = draw(st.sampled_from(BAD))
        if a.option_strings:
            single = a.nargs in (None, "?") and values          # --r=-1/3: a value, not an option
            argv += [f"{a.option_strings[0]}={values[0]}"] if single else [a.option_strings[0], *values]
        else:
            positional += values
    return argv + (["--"] + positional if positional else [])


def run_in_process(argv: list[str]) -> tuple[int, str]:
    """certify.cli.main(argv) with stdout and stderr captured, stopped after TIMEOUT s."""
    def stop(*_):
        raise KeyboardInterrupt
    err = io.StringIO()
    previous = signal.signal(signal.SIGALRM, stop)
    signal.alarm(TIMEOUT)
    try:
        with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(err):
            code = cli.main(argv)
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, previous)
    return code, err.getvalue()


@pytest.mark.parametrize("name", sorted(subparsers()))
def test_every_command_refuses_bad_values_in_one_line(name, monkeypatch):
    parser = subparsers()[name]
    with tempfile.TemporaryDirectory() as root:
        monkeypatch.chdir(root)                    # a default output (reports/) lands here, not in the checkout

        def no_benchmark(*_):
            raise AssertionError("a benchmark started on bad input")
        monkeypatch.setattr(claims, "load_bench", no_benchmark)   # they write the checkout's reports/BENCH.md
        where = paths(Path(root))

        @settings(max_examples=EXAMPLES, deadline=None, database=None, derandomize=True,
                  suppress_health_check=list(HealthCheck))
        @given(argv=command_line(name, parser, where))
        def check(argv):
            code, err = run_in_process(argv)
            shown = " ".join(a[:40] for a in argv)
            assert code in (0, 1, 2), f"{shown}: exit {code}: {err[:500]}"
            assert "Traceback" not in err and "internal error" not in err, f"{shown}: {err[:500]}"
            if code == 2:
                assert err.count("\n") == 1 and len(err) < 600, f"{shown}: {err[:800]}"
        check()
