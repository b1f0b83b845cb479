"""The fast conversions of certify.algebra.poly give what SymPy's own routes give: the
expression tree in RING (against
FIELD.from_expr), polynomials in r multiplied out by python-flint (against sp.Poly) and the
mpoly of a polynomial in r, λ, s (against sp.Poly)."""
import flint
import pytest
import sympy as sp

from certify.algebra import poly
from certify.algebra.poly import FIELD, MCTX, lam, parse, r, to_field, to_fmpq_poly, to_mpoly
from proofs.section3_theorem import (
    A_PRINTED,
    B_PRINTED,
    CP_PRINTED,
    D_PRINTED,
    DELTA_PRINTED,
    M_PRINTED,
    P0_PRINTED,
    P1_T5_PRINTED,
    U_PRINTED,
    V_PRINTED,
)

TEXTS = [M_PRINTED, CP_PRINTED, U_PRINTED, V_PRINTED, P1_T5_PRINTED, DELTA_PRINTED.replace("P0", f"({P0_PRINTED})"),
         "-2^2", "2^-1", "r^2^3", "1/2/3", "-r^2 - -3", "+r", "lam*λ", "x - u*v", "0^0", "[[1, r], [-r/2, (1+r)/2]]",
         "[]", "3*r\n + 2"]


@pytest.mark.parametrize("text", TEXTS[1:6])
def test_to_field_is_from_expr(text):
    e = parse(text)
    fast, ref = to_field(e), FIELD.from_expr(e)
    assert dict(fast.numer) == dict(ref.numer) and dict(fast.denom) == dict(ref.denom)


def test_to_field_reads_what_the_ring_does_not():
    with pytest.raises(ValueError):
        to_field(sp.Symbol("w") + 1)
    assert poly._ring_pair(sp.sqrt(r)) is None


@pytest.mark.parametrize("text", [DELTA_PRINTED.replace("P0", f"({P0_PRINTED})"), "(r - 1)^3/7 + 2", "5", "0"])
def test_to_fmpq_poly_is_polys(text):
    e = parse(text)
    coeffs = sp.Poly(e, r).all_coeffs()[::-1]
    assert to_fmpq_poly(e) == flint.fmpq_poly([flint.fmpq(int(sp.numer(c)), int(sp.denom(c))) for c in coeffs])


@pytest.mark.parametrize("text", [A_PRINTED, B_PRINTED, D_PRINTED, CP_PRINTED, "(r-1)^3*(λ^2/3 - r/7)"])
def test_to_mpoly_is_polys(text):
    P = sp.Poly(parse(text), r, lam, poly.s)
    den = 1
    for c in P.coeffs():
        den = sp.ilcm(den, sp.denom(c))
    assert to_mpoly(parse(text)) == MCTX.from_dict({m: int(c * den) for m, c in P.terms()})


def test_fraction_tree_is_the_fraction_and_refuses_what_it_cannot_read():
    leaf = {r: flint.fmpq_poly([0, 1])}.get
    rational = lambda q: flint.fmpq_poly([flint.fmpq(int(q.p), int(q.q))])   # noqa: E731
    n, d = poly.fraction_tree((r + sp.Rational(1, 2)) ** 2 / (r - 1) - 3, leaf, rational)
    x = flint.fmpq_poly([0, 1])
    assert n * (x - 1) == ((x + flint.fmpq(1, 2)) ** 2 - 3 * (x - 1)) * d          # n/d = (x + 1/2)²/(x − 1) − 3
    assert poly.fraction_tree(sp.Pow(r - r, -1, evaluate=False), leaf, rational) is None    # 0 to a negative power
    assert poly.fraction_tree(sp.sqrt(r), leaf, rational) is None
    assert poly.fraction_tree(lam + 1, leaf, rational) is None                               # not a leaf


# --- irreducible_factors_knowing: known factors divided out, the rest factored -----------

from hypothesis import HealthCheck, given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

from certify.algebra.poly import irreducible_factors_knowing  # noqa: E402

_SETTINGS = dict(deadline=None, database=None, suppress_health_check=[HealthCheck.too_slow])
# the factors that recur in the resultants of (ab)^n(cb)^n, and a few others
_RECURRING = [[0, 1], [1, 1], [-1, 1], [1, -10, 1], [1, -6, 1], [1, -12, -10, -12, 1], [-2, 0, 1], [3, 2], [1, 0, 0, 1]]


def _flint_factors(p):
    """python-flint's full factorisation, as irreducible_factors gives it (no memo)."""
    _, fs = p.factor()
    return sorted([(poly.primitive(f), m) for f, m in fs if f.degree() > 0], key=poly.factor_order)


