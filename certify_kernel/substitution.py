"""Substitution: ``at(E, x, v, y, w, ...)`` is E (a rational function, vector or matrix) with the
variables x, y, ... (``cos(θ)`` for a cosine) replaced by the rational functions v, w, ... at once:
p(1), q(1) "obtained when λ = 0" (l. 662), the limit bases at θ = 0 and π/2 (l. 545), t_c at
λ = −cos φ/tan θ + μ.  The value is computed exactly, monomial by monomial (:class:`values.RF`);
on the circles it does not depend on the representative (a polynomial of the ideal
(cos² + sin² − 1) vanishes at (cos, sin) = (1, 0) or (0, 1)).
"""
from __future__ import annotations

from .evaluate import FUNCTIONS, Matrix, value
from .values import RF, Undefined


def _variable(x) -> int:
    """The index of the variable x is (x a rational function that is one variable)."""
    if isinstance(x, RF) and len(x.num) == 1 and not any(any(k) for k in x.den) and set(x.den.values()) == {1}:
        (key, c), = x.num.items()
        if c == 1 and sorted(key)[-1] == 1 and sum(key) == 1:
            return key.index(1)
    raise Undefined("at(E, x, v): x must be a variable")


def _poly(p: dict, subs: dict) -> RF:
    """The polynomial p (exponent tuple -> coefficient) with variable i replaced by subs[i]: the
    monomials grouped by their exponents in the replaced variables."""
    groups: dict = {}
    for key, c in p.items():
        outer = tuple(key[i] for i in subs)
        inner = tuple(0 if i in subs else e for i, e in enumerate(key))
        groups.setdefault(outer, {})[inner] = c
    out = RF.const(0)
    for outer, rest in groups.items():
        term = RF(rest)
        for v, e in zip(subs.values(), outer):
            if e:
                term = term * v ** e
        out = out + term
    return out


def substitute(E, subs: dict):
    """E (a rational function, vector or matrix) with the variables of ``subs`` replaced."""
    if isinstance(E, RF):
        return _poly(E.num, subs) / _poly(E.den, subs)
    if isinstance(E, tuple):
        return tuple(substitute(x, subs) for x in E)
    if isinstance(E, Matrix):
        return Matrix([[substitute(x, subs) for x in row] for row in E.rows])
    raise Undefined("at(E, ...): E must be a function, a vector or a matrix")


def _at(ctx, E, *pairs):
    if not pairs or len(pairs) % 2:
        raise Undefined("at(E, x, v, ...): pairs of a variable and its value")
    subs: dict = {}
    for x, v in zip(pairs[::2], pairs[1::2]):
        val = value(v, ctx)
        if not isinstance(val, RF):
            raise Undefined("at(E, x, v): the value v must be a function")
        subs[_variable(value(x, ctx))] = val
    return substitute(value(E, ctx), subs)


FUNCTIONS["at"] = _at
