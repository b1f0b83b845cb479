"""The self-similar data at a point where the generic datum degenerates: exactly in Q(r₀).

Where two or three eigenvalue branches meet at an algebraic r₀ (a double or triple root
λ₀ of cp(r₀, λ)), the generic eigenvector (Cramer's rule on two rows of M - λI) is 0/0 on
every choice of rows, or the branches cannot be isolated at all: the engine left such points
undecided.  There, λ₀ lies in K = Q(r₀) (the root of the linear gcd(cp, cp'), or of a
square (λ - λ₀)²), and the self-similar data of the branch are *all* the eigenvectors:
E = ker(M(r₀) - λ₀I), computed exactly over K (Gaussian elimination, exact zero tests).
The point is feasible on the branch iff some q(0) ∈ E with q_1(0) = -1 (the normalisation;
a word starts with a, so q_1(0) < 0 is needed) realises the word.  This is decided here:

* every requirement on a velocity (u = q_2(0) > 0, q_i(t_{k-1}) < 0) is *linear* in q(0)
  (q(t_k) = K_k ⋯ K_1 q(0)): on the affine space {q ∈ E : q_1 = -1} of dimension 0, 1 or 2
  they cut an open polyhedron, found exactly (Fourier–Motzkin over K); empty: the point
  fails (proved: no datum of the eigenspace has the approaching pairs of the word);
* otherwise a witness q(0) (rational parameters inside the polyhedron) is run exactly in K
  (the times t_k = -p_i/q_i, positions affine in x), its position map's fixed point
  x = (a - d ± √Δ)/(2c) enclosed in balls, and every requirement checked at it with certified
  signs: all hold, the point is feasible (proved by the witness);
* on a line of data (E of dimension 2) the run is also made symbolically in the parameter s
  (:class:`Family`): the real roots of the norms to Q[s] of every part of every requirement cut
  the s-line into open cells where each has a constant sign; one exact witness per cell, and the
  isolated s where c or Δ vanishes (f affine, or x₊ = x₋) checked there: none feasible, the point
  fails (proved); else it stays undecided (a plane of data, E of dimension 3, only by witnesses).

x₊/x₋ at such a point are the fixed points (a - d ± √Δ)/(2c) of p_3(t_n)/p_1(t_n) = (ax + b)/(cx + d)
as the run gives them (where c = 0, the affine map's b/(d - a) for both, as elsewhere).
* dominance at a multiple eigenvalue fails exactly (cp'(λ₀) = 0, a polynomial in K): the
  point is never stable.

K's elements are python-flint ``fmpq_poly`` in r reduced modulo the minimal polynomial of r₀
(:mod:`certify.algebra.numberfield`); a non-zero element's sign is decided by balls at r₀
(it is non-zero at r₀: the minimal polynomial is irreducible).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from itertools import product

import flint

from certify.algebra import numberfield as nf
from certify.algebra.algebraic import Algebraic
from certify.algebra.balls import decide, ends, precision
from certify.algebra.branches import simple_rational_between, simplest_between
from certify.algebra.poly import Q, to_field, to_ring
from certify.dynamics.model import INDEX, collide
from certify.errors import UNDECIDED


class K:
    """An element of Q(r₀): an fmpq_poly in r modulo m, m the minimal polynomial of r₀."""

    __slots__ = ("c", "field")

    def __init__(self, c, fld: KField):
        self.c, self.field = nf.reduce(c, fld.m), fld

    def _lift(self, o) -> K:
        return o if isinstance(o, K) else K(flint.fmpq_poly([Q(o)]), self.field)

    def __add__(self, o):
        return K(self.c + self._lift(o).c, self.field)

    __radd__ = __add__

    def __sub__(self, o):
        return K(self.c - self._lift(o).c, self.field)

    def __rsub__(self, o):
        return self._lift(o) - self

    def __neg__(self):
        return K(-self.c, self.field)

    def __mul__(self, o):
        return K(self.c * self._lift(o).c, self.field)

    __rmul__ = __mul__

    def __truediv__(self, o):
        o = self._lift(o)
        if o.is_zero():
            raise ZeroDivisionError("division by 0 in Q(r0)")
        g, inv, _ = o.c.xgcd(self.field.m)
        return K(self.c * inv / g, self.field)

    def __rtruediv__(self, o):
        return self._lift(o) / self

    def is_zero(self) -> bool:
        return self.c.is_zero()

    def arb(self, prec: int) -> flint.arb:
        """A certified ball around the element's value at r₀."""
        return nf.arb_of(self.c, self.field.r0.arb(prec))

    def sign(self) -> int:
        """The exact sign: 0 iff the residue is 0, else by balls of growing precision."""
        if self.is_zero():
            return 0
        prec = 64
        while True:
            with precision(prec + 32):
                v = self.arb(prec)
                if v > 0 or v < 0:
                    return 1 if v > 0 else -1
            prec *= 2


