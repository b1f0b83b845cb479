"""What formulas mean (certify_kernel.evaluate): the kernel's own objects (the collision
matrices from the collision law, l. 160-166, as the paper prints them at l. 215-229; words;
det, charpoly, cofactors; resultants and discriminants in λ), identities modulo the circles and
modulo a polynomial, ``~``, sets, and the decisions over an interval of r: forall and {r in I :
F} on every piece, eigenvalue branches, fixed points of a Möbius map, changes().  Each case is a
statement decided by the kernel: "verified", "failed: ..." (the kernel decides the opposite, or
the formula is not one of the language) or "not verified: ..." (undecided)."""
from __future__ import annotations

import pytest

from certify_kernel.evaluate import collision, equal, expand_word, word_matrix
from certify_kernel.values import Undefined
from tests.kernel.kernel_support import outcome, repository_statements, truth_of, value_of

FALSE = "failed: Z9.1: the statement file says it holds; the kernel finds it false"


def verified(formula: str, **kw) -> bool:
    return outcome(formula, **kw) == "verified"


def refuted(formula: str, **kw) -> bool:
    """The kernel finds the formula false: a statement that it holds fails, one that it is
    refuted is verified."""
    return outcome(formula, **kw).startswith(FALSE) \
        and outcome(formula, verdict="refuted", **kw) == "verified"


# ------------------------------------------------------------------ the kernel's objects

def test_the_collision_matrices_are_the_printed_ones():
    """A, B, C built from the collision law (l. 160-166) are the matrices printed at l. 215-229."""
    assert verified("A = [[-r, 0, 0], [(1+r)/2, 1, 0], [0, 0, 1]]")
    assert verified("B = [[1, (1+r)/2, 0], [0, -r, 0], [0, (1+r)/2, 1]]")
    assert verified("C = [[1, 0, 0], [0, 1, (1+r)/2], [0, 0, -r]]")
    assert verified("A*C = C*A")                                          # l. 240
    assert refuted("A*B = B*A")
    assert verified("A*e_x = (-r, (1+r)/2, 0)")
    assert collision(0).n == 3


def test_words_and_their_matrices():
    assert expand_word("(ab)^3(cb)^2") == "abababcbcb"
    assert expand_word("a(bc)^2") == "abcbc"
    assert verified("word(ababcb) = B*C*B*A*B*A")                         # M_w = K_cn ··· K_c1 (l. 257)
    assert refuted("word(ababcb) = A*B*A*B*C*B")
    assert verified("word(ab) * word(cb) = word(cbab)")
    assert equal(word_matrix(""), value_of("I"))
    for bad in ("abd", "(ab", "ab)"):
        with pytest.raises(Undefined):
            word_matrix(bad)


@pytest.mark.parametrize("formula", [
    "det(A) = -r", "det(B*C*B*A*B*A) = r^6", "charpoly(A) = (λ + r)*(λ - 1)^2",
    "transpose(cof(A))*A = det(A)*I", "transpose(transpose(B)) = B",
    "charpoly([[0, 1], [-r, 0]]) = λ^2 + r",
    "resultant(λ - r, λ^2 - 2) = r^2 - 2", "resultant(λ^2 - 2, λ - r) = r^2 - 2",
    "disc(λ^2 - r) = 4*r", "disc(λ^3 - r) = -27*r^2", "disc(r*λ^2 + λ + 1) = 1 - 4*r",
    "coeff(λ^3 - 2*r*λ + 5, 1) = -2*r", "coeff(λ^3 - 2*r*λ + 5, 0) = 5", "coeff(charpoly(A), 3) = 1",
    "sqfree((r - 1)^2*(r + 2)) ~ (r - 1)*(r + 2)",
    "numerator((r + 1)/(r - 1)) = r + 1", "denominator((r + 1)/(r - 1)) = r - 1",
    "e_x ∧ e_y = e_z", "cross((1, 2, 3), (4, 5, 6)) = (-3, 6, -3)", "(1, 2, 3) · (4, 5, 6) = 32",
    "dot(e_x, e_x + e_y) = 1", "(1, r) + (r, 1) = (1 + r, 1 + r)", "2*(1, r) = (2, 2*r)",
    "[[1, 2], [3, 4]] * (1, 1) = (3, 7)", "[[1, 2], [3, 4]]^2 = [[7, 10], [15, 22]]",
])
def test_objects(formula):
    assert verified(formula), outcome(formula)


@pytest.mark.parametrize("formula", [
    "det(A) = r", "disc(λ^2 - r) = -4*r", "resultant(λ - r, λ^2 - 2) = r^2 + 2", "e_x ∧ e_y = -e_z",
    "coeff(λ^3 - 2*r*λ + 5, 1) = 2*r", "(1, 2, 3) · (4, 5, 6) = 31",
])
def test_objects_wrongly_stated_are_refuted(formula):
    assert refuted(formula)


