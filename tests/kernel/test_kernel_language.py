"""The statement language (certify_kernel.language): the trees its parser builds, the precedence
and associativity a statement's reader relies on (5-2√6 is 5 − 2·√6, −r² is −(r²), 2^3^2 is
2^(3^2)), and the one-line Syntax errors on text that is not a formula."""
from __future__ import annotations

import pytest

from certify_kernel.language import Syntax, parse, tokens

N = lambda s: ("num", s)           # noqa: E731
V = lambda s: ("name", s)          # noqa: E731


def B(op, a, b):
    return ("bin", op, a, b)


@pytest.mark.parametrize("text, tree", [
    ("1 + 2*r^3", B("+", N("1"), B("*", N("2"), B("^", V("r"), N("3"))))),
    ("1 - 2 - 3", B("-", B("-", N("1"), N("2")), N("3"))),                 # left-associative
    ("2^3^2", B("^", N("2"), B("^", N("3"), N("2")))),                     # ^ right-associative
    ("-r^2", ("neg", B("^", V("r"), N("2")))),                             # −(r²), not (−r)²
    ("5-2√6", B("-", N("5"), B("*", N("2"), ("sqrt", N("6"))))),           # 5 − 2·√6
    ("(7-2√10)/3", B("/", B("-", N("7"), B("*", N("2"), ("sqrt", N("10")))), N("3"))),
    ("√(4+3√2)", ("sqrt", B("+", N("4"), B("*", N("3"), ("sqrt", N("2")))))),
    ("√2/2", B("/", ("sqrt", N("2")), N("2"))),
    ("r/2*λ", B("*", B("/", V("r"), N("2")), V("λ"))),
    ("0.11384", N("0.11384")),
    ("M[1,2]", ("index", V("M"), (N("1"), N("2")))),
    ("v[3]", ("index", V("v"), (N("3"),))),
    ("(1, r, 3)", ("tuple", (N("1"), V("r"), N("3")))),
    ("[[1, 2], [3, r]]", ("matrix", ((N("1"), N("2")), (N("3"), V("r"))))),
    ("u ∧ v · w", B("·", B("∧", V("u"), V("v")), V("w"))),
    ("det(B*C)", ("call", "det", (B("*", V("B"), V("C")),))),
    ("]0, 1[", ("interval", N("0"), N("1"), False, False)),
    ("[0, 1]", ("interval", N("0"), N("1"), True, True)),
    ("]0, 1]", ("interval", N("0"), N("1"), False, True)),
    ("[r1, ∞[", ("interval", V("r1"), ("const", "∞"), True, False)),
    ("]0, π/2[", ("interval", N("0"), B("/", V("π"), N("2")), False, False)),     # π reads as a name
    ("{}", ("finite", ())),
    ("{1/2, r0}", ("finite", (B("/", N("1"), N("2")), V("r0")))),
])
def test_expressions(text, tree):
    assert parse(text) == tree


@pytest.mark.parametrize("text, tree", [
    ("a < b ≤ c", ("cmp", ("<", "≤"), (V("a"), V("b"), V("c")))),
    ("r − 1 <= 2", ("cmp", ("≤",), (B("-", V("r"), N("1")), N("2")))),     # − and <= are aliases
    ("a != b", ("cmp", ("≠",), (V("a"), V("b")))),
    ("x ≈ 0.22515", ("cmp", ("≈",), (V("x"), N("0.22515")))),
    ("P ~ Q", ("cmp", ("~",), (V("P"), V("Q")))),
    ("S ⊆ T", ("cmp", ("⊆",), (V("S"), V("T")))),
    ("1/2 in ]0, 1[", ("cmp", ("in",), (B("/", N("1"), N("2")), ("interval", N("0"), N("1"), False, False)))),
    ("not a and b", ("and", ("not", V("a")), V("b"))),
    ("a or b and c", ("or", V("a"), ("and", V("b"), V("c")))),
    ("a and b implies c", ("implies", ("and", V("a"), V("b")), V("c"))),
    ("a implies b iff c", ("iff", ("implies", V("a"), V("b")), V("c"))),
    ("E = F mod P", ("mod", ("cmp", ("=",), (V("E"), V("F"))), V("P"))),
    ("divides(P0, disc(cpM))", ("call", "divides", (V("P0"), ("call", "disc", (V("cpM"),))))),
    ("forall r in ]0, 1[, λ = upper(P): λ > 0",
     ("forall", (("r", "in", ("interval", N("0"), N("1"), False, False)), ("λ", "=", ("call", "upper", (V("P"),)))),
      ("cmp", (">",), (V("λ"), N("0"))))),
    ("forall r in ]0, 1[, x in fixed(a, b, c, d): not x > 0",
     ("forall", (("r", "in", ("interval", N("0"), N("1"), False, False)),
                 ("x", "in", ("call", "fixed", (V("a"), V("b"), V("c"), V("d"))))),
      ("not", ("cmp", (">",), (V("x"), N("0")))))),
    ("{r in ]0, 1[ : r > 1/2}",
     ("setof", (("r", "in", ("interval", N("0"), N("1"), False, False)),),
      ("cmp", (">",), (V("r"), B("/", N("1"), N("2")))))),
    ("{r in ]0, 1[ : changes(E)} = {r0}",
     ("cmp", ("=",), (("setof", (("r", "in", ("interval", N("0"), N("1"), False, False)),),
                               ("call", "changes", (V("E"),))), ("finite", (V("r0"),))))),
])
def test_formulas(text, tree):
    assert parse(text) == tree


def test_tokens_keep_names_with_digits_and_primes_whole():
    assert tokens("r1 + P0 - x′ * e_x") == [("name", "r1"), ("op", "+"), ("name", "P0"), ("op", "-"),
                                           ("name", "x′"), ("op", "*"), ("name", "e_x"), ("end", "")]
    assert [k for k, _ in tokens("forall r in I : F")][:3] == ["op", "name", "op"]


@pytest.mark.parametrize("text, says", [
    ("1 +", "unexpected"),
    ("r $ 2", "unexpected character '$'"),
    ("1 2", "unexpected '2'"),
    ("(1, 2", "expected ',' or ')'"),
    ("]0, 1", "an interval ends with [ or ]"),
    ("]0 1[", "expected ','"),
    ("[[1, 2], 3]", "a matrix is a list of rows"),
    ("forall 1 in ]0, 1[: r > 0", "a binder starts with a variable"),
    ("forall r < 1: r > 0", "a binder is 'NAME in SET' or 'NAME = EXPR'"),
    ("forall r in ]0, 1[ r > 0", "expected ':'"),
    ("{r in ]0, 1[ : r > 0", "expected '}'"),
    ("M[1, 2", "expected ']'"),
    ("", "unexpected 'end'"),
])
def test_syntax_errors_are_one_line_and_say_where(text, says):
    with pytest.raises(Syntax) as err:
        parse(text)
    assert says in str(err.value)
    assert "\n" not in str(err.value)


def test_nothing_of_the_text_is_run_as_python():
    for text in ("__import__('os').system('true')", "eval('1')", "r.__class__"):
        with pytest.raises(Syntax):
            parse(text)
