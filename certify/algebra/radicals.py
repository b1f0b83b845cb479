"""Printed radicals, nested, read into exact algebraic numbers.

``radical("3+2√2-2√(4+3√2)")`` is the real number as an :class:`Algebraic`: the text is
read by the grammar of :mod:`.statements` (integers, + - * /, √n, √(…), nothing else),
its minimal polynomial computed by SymPy (``minimal_polynomial``, exact), and the root
of that polynomial is singled out by a certified ball of the expression (python-flint
arb, every square root of a ball proven positive): refined until exactly one isolating
interval of a real root meets the ball.  :func:`statements.constant` reads a + b√n only.
"""
from __future__ import annotations

import flint
import sympy as sp

from certify.errors import StatementError

from .algebraic import Algebraic
from .balls import precision
from .poly import Q, to_fmpz_poly
from .statements import Names


def _ball(e: sp.Expr) -> flint.arb:
    """A certified ball around a constant built from rationals, +, *, integer powers
    and square roots."""
    if e.is_Rational:
        return flint.arb(Q(int(e.p), int(e.q)))
    if e.is_Add:
        return sum((_ball(a) for a in e.args), flint.arb(0))
    if e.is_Mul:
        out = flint.arb(1)
        for a in e.args:
            out *= _ball(a)
        return out
    if e.is_Pow and e.exp == sp.S.Half:
        b = _ball(e.base)
        if not b > 0:
            raise StatementError(f"√({e.base}): the radicand is not proven positive")
        return b.sqrt()
    if e.is_Pow and e.exp.is_Integer:
        return _ball(e.base) ** int(e.exp)
    if e.is_Pow and e.exp == -sp.S.Half:
        return 1 / _ball(sp.sqrt(e.base))
    raise StatementError(f"{e}: not a radical expression (rationals, + - * /, √)")


def radical(text: str) -> Algebraic:
    """The printed constant ``text`` (e.g. "4+√5-2√(5+2√5)") as an exact algebraic number."""
    e = Names.of({}).expr(text)
    if e.free_symbols:
        raise StatementError(f"{text!r} is not a constant")
    return of_expression(e)


def of_expression(e: sp.Expr) -> Algebraic:
    """A real radical SymPy expression as an exact algebraic number."""
    if e.is_Rational:
        return Algebraic.rational(sp.Rational(e))
    t = sp.Symbol("t")
    poly = to_fmpz_poly(sp.minimal_polynomial(e, t), t)
    roots = Algebraic.roots(poly)
    for prec in (64, 128, 256, 512, 1024, 2048):
        with precision(prec):
            z = _ball(e)
        m, d = z.mid().fmpq(), z.rad().fmpq()
        lo, hi = m - d, m + d
        hits = []
        for a in roots:
            a.refine((hi - lo) if hi > lo else Q(1, 2 ** prec))
            if not (a.hi < lo or a.lo > hi):
                hits.append(a)
        if len(hits) == 1:
            return hits[0]
    raise StatementError(f"{e}: its root could not be singled out")
