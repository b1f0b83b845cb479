"""`certify identify`: the simulator's periodic words, certified by `certify orbit`
(certify/run/identify.py)."""
import json
from fractions import Fraction

import flint
import pytest

from certify import cli
from certify.algebra.algebraic import Algebraic
from certify.run import identify as ident

COMPLEX = "abacbabcbcabcb"


def test_period_of_reads_the_shortest_period_after_a_transient():
    assert ident.period_of("cbcabacb" + "abcb" * 50) == "abcb"
    assert ident.period_of("ab" * 3 + COMPLEX * 20) == COMPLEX            # not a multiple of the period
    assert ident.period_of("abcb" * 5 + "acbc" * 5 + "abcb" * 3) is None      # the last half is not periodic
    assert ident.period_of(COMPLEX * 3) is None                                  # fewer than 4 periods in the last half


def _at(r):
    return Algebraic.rational(flint.fmpq(r.numerator, r.denominator))


def test_window_at_says_which_window_or_why_not():
    res = ident.orbit_analysis(COMPLEX)
    window, why = ident.window_at(res, _at(Fraction(3, 10)))
    assert window["pair"] == "complex" and window["branch"] == "upper" and "not a collapse" in why
    window, why = ident.window_at(res, _at(Fraction(1, 20)))         # middle branch: a saddle there
    assert window is None and "saddle" in why
    window, why = ident.window_at(res, _at(Fraction(1, 5)))          # outside every set
    assert window is None and "no periodic orbit" in why


def test_the_paper_orbits_at_three_tenths_settle_on_the_certified_complex_attractor():
    """The first orbit of the paper's grid at r = 3/10 settles on abacbabcbcabcb, whose
    attracting window, certified exactly, contains 3/10."""
    (x,) = ident.identify([Fraction(3, 10)], orbits=1, collisions=2000)
    assert x.word == COMPLEX and x.window is not None and x.window["pair"] == "complex"
    assert Fraction(x.window["lo"]["interval"][1]) < Fraction(3, 10) and x.window["hi"]["exact"] == "1"
    doc = json.loads(ident.json_text([x]))
    (o,) = doc["orbits"]
    assert {"r", "theta0", "phi0", "word", "window"} <= set(o) and o["r"] == "3/10"


def test_ab_cb_orbit_is_identified_in_its_window():
    (x,) = ident.identify([Fraction(1, 10)], orbits=1, collisions=2000)
    assert x.compact == "(ab)^3(cb)^3" and x.window["branch"] == "lower" and x.window["pair"] == "real"


@pytest.mark.parametrize("argv, says", [
    (["identify"], "--r R"),
    (["identify", "--r", "0.3", "--r-range", "0.1", "0.2", "3"], "--r R"),
    (["identify", "--r", "2"], "]0,1["),
    (["identify", "--r", "x"], "expected an exact number"),
    (["identify", "--r-range", "0.2", "0.1", "3"], "LO < HI"),
    (["identify", "--r-range", "0.1", "0.2", "z"], "COUNT"),
    (["identify", "--r", "0.3", "--orbits", "0"], "positive"),
    (["identify", "--section5", "--r", "0.3"], "--section5"),
    (["identify", "--r", "0.3", "--out", "somewhere"], "--out"),
])
def test_bad_input_is_one_line_and_exit_2(argv, says, capsys):
    assert cli.main(argv) == 2
    out, err = capsys.readouterr()
    assert out == "" and err.count("\n") == 1 and says in err, err