@st.composite
def _products(draw):
    """A product of powers of recurring and random polynomials, and a list of 'known' ones:
    the irreducible factors of some of them (as a spectrum learns them), in any order."""
    pieces = draw(st.lists(st.one_of(st.sampled_from(_RECURRING),
                                     st.lists(st.integers(-9, 9), min_size=2, max_size=6)), min_size=1, max_size=6))
    exps = draw(st.lists(st.integers(1, 40), min_size=len(pieces), max_size=len(pieces)))
    p = flint.fmpz_poly([draw(st.integers(-6, 6).filter(bool))])
    for c, e in zip(pieces, exps):
        f = flint.fmpz_poly(c)
        if f.degree() > 0:
            p *= f ** e
    seen = [f for c in draw(st.lists(st.sampled_from(pieces))) for f, _m in _flint_factors(flint.fmpz_poly(c))]
    known = list({str(f): f for f in draw(st.permutations(seen))}.values())
    return p, known


@settings(max_examples=150, **_SETTINGS)
@given(_products())
def test_known_factors_give_flint_factorisation(case):
    """The factors, multiplicities and order of python-flint's full factorisation, whatever is
    known; the new factors are exactly those not known, and the known ones are returned as
    the very objects given."""
    p, known = case
    got, new = irreducible_factors_knowing(p, known)
    assert got == _flint_factors(p)
    assert [str(f) for f in new] == [str(f) for f, _m in got if f not in known]
    for f, _m in got:
        assert f not in known or any(f is k for k in known)


def test_a_known_factor_that_is_not_irreducible_is_caught_by_the_comparison():
    """The shortcut trusts that the known factors are irreducible: given a reducible one it
    returns a factorisation that python-flint's disagrees with (what the test above checks)."""
    r1, r2 = flint.fmpz_poly([-1, 1]), flint.fmpz_poly([1, 1])
    p = r1 ** 3 * r2 ** 2
    got, _new = irreducible_factors_knowing(p, [r1 * r2])
    assert got != _flint_factors(p)


def test_a_multiplicity_too_high_modulo_the_prime_falls_back_to_the_full_factorisation():
    """r - p ≡ r modulo the prime p of the shortcut: r seems to divide it, the exact division
    refuses, and the whole polynomial is factored (the right answer, r not among the factors)."""
    big = flint.fmpz_poly([-poly._PRIME, 1])
    p = big ** 2 * flint.fmpz_poly([1, -10, 1])
    got, new = irreducible_factors_knowing(p, [flint.fmpz_poly([0, 1])])
    assert got == _flint_factors(p) and flint.fmpz_poly([0, 1]) not in [f for f, _m in got]


def test_frac_sum_is_the_canonical_sum():
    # Frac + Frac with different denominators (poly._sum: the gcd of the numerator with
    # gcd(d₁, d₂) only) gives the canonical pair the full gcd gives, and SymPy's sum in FIELD:
    # denominators coprime, sharing factors (also with a content and a sign), sums that
    # cancel a shared factor, and a sum that is 0
    from certify.algebra.poly import Frac, field_to_frac, frac_to_field
    d = [lam - r, 2 * lam + r ** 2, -(3 * r - 1), (lam - r) ** 2 * (6 * r + 2), lam * r + 1]
    es = [(1 + r) / d[0], lam / d[1], (lam - 2) / (d[0] * d[2]), 1 / d[3], (r - lam) / (d[0] * d[1]),
          lam ** 2 / (d[4] * d[2]), -(1 + r) / d[0], (2 * r - 1) / (d[3] * d[4]), sp.Rational(5, 6) * lam,
          1 / d[0], (-1 - r) / (d[0] * (lam + 1)),                # their sum 1/(λ + 1): λ - r cancels
          1 / (2 * d[0]), (-1 - r) / (2 * d[0] * (lam + 1))]       # the same with a content 2
    for a in es:
        for b in es:
            A, B = field_to_frac(to_field(a)), field_to_frac(to_field(b))
            S = A + B
            full = Frac(A.num * B.den + B.num * A.den, A.den * B.den)      # the full gcd
            assert (S.num, S.den) == (full.num, full.den), (a, b)
            assert frac_to_field(S) == to_field(a) + to_field(b)


def test_lr_to_ring_keeps_the_terms_in_order():
    # lr_to_ring reads the terms off monoms() and coeffs(): the element to_dict's items give,
    # term for term in the same order (fmpz_mpoly and fmpq_mpoly, with and without a scale)
    from certify.algebra.poly import LRCTX, LRQCTX, RING, lr_to_ring
    zq = LRQCTX.from_dict({(3, 1): flint.fmpq(-2, 7), (1, 5): 3, (0, 0): flint.fmpq(1, 9), (0, 2): 4})
    zz = LRCTX.from_dict({(4, 0): 5, (2, 3): -6, (0, 1): 1})
    for p in (zq, zz, zq - zq):
        for scale in (1, 6):
            got = lr_to_ring(p, scale)
            want = {(el, er, 0, 0, 0, 0): flint.fmpq(c) / scale for (el, er), c in p.to_dict().items()}
            assert got == RING.zero.new(want) and list(got.items()) == list(want.items())
