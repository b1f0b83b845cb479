"""certify.algebra.statements: the paper's printed conditions read whole, evaluated
on certified signs and numbers; a text the grammar does not read is an error."""
import flint
import pytest
import sympy as sp

from certify.algebra import Algebraic, lam
from certify.algebra import statements as S
from certify.algebra.statements import StatementError
from certify.algebra.trig import cφ, sφ

D, C, X = sp.symbols("D c X")
q = sp.Symbol("q", real=True)
R_STAR = Algebraic.roots(flint.fmpz_poly([41, -646, 3733, -14600, 42306, -78052, 42306, -14600, 3733, -646, 41]),
                         0, 1)[0]
R1 = Algebraic.surd(5, -2, 6)


# ---------------------------------------------------------------- relations
@pytest.mark.parametrize("text,truth", [
    ("Δ_cp < 0", {-1: True, 0: False, 1: False}),
    ("Δ_cp > 0", {-1: False, 0: False, 1: True}),
    ("Δ_cp ≤ 0", {-1: True, 0: True, 1: False}),
    ("Δ_cp ≥ 0", {-1: False, 0: True, 1: True}),
    ("Δ_cp = 0", {-1: False, 0: True, 1: False}),
    ("Δ_cp ≠ 0", {-1: True, 0: False, 1: True}),
    ("0 > Δ_cp", {-1: True, 0: False, 1: False}),
    ("-2*Δ_cp > 0", {-1: True, 0: False, 1: False}),
    ("Δ_cp/3 <= 0", {-1: True, 0: True, 1: False}),
])
def test_a_relation_is_evaluated_for_each_sign(text, truth):
    assert S.relation(text, {"Δ_cp": D}).truth(D) == truth


def test_the_operators_of_the_paper_and_ascii_are_the_same():
    for a, b in (("≤", "<="), ("≥", ">="), ("≠", "!="), ("=", "==")):
        assert S.relation(f"Δ_cp {a} 0", {"Δ_cp": D}).truth(D) == S.relation(f"Δ_cp {b} 0", {"Δ_cp": D}).truth(D)


def test_absolute_values_and_differences():
    rel = S.relation("|q| > 1", {"q": q})
    assert rel.holds({sp.Abs(q) - 1: 1}) and not rel.holds({sp.Abs(q) - 1: -1})
    assert S.relation("1 > |q|", {"q": q}).holds({sp.Abs(q) - 1: -1})
    t_c, t_b = sp.symbols("t_c t_b")
    names = {"t_c": t_c, "t_b": t_b}
    assert S.relation("t_c < t_b", names).holds({t_c - t_b: -1})
    assert not S.relation("t_c < t_b", names).holds({t_c - t_b: 1})
    assert S.relation("t_b < t_c", names).holds({t_c - t_b: 1})


def test_names_are_whole_tokens():
    """'c' does not match inside 'cos', 'cos(φ)' not inside "cos(φ')"."""
    rel = S.relation("cos(φ) > c", {"c": C, "cos(φ)": cφ})
    assert rel.members == (cφ, C)
    with pytest.raises(StatementError):
        S.relation("cos(φ') < 0", {"cos(φ)": cφ})


def test_trigonometric_conditions():
    names = {"cos(φ)": cφ, "sin(φ)": sφ}
    cos_pos, sin_pos = S.relation("cos(φ) > 0", names), S.relation("sin(φ) > 0", names)
    assert [cos_pos.holds({cφ: s, sφ: 1}) for s in (1, -1)] == [True, False]
    assert [sin_pos.holds({cφ: s, sφ: 1}) for s in (1, -1)] == [True, True]


def test_chains():
    rel = S.relation("0 < r < 5-2√6")
    assert len(rel.pairs()) == 2 and rel.sympy() == sp.And(sp.Lt(0, sp.Symbol("r")),
                                                              sp.Lt(sp.Symbol("r"), 5 - 2 * sp.sqrt(6)))


# ---------------------------------------------------------------- phrases
def test_comparatives_and_sign_words():
    t_c, t_b = sp.symbols("t_c t_b")
    rel = S.relation("t_c is smaller than t_b", {"t_c": t_c, "t_b": t_b})
    assert rel.pairs() == [(t_c, "<", t_b)]
    assert S.relation("t_c is then larger than t_b", {"t_c": t_c, "t_b": t_b}).pairs() == [(t_c, ">", t_b)]
    assert S.relation("negative", {"X": X}, subject="X").truth(X) == {-1: True, 0: False, 1: False}
    assert S.relation("X is non-negative", {"X": X}).truth(X) == {-1: False, 0: True, 1: True}
    assert S.relation("below 1/2", {"X": X}, subject="X").pairs() == [(X, "<", sp.Rational(1, 2))]


def test_comparisons_of_algebraic_numbers():
    root = Algebraic.roots(flint.fmpz_poly([5, -35, -86, 66, -15, 1]), 0, 1)[0]     # ≈ 0.11376
    assert S.relation("larger than 5-2√6", {"ρ": root}, subject="ρ").compare()
    assert not S.relation("smaller than 5-2√6", {"ρ": root}, subject="ρ").compare()
    assert not S.relation("above (7-2√10)/3 - 1/10", {"ρ": root}, subject="ρ").compare()     # ≈ 0.12515
    assert not S.relation("above 1/8", {"ρ": root}, subject="ρ").compare()
    assert S.relation("r* > 5-2√6", {"r*": R_STAR}).compare()