@dataclass
class KField:
    """K = Q(r₀) = Q[r]/(m)."""

    r0: Algebraic
    m: flint.fmpq_poly = field(init=False)

    def __post_init__(self):
        self.m = nf.modulus(self.r0)

    def of(self, c) -> K:
        return K(flint.fmpq_poly(c) if not isinstance(c, flint.fmpq_poly) else c, self)

    @property
    def r(self) -> K:
        return self.of(flint.fmpq_poly([0, 1]))


def multiple_eigenvalue(spec, r0: Algebraic) -> tuple[KField, K, int] | None:
    """(K, λ₀, multiplicity) when cp(r₀, λ) has a multiple root λ₀ (then in K, exactly):
    the root of the linear gcd(cp, cp') (double), or of gcd = (λ - λ₀)² (triple, cp cubic);
    None otherwise."""
    F = KField(r0)
    cp = nf.kpoly(spec.ring_cp, F.m)
    _sqf, g = nf.squarefree(cp, F.m)
    if len(g) == 2:
        g = nf.monic(g, F.m)
        return F, -F.of(g[1]), 2
    if len(g) == 3:
        g = nf.monic(g, F.m)
        lam0 = -F.of(g[1]) / 2
        if (F.of(g[2]) - lam0 * lam0).is_zero():
            return F, lam0, 3
    return None


def kernel(A: list[list[K]]) -> list[list[K]]:
    """A basis of ker A over K (exact Gaussian elimination)."""
    rows = [list(row) for row in A]
    n = len(rows[0])
    pivots, r = [], 0
    for j in range(n):
        piv = next((i for i in range(r, len(rows)) if not rows[i][j].is_zero()), None)
        if piv is None:
            continue
        rows[r], rows[piv] = rows[piv], rows[r]
        inv = 1 / rows[r][j]
        rows[r] = [e * inv for e in rows[r]]
        for i in range(len(rows)):
            if i != r and not rows[i][j].is_zero():
                f = rows[i][j]
                rows[i] = [a - f * b for a, b in zip(rows[i], rows[r])]
        pivots.append(j)
        r += 1
    zero, one = rows[0][0] - rows[0][0], rows[0][0] - rows[0][0] + 1
    basis = []
    for free in (j for j in range(n) if j not in pivots):
        v = [zero] * n
        v[free] = one
        for i, pj in enumerate(pivots):
            v[pj] = -rows[i][free]
        basis.append(v)
    return basis


def _apply(q, word: str, rK):
    out = [tuple(q)]
    for letter in word:
        q = collide(letter, q, rK)
        out.append(tuple(q))
    return out


def _strict_interval(cons, F):
    """The open interval of s ∈ R (ends in K or None for ±∞) where α + βs > 0 for every
    (α, β) of ``cons``; None when empty (exact)."""
    lo = hi = None
    for a, b in cons:
        sb = b.sign()
        if sb == 0:
            if a.sign() <= 0:
                return None
            continue
        t = -a / b
        if sb > 0:
            lo = t if lo is None or (t - lo).sign() > 0 else lo
        else:
            hi = t if hi is None or (t - hi).sign() < 0 else hi
    if lo is not None and hi is not None and (hi - lo).sign() <= 0:
        return None
    return lo, hi


