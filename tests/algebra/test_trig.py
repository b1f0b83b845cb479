"""certify.algebra.trig's shortcuts against the SymPy computations they replace (the evidence
strings of the certificates must not change)."""
import sympy as sp
from hypothesis import given, settings

from certify.algebra import trig as T
from tests.expressions import expressions

x, y, r = sp.symbols("x y r")
atoms = [x, y, r, T.cθ, T.sφ, sp.Rational(1, 2), sp.Rational(-3, 7), sp.Integer(2), sp.Integer(-1)]
polys = expressions(atoms, (1, 3), max_leaves=10)


@settings(max_examples=150, deadline=None)
@given(polys)
def test_factored_is_sympys_factor(p):
    """_factored (from the memoised factor list) is the expression sp.factor gives, printed alike."""
    g = sp.expand(p)
    assert T._factored(g) == sp.factor(g)
    assert T.show(T._factored(g)) == T.show(sp.factor(g))


def test_undecided_sign_shows_sympys_factor():
    """An undecided sign shows the polynomial factored as sp.factor shows it (from the memoised
    factor list of its expanded form)."""
    H = T.Signs(atoms=((r, 1),))
    p = sp.expand((x - y) * (x + 2 * y) * (r + 1) * 3)
    s, why = T._poly_sign(p, H)
    assert s is None and why[0].startswith(f"`{T.show(sp.factor(p))}`: ")


int_polys = expressions([x, y, r, T.cθ, T.sφ, sp.Integer(2), sp.Integer(-1), sp.Integer(3)], (1, 3))


def _same_as_sympy(g):
    """_factor_list(g) is sp.factor_list(g): the same constant, factors (as expressions, printed
    alike) and multiplicities, in the same order."""
    T.caches.reset()
    c, factors = sp.factor_list(g)
    got = T._factor_list(g)
    assert got == (c, tuple(factors)), (g, got, (c, factors))
    assert [T.show(f) for f, _ in got[1]] == [T.show(f) for f, _ in factors]
    assert type(got[0]) is type(c)


@settings(max_examples=300, deadline=None)
@given(int_polys, polys)
def test_flint_factor_list_is_sympys(p, q):
    """On sums with integer coefficients (common symbols, contents, signs, repeated factors,
    one or several generators) the flint route gives SymPy's factor list; other polynomials
    (rational coefficients, monomials, constants) go to SymPy."""
    for g in (sp.expand(p), sp.expand(p * q), sp.expand(p ** 2 * (x - y) * r)):
        _same_as_sympy(g)
        if not g.is_Add or any(not c.is_Integer for c in g.as_coefficients_dict().values()):
            assert T._flint_factor_list(g) is None


def test_flint_factor_list_on_the_step_lemmas():
    """The polynomials whose signs the step lemmas read (certify.dynamics.cones on the six cones)
    are factored by the flint route as SymPy factors them."""
    from certify.dynamics import cones as RC
    from proofs.section4_1_reduction_theorem import SECTION2_K
    seen = []
    original = T._flint_factor_list
    T._flint_factor_list = lambda g: seen.append(g)      # SymPy factors them all, as before
    try:
        T.caches.reset()
        RC.transitions(RC.steps(SECTION2_K))
    finally:
        T._flint_factor_list = original
    flint_route = [g for g in seen if original(g) is not None]
    assert len(flint_route) > 20
    for g in flint_route:
        _same_as_sympy(g)


fractions = expressions(atoms, (-2, 3))


def _same_lowest_terms(E):
    """_lowest_terms(E) is the numerator and denominator of SymPy's field Q(gens)."""
    E = sp.sympify(E)
    K, _ = T._field(T._gens(E))
    try:
        f = K.from_expr(E)
    except (ZeroDivisionError, ValueError, sp.PolynomialError):
        return
    assert T._lowest_terms(E) == (f.numer, f.denom), E
    assert T._flint_lowest_terms(E, T._gens(E)) is not None


@settings(max_examples=300, deadline=None)
@given(fractions, fractions)
def test_flint_lowest_terms_are_sympys(p, q):
    """Sums, products and integer powers of symbols and rationals (the denominators' signs,
    contents and common factors varied): python-flint's route gives SymPy's field's numerator
    and denominator, as ring elements."""
    for E in (p, p / q if q != 0 else p, p * q - 1 / (q - x) if q != x else p, 1 / (1 - x), (2 - x) ** -2 / 3):
        _same_lowest_terms(E)
    assert T._flint_lowest_terms(sp.sqrt(x) + 1, T._gens(x)) is None