# ---------------------------------------------------------------- ranges
def test_ranges_of_r():
    st = S.statement("Δ_cp ≥ 0 for r > r*", {"Δ_cp": D, "r*": R_STAR})
    assert st.range.lo == R_STAR and st.range.hi == 1 and str(st.range) == "r* < r < 1"
    st = S.statement("λ > 0 for 0 < r < 5-2√6", {"λ": lam})
    assert st.range.lo == 0 and st.range.hi == R1 and str(st.range) == "0 < r < 5-2√6"
    assert str(S.statement("c > 0", {"c": C}).range) == "0 < r < 1"


def test_signs_over_a_range_include_the_roots_inside():
    ivs = [(Algebraic.rational(0), R1, -1), (R1, Algebraic.rational(1), -1)]      # a double root at 5-2√6
    assert S.range_of("0 < r < 1").signs(ivs) == {-1, 0}
    assert S.range_of("r < 5-2√6").signs(ivs) == {-1}
    assert S.range_of("r > 5-2√6").signs(ivs) == {-1}


def test_holds_on_a_sign_table():
    rel = S.relation("λ > 0", {"λ": lam})
    assert rel.holds_on(lam, {1}) and not rel.holds_on(lam, {1, 0})
    assert not rel.holds_on(lam, set()) and not rel.holds_on(lam, {1, "missing"}) and not rel.holds_on(lam, {None})


def test_counts_extents_branches_products_and_word_rules():
    assert S.count("infinitely many collisions") == S.Count(True, "collisions")
    assert S.count("finitely many collisions") == S.Count(False, "collisions")
    assert S.extent("a prefix") == S.extent("the beginning") == "prefix" and S.extent("the whole") == "whole"
    assert [S.branch(t) for t in ("upper", "middle", "lower", "lowest")] == [0, 1, 2, 2]
    assert S.product_equation("AC = CA") == S.ProductEquation("AC", True, "CA")
    assert S.product_equation("AC≠CA") == S.ProductEquation("AC", False, "CA")
    rule = S.word_rule("c_k = a, c_{k+1} = c ⇒ c_{k+2} ≠ a")
    assert rule.premises == ((0, "a", True), (1, "c", True)) and rule.conclusions == ((2, "a", False),)
    assert rule.tally(["acbaca"]) == (2, 1)                  # acb keeps the rule, aca breaks it
    window = S.word_rule("c_k = b ⇒ c_{k+2} = b or c_{k+3} = b")
    assert window.tally(["babcbacab"]) == (3, 2) and window.reach == 3


# ---------------------------------------------------------------- what is not read
@pytest.mark.parametrize("text", [
    "Δ_cp << 0",                  # an empty member
    "Δ_cp",                       # no relation
    "Δ_cp < 0 for r ≤ r*",        # a closed end
    "Δ_cp < 0 for r > 2",         # an empty range
    "Δ_cp < 0 for r < r* for r > 0",
    "Δ_cp < 0 for Δ_cp < 1",      # a range not in r
    "μ < 0",                      # an unknown name
    "foo(r) < 0",                 # an unknown function
    "sin(r) < 0",                 # a function the caller did not declare
    "2r < 1",                     # implicit multiplication
    "|Δ_cp < 0",                  # an unbalanced bar
    "S < 0",                      # a SymPy name that is not an expression
    "huge",                       # not a sign word
    "larger than",                # a phrase without its object
])
def test_unread_text_is_an_error(text):
    with pytest.raises(StatementError, match="cannot read"):
        S.statement(text, {"Δ_cp": D, "r*": R_STAR})


def test_a_phrase_without_subject_is_an_error():
    with pytest.raises(StatementError, match="without its subject"):
        S.relation("negative", {"X": X})


@pytest.mark.parametrize("reader,text", [
    (S.count, "infinitely many orbits"), (S.count, "many collisions"), (S.count, "infinitely collisions"),
    (S.extent, "a part"), (S.branch, "central"), (S.product_equation, "AC = CD"),
    (S.product_equation, "AC CA"), (S.word_rule, "c_k = a, c_{k+1} = c"), (S.word_rule, "c_k = d ⇒ c_{k+1} = b"),
    (S.word_rule, "c_k = b ⇒ c_{k+2} = b and c_{k+3} = b"),
])
def test_unread_phrases_are_errors(reader, text):
    with pytest.raises(StatementError, match="cannot read"):
        reader(text)


def test_unevaluable_relations_are_errors():
    with pytest.raises(StatementError, match="cannot evaluate"):
        S.relation("Δ_cp < 1", {"Δ_cp": D}).holds({D: -1})
    with pytest.raises(StatementError, match="cannot evaluate"):
        S.relation("X < 0", {"X": X}).holds({D: -1})
    with pytest.raises(StatementError, match="cannot evaluate"):
        S.relation("r < 1/2").compare()
    with pytest.raises(StatementError, match="not certified"):
        S.relation("X < 0", {"X": X}).holds({X: "?"})


def test_stated_corrections():
    assert S.corrected("c > 0 for r > 5-2√6", "c > 0", "c < 0") == "c < 0 for r > 5-2√6"
    assert S.corrected("c ≥ 0 for r > 5-2√6", "c > 0", "c < 0") is None
