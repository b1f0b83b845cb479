"""The Python API (certify/api.py, docs/api.md): its functions give what the engine's give, bad
arguments are one-line ValueErrors naming the allowed values, and the rich display of a number or a
window says the number exactly (a minimal polynomial and an interval that isolates it)."""
import doctest
import re
from fractions import Fraction

import flint
import pytest
import sympy as sp

from certify import api
from certify.algebra import Algebraic
from certify.patterns import analyse, island_theorem
from certify.patterns.pattern import Window
from certify.run import identify as identification

ROOT_DOC = __import__("pathlib").Path(__file__).resolve().parent.parent / "docs" / "api.md"


@pytest.fixture(scope="module")
def family2():
    return analyse("(ab)^2(cb)^2")


def test_a_branch_by_name_is_refused_with_the_allowed_values(family2):
    """``intervals('stable', 'upper')`` gave [] silently: now a ValueError naming 0, 1, 2."""
    with pytest.raises(ValueError, match=r"branch must be None .* 0 \(upper\), 1 \(middle\), 2 \(lower\), not 'upper'"):
        family2.intervals("stable", "upper")
    for bad in (3, -1, True, 0.0):
        with pytest.raises(ValueError, match="branch must be"):
            family2.intervals("stable", bad)
    with pytest.raises(ValueError, match="branch must be"):
        family2.points("feasible", "lower")


def test_a_bad_stage_is_a_value_error_naming_the_stages(family2):
    """A bad stage raised a bare KeyError."""
    for method in (family2.intervals, family2.points):
        with pytest.raises(ValueError, match="stage must be one of 'exists', 'feasible', 'stable', not 'Stable'"):
            method("Stable")
    with pytest.raises(ValueError, match="stage must be one of"):
        api.windows("ab", "attracting")


def test_a_window_is_the_tuple_it_was(family2):
    """Window keeps the (branch, fixed point, lo, hi) tuple of every caller, with names."""
    [w] = family2.intervals("stable", 0)
    branch, point, lo, hi = w
    assert isinstance(w, Window) and w == (branch, point, lo, hi)
    assert (w.branch, w.fixed_point, w.lo, w.hi) == (0, "x₊", lo, hi) and w.branch_name == "upper"
    assert family2.intervals("stable", 1) == [] and family2.intervals("stable") == [w]


def _from_latex(text: str) -> Algebraic:
    """The number a LaTeX display names: its polynomial in r and its interval, read back."""
    m = re.fullmatch(r"\\text\{the root of \} (.+) \\text\{ in \} \\left\]([0-9.]+), ([0-9.]+)\\right\[ "
                     r"\\approx ([0-9.]+)", text)
    assert m, text
    r = sp.Symbol("r")
    expr = sp.sympify(m.group(1).replace("{", "(").replace("}", ")").replace("^", "**").replace(" r", "*r"),
                      locals={"r": r})
    coeffs = [int(c) for c in reversed(sp.Poly(expr, r).all_coeffs())]
    lo, hi = (flint.fmpq(Fraction(x).numerator, Fraction(x).denominator) for x in m.group(2, 3))
    return Algebraic(flint.fmpz_poly(coeffs), lo, hi)


@pytest.mark.parametrize("number", [Algebraic.surd(3, -2, 2), Algebraic.surd(5, -2, 6),
                                    Algebraic.roots(flint.fmpq_poly([5, -50, 107, -188, 107, -50, 5]), 0, 1)[0]])
def test_the_latex_of_a_number_names_it_exactly(number):
    """Read back, the polynomial and interval of the display isolate the number itself, and the
    digits are its own (a display from the midpoint or another root would fail)."""
    text = number.latex()
    assert _from_latex(text) == number
    assert text.endswith(number.digits(12))
    assert number._repr_latex_() == f"${text}$" and number._repr_markdown_() == f"${text}$"


def test_the_latex_of_a_rational_is_its_fraction():
    assert Algebraic.rational(flint.fmpq(-3, 7)).latex() == r"- \frac{3}{7}"
    assert Algebraic.rational(flint.fmpq(0)).latex() == "0"


def test_a_window_shows_its_ends_exactly(family2):
    [w] = family2.intervals("stable")
    latex = w._repr_latex_()
    assert latex.startswith("$$\\begin{aligned}") and "upper branch" in latex
    assert w.lo.latex() in latex and w.hi.latex() in latex
    md = w._repr_markdown_()
    assert f"$r_1 = {w.lo.latex()}$" in md and f"$r_2 = {w.hi.latex()}$" in md


