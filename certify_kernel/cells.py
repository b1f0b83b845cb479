"""Univariate cylindrical decomposition: the truth of a formula in r over an interval, decided on
finitely many pieces (the Li–Passmore–Paulson way, for one variable).

A *condition* is g = (N₀ + N₁√Δ)/(D₀ + D₁√Δ), N₀, ..., Δ polynomials in r and λ, read on the real
roots λ (the *branches*, largest first) of a polynomial cp(r, λ); without cp it is a function of
r alone.  Off the real roots of its *bounding polynomials* (:func:`bounding`) the number of real
branches and the sign of g on each are constant on every interval (continuity: no branch meets
another, none escapes to infinity, g has no zero and no pole and Δ keeps its sign).  So an
interval is cut at those roots, the formula is evaluated exactly at one rational sample of each
open cell and at each cut point (an algebraic r₀: arithmetic in Q(r₀), :mod:`certify_kernel.field`),
and its truth on the whole interval is the truth on every piece.
"""
from __future__ import annotations

from fractions import Fraction
from functools import cmp_to_key
from math import ceil, floor

from .field import AtR0
from .poly import at_r, badd, d_lambda, in_lambda, madd, mmul, mul, resultant_in, sign, squarefree, sub, value
from .sturm import real_roots
from .values import Undefined, number, roots_in


class Undecided(Exception):
    """The formula has no value at a point (a pole of a condition, a branch that is 0/0)."""


class Condition:
    """g = (N0 + N1 √delta)/(D0 + D1 √delta) on the branches of cp (dicts over (r, λ); cp None:
    polynomials in r alone, every part with λ-degree 0)."""

    def __init__(self, cp: dict | None, N0: dict, D0: dict, N1: dict | None = None, D1: dict | None = None,
                 delta: dict | None = None):
        self.cp, self.parts = cp, {"N0": N0, "D0": D0, "N1": N1 or {}, "D1": D1 or {}, "delta": delta or {}}
        if not D0 and not D1:
            raise Undefined("a condition with the denominator 0")
        self.key = repr((sorted((cp or {}).items()), sorted((k, sorted(v.items())) for k, v in self.parts.items())))

    def bounding(self) -> list:
        """The polynomials in r whose real roots bound the cells: with cp, Res_λ(cp, ∂cp/∂λ) (two
        branches meet), lc_λ(cp) (a branch escapes), Res_λ(P, cp) for P the norms N₀² − N₁²Δ and
        D₀² − D₁²Δ (zero where N₀ + N₁√Δ or its conjugate is) and Δ; without cp, the norms and Δ."""
        p = self.parts
        polys = [_norm(p["N0"], p["N1"], p["delta"]), _norm(p["D0"], p["D1"], p["delta"])] + \
            ([p["delta"]] if p["delta"] else [])
        out = []
        if self.cp is not None:
            out = [resultant_in(self.cp, d_lambda(self.cp)), in_lambda(self.cp)[-1]]
            for P in polys:
                if not P:
                    raise Undefined("a part of a condition vanishes identically")
                if any(k[1] for k in P):
                    R = resultant_in(P, self.cp)
                    if not R:
                        raise Undefined("a condition vanishes on a whole branch (Res_λ ≡ 0)")
                    out.append(R)
                else:
                    out.append(in_lambda(P)[0])
        else:
            out = [in_lambda(P)[0] if P else [] for P in polys]
        return [squarefree(b) for b in out if len(b) > 1]


def _norm(p0: dict, p1: dict, delta: dict) -> dict:
    """N₀² − N₁²Δ: the product of N₀ + N₁√Δ and its conjugate."""
    return madd(mmul(p0, p0), mmul(mmul(p1, p1), delta), -1) if p1 else p0


def _surd_sign(p0, p1, delta, sg, mul_, sub_) -> int:
    """sign(P₀ + P₁√Δ) where Δ ≥ 0, from the signs of P₀, P₁ and, when they differ, of P₀² − P₁²Δ."""
    s0, s1 = (sg(p0) if p0 else 0), (sg(p1) if p1 else 0)
    if s1 == 0 or s0 == s1:
        return s0 if s0 else s1
    if s0 == 0:
        return s1
    return s0 * sg(sub_(mul_(p0, p0), mul_(mul_(p1, p1), delta)))


def condition_sign(at: dict, sg, mul_=mul, sub_=sub):
    """The sign of g from its parts specialised at a point: None when Δ < 0 (x not real)."""
    delta = at.get("delta") or []
    if delta:
        sd = sg(delta)
        if sd < 0:
            return None
        if sd == 0:
            at = {k: v for k, v in at.items() if k not in ("N1", "D1")}
    sden = _surd_sign(at["D0"], at.get("D1") or [], delta, sg, mul_, sub_)
    if sden == 0:
        raise Undecided("a pole of a condition")
    return _surd_sign(at["N0"], at.get("N1") or [], delta, sg, mul_, sub_) * sden