def test_flint_lowest_terms_on_the_step_lemmas():
    """Every expression whose lowest terms the step lemmas (certify.dynamics.cones) ask for."""
    from certify.dynamics import cones as RC
    from proofs.section4_1_reduction_theorem import SECTION2_K
    seen = []
    original = T._flint_lowest_terms
    T._flint_lowest_terms = lambda E, gens: seen.append(E)      # SymPy's field for all, as before
    try:
        T.caches.reset()
        RC.steps(SECTION2_K)
    finally:
        T._flint_lowest_terms = original
    assert len(seen) > 50
    for E in seen:
        _same_lowest_terms(E)


def _same_cancel(E):
    """_flint_cancel(E) is sp.cancel(E): the same expression, printed alike."""
    got, want = T._flint_cancel(E), sp.cancel(E)
    assert got is not None and got == want and T.show(got) == T.show(want), (E, got, want)


@settings(max_examples=300, deadline=None)
@given(fractions, fractions)
def test_flint_cancel_is_sympys(p, q):
    """On quotients of sums, products and integer powers of symbols and rationals the flint route
    gives sp.cancel's expression; numbers and other expressions are left to sp.cancel."""
    if q == 0:
        return
    E = p / q
    if E.is_Number or E.has(sp.zoo, sp.nan):
        assert E.has(sp.zoo, sp.nan) or T._flint_cancel(E) is None
        return
    _same_cancel(E)
    assert T._flint_cancel(sp.sqrt(x) / y) is None


def test_flint_cancel_on_the_printed_cases():
    """Every ratio the six printed cases (S7.2's case_is_the_map) form."""
    from proofs import section4_2_final_expressions as S42
    seen = []
    original = T._flint_cancel
    T._flint_cancel = lambda E: seen.append(E)      # sp.cancel for all, as before
    try:
        T.caches.reset()
        for key, (c, _s) in S42.CASE_KEYS.items():
            S42.case_is_the_map(key, S42.PRINTED_S7[key], T.vector(S42.PRINTED_S7[f"p0_{c}"]),
                                T.vector(S42.PRINTED_S7[f"q0_{c}"]))
    finally:
        T._flint_cancel = original
    assert len(seen) >= 6
    for E in seen:
        _same_cancel(E)


def test_cancel_on_the_step_lemmas():
    """trig.cancel is sp.cancel on every expression the step lemmas cancel (p', ρ, n')."""
    from certify.dynamics import cones as RC
    from proofs.section4_1_reduction_theorem import SECTION2_K
    seen = []
    original = T.cancel
    T.cancel = lambda E: seen.append(E) or sp.cancel(E)
    try:
        T.caches.reset()
        RC.steps(SECTION2_K)
    finally:
        T.cancel = original
    assert len(seen) >= 6 * 7
    for E in seen:
        assert T.cancel(E) == sp.cancel(E) and T.show(T.cancel(E)) == T.show(sp.cancel(E))


@settings(max_examples=200, deadline=None)
@given(expressions([T.cθ, T.sθ, T.cφ, T.sφ, sp.Symbol("r"), sp.Rational(1, 2), sp.Integer(-3)], exponents=(-2, 3)))
def test_show_kept_for_a_run_is_the_text(e):
    """show's memo gives SymPy's text for the expression, the first time and the next ones, for a
    scalar and inside a vector; a Python number is shown as SymPy shows it."""
    want = sp.sstr(e, order="grlex").replace("**", "^").replace("*", " ")
    assert T.show(e) == want and T.show(e) == want
    assert T.show(sp.Matrix([e, 1, e])) == f"({want}, 1, {want})"
    assert T.show(3) == "3" and T.show(sp.Rational(-3, 7)) == "-3/7"


def test_sign_records_kept_for_a_run_are_not_changed_by_their_readers():
    """signed_witness reads the memoised _poly_data/_factor_data without changing them: the witness of
    a sign is the same the first time, the next ones, and after the caches' reset."""
    import copy

    from certify import caches
    H = T.hypotheses(1)
    for E in [T.cθ * T.sφ + T.cφ, (1 + T.cφ ** 2) / (T.sθ * (T.cθ ** 2 + T.sθ ** 2)), -T.sφ ** 3 * T.cθ]:
        n, d = T.fraction(E)
        first = T.signed_witness(E, H)
        data = copy.deepcopy(T._poly_data(n, H))
        assert T.signed_witness(E, H) == first and T._poly_data(n, H) == data
        caches.reset()
        assert T.signed_witness(E, H) == first