def test_analyse_and_windows_are_the_engines(family2):
    res = api.analyse("(ab)^2(cb)^2")
    assert res.to_json() == family2.to_json()
    assert res._repr_markdown_() == family2.markdown()
    assert api.windows("(ab)^2(cb)^2") == family2.intervals("stable")
    hi = api.windows("(ab)^2(cb)^2")[0].hi                 # 3 − 2√2, computed here by SymPy
    assert abs(sp.Float(hi.digits(30), 40) - sp.N(3 - 2 * sp.sqrt(2), 40)) < sp.Float(10) ** -28
    assert api.windows("abcb", "feasible", 2) == analyse("abcb").intervals("feasible", 2)
    lo, hi = Fraction(1, 10), Fraction(3, 20)
    assert api.analyse("(ab)^2(cb)^2", "1/10", "0.15").interval == (flint.fmpq(1, 10), flint.fmpq(3, 20))
    assert api.windows("(ab)^2(cb)^2", lo=lo, hi=hi)[0].hi == Algebraic.rational(flint.fmpq(3, 20))


@pytest.mark.parametrize("call, message", [
    (lambda: api.analyse("abd"), "invalid pattern word 'abd'"),
    (lambda: api.analyse("abcb", "1/2", "1/3"), "need 0 ≤ LO < HI ≤ 1"),
    (lambda: api.island(2), r"r must lie in \]0,1\[, got 2"),
    (lambda: api.island("one half"), "expected an exact number"),
    (lambda: api.identify("1/2", orbits=0), "orbits must be a positive integer"),
    (lambda: api.identify("1/2", collisions=2.5), "collisions must be a positive integer"),
    (lambda: api.certificate("Z9"), "unknown claim id 'Z9'"),
    (lambda: api.certificate("T25"), "'T25' names several certificates: one of T25.1"),
])
def test_bad_arguments_are_one_line_value_errors(call, message):
    with pytest.raises(ValueError, match=message) as info:
        call()
    assert "\n" not in str(info.value)


def test_island_is_the_theorem_at_r():
    for r in ("1/2", Fraction(1, 2), 0.5, "0.5"):
        T = api.island(r)
        assert T.r == flint.fmpq(1, 2) and T.c_max == island_theorem.theorem(flint.fmpq(1, 2)).c_max
    assert api.island("1/10").elliptic is False
    md = api.island("1/10")._repr_markdown_()
    assert "not elliptic" in md and "✓" in md and "every step proved" not in md


def test_identify_is_the_commands():
    [x] = api.identify("3/10", orbits=1, collisions=20_000)
    [y] = identification.identify([Fraction(3, 10)], orbits=1, collisions=20_000)
    assert x.to_json() == y.to_json()
    assert f"**{x.cls}**" in x._repr_markdown_()


def test_one_certificate_runs_as_the_runner_runs_it():
    c = api.certificate("t16")
    assert c.certificate.id == "T16" and c.status == c.outcome.status == "ERRATUM"
    md = c._repr_markdown_()
    assert md.startswith('### <a id="cert-t16"></a>T16 — ERRATUM') and "✗" in md


def test_docs_api_examples_use_every_function():
    """docs/api.md (collected as a doctest by the default test command) shows each function of the API."""
    examples = doctest.DocTestParser().get_examples(ROOT_DOC.read_text())
    sources = "".join(e.source for e in examples)
    for name in ("analyse", "windows", "island", "identify", "certificate"):
        assert f"api.{name}(" in sources, name
    assert "_repr_markdown_()" in sources and ".latex()" in sources


def test_family_window_joins_the_engine_and_the_theorem_and_its_upper_end_is_where_n_theta_is_pi():
    """family_window(7) (the engine) lies above family_window(8) (the theorem), disjoint (L5), and
    the theorem's upper end r_8 is the root in ]0, 1[ of r² − (6 + 8cos(π/8))r + 1, found here by
    mpmath independently of the tool."""
    import mpmath
    lo7, hi7 = api.family_window(7)
    lo8, hi8 = api.family_window(8)
    assert lo8 < hi8 < lo7 < hi7
    mpmath.mp.dps = 40
    c = 6 + 8 * mpmath.cos(mpmath.pi / 8)
    root = (c - mpmath.sqrt(c * c - 4)) / 2
    assert abs(mpmath.mpf(hi8.digits(30)) - root) < mpmath.mpf(10) ** -28


def test_analyse_refuses_a_family_word_beyond_n0_over_the_whole_range_at_once():
    """(ab)^31(cb)^31 over ]0, 1[ is hours of engine work: a ValueError naming family_window, at once."""
    with pytest.raises(ValueError, match=r"family_window\(31\)"):
        api.analyse("(ab)^31(cb)^31")
    with pytest.raises(ValueError, match="integer ≥ 2"):
        api.family_window(True)
