"""What the commands share: the parser (errors as UsageErrors), the one syntax of numbers
(integers: 10000, 1e4, 10^4; exact rationals: 3/10, 0.3, 1e-1; r in [2^-60, 1 - 2^-60]),
``--jobs``, the output directory, one-line messages, and the one way a command is registered
(:func:`add_command`).
"""
from __future__ import annotations

import argparse
import functools
import re
import signal
import sys
import threading
from fractions import Fraction
from pathlib import Path

from certify.cores import default_jobs
from certify.errors import UsageError

DEFAULT_OUT = Path("reports")

class Parser(argparse.ArgumentParser):
    """An argument parser whose errors are UsageErrors: one line, exit code 2.
    Negative numbers, fractions and decimals included ("-3/7", "-.5"), are values,
    not options."""

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        self._negative_number_matcher = re.compile(
            r"^-(\d+(/\d+)?|\d+\.?\d*([eE][+-]?\d+)?|\.\d+([eE][+-]?\d+)?|\d+\^-?\d+)$")

    def error(self, message):
        raise UsageError(message)

    def _get_values(self, action, arg_strings):
        """argparse's values, but ``--r=--`` is refused: argparse (3.11) drops the "--" and
        hands the option an untyped empty list."""
        if action.option_strings and action.nargs is None and arg_strings == ["--"]:
            self.error(f"argument {'/'.join(action.option_strings)}: expected a value, got '--'")
        return super()._get_values(action, arg_strings)


# --- numbers: one syntax for every command --------------------------------------------
#
# An integer: 10000, 1e4 or 10^4 (exactly an integer); an exact rational: 3/10, 0.3, 1e-1,
# -2 (a decimal is read exactly: 0.3 is 3/10, never the float 0.299999...).  Exponents are
# bounded (MAX_EXPONENT), so that no input makes a number too large to build.

MAX_EXPONENT = 10_000                 # |e| of 1e<e> and 10^<e>: 10^10000 is built at once
MAX_DIGITS = 1000                     # digits written in a number's text (Python reads at most 4300)
R_MARGIN = Fraction(1, 2 ** 60)       # r is at least this far from 0 and 1 (see r_value)
R_MARGIN_TEXT = "2^-60"
_DECIMAL = re.compile(r"[+-]?(\d+\.?\d*|\.\d+)(?:[eE]([+-]?\d+))?")
_POWER = re.compile(r"([+-]?\d+)\^([+-]?\d+)")
_FRACTION = re.compile(r"([+-]?\d+)/(\d+)")


def _named(name: str | None) -> str:
    return f"{name}: " if name else ""


ECHO = 200                            # characters of a word echoed in a message (a path fits)


def clip(message: str, width: int = ECHO) -> str:
    """``message`` with every word longer than ``width`` characters cut, saying how long it
    was: an error echoes what was typed, never 10 kB of it."""
    def cut(word: str) -> str:
        return word if len(word) <= width else f"{word[:width // 2]}…({len(word)} characters)"
    return " ".join(cut(w) for w in message.split(" "))


def exact(text: str, name: str | None = None) -> Fraction:
    """``text`` as an exact rational: 3/10, 0.3, 1e-1, 10^-1, -2 (a decimal read exactly).
    UsageError (one line, exit 2) otherwise, naming ``name``."""
    t = str(text).strip().replace("_", "")
    digits = sum(ch.isdigit() for ch in t)
    if digits > MAX_DIGITS:
        raise UsageError(f"{_named(name)}{clip(repr(text))} has {digits} digits: at most {MAX_DIGITS}")
    m, p, f = _DECIMAL.fullmatch(t), _POWER.fullmatch(t), _FRACTION.fullmatch(t)
    exponent = int(m.group(2) or 0) if m else int(p.group(2)) if p else 0
    if not (m or p or f):
        raise UsageError(f"{_named(name)}expected an exact number (3/10, 0.3, 1e-1 or 10^-1), got {text!r}")
    if abs(exponent) > MAX_EXPONENT:
        raise UsageError(f"{_named(name)}the exponent of {text!r} is beyond ±{MAX_EXPONENT}")
    if f and int(f.group(2)) == 0:
        raise UsageError(f"{_named(name)}{text!r} divides by zero")
    return Fraction(int(p.group(1))) ** exponent if p else Fraction(t)