@pytest.mark.parametrize("formula, says", [
    ("word(abd) = I", "'d' is not a collision"), ("A[4,1] = 0", "an entry out of range"),
    ("det([[1, 2, 3], [4, 5, 6]]) = 0", "not square"), ("M = I", "M is not defined"),
    ("frobnicate(A) = I", "frobnicate() is not a function"), ("root(r^2 - 2, [-2, 2]) = √2", "2 roots"),
    ("forall r in ]0, 1[: u > 0", "free variables ['u']"), ("forall r in ]0, 1[: λ > 0", "λ is free"),
    ("forall r in ]0, 1[, λ = middle(λ^2 - r): λ > 0", "middle() is the middle one of three"),
    ("λ^2 = r mod (2*λ^2 - r*λ^2)", "not monic"), ("1/3 ≈ 1/3", "printed decimal"),
    ("divides(0, r)", "divides(0, Q)"),
])
def test_what_is_not_a_formula_fails_with_a_message(formula, says):
    got = outcome(formula)
    assert got.startswith("failed: Z9.1 (test:1): ") and says in got, got


# ------------------------------------------------------------------ identities

def test_identities_modulo_the_circles():
    assert verified("cos(θ)^2 + sin(θ)^2 = 1")
    assert verified("tan(θ)*cos(θ) = sin(θ)")
    assert verified("cos(θ)^4 - sin(θ)^4 = cos(θ)^2 - sin(θ)^2")
    assert verified("(cos(θ)*cos(φ) - sin(θ)*sin(φ))^2 + (sin(θ)*cos(φ) + cos(θ)*sin(φ))^2 = 1")
    assert refuted("cos(θ)^2 = 1")
    assert refuted("cos(θ)^2 + sin(φ)^2 = 1")                              # two angles, two circles


def test_identities_modulo_a_polynomial_hold_on_its_roots():
    cp = "(λ^3 - λ^2/64*(r^6 - 10*r^5 + 23*r^4 - 44*r^3 + 15*r^2 - 74*r + 25) " \
         "+ λ/64*(25*r^6 - 74*r^5 + 15*r^4 - 44*r^3 + 23*r^2 - 10*r + 1) - r^6)"        # l. 335-339
    lets = {"M": "B*C*B*A*B*A", "cp": cp}
    assert verified("charpoly(M) = cp", lets=lets)
    assert verified("λ^3 = λ^3 - cp mod cp", lets=lets)                    # Cayley: λ³ ≡ λ³ − cp(λ)
    assert refuted("λ^3 = r^6 mod cp", lets=lets)
    assert refuted("λ^3 = λ^3 - cp", lets=lets)                            # not an identity without mod
    assert verified("λ^4 = λ*(λ^3 - cp) mod cp", lets=lets)
    assert verified("λ^2 = r mod (λ^2 - r)")
    assert verified("λ^2 = r mod (2*λ^2 - 2*r)")                           # monic up to a constant
    assert refuted("λ^3 = r mod (λ^2 - r)")
    assert verified("λ^3 = r*λ mod (λ^2 - r)")


def test_proportional():
    assert verified("2*r^2 - 2 ~ r^2 - 1")
    assert verified("(2, 4*r) ~ (1, 2*r)")
    assert refuted("r^2 - 1 ~ r^2 + 1")
    assert refuted("(r, 2*r) ~ (1, 2)")                                    # k = r is not a constant
    assert refuted("(2, 4) ~ (1, 3)")
    assert refuted("0 ~ 0")                                                # k ≠ 0 exists for no pair of zeros


# ------------------------------------------------------------------ numbers and sets

@pytest.mark.parametrize("formula", [
    "count(r^2 - 2, ]0, 2[) = 1", "count(r^2 - 2, ]-∞, ∞[) = 2", "count((r - 1)^2, [0, 2]) = 1",
    "count(r - 1, ]0, 1[) = 0", "count(r - 1, ]0, 1]) = 1", "root(r^2 - 2, [0, 2]) = √2",
    "divides(r - 1, r^3 - 1)", "{1/2} ⊆ ]0, 1[", "1 in ]0, 1]", "sup([0, 1/2]) = 1/2", "inf(]1/3, 1[) = 1/3",
    "{} = {}", "{1/2, 1/3} = {1/3, 1/2}", "[0, 1/2] ⊆ [0, 1]", "5-2√6 in ]0, 1[",
])
def test_numbers_and_sets(formula):
    assert verified(formula), outcome(formula)