def _samples(iv, F) -> list:
    """A few rationals strictly inside the open interval ``iv`` (ends in K or None)."""
    lo, hi = iv

    def rational_of(e, side):
        prec = 64
        while True:
            with precision(prec + 32):
                b = e.arb(prec)
                lo_, hi_ = ends(b)
            if hi_ - lo_ < Q(1, 10 ** 6) or prec > 1024:
                return hi_ if side > 0 else lo_
            prec *= 2
    if lo is None and hi is None:
        return [Q(0), Q(1), Q(-1), Q(1, 2), Q(-1, 2), Q(10), Q(-10)]
    if lo is None:
        h = rational_of(hi, -1)
        return [h - Q(1, 100), h - 1, h - Q(1, 10), h - 10]
    if hi is None:
        a = rational_of(lo, 1)
        return [a + Q(1, 100), a + 1, a + Q(1, 10), a + 10]
    a, h = rational_of(lo, 1), rational_of(hi, -1)
    if a >= h:
        return []
    w = h - a
    return [simplest_between(a + w * k / 8, a + w * (k + 1) / 8) for k in (3, 2, 5, 1, 6)] + [a + w / 2]


class Eigenspace:
    """The self-similar data of ``word`` at r₀ on an eigenvalue λ₀ of multiplicity ≥ 2."""

    def __init__(self, word: str, Mq, spec, r0: Algebraic):
        self.word, self.r0 = word, r0
        found = multiple_eigenvalue(spec, r0)
        self.ok = found is not None
        if not self.ok:
            return
        self.F, self.lam0, self.multiplicity = found
        F = self.F
        A = [[F.of(Mq[i][j]) - (self.lam0 if i == j else 0) for j in range(3)] for i in range(3)]
        basis = kernel(A)
        self.dim = len(basis)
        lead = next((v for v in basis if not v[0].is_zero()), None)
        self.q1_zero = lead is None
        if lead is None:
            return
        qa = [e * (-1 / lead[0]) for e in lead]
        dirs = [[e - b[0] / lead[0] * f for e, f in zip(b, lead)] for b in basis if b is not lead]
        self.qa, self.dirs = qa, dirs
        rK = F.r
        self.runs = [_apply(qa, word, rK)] + [_apply(d, word, rK) for d in dirs]
        self.letters = [INDEX[word[-1]]] + [INDEX[c] for c in word]

    def contains(self, ball) -> bool:
        """λ₀'s ball meets ``ball`` (the branch's eigenvalue) at 256 bits."""
        with precision(300):
            return self.lam0.arb(256).overlaps(ball(256))

    # -- linear requirements: u = q_2(0) > 0, q_i(t_k) < 0
    def linear(self, name: str, sign: int):
        """(α, β...) with sign·q = α + Σβ_j s_j, for a requirement on a velocity; None otherwise."""
        if name == "u = q_2(0)":
            i, k = 1, 0
        elif name.startswith("q_"):
            i, k = int(name[2]) - 1, int(name[name.index("t_") + 2:-1])
        else:
            return None
        return tuple(run[k][i] * sign for run in self.runs)

    def word_velocities(self) -> list:
        """The linear forms of the whole word's requirements on velocities: u = q_2(0) > 0 and
        -q_{i_k}(t_{k-1}) > 0 for every collision k (each pair approaches before it collides)."""
        forms = [tuple(run[0][1] for run in self.runs)]
        for k, c in enumerate(self.word, 1):
            forms.append(tuple(-run[k - 1][INDEX[c]] for run in self.runs))
        return forms

    def realises_no_velocities(self) -> bool:
        """No datum of E (q_1(0) = -1) meets the velocities' requirements of the whole word
        (:meth:`word_velocities`; exact, memoised): then no datum of E realises the word, whatever
        its positions.  (A pair with q_{i_k}(t_{k-1}) = 0 on all of E is such a case.)"""
        if "_no_velocities" not in self.__dict__:
            self._no_velocities = self.polyhedron(self.word_velocities()) is None
        return self._no_velocities

    def polyhedron(self, linear) -> list | None:
        """Parameters s where every linear form α + β·s is > 0: None when empty (exact), else
        a list of sample points inside (rational parameters)."""
        d = len(self.dirs)
        if d == 0:
            return [()] if all(a.sign() > 0 for a, *_ in linear) else None
        if d == 1:
            iv = _strict_interval([(a, b) for a, b in linear], self.F)
            return None if iv is None else [(s,) for s in _samples(iv, self.F)]
        # d = 2: Fourier–Motzkin on s_2 (positive combinations of strict inequalities stay strict)
        pos = [c for c in linear if c[2].sign() > 0]
        neg = [c for c in linear if c[2].sign() < 0]
        flat = [(a, b) for a, b, c in linear if c.sign() == 0]
        for (a1, b1, c1), (a2, b2, c2) in product(pos, neg):
            flat.append((a1 * (-c2) + a2 * c1, b1 * (-c2) + b2 * c1))
        iv = _strict_interval(flat, self.F)
        if iv is None:
            return None
        out = []
        for s1 in _samples(iv, self.F):
            iv2 = _strict_interval([(a + b * s1, c) for a, b, c in linear], self.F)
            if iv2 is not None:
                out += [(s1, s2) for s2 in _samples(iv2, self.F)[:2]]
        return out

    def family(self) -> Family:
        if getattr(self, "_family", None) is None:
            self._family = Family(self)
        return self._family

    def datum(self, s) -> list[K]:
        return [e + sum((d[i] * t for d, t in zip(self.dirs, s)), 0 * e) for i, e in enumerate(self.qa)]

    def run(self, s):
        """The exact run of the word from q(0) = datum(s), p(0) = (1, 0, x): [(p, q)] with
        p_i = (P0, P1) (P0 + x P1), in K; None when some q_i vanishes before its collision."""
        F = self.F
        q = self.datum(s)
        zero, one = F.of(0), F.of(1)
        p = [(one, zero), (zero, zero), (zero, one)]
        out = [(p, tuple(q))]
        for letter in self.word:
            i = INDEX[letter]
            if q[i].is_zero():
                return None
            w = -1 / q[i]
            t = (p[i][0] * w, p[i][1] * w)
            p = [(P0 + t[0] * qj, P1 + t[1] * qj) for (P0, P1), qj in zip(p, q)]
            p[i] = (zero, zero)
            q = collide(letter, q, F.r)
            out.append((p, tuple(q)))
        return out