def integer(text: str, name: str | None = None, least: int = 1) -> int:
    """``text`` as an integer at least ``least``: 10000, 1e4 or 10^4 (read exactly: 1.5e1
    is 15, 1e-1 is refused).  UsageError otherwise."""
    try:
        value = exact(text, name)
    except UsageError:
        value = None
    if value is None or value.denominator != 1 or value < least:
        kind = "a positive integer" if least == 1 else f"an integer ≥ {least}"
        raise UsageError(f"{_named(name)}expected {kind} (10000, 1e4 or 10^4), got {text!r}")
    return int(value)


def r_value(text: str, name: str | None = None) -> Fraction:
    """A restitution coefficient: an exact rational in [2^-60, 1 - 2^-60].  Closer to 0 or 1
    the certified enclosures would need more than their precision cap and float64 cannot
    tell r from 0 or 1 (1 - 10^-20 rounds to 1.0): refused with that reason (exit 2)."""
    r = exact(text, name)
    name = name or "r"
    if not 0 < r < 1:
        raise UsageError(f"{name} must lie in ]0,1[, got {text}")
    if not R_MARGIN <= r <= 1 - R_MARGIN:
        raise UsageError(f"{name} = {text} is within {R_MARGIN_TEXT} of {0 if r < R_MARGIN else 1}: not supported "
                         f"(the engines need r in [{R_MARGIN_TEXT}, 1 - {R_MARGIN_TEXT}])")
    return r


def r_end(text: str, name: str) -> Fraction:
    """An end of an r-range: 0, 1, or an r as :func:`r_value` reads it."""
    r = exact(text, name)
    return r if r in (0, 1) else r_value(text, name)


def r_range(lo: str, hi: str) -> tuple[Fraction, Fraction]:
    """``--r-range LO HI`` of the exact analyses: 0 ≤ LO < HI ≤ 1, ends as :func:`r_end`."""
    a, b = r_end(lo, "--r-range LO"), r_end(hi, "--r-range HI")
    if not a < b:
        raise UsageError(f"--r-range: need 0 ≤ LO < HI ≤ 1, got {lo} {hi}")
    return a, b


def r_grid(lo: str, hi: str, count: str) -> list[Fraction]:
    """``--r-range LO HI COUNT``: COUNT equally spaced exact r from LO to HI, ends included."""
    a, b, n = r_value(lo, "--r-range LO"), r_value(hi, "--r-range HI"), integer(count, "--r-range COUNT")
    if a > b or (a == b and n > 1):
        raise UsageError(f"--r-range LO HI COUNT needs LO < HI (or LO = HI with COUNT 1), got {lo} {hi} {count}")
    return [a] if n == 1 else [a + (b - a) * k / (n - 1) for k in range(n)]


def _typed(reader):
    """An argparse ``type`` from a reader: its UsageError becomes argparse's one-line error
    ("argument --collisions: expected a positive integer ...")."""
    def read(text: str):
        try:
            return reader(text)
        except UsageError as exc:
            raise argparse.ArgumentTypeError(str(exc)) from None
    read.__name__ = reader.__name__
    return read


def nonnegative(text: str, name: str | None = None) -> int:
    """An integer ≥ 0, read as :func:`integer` reads it."""
    return integer(text, name, least=0)


positive_int = _typed(integer)                 # --collisions, --orbits, --jobs, ...
count = _typed(nonnegative)                    # a number of things that may be 0 (atlas --data)
number = _typed(exact)                         # an exact rational (θ0, φ0, ...)
restitution = _typed(r_value)                  # --r, --trap


def add_jobs(p) -> None:
    """The --jobs option of the commands that run certificates."""
    p.add_argument("--jobs", type=positive_int, default=default_jobs(), metavar="N",
                   help="worker processes (default: all cores, here %(default)s; 1: one after another)")

def prepare_output(out: Path) -> Path:
    """Check that ``out`` and ``out/figures`` can be written, before any work."""
    from certify.run.files import ensure_writable
    ensure_writable(out)
    ensure_writable(out / "figures")
    return out


def kill_interrupts(command):
    """``command(args)`` run with SIGTERM raising KeyboardInterrupt as Ctrl-C does (``kill`` stops a long
    command like Ctrl-C, its workers too), the handler before restored when it returns or raises, so a
    caller of ``cli.main`` in-process (a test, a library) keeps its own.  Outside the main thread, where
    no handler can be set, the command runs as it is."""
    @functools.wraps(command)
    def run(args):
        if threading.current_thread() is not threading.main_thread():
            return command(args)
        before = signal.signal(signal.SIGTERM, signal.default_int_handler)
        try:
            return command(args)
        finally:
            signal.signal(signal.SIGTERM, signal.SIG_DFL if before is None else before)
    return run


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
