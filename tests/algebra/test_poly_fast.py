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
