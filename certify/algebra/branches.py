"""Signs of a condition on each real eigenvalue branch, certified over r-intervals.

Given cp(λ; r) ∈ Q[r][λ] and a condition g — a rational function of r and λ, or of
r, λ and the position fixed point x = (a - d + √Δ)/(2c), Δ = (a - d)² + 4bc — we
prove the sign of g on every real branch λ_k(r) (k = 0 the largest real root) over
an interval of r:

1. critical values: real roots in the interval of disc_λ(cp), of the leading
   coefficient, of Res_λ(norm(numerator of g), cp), Res_λ(norm(denominator), cp)
   and, when x occurs, of Res_λ(Δ, cp) and Res_λ(c, cp) (norm(N₀ + N₁√Δ) = N₀² - N₁²Δ);
   the count of critical values is made twice (Sturm and python-flint);
2. between consecutive critical values, the number of real branches and the sign
   of g on each are constant (g is continuous and has no zero there);
3. one exact rational sample per cell; the branches at the sample isolated by
   Sturm sequences over Q; g evaluated in ball arithmetic (python-flint arb),
   precision raised until the sign is proven.
At a critical value itself the sign is decided where the branches can be isolated
(exactly squarefree in Q(r)[λ], then certified complex root enclosures), and an
exact zero is proven by a gcd in Q(r)[λ] (:meth:`Spectrum.vanishes_at`).
"""
from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from functools import cached_property
from math import gcd as _gcd

import flint
import sympy as sp
from sympy.polys.rings import PolyElement

from certify import caches
from certify.errors import UNDECIDED, Undecided

from . import numberfield as nf
from .algebraic import Algebraic, sign_at
from .balls import GUARD, decide, precision
from .poly import (
    MCTX,
    RING,
    Q,
    Sf,
    Xf,
    coefficients_in,
    expr,
    factor_order,
    irreducible_factors_knowing,
    lam,
    lr_to_ring,
    mpoly_to_ring,
    mpoly_to_univariate,
    primitive,
    resultant_lambda,
    ring_terms,
    ring_to_lrq,
    ring_to_mpoly,
    to_field,
    to_fmpq,
    to_ring,
    x,
)
from .sturm import checked_real_root_count, isolate

SIGN = {1: "+", -1: "−", 0: "0", None: "·"}
BRANCH_NAMES = ("upper", "middle", "lower")   # the real eigenvalue branches, largest first: index 0, 1, 2
UPPER, MIDDLE, LOWER = range(3)
X_PLUS, X_MINUS = "x₊", "x₋"                 # the fixed points (a - d ± √Δ)/(2c) of f, sigma = 1 and -1
# the sign on a branch that does not exist at this r: an answer, not undecided (certify.errors)
NO_BRANCH = "missing"
_MORE_PRECISION = "more precision"     # an attempt of decide() that asks for more bits


@dataclass(frozen=True)
class FixedPoint:
    """The fixed point x₊ = (a - d + √Δ)/(2c) of f(x) = (ax + b)/(cx + d), Δ = (a-d)² + 4bc;
    a, b, c, d polynomials in r and λ."""

    a: sp.Expr
    b: sp.Expr
    c: sp.Expr
    d: sp.Expr

    @cached_property
    def delta(self) -> sp.Expr:
        return sp.expand((self.a - self.d) ** 2 + 4 * self.b * self.c)


def _integer_mpoly(p) -> tuple:
    """(A, d): p = A/d with A an integer polynomial (python-flint, in r, λ, s), d > 0."""
    d = 1
    for c in p.values():
        d = d * int(c.denominator) // _gcd(d, int(c.denominator))
    return ring_to_mpoly(p), d


def norm_mpoly(P0, P1, delta) -> flint.fmpz_mpoly:
    """A positive integer multiple of P₀² - P₁²Δ (polynomials of the engine's ring in
    r, λ) as a primitive ``fmpz_mpoly`` in (r, λ, s), by python-flint: the same zeros,
    which is all a norm is used for."""
    return _norm_of_pairs(_integer_mpoly(P0), _integer_mpoly(P1), _integer_mpoly(delta))


def _norm_of_pairs(P0, P1, delta) -> flint.fmpz_mpoly:
    """:func:`norm_mpoly` from the pairs (A, d) of :func:`_integer_mpoly`."""
    (A0, d0), (A1, d1), (AD, dD) = P0, P1, delta
    M = A0 * A0 * (d1 * d1 * dD) - A1 * A1 * AD * (d0 * d0)     # d0² d1² dD (P0² - P1²Δ)
    return M if M.is_zero() else M / M.content()


_DELTAS: dict = {}               # id of a Δ of the engine's ring -> (Δ, its (A, d), its terms)
caches.register(_DELTAS.clear)


def _delta_entry(delta) -> tuple:
    entry = _DELTAS.get(id(delta))
    if entry is None or entry[0] is not delta:
        if len(_DELTAS) > 1000:
            _DELTAS.clear()
        entry = _DELTAS[id(delta)] = (delta, _integer_mpoly(delta), ring_terms(delta))
    return entry


def _integer_delta(delta) -> tuple:
    """:func:`_integer_mpoly` of Δ (or of c), memoised by identity (every condition with x
    shares its Δ and c)."""
    return _delta_entry(delta)[1]


def _delta_terms(delta) -> list:
    """:func:`poly.ring_terms` of Δ (or of 0 when there is none), memoised by identity."""
    return ring_terms(RING.zero) if delta is None else list(_delta_entry(delta)[2])


def norm(P0, P1, delta):
    """:func:`norm_mpoly` as an element of the engine's ring."""
    return mpoly_to_ring(norm_mpoly(P0, P1, delta))


def _substitute_x(g, fp: FixedPoint):
    """g(x₊) as N/D with N, D ∈ Q[λ, r, s], s standing for √Δ."""
    A, B, C, D = (to_ring(e) for e in (fp.a, fp.b, fp.c, fp.d))
    alpha, two_c = A - D + Sf.numer, 2 * C

    def homogenise(P):
        # P(x) = Σ P_k x^k at x = alpha/two_c, times two_c^deg
        parts = coefficients_in(P, Xf.numer)
        n = max(parts, default=0)
        return sum((Pk * alpha ** k * two_c ** (n - k) for k, Pk in parts.items()), RING.zero), n

    G = to_field(g)
    N, n = homogenise(G.numer)
    Dn, m = homogenise(G.denom)
    if n > m:
        Dn = Dn * two_c ** (n - m)
    elif m > n:
        N = N * two_c ** (m - n)
    return N, Dn


