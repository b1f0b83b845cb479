"""Ball arithmetic (python-flint arb): the working precision, and deciding by
raising it.

Every ball computation in certify runs inside :func:`precision`; a question that
balls may fail to answer (a sign, a comparison) is asked by :func:`decide` at
doubling precisions until the answer is proven or the limit is reached.
"""
from __future__ import annotations

from contextlib import contextmanager
from typing import Callable

import flint

GUARD = 30          # extra working bits over the precision of the inputs


@contextmanager
def precision(bits: int | None):
    """Run ball arithmetic at ``bits`` of working precision (restored afterwards)."""
    old = flint.ctx.prec
    if bits is not None:
        flint.ctx.prec = bits
    try:
        yield
    finally:
        flint.ctx.prec = old


def decide(attempt: Callable[[int], object], prec: int = 128, maxprec: int = 1024,
           undecided: Callable[[object], bool] = lambda v: v == "?"):
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