@pytest.mark.parametrize("formula", [
    "count(r^2 - 2, ]0, 2[) = 2", "divides(r - 2, r^3 - 1)", "1 in ]0, 1[", "[0, 1] = [0, 1/2]",
    "]0, 1] ⊆ ]0, 1[", "{1/2} = {1/3}", "5-2√7 ≈ 0.10102",
])
def test_numbers_and_sets_refuted(formula):
    assert refuted(formula)


# ------------------------------------------------------------------ forall and {r in I : F}

@pytest.mark.parametrize("formula", [
    "forall r in ]0, 1[: r > 0 and r < 1",
    "forall r in ]0, 1[: (r - 1/2)^2 ≥ 0",
    "forall r in ]0, 1[: r < 1/2 or r ≥ 1/2",
    "forall r in ]0, 1[: r > 1/2 implies r > 1/4",
    "forall r in ]0, 1[: r < 1/2 iff not r ≥ 1/2",
    "forall r in ]0, 1[: r ≠ 2",
    "forall r in [1/2, 1/2]: r = 1/2",
    "forall r in ]0, 5-2√6[: r^2 - 10*r + 1 > 0",                         # l. 291: 5-2√6 is a root
    "forall r in [5-2√6, 5-2√6]: r^2 - 10*r + 1 = 0",
    "forall r in ]0, 1[: r^2 - 10*r + 1 > 0 iff r < 5-2√6",
    "forall r in ]0, 1[: r = √2/2 implies r^2 = 1/2",
    "forall r in ]0, 1[: (r^2 - 1/4)/(r - 1/2) > 0",                       # the common factor cancelled
])
def test_forall_holds_on_every_piece(formula):
    assert verified(formula), outcome(formula)


@pytest.mark.parametrize("formula, at", [
    ("forall r in ]0, 1[: (r - 1/2)^2 > 0", "0.5"),                        # only at a cut point
    ("forall r in [0, 1]: r > 0", "0.0"),                                   # only at a closed end
    ("forall r in ]0, 1]: r < 1", "1.0"),
    ("forall r in ]0, 1[: r < 1/2", "0.5"),                                # at the cut point and beyond
    ("forall r in ]0, 1[: r ≠ √2/2", "0.707"),
    ("forall r in ]0, 5-2√6]: r^2 - 10*r + 1 > 0", "0.101"),
    ("forall r in ]0, 1[: r^2 - 10*r + 1 > 0 iff r < 5-2√7", ""),
])
def test_forall_fails_where_one_piece_fails(formula, at):
    got = outcome(formula)
    assert refuted(formula), got
    assert f"(at r = {'≈' if '.' in at else ''}{at}" in got


def test_a_pole_of_a_condition_is_undecided_and_named():
    got = outcome("forall r in ]0, 1[: 1/(r - 1/2) > 0 or r < 1/2")
    assert got == "not verified: undecided at r = ≈0.5000000000"
    assert outcome("forall r in ]0, 1[: 1/(r - 1/2) > 0 or r < 1/2", verdict="refuted").startswith("not verified")
    for verdict in ("holds", "refuted"):       # the set is ]1/2, 1[ or ]1/2, 1[ ∪ {1/2}: undecided, whichever is said
        assert outcome("{r in ]0, 1[ : 1/(r - 1/2) > 0} = ]1/2, 1[", verdict=verdict) == \
            "not verified: undecided at r = ≈0.5000000000"


@pytest.mark.parametrize("formula", [
    "{r in [0, 1] : r^2 ≥ 1/4} = [1/2, 1]",
    "{r in ]0, 1[ : r^2 - r + 3/16 < 0} = ]1/4, 3/4[",
    "{r in ]0, 1[ : r^2 - r + 3/16 ≤ 0} = [1/4, 3/4]",
    "{r in ]0, 1[ : r = 1/3 or r = 2/3} = {1/3, 2/3}",
    "{r in ]0, 1[ : r = √2/2} = {√2/2}",
    "{r in ]0, 1[ : r > 2} = {}",
    "{r in ]0, 1[ : r^2 < 1/2} = ]0, √2/2[",
    "sup({r in ]0, 1[ : r^2 < 1/2}) = √2/2",
    "inf({r in [0, 1] : 4*r^2 ≥ 1}) = 1/2",
    "{r in ]0, 1[ : r^2 < 1/2} ≈ ]0.00000, 0.70711[",
    "{r in ]0, 1[ : r^2 < 1/2} ⊆ ]0, 0.71[",
])
def test_sets_of_r(formula):
    assert verified(formula), outcome(formula)


@pytest.mark.parametrize("formula", [
    "{r in [0, 1] : r^2 ≥ 1/4} = ]1/2, 1]", "{r in ]0, 1[ : r^2 - r + 3/16 < 0} = [1/4, 3/4]",
    "{r in ]0, 1[ : r^2 < 1/2} ≈ ]0.00000, 0.70710[", "{r in ]0, 1[ : r^2 < 1/2 or r > 3/4} ≈ ]0.00000, 0.70711[",
    "{r in ]0, 1[ : r^2 < 1/2} = ]0, √3/2[",
])
def test_sets_of_r_refuted(formula):
    assert refuted(formula)


