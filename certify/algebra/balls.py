"""Ball arithmetic (python-flint arb): the working precision, and deciding by
raising it.

Every ball computation in certify runs inside :func:`precision`; a question that
balls may fail to answer (a sign, a comparison) is asked by :func:`decide` at
doubling precisions until the answer is proven or the limit is reached.  Balls are
ordered and measured through their exact rational ends (:func:`ends`), never
through a float: two roots that agree to 20 digits are still ordered correctly.
"""
from __future__ import annotations

from collections.abc import Callable
from typing import TypeVar

import flint

from certify.errors import UNDECIDED

GUARD = 30          # extra working bits over the precision of the inputs
T = TypeVar("T")    # what an attempt of :func:`decide` answers


class precision:
    """Run ball arithmetic at ``bits`` of working precision (restored afterwards): ``with
    precision(bits):``.  A class rather than a generator context: the orbits enter it at
    every collision."""

    __slots__ = ("bits", "old")

    def __init__(self, bits: int | None):
        self.bits = bits

    def __enter__(self) -> None:
        self.old = flint.ctx.prec
        if self.bits is not None:
            flint.ctx.prec = self.bits

    def __exit__(self, *exc) -> None:
        flint.ctx.prec = self.old


def decide(attempt: Callable[[int], T], prec: int = 128, maxprec: int = 1024,
           undecided: Callable[[T], bool] = lambda v: v == UNDECIDED):
    """``attempt(prec)`` at prec, 2·prec, ... ≤ maxprec, each under a working precision
    of prec + GUARD bits; the first answer that is not ``undecided``, else the last."""
    answer = None
    while prec <= maxprec:
        with precision(prec + GUARD):
            answer = attempt(prec)
        if not undecided(answer):
            return answer
        prec *= 2
    return answer


def ends(z: flint.arb) -> tuple[flint.fmpq, flint.fmpq]:
    """The exact rational ends (mid - rad, mid + rad) of a finite ball."""
    m, d = z.mid().fmpq(), z.rad().fmpq()
    return m - d, m + d


def ordered(balls, reverse: bool = False) -> list | None:
    """The balls in increasing order (decreasing with ``reverse``), decided by exact
    comparison of their rational ends; None when two of them overlap: their order is
    then undecided, and the caller refines them (raises the precision)."""
    keyed = sorted(((ends(z), z) for z in balls), key=lambda e: e[0][0])
    if any(not a[1] < b[0] for (a, _), (b, _) in zip(keyed, keyed[1:])):
        return None
    out = [z for _, z in keyed]
    return out[::-1] if reverse else out


def tight(z: flint.arb, bits: int) -> bool:
    """rad(z) < 2^-bits |mid(z)| (rad(z) < 2^-bits when mid(z) = 0), decided exactly on
    the rational midpoint and radius."""
    m, d = z.mid().fmpq(), z.rad().fmpq()
    bound = abs(m) if m != 0 else flint.fmpq(1)
    return d * 2 ** bits < bound