RS = flint.fmpq_mpoly_ctx.get(("r", "s"), "lex")
# the largest degree of a norm to Q[s] the cells are made of: beyond it (the resultants of python-flint
# take seconds each, tens of them a point) the point stays undecided; measured in the report of issue 35
NORM_DEGREE = 120


def _rs(c: K):
    """An element of K as a polynomial in r (an fmpq_mpoly in r, s)."""
    return RS.from_dict({(j, 0): e for j, e in enumerate(c.c.coeffs()) if e != 0})


def _rs_ball(f, R: flint.arb, S: flint.arb) -> flint.arb:
    val = flint.arb(0)
    for (i, j), c in f.to_dict().items():
        val += flint.arb(c) * R ** i * S ** j
    return val


class Family:
    """The one-parameter family q(0) = q_a + s·d of an eigenspace of dimension 2 (q_1 = -1), run
    symbolically in s over K (fmpq_mpoly in r, s reduced modulo m): positions as numerators
    (A + xB) over the common denominator D_k = Π q_{i_l}(t_{l-1}), the position map's a, b, c, d.
    :meth:`cuts` lists the polynomials in s whose real roots cut the s-line into open cells on which
    every requirement has a constant sign (with x = (a - d ± √Δ)/(2c) continuous there)."""

    def __init__(self, es: Eigenspace):
        self.es = es
        self.m = RS.from_dict({(j, 0): e for j, e in enumerate(es.F.m.coeffs()) if e != 0})
        r, s = RS.gens()
        red = self.red
        q = [red(_rs(a) + s * _rs(b)) for a, b in zip(es.qa, es.dirs[0])]
        one, zero = RS.from_dict({(0, 0): 1}), RS.from_dict({})
        P = [(one, zero), (zero, zero), (zero, one)]
        self.steps = [(P, q)]
        self.qcuts = []
        for letter in es.word:
            i = INDEX[letter]
            qi = q[i]
            self.qcuts.append(qi)
            P = [(red(A * qi - P[i][0] * qj), red(B * qi - P[i][1] * qj)) for (A, B), qj in zip(P, q)]
            P[i] = (zero, zero)
            q = [red(e) for e in collide(letter, q, r)]
            self.steps.append((P, q))
        (d, c), _p2, (b, a) = P
        self._roots: dict = {}
        self.abcd = self.cancel((a, b, c, d))
        self._witnesses: dict = {}
        self._zeros: dict = {}

    def kpoly(self, f) -> list[flint.fmpq_poly]:
        """f as a polynomial in s over K (coefficients highest first)."""
        d: dict = {}
        for (i, j), c in f.to_dict().items():
            d.setdefault(j, {})[i] = c
        return [flint.fmpq_poly([d.get(j, {}).get(i, 0) for i in range(max(d.get(j, {0: 0})) + 1)])
                for j in range(max(d), -1, -1)]

    def _to_rs(self, fk):
        """A polynomial in s over K (coefficients highest first) as an fmpq_mpoly in r, s."""
        n = len(fk) - 1
        return RS.from_dict({(i, n - j): e for j, c in enumerate(fk) for i, e in enumerate(c.coeffs()) if e != 0})

    def _divide_linear(self, fk, root):
        """f / (s - root) in K[s] when s - root divides f exactly, else None (numberfield.divides,
        numberfield.divide)."""
        m, g = self.es.F.m, [flint.fmpq_poly([1]), -root]
        return nf.divide(fk, g, m) if nf.divides(g, fk, m) else None

    def cancel(self, abcd):
        """The position map's (a, b, c, d) divided by their common factors among the times'
        q_{i_k}(t_{k-1}) (linear in s; exact division in K[s]): the same Möbius map wherever every
        q_{i_k}(t_{k-1}) ≠ 0, that is on every open cell and at every isolated s where the run is
        defined (where one vanishes the run stops: no datum there, as before).  Without it Δ is a
        constant times a square and b, c share most of their roots (the 20-letter words at
        ≈0.16029: degree 19 in s, norms of degree 532), with it the map has a small degree in s."""
        m = self.es.F.m
        if any(e.is_zero() for e in abcd):
            return abcd
        fks = [self.kpoly(e) for e in abcd]
        roots: list = []
        for q in self.qcuts:
            if q.degrees()[1] != 1:
                continue
            q1, q0 = self.kpoly(q)                      # q = q1·s + q0, q1 ≠ 0 in K
            g, inv, _ = q1.xgcd(m)
            root = nf.reduce(-q0 * inv / g, m)
            if all(not (root - e).is_zero() for e in roots):
                roots.append(root)
        changed = False
        for root in roots:
            while min(len(fk) for fk in fks) > 1:
                out = [self._divide_linear(fk, root) for fk in fks]
                if any(o is None for o in out):
                    break
                fks, changed = out, True
        return tuple(self._to_rs(fk) for fk in fks) if changed else abcd

    def witness(self, t, sigma: int) -> Witness:
        key = (str(t), sigma)
        if key not in self._witnesses:
            self._witnesses[key] = Witness(self.es, (t,), sigma)
        return self._witnesses[key]

    def red(self, f):
        return divmod(f, self.m)[1]

    def _x_parts(self):
        """Memoised :meth:`_x_parts_of`."""
        if "_xp" not in self.__dict__:
            self._xp = self._x_parts_of()
        return self._xp

    def special_roots(self, f) -> list:
        """[(g, ρ)]: the real roots ρ of the norm of f with their irreducible factor g (memoised)."""
        key = ("special", id(f))
        if key not in self._roots:
            self._roots[key] = [(g, rho) for g, _e in self.norm(f).factor()[1] if g.degree() > 0
                                for rho in Algebraic.roots(g)]
        return self._roots[key]

    def _x_parts_of(self):
        """(the polynomials of the fixed point, (A, B) -> the parts of A + xB whose signs fix its
        sign), or None where f has no fixed point formula (c ≡ 0 and a ≡ d)."""
        a, b, c, d = self.abcd
        red = self.red
        amd, delta = red(a - d), red((a - d) ** 2 + 4 * b * c)
        if c.is_zero():
            if amd.is_zero():
                return None
            return [amd], lambda A, B: [red(-amd * A + b * B)]                # x = b/(d - a)
        if delta.is_zero():
            return [c], lambda A, B: [red(2 * c * A + amd * B)]               # x = (a - d)/(2c)

        def parts(A, B):
            P, Q = red(2 * c * A + amd * B), B
            return [P, Q, red(P * P - Q * Q * delta)]
        return [c, delta], parts

    def roots(self, name: str | None) -> list | None:
        """The real roots (over Q, memoised) of the norms of the parts of requirement ``name``
        (None: of the times' q_{i_k}(t_{k-1}), c and Δ); None without a fixed point formula."""
        if name in self._roots:
            return self._roots[name]
        found = self._x_parts()
        if found is None:
            return None
        base, parts = found
        if name is None:
            polys = list(self.qcuts) + base
        elif name == "x":
            polys = parts(RS.from_dict({}), RS.from_dict({(0, 0): 1}))
        elif name.startswith("p_"):
            i, k = int(name[2]) - 1, int(name[name.index("t_") + 2:-1])
            polys = parts(*self.steps[k][0][i])
        else:
            polys = []
        out = []
        for f in polys:
            if f.is_zero() or f.degrees()[1] == 0:
                continue
            if f.degrees()[1] * self.es.F.m.degree() > NORM_DEGREE:
                self._roots[name] = None
                return None              # beyond the budget: the point stays undecided
            for g, _e in self.norm(f).factor()[1]:
                if g.degree() > 0:
                    out += Algebraic.roots(g)
        self._roots[name] = out
        return out

    def nonzero_ball(self, f, rho: Algebraic) -> bool:
        """f(r₀, ρ) ≠ 0, proven by balls (up to 2048 bits); False when they do not prove it."""
        for prec in (256, 1024, 2048):
            with precision(prec + 64):
                v = _rs_ball(f, self.es.r0.arb(prec), rho.arb(prec))
                if v > 0 or v < 0:
                    return True
        return False

    def vanishes_at(self, f, g: flint.fmpq_poly, rho: Algebraic):
        """Memoised :meth:`_vanishes_at`."""
        key = (id(f), str(g), str(rho.lo), str(rho.hi))
        if key not in self._zeros:
            self._zeros[key] = (f, self._vanishes_at(f, g, rho))
        return self._zeros[key][1]

    def _vanishes_at(self, f, g: flint.fmpq_poly, rho: Algebraic):
        """Whether f(r₀, ρ) = 0, ρ a real root of the irreducible g ∈ Q[s] (exact): f modulo g in
        K[s] is 0 (every root of g is a root), or its gcd with g is linear with ρ as root; False when
        that gcd is 1; None when it cannot tell."""
        F = self.es.F
        fk = [F.of(c) for c in self.kpoly(f)]                   # highest first
        gq = [c / g[g.degree()] for c in reversed(g.coeffs())]  # monic over Q, highest first
        n = len(gq) - 1
        while len(fk) > n:                                      # f mod g, without growth (g monic)
            lead = fk[0]
            fk = [e - lead * c for e, c in zip(fk[1:], gq[1:])] + fk[n + 1:]
        while fk and fk[0].is_zero():
            fk = fk[1:]
        if not fk:
            return True
        G = nf.gcd([e.c for e in fk], [flint.fmpq_poly([c]) for c in gq], F.m, make_monic=False)
        if len(G) == 1:
            return False
        if len(G) == 2:
            # its root s* = -G₁/G₀ ∈ K is a root of g (G divides g): s* = ρ iff its ball meets ρ's and
            # no other real root's of g (balls of s*, no inverse in K: G's coefficients can be large)
            if rho.is_rational:
                return (F.of(G[0]) * rho.lo + F.of(G[1])).is_zero()
            others = [a for a in Algebraic.roots(g) if not a == rho]
            with precision(700):
                b = -nf.arb_of(G[1], F.r0.arb(600)) / nf.arb_of(G[0], F.r0.arb(600))
                near = [a for a in others if a.arb(600).overlaps(b)]
                if b.overlaps(rho.arb(600)) and not near:
                    return True
                if not b.overlaps(rho.arb(600)):
                    return False
        return None

    def special_status(self, kind: str, rho: Algebraic, g, wanted, prec: int = 512):
        """At s = ρ where c (kind "c": f affine, x = b/(d - a)) or Δ (kind "Δ": x = (a - d)/(2c))
        vanishes (exactly, the caller's test): "holds" when every requirement of ``wanted`` has its
        sign there (balls; the run defined: every q_{i_k}(t_{k-1}) ≠ 0), "fails" when one is
        certified to fail or the run stops (a q_{i_k}(t_{k-1}) = 0 exactly), else None."""
        with precision(prec + 64):
            R, S = self.es.r0.arb(prec), rho.arb(prec)
            qs = [_rs_ball(e, R, S) for e in self.qcuts]
            for e, v in zip(self.qcuts, qs):
                if not (v > 0 or v < 0):
                    return "fails" if self.vanishes_at(e, g, rho) else None
            a, b, c, d = (_rs_ball(e, R, S) for e in self.abcd)
            den = d - a if kind == "c" else 2 * c
            if not (den > 0 or den < 0):
                return None
            x = (b if kind == "c" else a - d) / den
            status = "holds"
            for q in wanted:
                name = q.name
                if name == "x":
                    v = x
                elif name == "u = q_2(0)":
                    v = _rs_ball(self.steps[0][1][1], R, S)
                elif name[:2] in ("p_", "q_"):
                    i, k = int(name[2]) - 1, int(name[name.index("t_") + 2:-1])
                    if name[0] == "q":
                        v = _rs_ball(self.steps[k][1][i], R, S)
                    else:
                        A, B = self.steps[k][0][i]
                        D = flint.arb(1)
                        for v in qs[:k]:
                            D *= v
                        v = (_rs_ball(A, R, S) + x * _rs_ball(B, R, S)) / D
                else:
                    return None
                if (v > 0 and q.sign < 0) or (v < 0 and q.sign > 0):
                    return "fails"
                if not (v > 0 or v < 0):
                    status = None
        return status

    def norm(self, f) -> flint.fmpq_poly:
        """Res_r(f, m) as a polynomial in s over Q: its real roots hold those of f(r₀, s)."""
        if f.degrees()[1] == 0:
            return flint.fmpq_poly([1])
        return flint.fmpq_poly(_s_coeffs(f.resultant(self.m, "r")))