class Point:
    """A value r₀ of r: a rational sample of a cell, or an algebraic cut point.  ``branches(cp)``:
    the real roots of cp(r₀, λ) with multiplicity, largest first; ``sign(cond, k)``: the sign of
    the condition on the k-th (None: x not real)."""

    def __init__(self, r0, cell: bool):
        self.r0, self.cell, self.left, self.right = r0, cell, None, None
        self._roots: dict = {}
        self._signs: dict = {}
        self._at = None if cell else AtR0(number(r0))

    def __repr__(self) -> str:
        r0 = self.r0
        return str(r0) if isinstance(r0, Fraction) else f"≈{float(r0.lo):.10f}"

    def branches(self, cp: dict) -> int:
        key = repr(sorted(cp.items()))
        if key not in self._roots:
            if self.cell:
                self._roots[key] = (None, real_roots(at_r(cp, self.r0)))
            else:
                cpl = in_lambda(cp)
                self._roots[key] = (cpl, self._at.branches(cpl))
        return len(self._roots[key][1])

    def distinct(self, cp: dict) -> int:
        """The number of distinct real roots of cp(r₀, λ) (in a cell every root is simple)."""
        n = self.branches(cp)
        return n if self.cell else len(self._at.roots(in_lambda(cp))[1])

    def sign(self, cond: Condition, k: int | None):
        key = (cond.key, k)
        if key not in self._signs:
            self._signs[key] = self._sign(cond, k)
        return self._signs[key]

    def _sign(self, cond: Condition, k):
        if cond.cp is None:
            at = {n: in_lambda(P)[0] if P else [] for n, P in cond.parts.items()}
            if self.cell:
                return condition_sign(at, lambda c: sign(value(c, self.r0)))
            return condition_sign(at, self._at.sign, mul, sub)
        if k is None or k >= self.branches(cond.cp):
            raise Undefined("no such branch")
        cpl, roots = self._roots[repr(sorted(cond.cp.items()))]
        if self.cell:
            lam = roots[k]
            return condition_sign({n: at_r(P, self.r0) for n, P in cond.parts.items()}, lam.sign_of)
        A, iv = self._at, roots[k]
        at = {n: in_lambda(P) for n, P in cond.parts.items()}
        return condition_sign(at, lambda P: A.taq(P, cpl, *iv), A.mul, lambda P, Q: badd(P, Q, -1))


def _between(a, b) -> Fraction:
    """The simplest rational strictly between two numbers (algebraic, or None for ∓∞)."""
    if a is None:
        return Fraction(int(number(b).lo) - 1) if b is not None else Fraction(0)
    if b is None:
        return Fraction(int(number(a).hi) + 1)
    a, b = number(a), number(b)
    while not a.hi < b.lo:
        if a.rational and b.rational:
            break
        a.bisect()
        b.bisect()
    lo, hi = (a.hi, b.lo) if not (a.rational and b.rational) else (a.lo, b.lo)
    return _simplest(lo, hi) if lo < hi else (lo + hi) / 2


def _simplest(lo: Fraction, hi: Fraction) -> Fraction:
    """The fraction of least denominator in ]lo, hi[ (continued fractions: x ∈ ]a, b[ ⇔ 1/x ∈ ]1/b, 1/a[)."""
    if floor(lo) + 1 < hi:                              # an integer inside: the one nearest 0
        return Fraction(0) if lo < 0 < hi else Fraction(floor(lo) + 1 if lo >= 0 else ceil(hi) - 1)
    n = floor(lo)
    a, b = lo - n, hi - n                               # 0 ≤ a < b ≤ 1
    t = Fraction(floor(1 / b) + 1) if a == 0 else _simplest(1 / b, 1 / a)
    return n + 1 / t


_ROOTS: dict = {}
ORDER = cmp_to_key(lambda a, b: a.compare(b))       # algebraic numbers sorted by their order


def cut_points(polys, lo, hi) -> list:
    """The real roots in ]lo, hi[ of the polynomials, increasing, each once (with the polynomial it was
    found of first)."""
    pts: list = []
    for p in polys:
        for a in roots_in(p, lo, hi):
            if not any(a.compare(b) == 0 for b, _ in pts):
                pts.append((a, p))
    return sorted(pts, key=lambda e: ORDER(e[0]))


def pieces(conds: list, lo, hi, lo_closed: bool = False, hi_closed: bool = False) -> list[Point]:
    """The pieces of the interval: its open cells (a rational sample each) and the cut points
    between them (and its ends when closed), in increasing order, each point knowing the cells
    beside it."""
    if lo is not None and hi is not None and number(lo).compare(number(hi)) >= 0:
        if not (lo_closed and hi_closed) or number(lo).compare(number(hi)) > 0:
            raise Undefined("an empty interval")
        return [Point(number(lo), cell=False)]
    polys: dict = {}
    for c in conds:
        if c.key not in _ROOTS:
            _ROOTS[c.key] = c.bounding()
        for p in _ROOTS[c.key]:
            polys.setdefault(repr(p), p)
    cuts = [a for a, _ in cut_points(polys.values(), lo, hi)]
    ends = [lo] + cuts + [hi]
    out: list[Point] = []
    if lo_closed:
        out.append(Point(number(lo), cell=False))
    for k, (a, b) in enumerate(zip(ends, ends[1:])):
        cell = Point(_between(a, b), cell=True)
        if out:
            out[-1].right = cell
            cell.left = out[-1]
        out.append(cell)
        if k < len(cuts):
            pt = Point(cuts[k], cell=False)
            pt.left = cell
            out.append(pt)
    if hi_closed:
        pt = Point(number(hi), cell=False)
        pt.left = out[-1]
        out.append(pt)
    for a, b in zip(out, out[1:]):
        if not a.cell:
            a.right = b
    return out