def _split_sqrt(P, delta):
    """P = P₀ + P₁ s modulo s² = Δ."""
    P0, P1 = RING.zero, RING.zero
    for k, Pk in coefficients_in(P, Sf.numer).items():
        term = Pk * (delta ** (k // 2) if delta is not None and k > 1 else RING.one)   # no 0**0 when Δ ≡ 0
        if k % 2:
            P1 += term
        else:
            P0 += term
    return P0, P1


def _lrq_terms(q) -> list[tuple[flint.fmpq, int, int]]:
    """:func:`poly.ring_terms` of an fmpq_mpoly in (λ, r) (lex, λ first: the same terms in
    the same order as those of the equal element of the engine's ring; read off its monomials
    and coefficients, in order, without the dict to_dict builds from them)."""
    return [(c, er, el) for (el, er), c in zip(q.monoms(), q.coeffs())]


def _lrq_to_mpoly(q) -> tuple:
    """(A, d): q = A/d with A an integer ``fmpz_mpoly`` in (r, λ, s) and d > 0 the lcm of
    q's denominators (q an fmpq_mpoly in (λ, r)): :func:`_integer_mpoly` without the ring."""
    cs = q.coeffs()
    d = flint.fmpz(1)
    for c in cs:
        d = d.lcm(c.q)
    return MCTX.from_dict({(er, el, 0): (c * d).p for (el, er), c in zip(q.monoms(), cs)}), d


class Condition:
    """g = N/D with N = N₀ + N₁√Δ, D = D₀ + D₁√Δ, over Q[r, λ]; built once per (g, x).

    ``lrq`` (optional): N₀, N₁, D₀ as fmpq_mpoly in (λ, r) (D₁ = 0), the same polynomials:
    the terms and norms are read from them, and ``N``, ``D`` (elements of the engine's
    ring) are made only when first asked for (an exact zero test)."""

    _cache: dict = {}
    degenerate: list[tuple[str, object]]   # (label, norm): norms ≡ 0 on whole branches (_resultant_off_common_factor)
    _forms: dict | None = None             # the Horner forms of the parts (_forms), made on first use
    _ring_parts: list | None = None        # c, g, Q of the split in the engine's ring (Spectrum._split_ring_parts)

    def __init__(self, name, N, D, delta, c, lrq: tuple | None = None, terms: dict | None = None,
                 split: tuple | None = None):
        self.name, self._N, self._D, self.delta, self.c = name, N, D, delta, c
        self._lrq = lrq
        # ((g, Q), (d₀, d₁)): N₀² - N₁²Δ ≡ 4c·g²·Q and D₀ ≡ 2c·d₀d₁ modulo cp (fmpq_mpoly in (λ, r))
        self.split = split
        self.degenerate = []
        if terms is not None:                  # the terms of lrq, known to the caller (a twin's)
            self.terms = terms
        elif lrq is None:
            self.terms = {k: ring_terms(p) for k, p in
                          (("N0", N[0]), ("N1", N[1]), ("D0", D[0]), ("D1", D[1]), ("delta", delta or RING.zero))}
        else:
            self.terms = {"N0": _lrq_terms(lrq[0]), "N1": _lrq_terms(lrq[1]), "D0": _lrq_terms(lrq[2]), "D1": [],
                          "delta": _delta_terms(delta)}

    @cached_property
    def top(self) -> int:
        """The highest exponent of r or λ in any part: how many powers a ball evaluation needs."""
        return max((max(i, j) for ts in self.terms.values() for _c, i, j in ts), default=0)

    @property
    def N(self) -> tuple:
        if self._N is None:
            assert self._lrq is not None          # built from flint polynomials
            self._N = (lr_to_ring(self._lrq[0]), lr_to_ring(self._lrq[1]))
        return self._N

    @property
    def D(self) -> tuple:
        if self._D is None:
            assert self._lrq is not None
            self._D = (lr_to_ring(self._lrq[2]), RING.zero)
        return self._D

    @classmethod
    def of(cls, name: str, g, fixed_point: FixedPoint | None = None) -> Condition:
        g = expr(g)
        key = (g, fixed_point if (fixed_point is not None and g.has(x)) else None)
        if key not in cls._cache:
            cls._cache[key] = cls._build(name, g, key[1])
        return cls._cache[key]

    @classmethod
    def _build(cls, name, g, fp):
        if fp is not None:
            num, den = _substitute_x(g, fp)
            delta, c = to_ring(fp.delta), to_ring(fp.c)
        else:
            G = to_field(g)
            num, den, delta, c = G.numer, G.denom, None, None
        return cls(name, _split_sqrt(num, delta), _split_sqrt(den, delta), delta, c)

    def norms(self) -> list:
        """Polynomials in r, λ whose zeros contain every zero and pole of g."""
        return [p for _label, p in self.labelled_norms()]

    def share_norms(self, twin: Condition) -> None:
        """Take the norms of ``twin``, a condition with the same N₀, D₀, Δ, c and N₁ up to
        its sign (the other fixed point): the same polynomials N₀² - N₁²Δ, D₀, Δ, c (and the
        same parts of the first, :meth:`critical_norms`), made once, when first asked for."""
        self._twin = twin

    def labelled_norms(self) -> list:
        """The norms with what they come from: "N", "D", "delta", "c", as primitive
        integer ``fmpz_mpoly`` in (r, λ, s) (positive multiples: the same zeros); memoised."""
        if getattr(self, "_norms", None) is None and getattr(self, "_twin", None) is not None:
            self._norms = self._twin.labelled_norms()
        if getattr(self, "_norms", None) is None:
            out = []
            if self._lrq is None:
                for label, (P0, P1) in (("N", self.N), ("D", self.D)):
                    out.append((label, norm_mpoly(P0, P1, self.delta) if P1 else ring_to_mpoly(P0)))
            else:
                N0, N1, D0 = self._lrq
                out.append(("N", _lrq_to_mpoly(N0)[0] if N1.is_zero() else
                            _norm_of_pairs(_lrq_to_mpoly(N0), _lrq_to_mpoly(N1), _integer_delta(self.delta))))
                out.append(("D", _lrq_to_mpoly(D0)[0]))
            if self.delta is not None:
                out += [("delta", _integer_delta(self.delta)[0]), ("c", _integer_delta(self.c)[0])]
            self._norms = [(label, p) for label, p in out if not p.is_constant()]
        return self._norms

    def critical_norms(self, cp_monic: bool) -> list:
        """What the critical values are read from: :meth:`labelled_norms`, but where the
        condition carries its ``split`` and cp has a constant leading coefficient in λ
        (``cp_monic``), the numerator's norm N₀² - N₁²Δ ≡ 4c·g²·Q and the denominator
        D₀ ≡ 2c·d₀d₁ are given by their parts ("N", [c, g, Q]; "D", [c, d₀, d₁]; the norm not
        made then).  Res_λ(cp, ·) = lc^k Π ·(λ_i) is then multiplicative and blind to
        multiples of cp: the irreducible factors of a resultant are those of the parts'
        resultants together.  Entries (label, polynomial or list of them)."""
        if self.split is None or not cp_monic or self._lrq is None or self._lrq[1].is_zero():
            return self.labelled_norms()
        if getattr(self, "_twin", None) is not None:
            return self._twin.critical_norms(cp_monic)
        if getattr(self, "_critical", None) is None:
            c, parts = self.split_parts()
            out = [(label, [p for p in [c] + list(qs) if p.is_zero() or not p.is_constant()])   # 0: ≡ 0 modulo cp
                   for label, qs in zip("ND", parts)]
            out += [("delta", _integer_delta(self.delta)[0]), ("c", c)]
            self._critical = [(label, p) for label, p in out if isinstance(p, list) or not p.is_constant()]
        return self._critical

    def split_parts(self) -> tuple:
        """(c, ((g, Q), (d₀, d₁))): the ``split`` as integer ``fmpz_mpoly`` in (r, λ, s) (positive
        multiples), c that of the label "c"; memoised (a twin's are the same)."""
        if getattr(self, "_twin", None) is not None:
            return self._twin.split_parts()
        if getattr(self, "_parts", None) is None:
            assert self.split is not None
            self._parts = (_integer_delta(self.c)[0], tuple(tuple(_lrq_to_mpoly(q)[0] for q in qs)
                                                            for qs in self.split))
        return self._parts

    def numerator_norm(self):
        """N₀² - N₁²Δ as :meth:`labelled_norms` holds it (the very polynomial :func:`norm_mpoly`
        makes of N₀, N₁, Δ), when N₁ ≠ 0 and it is not constant; else None."""
        zero = self._lrq[1].is_zero() if self._lrq is not None else not self.N[1]
        if self.delta is None or zero:
            return None
        return next((p for label, p in self.labelled_norms() if label == "N"), None)


caches.register(Condition._cache.clear)


def _eval_terms(terms, Rp, Lp) -> flint.arb:
    total = flint.arb(0)
    for c, i, j in terms:
        total += c * Rp[i] * Lp[j]
    return total


def _lambda_polys(terms) -> list[flint.fmpq_poly]:
    """:func:`poly.ring_terms` of h(r, λ) as h's coefficients in λ (lowest first), each an
    ``fmpq_poly`` in r (made an ``arb_poly`` at the working precision to evaluate at a ball)."""
    rows: dict[int, dict[int, flint.fmpq]] = {}
    for c, i, j in terms:
        rows.setdefault(j, {})[i] = c
    out = []
    for j in range(max(rows, default=0) + 1):
        row = rows.get(j, {})
        coeffs = [flint.fmpq(0)] * (max(row, default=0) + 1)
        for i, c in row.items():
            coeffs[i] = c
        out.append(flint.fmpq_poly(coeffs))
    return out


def _horner(coeffs, z):
    """Σ coeffs[j] z^j (balls, lowest first) by Horner's rule."""
    total = z * 0
    for c in reversed(coeffs):
        total = total * z + c
    return total


def _powers(z, n):
    out = [flint.arb(1)]
    for _ in range(n):
        out.append(out[-1] * z)
    return out


def _horner_form(terms) -> tuple:
    """The terms (c, i, j) of a polynomial in r, λ as ([(j, P_j)], d): the polynomial is
    Σ_j P_j(r) λ^j / d with P_j ∈ Z[r] (fmpz_poly) and d > 0 the lcm of the denominators."""
    d = flint.fmpz(1)
    for c, _i, _j in terms:
        d = d.lcm(c.q)
    by_j: dict = {}
    for c, i, j in terms:
        by_j.setdefault(j, {})[i] = (c * d).p
    return [(j, flint.fmpz_poly([row.get(i, 0) for i in range(max(row) + 1)])) for j, row in sorted(by_j.items())], d


def _eval_form(form, R, L) -> flint.arb:
    """A ball around Σ_j P_j(R) L^j / d (:func:`_horner_form`): each P_j at the ball R by
    python-flint, then Horner in L, at the working precision."""
    rows, d = form
    if not rows:
        return flint.arb(0)
    total = flint.arb(0)
    k = rows[-1][0]
    for j, P in reversed(rows):
        while k > j:
            total *= L
            k -= 1
        total += P(R)
    while k > 0:
        total *= L
        k -= 1
    return total / d


@caches.by_identity
def _form_of(terms) -> tuple:
    """:func:`_horner_form` of a list of terms, memoised by identity (a condition and its
    twin at the other fixed point share the lists of N₀ and D₀)."""
    return _horner_form(terms)


def _forms(cond: Condition) -> dict:
    forms = getattr(cond, "_forms", None)
    if forms is None:
        forms = cond._forms = {k: _form_of(ts) for k, ts in cond.terms.items()
                               if k != "delta" or cond.delta is None}
        if cond.delta is not None:           # every condition with x shares its Δ: one form
            entry = _delta_entry(cond.delta)
            if len(entry) < 4:
                entry = _DELTAS[id(cond.delta)] = entry + (_horner_form(entry[2]),)
            forms["delta"] = entry[3]
    return forms


def _sign_ball(cond: Condition, R, L, delta_is_zero=False):
    """Sign of g at balls R, L (r and λ); None when x is not real (Δ < 0); '?' if
    the balls do not decide it.  ``delta_is_zero``: Δ = 0 there is known exactly."""
    forms = _forms(cond)
    S = flint.arb(0)
    if cond.delta is not None and not delta_is_zero:
        dv = _eval_form(forms["delta"], R, L)
        if dv < 0:
            return None
        if not dv > 0:
            return UNDECIDED
        S = dv.sqrt()
    num = _eval_form(forms["N0"], R, L) + _eval_form(forms["N1"], R, L) * S
    den = _eval_form(forms["D0"], R, L) + _eval_form(forms["D1"], R, L) * S
    sn = 1 if num > 0 else -1 if num < 0 else None
    sd = 1 if den > 0 else -1 if den < 0 else None
    if sn is None or sd is None:
        return UNDECIDED
    return sn * sd


def ball_value(cond: Condition, R, L) -> flint.arb:
    """g = N₀/D₀ at balls R, L, for a condition without √Δ."""
    if cond.delta is not None:
        raise ValueError("ball_value needs a condition without √Δ")
    Rp, Lp = _powers(R, cond.top), _powers(L, cond.top)
    return _eval_terms(cond.terms["N0"], Rp, Lp) / _eval_terms(cond.terms["D0"], Rp, Lp)


def evaluate_sign(cond: Condition, r0, L: Algebraic, prec: int = 64, maxprec: int = 8192):
    """The sign of g at r = r0 (rational) on the branch λ = L, proven in ball
    arithmetic; None when x is not real there (Δ < 0)."""
    sg = decide(lambda p: _sign_ball(cond, flint.arb(Q(r0)), L.arb(p)), prec, maxprec)
    if sg == UNDECIDED:
        raise Undecided(f"sign of {cond.name} undecided at r = {r0}")
    return sg


class Lazy(Sequence):
    """A list of known length whose entries are computed on first access and kept:
    a sign table computes only the signs its reader asks for (the same values as an
    eager table, entry by entry)."""

    _done: dict[int, object]

    def __init__(self, n: int, entry):
        self._n, self._entry, self._done = n, entry, {}

    def __len__(self) -> int:
        return self._n

    def __getitem__(self, k):
        if isinstance(k, slice):
            return [self[i] for i in range(*k.indices(self._n))]
        if k < 0:
            k += self._n
        if not 0 <= k < self._n:
            raise IndexError(k)
        if k not in self._done:
            self._done[k] = self._entry(k)
        return self._done[k]

    def __eq__(self, other) -> bool:
        return list(self) == list(other)

    def __repr__(self) -> str:
        return repr(list(self))


class Cell:
    """An open r-interval between consecutive critical values, with its sample; the real
    λ at the sample (largest first) and the sign of g on each branch (None: x not real)
    are computed when first read."""

    def __init__(self, lo: Algebraic, hi: Algebraic, sample: flint.fmpq, branches_at, sign_of):
        self.lo, self.hi, self.sample = lo, hi, sample
        self._branches_at, self._sign_of = branches_at, sign_of
        self._branches: list[Algebraic] | None = None

    @property
    def branches(self) -> list[Algebraic]:
        """The real eigenvalues at the sample, largest first: their number is that on the cell."""
        if self._branches is None:
            self._branches = self._branches_at(self.sample)
        return self._branches

    @cached_property
    def signs(self) -> Lazy:
        lams = self.branches
        return Lazy(len(lams), lambda k: self._sign_of(self.sample, lams[k]))


class SignTable:
    """The certified sign of a condition on each branch, cell by cell, and at each
    critical value (a list of signs, UNDECIDED where undecided; None where the branches
    could not be isolated).  Signs are computed when first read (:class:`Lazy`)."""

    def __init__(self, condition: str, interval: tuple, critical: list, cells: list, point_at=None):
        self.condition, self.interval, self.critical, self.cells = condition, interval, critical, cells
        self.source: tuple | None = None        # (spectrum, condition): what it was made from
        self._points = Lazy(len(critical), (lambda k: point_at(critical[k])) if point_at else (lambda k: None))

    def has_point(self, k: int) -> bool:
        """Whether the signs at the k-th critical value are computed already."""
        return k in self._points._done

    @property
    def points(self) -> Lazy:
        """The signs at the critical values, each computed when first read."""
        return self._points

    def signs(self, branch: int, lo=None, hi=None, include_points=True) -> set:
        """Signs taken by g on branch ``branch`` (0 = largest real eigenvalue) over
        ]lo, hi[ (default: the whole interval), interior critical values included.
        NO_BRANCH is in the set where the branch does not exist, UNDECIDED where undecided."""
        lo = self.interval[0] if lo is None else lo
        hi = self.interval[1] if hi is None else hi
        out = set()
        for cell in self.cells:
            if at_most(cell.hi, lo) or at_most(hi, cell.lo):
                continue
            out.add(cell.signs[branch] if branch < len(cell.signs) else NO_BRANCH)
        if include_points:
            for k, rc in enumerate(self.critical):
                if less(lo, rc) and less(rc, hi):
                    pt = self.points[k]
                    out.add(UNDECIDED if pt is None else pt[branch] if branch < len(pt) else NO_BRANCH)
        return out

    def holds(self, branch: int, sign: int, lo=None, hi=None) -> bool:
        """g has the sign ``sign`` at every point of branch ``branch`` over ]lo, hi[."""
        return self.signs(branch, lo, hi) == {sign}

    def within(self, branch: int, allowed, lo=None, hi=None) -> bool:
        """g takes only signs in ``allowed`` (1, -1, 0, None: not real, NO_BRANCH) at the points
        of branch ``branch`` over ]lo, hi[, interior critical values included."""
        return self.signs(branch, lo, hi) <= set(allowed)

    def _around(self, point):
        """The cells on either side of the critical value ``point`` (None where there is none)."""
        left = [c for c in self.cells if same(c.hi, point)]
        right = [c for c in self.cells if same(c.lo, point)]
        return (left[0], right[0]) if left and right else None

    def changes_at(self, branch: int, point) -> bool:
        """The sign on ``branch`` differs on the two cells adjacent to ``point``."""
        cells = self._around(point)
        if cells is None or any(branch >= len(c.signs) for c in cells):
            return False
        return cells[0].signs[branch] * cells[1].signs[branch] < 0

    def keeps_sign_at(self, branch: int, point) -> bool:
        """No sign change on ``branch`` across ``point`` (true where the branch ends there)."""
        cells = self._around(point)
        if cells is None or any(branch >= len(c.signs) for c in cells):
            return True
        return cells[0].signs[branch] == cells[1].signs[branch]

    def markdown(self, names=BRANCH_NAMES) -> str:
        """The sign table: one row per cell and per critical value."""
        width = max([len(c.signs) for c in self.cells] + [1])
        labels = (names[k] if k < len(names) else f"λ{k}" for k in range(width))
        head = "| r | sample | real λ | " + " | ".join(labels) + " |"
        rows = [head, "|" + "---|" * (3 + width)]
        for k, cell in enumerate(self.cells):
            signs = [SIGN.get(sg, UNDECIDED) for sg in cell.signs] + [""] * (width - len(cell.signs))
            rows.append(f"| ]{_short(cell.lo)}, {_short(cell.hi)}[ | {cell.sample} | {len(cell.branches)} | "
                        + " | ".join(signs) + " |")
            if k < len(self.critical):
                pt = self.points[k]
                signs = ([UNDECIDED] * width if pt is None
                         else [SIGN.get(sg, UNDECIDED) for sg in pt] + [""] * (width - len(pt)))
                rows.append(f"| {_short(self.critical[k])} | (critical) | {'' if pt is None else len(pt)} | "
                            + " | ".join(signs) + " |")
        return "\n".join(rows)


def _short(a) -> str:
    return a.short(6)


def sign_word(signs) -> str:
    """A set of signs read off a sign table, in words (sorted): "> 0", "not real", ..."""
    names = {1: "> 0", -1: "< 0", 0: "= 0", None: "not real", NO_BRANCH: "absent", UNDECIDED: "undecided"}
    return ", ".join(sorted(names.get(s, str(s)) for s in signs))


class Spectrum:
    """The real eigenvalue branches of cp(λ; r), cp ∈ Q[r][λ]."""

    def __init__(self, cp, ring_cp=None):
        """``cp`` an expression (or text) in r, λ; ``ring_cp`` the same polynomial as an
        element of the engine's ring, when the caller has it (no conversion then)."""
        self._given = cp
        self.ring_cp = ring_cp if ring_cp is not None else to_ring(sp.expand(expr(cp)))
        self.mpoly_cp = ring_to_mpoly(self.ring_cp)
        self.lrq_cp = ring_to_lrq(self.ring_cp)
        self.degree = self.ring_cp.degree(RING.gens[0])
        self.disc = primitive(mpoly_to_univariate(self.mpoly_cp.discriminant("lam")))
        if self.disc.is_zero():
            # the branches of a squarefree part could change number where no discriminant vanishes
            raise ValueError("cp has a repeated factor in λ (its discriminant is identically 0)")
        lead = _lambda_coefficients(self.mpoly_cp)
        self.lc = primitive(lead[-1])
        self._cp_coeffs = lead if self.lc.degree() <= 0 else None
        self._resultants = {}
        self._tables = {}
        self._branches = {}
        self._eigenvalues = {}
        self._common = {}                  # (h or id of h, key of rc) -> (h, common roots of cp and h there,
        #                                    (branch, maxprec) -> whether h vanishes on it)
        self._sqf = {}                     # key of rc -> the squarefree part of cp(rc, λ) in Q(rc)[λ]
        self._sqf_modulo = {}              # str of m -> (that part in Q[r]/(m)[λ], gcd(cp, cp'))
        self._gcds = {}                    # (h or id of h, str of m) -> (h, gcd(cp, h) in Q[r]/(m)[λ] as it comes)
        self._monics = {}                  # id of such a gcd G -> [G, G monic, its squarefree part or None]
        self._resultant_ids = {}           # id of h -> (h, Res_λ(h, cp))
        self._norms = {}                   # ids of (P₀, P₁, Δ) -> (P₀, P₁, Δ, norm(P₀, P₁, Δ))
        self._checked = {}                 # id of a factor -> (it, its real roots counted both ways)
        self._factor_ids = {}              # id of a polynomial in r -> (it, its irreducible factors)
        self._known: list = []             # the irreducible factors met so far (of disc cp, resultants)
        self._texts: dict = {}             # id of a known factor -> its text
        self._branch_signs: dict = {}      # (id of a condition, key of rc, k, maxprec) -> (it, its sign there)

    def known_factors(self) -> list:
        """The irreducible factors (fmpz_poly) met so far by this spectrum's tables."""
        return list(self._known)

    @cached_property
    def cp(self) -> sp.Expr:
        """cp as an expanded SymPy expression (for readers)."""
        return sp.expand(expr(self._given))

    @cached_property
    def P(self) -> sp.Poly:
        """cp as a SymPy Poly in λ (for readers)."""
        return sp.Poly(self.cp, lam)

    @cached_property
    def _coefficients(self) -> list[flint.fmpq_poly]:
        """The coefficients of cp in λ, lowest first, as fmpq_poly in r."""
        out: dict = {}
        for c, i, j in ring_terms(self.ring_cp):
            out.setdefault(j, {})[i] = c
        return [flint.fmpq_poly([out.get(j, {}).get(i, 0) for i in range(max(out.get(j, {0: 0})) + 1)])
                for j in range(self.degree + 1)]

    def at(self, r0) -> flint.fmpq_poly:
        """cp(λ; r0) ∈ Q[λ] for a rational r0."""
        t = to_fmpq(r0)
        return flint.fmpq_poly([c(t) for c in self._coefficients])

    def real_eigenvalues(self, r0) -> list[Algebraic]:
        """The real roots λ of cp(λ; r0), largest first, as algebraic numbers (Sturm);
        memoised, as the same samples recur across tables."""
        key = str(to_fmpq(r0))
        if key not in self._eigenvalues:
            p = self.at(r0)
            self._eigenvalues[key] = [Algebraic(p, lo, hi) for lo, hi in isolate(p)][::-1]
        return self._eigenvalues[key]

    def resultant(self, g) -> flint.fmpz_poly:
        """Res_λ(g, cp) ∈ Z[r] (python-flint), primitive; g an integer ``fmpz_mpoly`` in
        (r, λ, s) or an element of the engine's ring; cached by g's text."""
        G = g if isinstance(g, flint.fmpz_mpoly) else ring_to_mpoly(g)
        if not G.is_zero():                # the same key for proportional polynomials (the same zeros)
            G = G / G.content()  # type: ignore[attr-defined]
            if G.coeffs()[0] < 0:
                G = -G
        # a cheap key (size, degrees, outer coefficients) and python-flint's equality within it:
        # the same as keying by the text, without printing a polynomial of thousands of terms
        coeffs = G.coeffs()
        key = (len(coeffs), tuple(G.degrees()), int(coeffs[0]) if coeffs else 0, int(coeffs[-1]) if coeffs else 0)
        bucket = self._resultants.setdefault(key, [])
        for H, R in bucket:
            if H == G:
                return R
        R = None
        if self._cp_coeffs is not None and not G.is_zero() and G.degrees()[2] == 0:          # free of s
            R = self._resultant_free_of_s(_lambda_coefficients(G))
        if R is None:
            R = mpoly_to_univariate(G.resultant(self.mpoly_cp, "lam"))
        bucket.append((G, primitive(R)))
        return bucket[-1][1]

    def _resultant_free_of_s(self, g: list) -> flint.fmpz_poly | None:
        """A non-zero rational multiple of Res_λ(g, cp) (0 when it is 0), g ∈ Z[r][λ] given by its
        coefficients in λ and cp of constant leading coefficient: by :func:`_norm_modulo` for a cp of
        degree ≤ 3; None for a higher degree (:meth:`resultant` takes the subresultant then).  A
        subclass with a cheaper route for its degree overrides this."""
        return _norm_modulo(g, self._cp_coeffs) if len(self._cp_coeffs) <= 4 else None

    def _resultant_off_common_factor(self, e, cond: Condition, label: str) -> flint.fmpz_poly:
        """Res_λ(e, cp) ≡ 0: e and cp share a factor G in Q(r)[λ] (cp is reducible), so e
        vanishes identically on the branches that are roots of G.  The zeros of e on the
        other branches are the roots of Res_λ(e, cp/G) (not ≡ 0: cp is squarefree, so
        gcd(e, cp/G) = 1); where a root of G meets a root of cp/G, disc cp vanishes, so on
        each cell a branch is a root of G throughout or nowhere.  The condition is marked
        degenerate, and its cells are signed exactly there (:meth:`_cell_sign`)."""
        G = e.gcd(self.ring_cp)
        if G.degree(RING.gens[0]) <= 0:
            raise ArithmeticError(f"{cond.name}: a factor vanishes on a whole branch")
        H, rem = self.ring_cp.div(G)
        if rem != 0:
            raise ArithmeticError(f"{cond.name}: cp is not divisible by its gcd with a condition")
        R = primitive(resultant_lambda(H, e))
        if R.is_zero():
            raise ArithmeticError(f"{cond.name}: a factor vanishes on a whole branch")
        cond.degenerate = [d for d in cond.degenerate if d[0] != label] + [(label, e)]
        return R

    def critical_values(self, cond: Condition | None, lo, hi) -> list[Algebraic]:
        """The critical values in ]lo, hi[, increasing: the polynomials are factored
        over Q (python-flint) and each irreducible factor's real roots isolated by
        Sturm sequences, their number checked against python-flint's isolation."""
        factor_lists = [self._factors(p) for p in [self.disc] + ([self.lc] if self.lc.degree() > 0 else [])]
        for label, e in (cond.critical_norms(self.lc.degree() <= 0) if cond is not None else []):
            assert cond is not None
            if isinstance(e, list):               # the parts of a split norm (N) or denominator (D)
                Rs = [self._resultant_of(p) for p in e]
                if not any(R.is_zero() for R in Rs):
                    factor_lists.append(_union(self._factors(R) for R in Rs))
                    continue
                e = next((p for lab, p in cond.labelled_norms() if lab == label), None)   # ≡ 0 on a branch
                if e is None:
                    continue
            R = self._resultant_of(e)
            if R.is_zero():
                R = self._resultant_off_common_factor(mpoly_to_ring(e), cond, label)
            factor_lists.append(self._factors(R))
        lo, hi = _alg(lo), _alg(hi)
        roots = []
        for f in {k: f for fl in factor_lists for f, k in fl}.values():
            entry = self._checked.get(id(f))
            if entry is None or entry[0] is not f:     # Sturm and python-flint agree (once per factor)
                entry = self._checked[id(f)] = (f, checked_real_root_count(f))
            if entry[1]:                               # without real roots (both routes): none to isolate
                roots += [a for a in Algebraic.roots(f, lo.lo, hi.hi) if strictly_between(lo, a, hi)]
        return sorted_numbers(roots)

    def _factors(self, p) -> list:
        """(factor, its text) for the irreducible factors of p, memoised by the identity of p
        (the discriminant and the cached resultants are the same objects in every table).
        The factors found in this spectrum before (of disc cp, of earlier resultants: the
        same few recur, to high powers) are divided out first and only the cofactor is
        factored (:func:`poly.irreducible_factors_knowing`): the same factors."""
        entry = self._factor_ids.get(id(p))
        if entry is None or entry[0] is not p:
            factors, new = irreducible_factors_knowing(p, self._known)
            for f in new:
                self._known.append(f)
                self._texts[id(f)] = str(f)
            entry = self._factor_ids[id(p)] = (p, [(f, self._texts[id(f)]) for f, _m in factors])
        return entry[1]

    def table(self, name: str, g, lo, hi, fixed_point: FixedPoint | None = None) -> SignTable:
        """:meth:`sign_table` of the condition ``g`` (named ``name``; x the fixed point
        ``fixed_point`` of f when given), the one way a proof asks for a sign table."""
        return self.sign_table(Condition.of(name, g, fixed_point), lo, hi)

    def sign_table(self, cond: Condition, lo, hi) -> SignTable:
        """Certified signs of ``cond`` on every branch over ]lo, hi[ (memoised per
        condition and interval, so certificates sharing a condition share the work)."""
        key = (id(cond), _alg(lo).key(), _alg(hi).key())
        if key not in self._tables or self._tables[key][0] is not cond:   # ids of dead objects are reused
            self._tables[key] = (cond, self._sign_table(cond, lo, hi))
        return self._tables[key][1]

    def _sign_table(self, cond: Condition, lo, hi) -> SignTable:
        crit = self.critical_values(cond, lo, hi)
        ends = [_alg(lo)] + crit + [_alg(hi)]
        cells = [Cell(a, b, simple_rational_between(a, b), self.real_eigenvalues,
                      lambda t, L: self._cell_sign(cond, t, L)) for a, b in zip(ends, ends[1:])]
        table = SignTable(cond.name, (_alg(lo), _alg(hi)), crit, cells, lambda rc: self.sign_at_point(cond, rc))
        table.source = (self, cond)      # what it was made from (read by certify.patterns.feasibility)
        return table

    def _cell_sign(self, cond: Condition, t, L: Algebraic):
        """The sign of g at the sample t of a cell on the branch L: the sign over the
        cell.  For a degenerate condition (:meth:`_resultant_off_common_factor`: a norm
        vanishing identically on the branches that are roots of a factor G of cp), the
        zeros of g on those branches are not among the critical values, so there:

        * without √Δ the degenerate norm is N₀ or D₀ itself: N₀ ≡ 0 (g ≡ 0) or D₀ ≡ 0
          (a pole on the whole branch) gives 0, which defeats a strict inequality (as at a
          point, :meth:`feasibility.Analysis._point`); both give '?';
        * with √Δ, only the numerator's norm N₀² - N₁²Δ ≡ 0: one of N₀ ± N₁√Δ is ≡ 0 on the
          cell (real-analytic); where Δ > 0 and N₀, N₁ have opposite signs at the sample, it
          is ours (the other, -2N₁√Δ there, is not ≡ 0): g ≡ 0, sign 0; Δ < 0: x is not real
          on the cell (Δ's zeros are critical), None; else '?'.

        A branch is a root of G at the sample iff the degenerate norm vanishes there
        (elsewhere its zeros are critical values): decided exactly in Q[λ]."""
        degenerate = cond.degenerate
        if not degenerate:
            return evaluate_sign(cond, t, L)
        on = {label for label, e in degenerate if sign_at(_at_r(e, t), L) == 0}
        if not on:
            return evaluate_sign(cond, t, L)
        if cond.delta is None:
            return 0 if on in ({"N"}, {"D"}) else UNDECIDED
        if on != {"N"}:
            return UNDECIDED
        terms = [cond.terms[k] for k in ("delta", "N0", "N1")]
        n = max((max(i, j) for ts in terms for _c, i, j in ts), default=0)

        def attempt(p):
            Rp, Lp = _powers(flint.arb(Q(t)), n), _powers(L.arb(p), n)
            dv, v0, v1 = (_eval_terms(ts, Rp, Lp) for ts in terms)
            if dv < 0:
                return None
            if dv > 0 and (v0 > 0 or v0 < 0) and (v1 > 0 or v1 < 0):
                return 0 if (v0 > 0) != (v1 > 0) else UNDECIDED
            return _MORE_PRECISION
        out = decide(attempt, 128, 1024, undecided=lambda v: v == _MORE_PRECISION)
        return UNDECIDED if out == _MORE_PRECISION else out

    def branches_at(self, rc: Algebraic, maxprec: int = 1024):
        """The real eigenvalues at the algebraic r = rc, largest first, each repeated
        by its multiplicity (1, or 2 for the root of a linear gcd(cp, cp')), as
        functions prec -> certified ball; None when they cannot be isolated."""
        key = rc.key()
        if key not in self._branches:
            self._branches[key] = self._branches_at(rc, maxprec)
        return self._branches[key]

    def _branches_at(self, rc, maxprec):
        m = nf.modulus(rc)
        if str(m) not in self._sqf_modulo:                 # the same for every root of m
            self._sqf_modulo[str(m)] = nf.squarefree(nf.kpoly(self.ring_cp, m), m)
        sqf, g = self._sqf_modulo[str(m)]
        self._sqf[rc.key()] = sqf
        if len(g) > 2:
            return None                  # a root of multiplicity > 2: not handled
        prec = 128
        while prec <= maxprec:
            reals = nf.real_roots(sqf, rc, prec)
            if reals is not None:
                mult = [1] * len(reals)
                if len(g) == 2:
                    with precision(prec + GUARD):
                        hits = [i for i, z in enumerate(reals) if nf.evaluate(g, rc.arb(prec), z).contains(0)]
                    if len(hits) != 1:
                        prec *= 2
                        continue
                    mult[hits[0]] = 2
                isolated = {prec: reals}
                return [_root_ball(sqf, rc, k, isolated) for k in range(len(reals)) for _ in range(mult[k])]
            prec *= 2
        return None

    def sign_at_point(self, cond: Condition, rc: Algebraic, maxprec: int = 1024):
        """Signs of g on the branches at an algebraic r (UNDECIDED where undecided: g
        vanishing or a pole there), or None when the branches cannot be isolated."""
        roots = self.branches_at(rc)
        if roots is None:
            return None
        quick = min(256, maxprec)
        out = decide(lambda p: [_sign_ball(cond, rc.arb(p), L(p)) for L in roots], 128, quick,
                     undecided=lambda signs: UNDECIDED in signs)
        # where balls of 256 bits do not decide, the exact zero test first (a critical value is
        # often a zero of g: no precision decides it), then balls up to maxprec for the rest
        return [self._undecided_sign(cond, rc, k, roots[k], 2 * quick, maxprec) if sg == UNDECIDED else sg
                for k, sg in enumerate(out)]

    def sign_on_branch_at(self, cond: Condition, rc: Algebraic, k: int, maxprec: int = 1024):
        """``sign_at_point(cond, rc)[k]`` computed for the branch k alone (the same sign: balls
        decide a sign only where it is proven, and the exact tests are those of branch k);
        UNDECIDED when the branches cannot be isolated (sign_at_point's None), NO_BRANCH when
        there are fewer than k + 1.  Computed once per condition, point and branch (a point
        of several regions, or of the two fixed points' regions, asks again; an exact answer)."""
        key = (id(cond), rc.key(), k, maxprec)
        entry = self._branch_signs.get(key)
        if entry is not None and entry[0] is cond:
            return entry[1]
        sg = self._sign_on_branch_at(cond, rc, k, maxprec)
        self._branch_signs[key] = (cond, sg)
        return sg

    def _sign_on_branch_at(self, cond: Condition, rc: Algebraic, k: int, maxprec: int):
        roots = self.branches_at(rc)
        if roots is None:
            return UNDECIDED
        if k >= len(roots):
            return NO_BRANCH
        quick = min(256, maxprec)
        sg = decide(lambda p: _sign_ball(cond, rc.arb(p), roots[k](p)), 128, quick)
        return self._undecided_sign(cond, rc, k, roots[k], 2 * quick, maxprec) if sg == UNDECIDED else sg

    def _undecided_sign(self, cond: Condition, rc: Algebraic, k: int, ball, prec: int, maxprec: int):
        """The sign of g on branch k at rc where balls of < ``prec`` bits did not decide it: the
        exact zero test (:meth:`_exact_sign`), then balls of ``prec`` to ``maxprec`` bits where
        it finds no zero; where the exact test itself cannot conclude, the balls, and its
        error only if they do not decide either (the order of the two routes changes no sign)."""
        def balls():
            return decide(lambda p: _sign_ball(cond, rc.arb(p), ball(p)), prec, maxprec)
        try:
            sg = self._exact_sign(cond, rc, k, ball)
        except ArithmeticError:
            sg = balls()
            if sg == UNDECIDED:
                raise
            return sg
        return balls() if sg == UNDECIDED else sg

    def _exact_sign(self, cond: Condition, rc: Algebraic, k: int, ball, maxprec: int = 1024):
        """The sign of g on branch k at rc where balls alone do not decide it: 0 when
        the numerator vanishes there exactly (and the denominator does not); with
        Δ = 0 exactly, g evaluated with √Δ = 0; '?' otherwise."""
        if cond.delta is None:
            if self.vanishes_at(cond.N[0], rc, k) and not self.vanishes_at(cond.D[0], rc, k):
                return 0
            return UNDECIDED
        if not self.vanishes_at(cond.delta, rc, k):
            if self._root_with_sqrt(cond.N, cond.delta, rc, k, ball,
                                    lambda: (cond.numerator_norm(), self._split_norm_resultant(cond)),
                                    self._split_ring_parts(cond)) and \
                    self._root_with_sqrt(cond.D, cond.delta, rc, k, ball) is False:
                return 0
            return UNDECIDED
        return decide(lambda p: _sign_ball(cond, rc.arb(p), ball(p), delta_is_zero=True), 128, maxprec)

    def _split_norm_resultant(self, cond: Condition):
        """Res_λ(cp, N₀² - N₁²Δ) (primitive, :meth:`resultant`'s polynomial) as the product of
        the resultants of its split, Res(c)·Res(g)²·Res(Q) (:meth:`Condition.critical_norms`:
        the same polynomial, their resultants known from the table); None without a split."""
        if cond.split is None or self.lc.degree() > 0 or cond._lrq is None or cond._lrq[1].is_zero():
            return None
        c, ((g, Q), _d) = cond.split_parts()
        Rg = self.resultant(g)
        return primitive(self.resultant(c) * Rg * Rg * self.resultant(Q))

    def _split_ring_parts(self, cond: Condition):
        """c, g, Q of the split of the numerator's norm (N₀² - N₁²Δ ≡ 4c·g²·Q modulo cp) as
        elements of the engine's ring, or None without a split."""
        if cond.split is None or cond._lrq is None or cond._lrq[1].is_zero():
            return None
        parts = cond._ring_parts
        if parts is None:
            parts = cond._ring_parts = [cond.c] + [lr_to_ring(q) for q in cond.split[0]]
        return parts

    def _root_with_sqrt(self, P, delta, rc, k, ball, norm=None, parts=None, maxprec: int = 1024):
        """Whether P₀ + P₁√Δ vanishes on branch k at rc, where Δ > 0: exactly when the
        norm P₀² - P₁²Δ vanishes (exact test) and P₀ = -P₁√Δ, that is P₁ = 0 (then
        P₀ = 0 too) or P₀, P₁ of opposite signs (balls; both are non-zero then).
        None when undecided.  ``norm``: () -> (the norm as :func:`norm_mpoly` makes it, its
        resultant), when the caller knows them.  ``parts``: c, g, Q with P₀² - P₁²Δ ≡ 4c·g²·Q
        modulo cp (:meth:`Condition.critical_norms`): at r = rc and a root λ of cp the norm
        vanishes iff one of them does, smaller polynomials to test (the norm itself where
        one of those tests is undecided)."""
        P0, P1 = P
        if not P1:                     # the norm is (a positive multiple of) P₀²: the zeros of P₀
            return self.vanishes_at(P0, rc, k)
        zero = None
        if parts is not None:
            try:
                zero = any(self.vanishes_at(h, rc, k) for h in parts)
            except Undecided:
                zero = None
        if zero is None:
            M, R = norm() if norm is not None else (None, None)
            zero = self.vanishes_at(self._norm_of(P0, P1, delta, M, R), rc, k)
        if not zero:
            return False
        if not P1 or self.vanishes_at(P1, rc, k):
            return True
        t0, t1 = ring_terms(P0), ring_terms(P1)
        n = max((max(i, j) for _c, i, j in t0 + t1), default=0)

        def opposite(p):
            Rp, Lp = _powers(rc.arb(p), n), _powers(ball(p), n)
            v0, v1 = _eval_terms(t0, Rp, Lp), _eval_terms(t1, Rp, Lp)
            if (v0 > 0 or v0 < 0) and (v1 > 0 or v1 < 0):
                return (v0 > 0) != (v1 > 0)
            return None
        return decide(opposite, 128, maxprec, undecided=lambda v: v is None)

    def _common_roots(self, h, rc: Algebraic):
        """The common roots of cp(rc, λ) and h(rc, λ): True when h(rc, λ) ≡ 0, False when
        there is none, else prec -> certified balls around the real ones.  Three routes,
        cheapest first, each exact or certified:

        1. no common root when Res_λ(h, cp) does not vanish at rc (cp monic in λ up to a
           constant: Res_λ(h, cp)(rc) = ±c^k Π h(rc, λ_i) over the roots λ_i of cp(rc, λ),
           an identity of polynomials that evaluation at rc respects), decided exactly
           over Z: the minimal polynomial of rc does not divide the resultant;
        2. where it vanishes, some root of cp(rc, λ) is a root of h: every one when the
           squarefree part of cp(rc, λ) (a rational leading coefficient) divides h(rc, λ)
           exactly (a division in Q(rc)[λ] without inverses; it happens where n* is 0/0 on
           every branch); else, when certified balls exclude h = 0 at every root of
           cp(rc, λ) but one, that one is the common root (:meth:`_single_common_root`);
        3. else the gcd in Q(rc)[λ]; of degree 1, or 2 with distinct roots, its roots are
           enclosed as it comes (up to a factor of Q(rc)), else it is made monic (an inverse in
           Q(rc)) and squarefree: evaluating a gcd of pseudo-remainders at a ball instead lost the
           branches of (ab)^12(cb)^12 at 1024 bits."""
        m = nf.modulus(rc)
        if not isinstance(h, PolyElement):
            h = to_ring(sp.expand(expr(h)))
        # route 1 before h(rc, λ) is formed: R(rc) ≠ 0 also proves h(rc, λ) ≢ 0 (Π h(rc, λ_i) ≠ 0);
        # m irreducible divides R iff gcd(R, m) ≠ 1 (a gcd over Z: cheaper than R mod m over Q)
        R = self._resultant_of(h) if self.lc.degree() <= 0 else None
        if R is not None and not R.is_zero() and R.gcd(m.numer()).degree() <= 0:
            return False
        hk = nf.kpoly(h, m)
        if not hk:
            return True
        if R is not None:
            if not R.is_zero():
                if self.branches_at(rc) is not None and nf.divides(self._sqf[rc.key()], hk, m):
                    sqf = self._sqf[rc.key()]          # every root of cp(rc, λ) is a root of h
                    return lambda prec: nf.real_roots(sqf, rc, prec)
                single = self._single_common_root(h, rc)
                if single is not None:
                    return single
        G = self._gcd_modulo(h, hk, m)
        if len(G) == 1:
            return False
        if len(G) == 2 or len(G) == 3 and nf.squarefree_quadratic(G, m):
            # squarefree already: its roots enclosed as it comes (no inverse in Q(rc)), and, where
            # those enclosures leave the zero test undecided, those of the monic gcd (an inverse)
            def roots(prec):
                return nf.real_roots(G, rc, prec)
            roots.fallback = lambda: _monic_roots(self._monic_modulo(G, m), rc)   # type: ignore[attr-defined]
            return roots
        G = self._monic_modulo(G, m, squarefree=True)
        return lambda prec: nf.real_roots(G, rc, prec)

    def _gcd_modulo(self, h, hk, m):
        """gcd(cp, h) in Q[r]/(m)[λ] as it comes (``nf.gcd``, not monic; hk = h in Q[r]/(m)[λ]), once
        per h and m: the gcd is computed in Q[r]/(m), so it is the same object at every root of m (a
        critical value's conjugates are critical values too)."""
        key = (h if isinstance(h, PolyElement) else id(h), str(m))
        entry = self._gcds.get(key)
        if entry is None or entry[0] is not h and not isinstance(h, PolyElement):
            entry = self._gcds[key] = (h, nf.gcd(nf.kpoly(self.ring_cp, m), hk, m, make_monic=False))
        return entry[1]

    def _monic_modulo(self, G, m, squarefree: bool = False):
        """G (a gcd of :meth:`_gcd_modulo`) made monic in Q[r]/(m)[λ] (``nf.monic``), or its squarefree
        part, once per G: the same at every root of m."""
        entry = self._monics.get(id(G))
        if entry is None or entry[0] is not G:
            entry = self._monics[id(G)] = [G, nf.monic(G, m), None]
        if not squarefree:
            return entry[1]
        if entry[2] is None:
            entry[2] = nf.squarefree(entry[1], m)[0]
        return entry[2]

    def _norm_of(self, P0, P1, delta, M=None, R=None):
        """:func:`norm` of P₀ + P₁√Δ, memoised by the identity of the three (the same object
        for the same parts: the exact tests at other points find their work done); ``M``
        that norm as :func:`norm_mpoly` makes it, when the caller holds it already, ``R`` its
        resultant (:meth:`_split_norm_resultant`)."""
        key = (id(P0), id(P1), id(delta))
        entry = self._norms.get(key)
        if entry is None or entry[0] is not P0 or entry[1] is not P1 or entry[2] is not delta:
            M = norm_mpoly(P0, P1, delta) if M is None else M
            h = mpoly_to_ring(M)
            if self.lc.degree() <= 0:        # its resultant from M itself (no conversion back)
                R = self.resultant(M) if R is None else R
                self._resultant_ids[h] = (h, R)     # keyed as _resultant_of keys a ring element
            entry = self._norms[key] = (P0, P1, delta, h)
        return entry[3]

    def _resultant_of(self, h) -> flint.fmpz_poly:
        """:meth:`resultant` of the polynomial h, memoised by its value (a ring element) or
        its identity (the same h is tested at many r)."""
        content = isinstance(h, PolyElement)
        key = h if content else id(h)
        entry = self._resultant_ids.get(key)
        if entry is None or not content and entry[0] is not h:
            if content and any(e[2] or e[3] or e[4] or e[5] for e in h.itermonoms()):
                raise ValueError("polynomial still depends on x, u, v or s")      # as nf.kpoly says
            entry = self._resultant_ids[key] = (h, self.resultant(h))
        return entry[1]

    def _single_common_root(self, h, rc: Algebraic, maxprec: int = 4096):
        """Given that cp(rc, λ) and h(rc, λ) have a common root (route 1 of
        :meth:`_common_roots`): prec -> [the real common root's ball] or [] (it is not
        real), when at some precision P ≤ ``maxprec`` certified balls exclude h = 0 at
        every distinct root of cp(rc, λ) (the roots of its squarefree part) but one, which
        is then the common root, or but a pair of complex conjugate roots (h and cp are real
        at the real rc: the common roots are closed under conjugation, so both are common,
        and neither is real); balls asked below P are made at P.  None when no precision
        decides so (the gcd decides then)."""
        if self.branches_at(rc) is None:
            return None
        sqf = self._sqf[rc.key()]
        try:
            terms = ring_terms(h)
        except ValueError:                  # h still has √Δ: the gcd decides
            return None
        in_lambda = _lambda_polys(terms)

        seen = []                            # how many roots balls left at each precision tried

        def candidates(prec):
            roots = nf.root_balls(sqf, rc, prec)
            if roots is None:
                return None
            with precision(prec + GUARD):
                R = rc.arb(prec)                   # h(rc, λ)'s coefficients, balls at this precision
                at_rc = [flint.arb_poly(p)(R) for p in in_lambda]
                left = [i for i, z in enumerate(roots) if _horner(at_rc, z).contains(0)]
                seen.append(len(left))
                if len(left) == 2 and _conjugate_pair(roots, *left):
                    return []                    # both common (h is real), neither real
                if len(left) != 1:
                    return None
                left = [roots[i] for i in left]
                z = left[0]
                if z.imag > 0 or z.imag < 0:
                    return []
                conj = z.conjugate()
                if not z.overlaps(conj) or any(w is not z and w.overlaps(conj) for w in roots):
                    return None
                return [z.real]
        prec = 128
        while prec <= maxprec:
            found = candidates(prec)
            if found is not None:
                return _at_least(candidates, prec, found)
            if len(seen) >= 2 and seen[-1] == seen[-2] >= 2 and prec >= 512:
                return None                      # several real roots stay: likely all common, the gcd says
            prec *= 2
        return None

    def vanishes_at(self, h, rc: Algebraic, branch: int, maxprec: int = 1024) -> bool:
        """Exact test that the polynomial h(r, λ) (an expression or an element of
        ``poly.RING``) vanishes on branch ``branch`` at r = rc:
        G = gcd(cp(λ; rc), h(rc, λ)) is computed in Q(rc)[λ]; h vanishes there iff
        the branch's eigenvalue is a root of G, decided by disjoint certified balls."""
        content = isinstance(h, PolyElement)        # the same polynomial rebuilt (a norm, a condition): one test
        key = (h if content else id(h), rc.key())
        entry = self._common.get(key)
        if entry is None or not content and entry[0] is not h:
            entry = self._common[key] = (h, self._common_roots(h, rc), {})
        G, known = entry[1], entry[2]
        if G is True or G is False:
            return G
        if (branch, maxprec) not in known:        # the balls' answer, once per branch
            known[branch, maxprec] = self._vanishes_on(G, rc, branch, maxprec)
        return known[branch, maxprec]

    def _vanishes_on(self, G, rc: Algebraic, branch: int, maxprec: int) -> bool:
        """Whether branch ``branch`` at rc is one of the common roots G (:meth:`_common_roots`'
        balls), by disjoint certified balls; Undecided when they do not separate."""
        branches = self.branches_at(rc)
        if branches is None or branch >= len(branches):
            raise Undecided("branch not isolated at this point")
        for zeros_at, prec, top in self._attempts(G, maxprec):
            while prec <= top:
                zeros = zeros_at(prec)
                balls = [b(prec) for b in branches]
                if zeros is not None:
                    mine = balls[branch]
                    others = [b for k, b in enumerate(balls) if k != branch and not b.overlaps(mine)]
                    hit = [z for z in zeros if z.overlaps(mine)]
                    if all(not z.overlaps(o) for z in hit for o in others):
                        return bool(hit)
                prec *= 2
        raise Undecided("zero test undecided")

    def _attempts(self, G, maxprec: int):
        """What :meth:`_vanishes_on` tries in turn: (enclosures, first precision, last precision), each
        of :func:`_zero_routes` from 128 bits to ``maxprec``, doubling; a subclass may add attempts.  Any
        answer the disjoint balls give is exact, whatever the route and precision: the order of the
        attempts changes the time, never the answer, nor whether there is one."""
        for zeros_at in _zero_routes(G):
            yield zeros_at, 128, maxprec


def _union(factor_lists) -> list:
    """The (factor, text) pairs of several lists of :meth:`Spectrum._factors`, each once, in
    the order of :func:`poly.irreducible_factors` (by degree, then coefficients): the list
    the product of those polynomials would have."""
    seen = {k: f for fl in factor_lists for f, k in fl}
    return sorted(((f, k) for k, f in seen.items()), key=lambda fk: factor_order((fk[0], 1)))


def _lambda_coefficients(G: flint.fmpz_mpoly) -> list[flint.fmpz_poly]:
    """G ∈ Z[r][λ] (an fmpz_mpoly in (r, λ, s) free of s) as its coefficients in λ,
    lowest first, each an fmpz_poly in r."""
    if G.is_zero():
        return [flint.fmpz_poly(0)]
    dr, dl, _ds = G.degrees()
    rows: list[list] = [[0] * (dr + 1) for _ in range(dl + 1)]
    for (er, el, _es), c in zip(G.monoms(), G.coeffs()):
        rows[el][er] = c
    return [flint.fmpz_poly(row) for row in rows]


def _norm_modulo(g: list, cp: list) -> flint.fmpz_poly:
    """Res_λ(cp, g) for cp monic in λ up to a constant factor (cp's leading coefficient a
    non-zero integer c): the determinant of multiplication by g on Q[r][λ]/(cp) in the
    basis 1, λ, ..., λ^{n-1}, which is Π g(λ_i) over the roots λ_i of cp (cp/c monic: the
    reduction over Q[r], no power of c accumulates in the coefficients), returned as the
    numerator of that determinant (a non-zero rational multiple of the resultant: the same
    zeros in r).  Univariate python-flint arithmetic, no Sylvester matrix."""
    n = len(cp) - 1
    lead = flint.fmpq(int(cp[n][0]))
    monic = [flint.fmpq_poly(c) / lead for c in cp[:n]]
    zero = flint.fmpq_poly(0)

    def reduce(h):
        h = list(h) + [zero] * max(0, n - len(h))
        for k in range(len(h) - 1, n - 1, -1):          # λ^k ≡ -Σ monic[i] λ^(k-n+i)
            t = h[k]
            if t.is_zero():
                continue
            for i in range(n):
                h[k - n + i] -= t * monic[i]
            h[k] = zero
        return h[:n]

    cols = [reduce([flint.fmpq_poly(c) for c in g])]
    for _ in range(n - 1):
        cols.append(reduce([zero] + cols[-1]))
    A = [[cols[j][i] for j in range(n)] for i in range(n)]
    if n == 1:
        det = A[0][0]
    elif n == 2:
        det = A[0][0] * A[1][1] - A[0][1] * A[1][0]
    elif n == 3:
        (a, b, c), (d, e, f), (p, q, t) = A
        det = a * (e * t - f * q) - b * (d * t - f * p) + c * (d * q - e * p)
    else:
        raise ValueError("multiplication determinant implemented for degree ≤ 3")
    return det.numer()


def _root_ball(sqf, rc, k, isolated=None):
    """prec -> a ball around the k-th largest real root of a squarefree K[λ] polynomial;
    ``isolated`` (prec -> the real roots or None) is shared by the roots of one polynomial,
    so that each precision isolates them once.  A ball isolated at a higher precision than
    asked is as good (it is tighter), and the roots are often isolated only from some
    precision on (huge coefficients: :meth:`Spectrum._branches_at` found them at the
    precision it seeds ``isolated`` with): the smallest successful isolation at or above
    ``prec`` is used, else prec, 2·prec, 4·prec are tried, else the tightest ball known
    (a true ball, only coarser: the caller's own test then stays undecided, never wrong).
    Every isolation certifies the same number of real roots in the same order, so the
    k-th ball encloses the same root at every precision."""
    isolated = {} if isolated is None else isolated

    def ball(prec):
        above = sorted(p for p, v in isolated.items() if p >= prec and v is not None)
        if above:
            return isolated[above[0]][k]
        for p in (prec, 2 * prec, 4 * prec):
            if p not in isolated:
                isolated[p] = nf.real_roots(sqf, rc, p)
            if isolated[p] is not None:
                return isolated[p][k]
        known = [p for p, v in isolated.items() if v is not None]
        if not known:
            raise Undecided("the real roots could not be isolated")
        return isolated[max(known)][k]
    return ball


def _zero_routes(G):
    """The enclosures of the common roots (prec -> balls) to try in turn: G itself, then, for
    a gcd taken as it comes, those of the monic gcd (made once, on first need)."""
    yield G
    if getattr(G, "fallback", None) is not None:
        if getattr(G, "monic", None) is None:
            G.monic = G.fallback()
        yield G.monic


def _monic_roots(M, rc):
    """prec -> the real roots of a gcd G ∈ Q(rc)[λ] (squarefree) enclosed from M, G made monic."""
    return lambda prec: nf.real_roots(M, rc, prec)


def _conjugate_pair(roots, i: int, j: int) -> bool:
    """roots[i], roots[j] (disjoint certified balls around distinct roots, every root in
    one) enclose two complex conjugate non-real roots: roots[i] excludes the real axis and
    its conjugate ball meets roots[j] and no other ball (the conjugate of its root is a root,
    in a ball meeting that conjugate ball)."""
    z = roots[i]
    if not (z.imag > 0 or z.imag < 0):
        return False
    conj = z.conjugate()
    return [k for k, w in enumerate(roots) if w.overlaps(conj)] == [j]


def _at_least(compute, P: int, found):
    """prec -> compute(prec) for prec > P (memoised), ``found`` (= compute(P)) below: a
    ball made at a higher precision than asked is as good."""
    done = {P: found}

    def at(prec):
        if prec <= P:
            return found
        if prec not in done:
            done[prec] = compute(prec)
        return done[prec]
    return at


def _at_r(P, t) -> flint.fmpq_poly:
    """P(t, λ) ∈ Q[λ] for P in the engine's ring (r, λ only) and a rational t."""
    t = to_fmpq(t)
    coeffs: dict = {}
    for c, i, j in ring_terms(P):
        coeffs[j] = coeffs.get(j, Q(0)) + c * t ** i
    n = max(coeffs, default=0)
    return flint.fmpq_poly([coeffs.get(j, Q(0)) for j in range(n + 1)])



def _apart(a: Algebraic, b: Algebraic) -> bool:
    """a < b read off the isolating intervals alone (no refinement, no comparison): True
    only when it is certain that way; False says nothing."""
    return a.hi < b.lo or (a.hi == b.lo and not (a.lo == a.hi and b.lo == b.hi))


def less(a, b) -> bool:
    """a < b, exact: from the isolating intervals where they are apart (an exact comparison
    would then refine nothing either), else by the exact comparison."""
    if a is b:                  # one object: a = a, without a comparison
        return False
    if isinstance(a, Algebraic) and isinstance(b, Algebraic):
        if _apart(a, b):
            return True
        if _apart(b, a):
            return False
    return a < b


def at_most(a, b) -> bool:
    """a ≤ b, exact (as :func:`less`)."""
    if a is b:                  # one object: a = a, without a comparison
        return True
    if isinstance(a, Algebraic) and isinstance(b, Algebraic):
        if _apart(a, b):
            return True
        if _apart(b, a):
            return False
    return a <= b


def same(a, b) -> bool:
    """a = b, exact (as :func:`less`)."""
    if a is b:                  # one object: a = a, without a comparison
        return True
    if isinstance(a, Algebraic) and isinstance(b, Algebraic) and (_apart(a, b) or _apart(b, a)):
        return False
    return a == b


def strictly_between(lo, a: Algebraic, hi) -> bool:
    """lo < a < hi, exact: from the isolating intervals where they are apart (where an exact
    comparison would not refine them either), else by exact comparisons."""
    if isinstance(lo, Algebraic) and isinstance(hi, Algebraic) and _apart(lo, a) and _apart(a, hi):
        return True
    return lo < a < hi


def sorted_numbers(numbers: list) -> list:
    """``sorted(numbers)`` (distinct Algebraic numbers): by the left ends of the isolating
    intervals when consecutive intervals are then apart (the order is certain, and exact
    comparisons would refine nothing), else by exact comparisons."""
    out = sorted(numbers, key=lambda a: a.lo)
    if all(_apart(a, b) for a, b in zip(out, out[1:])):
        return out
    return sorted(numbers)


def _alg(a) -> Algebraic:
    return a if isinstance(a, Algebraic) else Algebraic.rational(a)


def simplest_between(lo: flint.fmpq, hi: flint.fmpq) -> flint.fmpq:
    """The rational with the smallest denominator in [lo, hi] (continued fractions)."""
    lo, hi = Q(lo), Q(hi)
    if lo > hi:
        raise ValueError("empty interval")
    fl = lo.floor()
    if Q(fl) == lo:
        return lo
    if Q(fl) + 1 <= hi:
        return Q(fl) + 1
    return Q(fl) + 1 / simplest_between(1 / (hi - fl), 1 / (lo - fl))


def simple_rational_between(a: Algebraic, b: Algebraic) -> flint.fmpq:
    """A rational strictly between a < b with a small denominator (readable samples):
    the simplest rational in the middle half of a rational gap between them."""
    width = Q(1, 2)
    while True:
        a.refine(width)
        b.refine(width)
        lo, hi = a.hi, b.lo
        if lo < hi:
            w = (hi - lo) / 4
            t = simplest_between(lo + w, hi - w)
            if a < t < b:
                return t
        width /= 16