def cell_samples(roots) -> list:
    """A rational in each open cell of the s-line cut at ``roots`` (real algebraic numbers)."""
    roots = sorted(roots)
    distinct = [a for k, a in enumerate(roots) if k == 0 or not a == roots[k - 1]]
    if not distinct:
        return [Q(0)]
    first, last = distinct[0], distinct[-1]
    out = [Q(first.refine(Q(1)).lo.floor() - 1)]
    out += [simple_rational_between(a, b) for a, b in zip(distinct, distinct[1:])]
    return out + [Q(last.refine(Q(1)).hi.floor() + 1)]


def decide_on_cells(es: Eigenspace, wanted, sigma: int):
    """(status, witness).  On an eigenspace of dimension 2 (a line of data q_a + s·d): "holds" (with the
    :class:`Witness` of the cell's sample, or None at an isolated s) when the sample of some
    open cell of the s-line (cut at every root of the requirements' parts, :meth:`Family.roots`) meets
    every requirement of ``wanted`` (certified signs at that exact datum), "fails" when none does and
    no root of c or Δ (where x may be defined at an isolated s) is a real root at r₀; None otherwise.
    Sound: on an open cell every requirement has a constant sign (its parts do not vanish there, x is
    continuous), and a datum meeting the strict requirements where c, Δ ≠ 0 has a neighbourhood that
    meets them, hence a whole cell."""
    fam = es.family()
    roots = [fam.roots(None)] + [fam.roots(q.name) for q in wanted]
    if any(rs is None for rs in roots):
        return None, None
    for t in cell_samples([a for rs in roots for a in rs]):
        w = fam.witness(t, sigma)
        if all(w.value_sign(q.name) == q.sign for q in wanted):
            return "holds", w
    base = fam._x_parts()[0]
    for kind, f in (zip(("c", "Δ"), base) if len(base) == 2 else ()):   # else x has a pole at each root
        if f.is_zero() or f.degrees()[1] == 0:
            continue
        for g, rho in fam.special_roots(f):
            if fam.nonzero_ball(f, rho):
                continue                      # f ≠ 0 there: a regular point, in the cells
            zero = fam.vanishes_at(f, g, rho)
            if zero is False:
                continue
            for prec in (512, 2048, 8192):         # the map's entries cancel to ~1e-64 at 512 bits
                status = fam.special_status(kind, rho, g, wanted, prec)
                if status is not None:
                    break
            if status == "holds" and zero:
                return "holds", None
            if status != "fails":
                return None, None
    return "fails", None


