"""What the commands share: the parser (errors as UsageErrors), the option types
(positive integers, numbers, counts), ``--jobs``, the output directory, one-line messages,
and the one way a command is registered (:func:`add_command`).
"""
from __future__ import annotations

import argparse
import re
import sys
from fractions import Fraction
from pathlib import Path

from certify.errors import UsageError
from certify.run import runner
from certify.run.files import ensure_writable

DEFAULT_OUT = Path("reports")

class Parser(argparse.ArgumentParser):
    """An argument parser whose errors are UsageErrors: one line, exit code 2.
    Negative numbers, fractions and decimals included ("-3/7", "-.5"), are values,
    not options."""

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        self._negative_number_matcher = re.compile(r"^-(\d+(/\d+)?|\d+\.\d*|\.\d+)$")

    def error(self, message):
        raise UsageError(message)


def positive_int(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        value = 0
    if value < 1:
        raise argparse.ArgumentTypeError(f"expected a positive integer, got {text!r}")
    return value

def number(text: str) -> float:
    """A real number: decimal or fraction ("0.15", "3/20")."""
    try:
        return float(Fraction(text))
    except (ValueError, ZeroDivisionError):
        raise argparse.ArgumentTypeError(f"expected a number, got {text!r}") from None


def count(text: str) -> int:
    """A non-negative integer: 10000, 1e4 or 10^4."""
    try:
        if "^" in text:
            base, exp = text.split("^")
            value = int(base) ** int(exp)
        else:
            f = float(text)
            value = int(f) if f == int(f) else -1
    except (ValueError, OverflowError):
        value = -1
    if value < 0:
        raise argparse.ArgumentTypeError(f"expected a non-negative integer, got {text!r}")
    return value

def add_jobs(p) -> None:
    """The --jobs option of the commands that run certificates."""
    p.add_argument("--jobs", type=positive_int, default=runner.default_jobs(), metavar="N",
                   help="worker processes (default: all cores, here %(default)s; 1: one after another)")

def prepare_output(out: Path) -> Path:
    """Check that ``out`` and ``out/figures`` can be written, before any work."""
    ensure_writable(out)
    ensure_writable(out / "figures")
    return out

def say(message: str) -> None:
    """One line on stderr, prefixed with the program name."""
    print(f"certify: {message}", file=sys.stderr)

def add_command(commands, name: str, run, **parser_kwargs):
    """Register the command ``name``: its parser (``help``, ``description``) among
    ``commands``, run by ``run(args)``, which returns the exit code.  Returns the parser,
    for the command's options.  Every command is registered this way."""
    p = commands.add_parser(name, **parser_kwargs)
    p.set_defaults(func=run)
    return p
