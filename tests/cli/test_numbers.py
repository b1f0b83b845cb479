"""One syntax for numbers in every command (certify/cli/options.py): integers 10000, 1e4,
10^4; exact rationals 3/10, 0.3, 1e-1; r in [2^-60, 1 - 2^-60], with a one-line reason and
exit code 2 for anything else, never an internal error."""
from __future__ import annotations

from fractions import Fraction

import pytest

from certify import cli
from certify.cli import options
from certify.errors import UsageError


@pytest.mark.parametrize("text, value", [("10000", 10000), ("1e4", 10000), ("10^4", 10000), ("1.5e1", 15),
                                         ("10_000", 10000)])
def test_one_reader_of_integers(text, value):
    assert options.integer(text) == value


@pytest.mark.parametrize("text", ["0", "-3", "1.5", "1e-1", "x", "", "1e99999", "3/2"])
def test_integers_refused_say_what_is_expected(text):
    with pytest.raises(UsageError, match=r"expected a positive integer \(10000, 1e4 or 10\^4\)"):
        options.integer(text)


@pytest.mark.parametrize("text, value", [("3/10", Fraction(3, 10)), ("0.3", Fraction(3, 10)),
                                         ("1e-1", Fraction(1, 10)), ("10^-1", Fraction(1, 10)),
                                         (".5", Fraction(1, 2)), ("-2", Fraction(-2)),
                                         ("1e-400", Fraction(1, 10 ** 400))])
def test_one_reader_of_exact_rationals(text, value):
    assert options.exact(text) == value


@pytest.mark.parametrize("text, says", [("3/0", "divides by zero"), ("0.3.1", "expected an exact number"),
                                        ("1e-99999", "exponent"), ("nan", "expected an exact number")])
def test_rationals_refused(text, says):
    with pytest.raises(UsageError, match=says):
        options.exact(text)


def test_r_is_bounded_away_from_0_and_1_with_the_limit_named():
    assert options.r_value("1e-18") == Fraction(1, 10 ** 18)          # above 2^-60 ≈ 8.7e-19
    for text, end in (("1e-400", 0), ("99999999999999999999/100000000000000000000", 1)):
        with pytest.raises(UsageError, match=f"within 2\\^-60 of {end}: not supported"):
            options.r_value(text)
    assert options.r_range("0", "1e-3") == (0, Fraction(1, 1000))     # the ends 0 and 1 themselves are fine
    with pytest.raises(UsageError, match="LO < HI"):
        options.r_range("0.5", "0.5")


def run(capsys, *argv):
    code = cli.main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


# The commands of issue 25, item 4: each was an "internal error" with exit code 1
@pytest.mark.parametrize("argv, says", [
    (["orbit", "abacbabcbcabcb", "--trap", "99999999999999999999/100000000000000000000"], "within 2^-60 of 1"),
    (["orbit", "abcb", "--r-range", "0", "1e-400"], "--r-range HI = 1e-400 is within 2^-60 of 0"),
    (["pattern", "abcb", "--r-range", "0", "1e-400"], "--r-range HI = 1e-400 is within 2^-60 of 0"),
    (["identify", "--r", "1e-400"], "within 2^-60 of 0"),
    (["identify", "--r", "0.99999999999999999999"], "within 2^-60 of 1"),
    (["simulate", "--r", "0.99999999999999999"], "rounds to 1.0 in float64"),
    (["simulate", "--r", "1e-310"], "within 2^-60 of 0"),
    (["particles", "--x", "0", "1", "2", "3", "--v", "1", "0", "0", "-1", "--r", "1e-400"], "within 2^-60 of 0"),
])
def test_valid_rationals_beyond_the_limits_are_refused_in_one_line(argv, says, capsys):
    code, out, err = run(capsys, *argv)
    assert code == 2 and out == "" and err.count("\n") == 1 and says in err, err


# Issue 25, item 11: the same numbers accepted, and refused, by every command
@pytest.mark.parametrize("argv", [
    ["simulate", "--r", "0.3", "--collisions", "0", "--orbits", "1"],
    ["identify", "--r", "0.3", "--collisions", "0"],
    ["particles", "--x", "0", "1", "2", "3", "--v", "1", "0", "0", "-1", "--r", "1/2", "--collisions", "0"],
    ["simulate", "--r", "0.3", "--keep", "0"],
    ["census", "--max-length", "0"],
])
def test_zero_is_refused_where_it_is_meaningless(argv, capsys):
    code, _, err = run(capsys, *argv)
    assert code == 2 and "expected a positive integer (10000, 1e4 or 10^4), got '0'" in err, err


def test_exponents_are_read_by_every_command(capsys):
    code, out, _ = run(capsys, "simulate", "--r", "1e-1", "--collisions", "1e2", "--orbits", "1", "--keep", "1e1")
    assert code == 0 and "1 value(s) of r × 1 orbit(s), 100 collisions at most, 10 kept" in out
    code, out, _ = run(capsys, "particles", "--x", "0", "1", "2", "3", "--v", "1e0", "0", "0", "-1",
                       "--r", "5e-1", "--collisions", "1e0")
    assert code == 0 and "1 collision done" in out
    code, out, _ = run(capsys, "orbit", "abcb", "--r-range", "1e-1", "5e-1")
    assert code == 0 and "abcb" in out
    code, out, err = run(capsys, "orbit", "abcb", "--trap", "1e-1")
    assert code == 1 and "r = 1/10" in out, err                 # read, and no attracting orbit there