# ------------------------------------------------------------------ branches, fixed points, changes

CP3 = "(λ - r)*(λ^2 - r + 1/4)"          # roots r (simple) and ±√(r − 1/4) (real for r ≥ 1/4)


@pytest.mark.parametrize("formula", [
    "forall r in ]0, 1[, λ = upper(λ^2 - r): λ > 0",
    "forall r in ]0, 1[, λ = lower(λ^2 - r): λ < 0",
    "forall r in ]0, 1[, λ = branch(λ^2 - r, 2): λ < 0",
    "forall r in ]0, 1[, λ in roots(λ^2 - r): λ > 0 or λ < 0",
    "forall r in [1/4, 1[, λ = middle(" + CP3 + "): λ ≥ 0",
    "forall r in ]1/4, 1[, λ = lower(" + CP3 + "): λ < 0",
    "forall r in ]0, 1/4[, λ = upper(" + CP3 + "): λ < 1/4",             # the one real root, λ = r
    "{r in ]0, 1[, λ = upper(λ^2 - r + 1/4): λ < 5} = [1/4, 1[",          # no branch below 1/4
    "{r in ]0, 1[, λ = middle(" + CP3 + "): λ > 1} = {}",
    "forall r in ]0, 1[, x = xplus(1, r, 1, 0): x > 1",                   # x ↦ (x + r)/x: x² = x + r
    "forall r in ]0, 1[, x = xminus(1, r, 1, 0): x < 0",
    "forall r in ]0, 1[, x in fixed(1, r, 1, 0): x^2 - x - r = 0",
    "forall r in ]0, 1[, x in fixed(0, -1, 1, 0): not x > 0",             # x² = −1: not real
    "{r in ]0, 1[, x = xplus(1, r - 1/4, 1, 0) : x > 0} = ]0, 1[",
    "{r in ]0, 1[, x = xplus(1, r - 1/2, 1, 0) : x > 0} = [1/4, 1[",        # Δ = 4r − 1: x real from 1/4 on
    "{r in ]0, 1[, λ = upper(λ^2 - r), x = xplus(λ, 1, 1, 0) : x > λ} = ]0, 1[",
    "{r in ]0, 1[ : changes(r^2 - r + 3/16)} = {1/4, 3/4}",
    "{r in ]0, 1[ : changes((r - 1/2)^2)} = {}",
    "{r in ]0, 1[ : changes((r - 1/2)^3)} = {1/2}",
    "forall r in ]0, 1[: changes(r - 1/2) implies r = 1/2",
    "{r in ]0, 1[, λ = upper(λ^2 - r) : changes(λ - 1/2)} = {1/4}",
])
def test_branches_fixed_points_and_changes(formula):
    assert verified(formula), outcome(formula)


@pytest.mark.parametrize("formula", [
    "forall r in ]0, 1[, λ = upper(λ^2 - r + 1/4): λ > 0",                # no real branch for r < 1/4
    "forall r in ]0, 1[, λ = branch(λ^2 - r, 3): λ < 0",                  # there is no third root
    "forall r in ]0, 1[, λ = middle(" + CP3 + "): λ ≥ 0",                 # middle exists from 1/4 on
    "forall r in ]0, 1[, λ in roots(λ^2 - r): λ > 0",
    "forall r in ]0, 1[, λ = upper(λ^2 + r): λ > 0",
    "forall r in ]0, 1[, x = xplus(1, r, 1, 0): x > 2",
    "forall r in ]0, 1[, x in fixed(0, -1, 1, 0): x > 0 or x < 0",       # a statement about a non-real x is false
    "forall r in ]0, 1[: changes(r - 1/2)",
    "forall r in [1/2, 1/2]: changes(r - 1/2)",                           # a point interval has no sides
])
def test_branches_fixed_points_and_changes_refuted(formula):
    assert refuted(formula), outcome(formula)


# ------------------------------------------------------------------ the repository's definitions

def test_the_definitions_of_the_statement_files_evaluate():
    """Every `let` of statements/ is an object of the language (each is evaluated once here)."""
    paper = repository_statements()
    from certify_kernel import prepare
    from certify_kernel.evaluate import Context
    prepare(paper)
    ctx = Context(paper.lets)
    for name in paper.lets:
        try:
            ctx.name(name)
        except Undefined as exc:
            pytest.fail(f"let {name}: {exc}")
    assert truth_of("det(M) = r^6", paper.lets) if "M" in paper.lets else True