def _power(x: K, j: int) -> K:
    out = x - x + 1
    for _ in range(j):
        out = out * x
    return out


def _s_coeffs(n) -> list:
    d = n.to_dict()
    top = max((j for (_i, j) in d), default=0)
    out = [flint.fmpq(0)] * (top + 1)
    for (_i, j), c in d.items():
        out[j] = c
    return out


def _sign_ball(v) -> int | str:
    if v > 0:
        return 1
    if v < 0:
        return -1
    return UNDECIDED


class Witness:
    """A datum q(0) ∈ E at r₀ run exactly, its fixed point x_σ in balls, and the certified
    sign of every requirement at it."""

    def __init__(self, es: Eigenspace, s, sigma: int):
        self.es, self.s, self.sigma = es, s, sigma
        self.steps = es.run(s)
        self.x = None
        if self.steps is None:
            return
        (d, c), _p2, (b, a) = self.steps[-1][0]
        self.abcd = (a, b, c, d)
        if c.is_zero():
            if not (d - a).is_zero():
                self.x = ("affine", b / (d - a))
            return
        delta = (a - d) * (a - d) + 4 * b * c
        if delta.sign() < 0:
            return
        self.x = ("quadratic", a - d, delta, c)

    def x_ball(self, prec: int):
        kind = self.x[0]
        if kind == "affine":
            return self.x[1].arb(prec)
        _k, amd, delta, c = self.x
        return (amd.arb(prec) + self.sigma * delta.arb(prec).sqrt()) / (2 * c.arb(prec))

    def value_sign(self, name: str) -> int | str:
        """The certified sign of the quantity ``name`` of a requirement at this witness (memoised)."""
        memo = self.__dict__.setdefault("_signs", {})
        if name not in memo:
            memo[name] = self._value_sign(name)
        return memo[name]

    def _value_sign(self, name: str) -> int | str:
        steps = self.steps
        if steps is None:
            return UNDECIDED
        if name == "u = q_2(0)":
            return steps[0][1][1].sign()
        if name.startswith("q_"):
            i, k = int(name[2]) - 1, int(name[name.index("t_") + 2:-1])
            return steps[k][1][i].sign()
        if self.x is None:
            return UNDECIDED          # x not real (or f the identity): no fixed point

        def attempt(prec):
            x = self.x_ball(prec)
            if name == "x":
                return _sign_ball(x)
            if name.startswith("p_"):
                i, k = int(name[2]) - 1, int(name[name.index("t_") + 2:-1])
                P0, P1 = steps[k][0][i]
                if P0.is_zero() and P1.is_zero():
                    return 0
                return _sign_ball(P0.arb(prec) + x * P1.arb(prec))
            if name.startswith("attracting"):
                a, b, c, d = (e.arb(prec) for e in self.abcd)
                det = a * d - b * c
                sq = (c * x + d) ** 2
                return _sign_ball(sq - det if "- (ad-bc)" in name else sq + det)
            return UNDECIDED
        return decide(attempt, 64, 2048)


    def kernel_form(self) -> dict:
        """The datum as a witness for the kernel (certify_kernel/particles.py, ``realised_at``):
        r₀ by its minimal polynomial and isolating interval, λ₀ and q(0) as polynomials in r
        (elements of Q(r₀)), x = α + β√Δ with α, β, Δ in Q(r₀); every number an exact rational
        written as text.  The kernel trusts none of it: it re-runs the particles from it."""
        F, x = self.es.F, self.x
        text = lambda e: [str(c) for c in e.c.coeffs()]           # noqa: E731
        if x[0] == "affine":
            alpha, beta, delta = x[1], F.of(0), F.of(0)
        else:
            _kind, amd, delta, c = x
            alpha, beta = amd / (2 * c), F.of(self.sigma) / (2 * c)
        return {"word": self.es.word, "r": {"polynomial": [str(c) for c in F.m.coeffs()],
                                            "interval": list(self.es.r0.decimal_ends())},
                "lambda": text(self.es.lam0), "q": [text(e) for e in self.steps[0][1]],
                "x": {"alpha": text(alpha), "beta": text(beta), "delta": text(delta)}}


def polynomial_at(e, F: KField, lam0: K) -> K | None:
    """A polynomial (or fraction) in (λ, r) at (r₀, λ₀), exactly in K; None at a pole."""
    f = to_field(e)

    def at(p):
        val = F.of(0)
        for c in nf.kpoly(to_ring(p), F.m):
            val = val * lam0 + F.of(c)
        return val
    num, den = at(f.numer), at(f.denom)
    return None if den.is_zero() else num / den
