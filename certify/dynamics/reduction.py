"""The spherical billiard reduction of Section 4: (c_k, P(k)) ↦ (c_{k+1}, P(k+1)).

A state right after a collision is the contact c_k (the pair in contact: a, b, c,
i.e. p_i = 0 for i = INDEX[c_k]) and the plane P(k) = Span(p(k), q(k)).  One model,
three representations:

* **projective, exact** (:class:`Plane`): P as a normal vector n in Z^3, primitive
  and oriented by the paper's convention e_t · n > 0 (t = y, z, x for the contacts
  a, b, c, l. 950).  Nothing is ever normalised, so every step stays in Q.
* **vectorial** (:func:`vectorial_step`): the paper's trilinear formula (l. 975),
  ũ(1) = [u(0) ∧ e_j] ∧ [K_j (u(0) ∧ [e_i ∧ u(0)])], relabelled for each contact.
* **trigonometric** (:class:`Angles`, :func:`trig_step`): (contact, θ, φ) with
  cos and sin as certified balls, stepped by the paper's six cases (l. 881-929).

Why the plane is all that matters.  For the physical state (p, q) right after a
collision put u = p ∧ q.  The next collision j happens at p' = p + t q, and the
velocity becomes K_j q.  K_j fixes the plane {x_j = 0} pointwise, so K_j p' = p', and
u' = p' ∧ K_j q = K_j p' ∧ K_j q = cof(K_j)(p' ∧ q) = cof(K_j) u,
with cof(K) = det(K) K^{-T}: the normal moves *linearly*, whatever the radial part
of q (the λ of the paper).  That is Theorem 4.1, and it is how :func:`step` works;
the tangential velocity at p inside P is w = |n|² e_i − n_i n (w_i > 0), and the next
contact is the j ≠ i with w_j < 0, i.e. n_i n_j > 0.

>>> from flint import fmpq
>>> from certify.dynamics.simulate import exact
>>> P = plane("a", exact([0, 1, 1]), exact([1, -2, "1/2"]))
>>> [Q.letter for Q in orbit(P, fmpq(1, 10), 6)]
['a', 'b', 'c', 'a', 'b', 'a', 'b']
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import cache

import flint

from certify import caches
from certify.algebra.balls import precision
from certify.algebra.poly import to_fmpq

from .model import INDEX, LETTERS, NEXT, collide, collide_integral, det3
from .simulate import Undecided, sign

ORIENTATION = {"a": 1, "b": 2, "c": 0}       # t with e_t · u(k) ≥ 0 (l. 950)
E = ((1, 0, 0), (0, 1, 0), (0, 0, 1))


class Corner(ArithmeticError):
    """The orbit meets a corner of the spherical triangle (cos φ = 0, or the position
    on an edge's end): the reduction map is not defined there."""


# --- vectors ---------------------------------------------------------------------

def cross(v, w) -> tuple:
    """v ∧ w, in any ring."""
    return (v[1] * w[2] - v[2] * w[1], v[2] * w[0] - v[0] * w[2], v[0] * w[1] - v[1] * w[0])


def dot(v, w):
    """v · w, in any ring."""
    return v[0] * w[0] + v[1] * w[1] + v[2] * w[2]


def scale(c, v) -> tuple:
    return tuple(c * z for z in v)


_EXACT = (flint.fmpq, flint.fmpz, int)       # taken by fmpq_poly as they are


def integral(n) -> tuple:
    """den·n, den > 0 the lcm of the denominators of the rational vector n: the numerator
    of n as a canonical fmpq_poly (its content is coprime to its positive denominator)."""
    m = flint.fmpq_poly([z if isinstance(z, _EXACT) else to_fmpq(z) for z in n]).numer()
    return (m[0], m[1], m[2])


def primitive(n) -> tuple:
    """The primitive integer vector positively proportional to the rational n ≠ 0."""
    fmpz = flint.fmpz
    if not (type(n[0]) is fmpz and type(n[1]) is fmpz and type(n[2]) is fmpz) and \
            not all(isinstance(z, fmpz) for z in n):
        n = integral(n)
    g = n[0].gcd(n[1]).gcd(n[2])
    if g == 0:
        raise ValueError("the zero vector spans no plane")
    return n if g == 1 else (n[0] // g, n[1] // g, n[2] // g)


def cofactor_columns(letter: str, r, unit=E) -> list[tuple]:
    """The columns of cof(K) = det(K) K^{-T} for K = A, B, C, in any ring holding r
    (SymPy symbols, rationals): since e_1 = e_2 ∧ e_3 (cyclically), cof(K) e_m =
    K e_{m+1} ∧ K e_{m+2}.  ``unit``: e_1, e_2, e_3 in that ring."""
    Ke = [collide(letter, e, r) for e in unit]
    return [cross(Ke[(m + 1) % 3], Ke[(m + 2) % 3]) for m in range(3)]


@cache
def cofactor(letter: str, r: flint.fmpq) -> tuple:
    """The rows of cof(K) (:func:`cofactor_columns`) at a rational r, times the positive
    integer that clears its denominators (a positive multiple keeps the plane and its
    orientation)."""
    unit = tuple(tuple(flint.fmpq(z) for z in e) for e in E)
    cols = cofactor_columns(letter, flint.fmpq(r), unit)
    den = flint.fmpz(1)
    for col in cols:
        for z in col:
            den = den.lcm(z.q)
    return tuple(tuple((cols[m][k] * den).p for m in range(3)) for k in range(3))


caches.register(cofactor.cache_clear)


def cofactors(r) -> dict[str, tuple]:
    """{letter: cofactor(letter, r)} for the three collisions, looked up once for an
    orbit at a fixed r (a lookup hashes the fmpq r, which python-flint does slowly)."""
    r = flint.fmpq(r)
    return {L: cofactor(L, r) for L in LETTERS}


def apply(rows: tuple, n) -> tuple:
    """The matrix with these rows times n."""
    n0, n1, n2 = n
    r0, r1, r2 = rows
    return (r0[0] * n0 + r0[1] * n1 + r0[2] * n2, r1[0] * n0 + r1[1] * n1 + r1[2] * n2,
            r2[0] * n0 + r2[1] * n1 + r2[2] * n2)


def cofactor_apply(letter: str, r, n) -> tuple:
    """A positive multiple of cof(K) n: the normal of K P when n is the normal of P."""
    return apply(cofactor(letter, flint.fmpq(r)), n)


# --- the projective, exact representation --------------------------------------

@dataclass(frozen=True)
class Plane:
    """The state (c_k, P(k)): the contact letter and the primitive normal n of P,
    oriented so that e_t · n > 0 (t = ORIENTATION[letter])."""

    letter: str
    n: tuple

    @property
    def bits(self) -> int:
        """The largest bit length of the coordinates of n."""
        return max(int(z).bit_length() for z in self.n)


def canonical(letter: str, n) -> Plane:
    """The Plane with contact ``letter`` and normal ∝ n (orientation e_t · n > 0)."""
    return oriented(letter, primitive(n))


def oriented(letter: str, n) -> Plane:
    """:func:`canonical` for a primitive integer n (±n is the Plane's normal)."""
    s = sign(n[ORIENTATION[letter]])
    if s == 0:
        raise Corner(f"e_t · n = 0 at contact {letter}: the position is a corner")
    return Plane(letter, n if s > 0 else (-n[0], -n[1], -n[2]))


def normal(p, q, candidate: tuple | None = None) -> tuple:
    """The primitive integer vector positively proportional to p ∧ q (p, q rational):
    p and q are first scaled to integer vectors by positive factors (integer ones are).
    ``candidate``: a primitive integer vector, perhaps ±the answer (e.g. the normal of the
    reduction's plane there): when the integer p ∧ q is k·candidate for an integer k ≠ 0, the
    answer is sign(k)·candidate (the primitive vector positively proportional to a vector is
    unique), read with one division instead of the gcd of long entries; otherwise, by the gcd."""
    fmpz = flint.fmpz
    if type(p[0]) is fmpz and type(p[1]) is fmpz and type(p[2]) is fmpz and \
            type(q[0]) is fmpz and type(q[1]) is fmpz and type(q[2]) is fmpz:
        m = cross(p, q)
        if candidate is not None:
            k = _quotient(m, candidate)
            if k is not None:
                return candidate if k > 0 else (-candidate[0], -candidate[1], -candidate[2])
        return primitive(m)
    return primitive(cross(integral(p), integral(q)))


def _quotient(m: tuple, c: tuple):
    """The integer k ≠ 0 with m = k·c (integer vectors), or None."""
    for t in range(3):
        if c[t] != 0:
            k, rest = divmod(m[t], c[t])
            if rest != 0 or k == 0:
                return None
            u, v = (t + 1) % 3, (t + 2) % 3
            return k if m[u] == k * c[u] and m[v] == k * c[v] else None
    return None


def plane(letter: str, p, q, candidate: tuple | None = None) -> Plane:
    """The reduction state of a physical state (p, q) right after a collision of
    type ``letter`` (p_i = 0, q_i > 0): P = Span(p, q), normal p ∧ q (``candidate``:
    as in :func:`normal`)."""
    i = INDEX[letter]
    if p[i] != 0 or sign(q[i]) <= 0:
        raise ValueError(f"not a state right after a collision {letter}: need p_{i + 1} = 0 < q_{i + 1}")
    return oriented(letter, normal(p, q, candidate))


def position(P: Plane) -> tuple:
    """The direction of p in P ∩ {x_i = 0}: ±(n ∧ e_i), with non-negative entries;
    Corner when it has another zero entry or leaves the octant."""
    i = INDEX[P.letter]
    p = cross(P.n, E[i])
    signs = {sign(z) for k, z in enumerate(p) if k != i}
    if signs == {1}:
        return p
    if signs == {-1}:
        return scale(-1, p)
    raise Corner(f"the plane {P.n} meets the face {P.letter} outside its interior")


def tangent(P: Plane) -> tuple:
    """The tangential velocity at p inside P: w = |n|² e_i − n_i n (so w ⊥ n, w ⊥ p
    and w_i = n_j² + n_k² > 0)."""
    i, n = INDEX[P.letter], P.n
    nn = dot(n, n)
    return tuple((nn if k == i else 0) - n[i] * n[k] for k in range(3))


def next_letter(P: Plane) -> str:
    """The next contact: the j ≠ i where w_j < 0, i.e. n_i n_j > 0.  With the
    orientation e_t · n > 0 this is the cyclic successor (a→b→c→a) iff cos φ > 0,
    and cos φ = n_i / |n| (l. 881-929)."""
    i, n = INDEX[P.letter], P.n
    if all(type(z) is flint.fmpz for z in n):
        return _next_letter_exact(P.letter, i, n)
    position(P)                              # the state must lie inside its face
    closing = [L for L in LETTERS if L != P.letter and sign(n[i] * n[INDEX[L]]) > 0]
    if len(closing) != 1:
        raise Corner(f"cos φ = 0 at {P}: the orbit heads for a corner")
    return closing[0]


def _next_letter_exact(letter: str, i: int, n: tuple) -> str:
    """:func:`next_letter` for an integer normal, from the signs s of its entries (each
    read once): with j, k = i+1, i+2 (mod 3), n ∧ e_i has the entries s_k at j and −s_j
    at k, so p lies inside the face iff s_k = −s_j ≠ 0 (:func:`position`); then
    n_i n_j > 0 for exactly one of j, k when s_i ≠ 0, and for none when s_i = 0."""
    j, k = NEXT[i]
    a, b, c = n[i], n[j], n[k]
    if not ((b > 0 and c < 0) or (b < 0 and c > 0)):
        raise Corner(f"the plane {n} meets the face {letter} outside its interior")
    if a == 0:
        raise Corner(f"cos φ = 0 at {Plane(letter, n)}: the orbit heads for a corner")
    return LETTERS[j] if (a > 0) == (b > 0) else LETTERS[k]


def step(P: Plane, r, rows: dict | None = None) -> Plane:
    """(c_k, P(k)) ↦ (c_{k+1}, P(k+1)) with P(k+1) = K_j P(k): normal cof(K_j) n.
    ``rows``: :func:`cofactors` of r, when the caller has them."""
    j = next_letter(P)
    return canonical(j, apply((rows or cofactors(r))[j], P.n))


def orbit(P: Plane, r, n: int, stop_at_corner: bool = True) -> list[Plane]:
    """P and its first n images (fewer if a corner is met and stop_at_corner).

    After the first step every normal is primitive, and then the content g of m = M n (M the
    integer rows of cof(K_j)) divides det M: adj(M) m = det(M) n, so g divides det(M)·n_k for
    every k, and n is primitive.  So g = gcd(det M, m_1, m_2, m_3): gcds of the long entries
    with a short number, the same primitive normal as :func:`canonical`'s."""
    out, rows = [P], cofactors(r)
    dets = {L: det3(rows[L]) for L in LETTERS}
    fmpz = flint.fmpz
    for k in range(n):
        try:
            Q = out[-1]
            m = Q.n
            if k == 0 or not (type(m[0]) is fmpz and type(m[1]) is fmpz and type(m[2]) is fmpz):
                out.append(step(Q, r, rows))
                continue
            j = _next_letter_exact(Q.letter, INDEX[Q.letter], m)
            m = apply(rows[j], m)
            g = dets[j].gcd(m[0]).gcd(m[1]).gcd(m[2])
            out.append(oriented(j, m if g == 1 else (m[0] // g, m[1] // g, m[2] // g)))
        except Corner:
            if not stop_at_corner:
                raise
            break
    return out


def word_of(P: Plane, r, n: int, reduce_every: int = 64) -> tuple[str, Plane]:
    """The next n collision letters from P, and the final Plane, without keeping the
    orbit: the normal is made primitive only every ``reduce_every`` steps (its gcd
    is small, and the sign tests do not need it).  Stops early at a corner."""
    letters, rows = [], cofactors(r)
    fmpz = flint.fmpz
    if not all(type(z) is fmpz for z in P.n):
        try:
            for k in range(n):
                j = next_letter(P)
                m = apply(rows[j], P.n)
                if m[ORIENTATION[j]] < 0:
                    m = tuple(-z for z in m)
                P = canonical(j, m) if k % reduce_every == 0 else Plane(j, m)
                letters.append(j)
        except Corner:
            pass
        return "".join(letters), canonical(P.letter, P.n)
    # the same steps on (letter, normal) without a Plane per step (integer normals stay integer)
    L, m = P.letter, P.n
    try:
        for k in range(n):
            j = _next_letter_exact(L, INDEX[L], m)
            m2 = apply(rows[j], m)
            if m2[ORIENTATION[j]] < 0:
                m2 = (-m2[0], -m2[1], -m2[2])
            if k % reduce_every == 0:
                m2 = canonical(j, m2).n          # a Corner here keeps (L, m), as the Plane path does
            L, m = j, m2
            letters.append(j)
    except Corner:
        pass
    return "".join(letters), canonical(L, m)


def ball_run(letter: str, n, r, count: int, prec: int) -> tuple[str, str, tuple]:
    """The first ``count`` collisions from the state (letter, n), n a ball (or exact)
    normal, with the normal in balls at ``prec`` bits, rescaled each step so that
    max |n_k| ≈ 1 and oriented (e_t · n > 0, :data:`ORIENTATION`): (the letters, the
    last contact, a ball vector containing a positive multiple of the last oriented normal).
    Every letter is proven by the balls (:func:`next_letter`); the run stops at the first
    sign they cannot decide, or at a corner."""
    letters, rows = [], cofactors(r)
    rows = [rows[L] for L in LETTERS]
    with precision(prec):
        m = tuple(flint.arb(z) for z in n)
        i = INDEX[letter]
        try:
            for _ in range(count):
                j = _next_index_ball(i, m)
                if j < 0:
                    break
                x, y, z = apply(rows[j], m)
                top = max(abs(x).upper(), abs(y).upper(), abs(z).upper()) * sign((x, y, z)[_ORIENTATION[j]])
                i, m = j, (x / top, y / top, z / top)          # oriented: e_t · n > 0, max |n_k| ≈ 1
                letters.append(LETTERS[j])
        except Undecided:
            pass
    return "".join(letters), LETTERS[i], m


_ORIENTATION = tuple(ORIENTATION[L] for L in LETTERS)


def _next_index_ball(i: int, n: tuple) -> int:
    """The index of :func:`next_letter` of the Plane (i's letter, n) for a ball normal n, or -1
    where it raises (Undecided or Corner: the run stops), from the same ball products and
    comparisons (n ∧ e_i has the entries n_k at j and −n_j at k, exact copies of the balls):
    n_k and n_j of opposite decided signs, then n_i n_j and n_i n_k, exactly one > 0 and
    both decided."""
    j, k = NEXT[i]
    a, b, c = n[i], n[j], n[k]
    if not ((c > 0 and b < 0) or (c < 0 and b > 0)):
        return -1
    pj, pk = a * b, a * c
    if pj > 0 and pk < 0:
        return j
    if pj < 0 and pk > 0:
        return k
    return -1


def ball_word(P: Plane, r, n: int, prec: int) -> str:
    """The first n collision letters from P with the normal in balls at ``prec`` bits
    (:func:`ball_run`); every letter is proven by the balls, and the word stops at the
    first sign they cannot decide."""
    return ball_run(P.letter, P.n, r, n, prec)[0]


def word(planes) -> str:
    """The collision word c_1 c_2 ... of an orbit (without its initial contact)."""
    return "".join(P.letter for P in planes[1:])


# --- the vectorial representation (l. 931-987) --------------------------------

def vectorial_step(letter: str, u, r) -> tuple[str, tuple]:
    """The paper's trilinear formula, relabelled for the contact i and the next
    collision j: ũ(1) = [u ∧ e_j] ∧ [K_j (u ∧ [e_i ∧ u])], unnormalised (a positive
    multiple of u(1)).  j is decided by the sign of cos φ = u_i (cyclic successor
    when positive).  Exact on rationals."""
    i = INDEX[letter]
    s = sign(u[i])
    if s == 0:
        raise Corner("cos φ = 0: the orbit heads for a corner")
    succ = LETTERS[(i + 1) % 3]
    other = LETTERS[(i + 2) % 3]
    j = succ if s > 0 else other
    return j, trilinear(letter, j, u, r)


def vectorial_ray(letter: str, u, r) -> tuple[str, tuple]:
    """:func:`vectorial_step` up to a positive factor, in integers for an integer u and a
    rational r = m/d: K_j occurs once in the trilinear formula, and 2d·K_j
    (:func:`certify.dynamics.model.collide_integral`) in its place multiplies ũ(1) by 2d > 0."""
    i = INDEX[letter]
    s = sign(u[i])
    if s == 0:
        raise Corner("cos φ = 0: the orbit heads for a corner")
    j = LETTERS[(i + 1) % 3] if s > 0 else LETTERS[(i + 2) % 3]
    return j, cross(cross(u, E[INDEX[j]]), collide_integral(j, cross(u, cross(E[i], u)), r))


def same_ray(v, w) -> bool:
    """v = k w for some k > 0 (exact; False when w = 0): v ∧ w = 0 and v · w > 0, read from
    one non-zero entry w_k of w (v_k w_k > 0 and v_j w_k = v_k w_j for every j)."""
    for k in range(3):
        if w[k] != 0:
            vk, wk = v[k], w[k]
            if (vk > 0) != (wk > 0) or vk == 0:
                return False
            j, m = (k + 1) % 3, (k + 2) % 3
            return v[j] * wk == vk * w[j] and v[m] * wk == vk * w[m]
    return False


def trilinear(letter: str, j: str, u, r) -> tuple:
    """ũ(1) = [u ∧ e_j] ∧ [K_j (u ∧ [e_i ∧ u])] for the contact ``letter`` = i and the
    next collision j, in any ring (rationals, SymPy symbols)."""
    i = INDEX[letter]
    p1 = cross(u, E[INDEX[j]])
    q0 = cross(u, cross(E[i], u))
    return cross(p1, collide(j, q0, r))


# --- the trigonometric representation (l. 881-929) ----------------------------

P0 = {"a": lambda ct, st: (0, ct, st), "b": lambda ct, st: (st, 0, ct), "c": lambda ct, st: (ct, st, 0)}
Q0 = {"a": lambda ct, st, cp, sp: (sp, -st * cp, ct * cp),
      "b": lambda ct, st, cp, sp: (ct * cp, sp, -st * cp),
      "c": lambda ct, st, cp, sp: (-st * cp, ct * cp, sp)}
# (contact, sign of cos φ) -> (next contact, p(t1) before normalisation), as printed
CASES = {("a", 1): ("b", lambda ct, st, cp, sp: (ct * sp, 0, cp)),
         ("a", -1): ("c", lambda ct, st, cp, sp: (st * sp, -cp, 0)),
         ("b", 1): ("c", lambda ct, st, cp, sp: (cp, ct * sp, 0)),
         ("b", -1): ("a", lambda ct, st, cp, sp: (0, st * sp, -cp)),
         ("c", 1): ("a", lambda ct, st, cp, sp: (0, cp, ct * sp)),
         ("c", -1): ("b", lambda ct, st, cp, sp: (-cp, 0, st * sp))}


def e_theta(letter: str, ct, st) -> tuple:
    """e_θ = dp(0)/dθ, the unit tangent with q(0) = cos φ e_θ + sin φ e_i."""
    return Q0[letter](ct, st, 1, 0)


@dataclass
class Angles:
    """(contact, θ, φ) by cos θ, sin θ, cos φ, sin φ (balls or exact): p(0) =
    P0[letter](cos θ, sin θ), q(0) = Q0[letter](...)."""

    letter: str
    ct: object
    st: object
    cp: object
    sp: object

    def p(self) -> tuple:
        return P0[self.letter](self.ct, self.st)

    def q(self) -> tuple:
        return Q0[self.letter](self.ct, self.st, self.cp, self.sp)

    def u(self) -> tuple:
        """u = p(0) ∧ q(0), the oriented normal (l. 943)."""
        return cross(self.p(), self.q())


def norm(v):
    return dot(v, v).sqrt()


def angles_of(letter: str, p, q) -> Angles:
    """θ and φ of a state (p, q) with p_i = 0, in balls: p̂ = p/|p| gives cos θ, sin θ;
    the unit tangential part of q gives sin φ = q̂_i and cos φ = q̂ · e_θ.  The
    tangential part |p|² q − (q · p) p is formed before rounding (exactly, when p and q
    are exact: near a collapse q is almost radial and rounding first would cancel)."""
    # dot, scale and norm written out (this runs ~10^5 times in S7.2), the same operations in the same order
    arb = flint.arb
    p0, p1, p2 = p
    q0, q1, q2 = q
    pp, qp = p0 * p0 + p1 * p1 + p2 * p2, q0 * p0 + q1 * p1 + q2 * p2
    w0, w1, w2 = arb(pp * q0 - qp * p0), arb(pp * q1 - qp * p1), arb(pp * q2 - qp * p2)
    p0, p1, p2 = arb(p0), arb(p1), arb(p2)
    c, d = 1 / (p0 * p0 + p1 * p1 + p2 * p2).sqrt(), 1 / (w0 * w0 + w1 * w1 + w2 * w2).sqrt()
    ph, wh = (c * p0, c * p1, c * p2), (d * w0, d * w1, d * w2)
    ct, st = (ph[1], ph[2]) if letter == "a" else (ph[2], ph[0]) if letter == "b" else (ph[0], ph[1])
    e0, e1, e2 = e_theta(letter, ct, st)
    return Angles(letter, ct, st, wh[0] * e0 + wh[1] * e1 + wh[2] * e2, wh[INDEX[letter]])


def angles(P: Plane, prec: int | None = None) -> Angles:
    """The trigonometric representation of a Plane (balls at ``prec`` bits)."""
    with precision(prec):
        return angles_of(P.letter, position(P), tangent(P))


def trig_step(T: Angles, r) -> Angles:
    """One step of the paper's six cases: the sign of cos φ picks the case, p(t1) is
    the printed vector normalised, q(t1) = Kq(0) − (Kq(0)·p(t1)) p(t1), normalised; θ', φ'
    read from them (:func:`_step_angles`)."""
    s = sign(T.cp)
    if s == 0:
        raise Corner("cos φ = 0")
    j, p1 = CASES[(T.letter, s)]
    arb = flint.arb
    x0, x1, x2 = p1(T.ct, T.st, T.cp, T.sp)
    x0, x1, x2 = arb(x0), arb(x1), arb(x2)
    c = 1 / (x0 * x0 + x1 * x1 + x2 * x2).sqrt()
    x0, x1, x2 = c * x0, c * x1, c * x2
    k0, k1, k2 = collide(j, T.q(), arb(r))
    d = k0 * x0 + k1 * x1 + k2 * x2
    return Angles(j, *_step_angles(j, x0, x1, x2, k0 - d * x0, k1 - d * x1, k2 - d * x2))


def _step_angles(letter: str, x0, x1, x2, w0, w1, w2) -> tuple:
    """(cos θ, sin θ, cos φ, sin φ) at the contact ``letter`` from the unit position x and a
    tangent w ⊥ x (balls): cos θ, sin θ are x's free components, and with ŵ = w/|w|,
    cos φ = ŵ·e_θ, sin φ = ŵ_i (as :func:`angles_of`, which normalises x and projects w again)."""
    e = 1 / (w0 * w0 + w1 * w1 + w2 * w2).sqrt()
    i = INDEX[letter]
    ct, st = (x1, x2) if i == 0 else (x2, x0) if i == 1 else (x0, x1)
    e0, e1, e2 = Q0[letter](ct, st, 1, 0)               # e_theta
    w0, w1, w2 = e * w0, e * w1, e * w2
    return ct, st, w0 * e0 + w1 * e1 + w2 * e2, (w0, w1, w2)[i]


def trig_agreement(planes: list, r, prec: int = 128) -> tuple[int, int]:
    """Along an orbit of Planes: at how many steps P → P1 the trigonometric step
    (:func:`trig_step`) from the angles of P gives P1's contact and balls of cos, sin of θ, φ
    overlapping P1's, and at how many a sign was undecided.  The angles of a state are balls
    at ``prec`` bits of the exact ones, from their closed forms for an integer normal
    (:func:`closed_angles`; the same numbers as :func:`angles`), computed once (they end one
    step and start the next); the step is :func:`trig_step`, in one precision context.  Balls
    of the true values overlap: a step that does not agree is one where the six cases do not
    give the next state."""
    agree = undecided = 0
    arb, fmpz = flint.arb, flint.fmpz
    with precision(prec):
        rr = arb(r)
        last = None
        for P, P1 in zip(planes, planes[1:]):
            try:
                if last is None or last[0] is not P:
                    last = (P, _angles(P, fmpz, arb))
                T = last[1]
                X = _angles(P1, fmpz, arb)
                last = (P1, X)
                Y = trig_step(Angles(*T), rr)
                agree += Y.letter == P1.letter and Y.ct.overlaps(X[1]) and Y.st.overlaps(X[2]) and \
                    Y.cp.overlaps(X[3]) and Y.sp.overlaps(X[4])
            except Undecided:
                undecided += 1
    return agree, undecided


def _angles(P: Plane, fmpz, arb) -> tuple:
    """The angles of P at the working precision, as (letter, cos θ, sin θ, cos φ, sin φ): for an
    integer normal n from their closed forms (:func:`closed_angles`), else :func:`angles`'s."""
    n = P.n
    if type(n[0]) is fmpz and type(n[1]) is fmpz and type(n[2]) is fmpz:
        return closed_angles(P.letter, n, arb)
    A = angles_of(P.letter, position(P), tangent(P))
    return P.letter, A.ct, A.st, A.cp, A.sp


def closed_angles(letter: str, n: tuple, arb=flint.arb) -> tuple:
    """(letter, cos θ, sin θ, cos φ, sin φ) of the Plane (letter, n), n an integer normal, as balls
    of the exact values: with j, k = i+1, i+2 (mod 3), the position p = ε(n ∧ e_i) has p_j = εn_k,
    p_k = −εn_j (ε = ±1 making both > 0, else Corner), so cos θ = p_j/√s, sin θ = p_k/√s with
    s = n_j² + n_k²; the tangent w = |n|² e_i − n_i n has |w|² = |n|² s, sin φ = w_i/|w| = √s/|n|
    and cos φ = (w/|w|)·e_θ = n_i (n_j p_k − n_k p_j)/(|n| s) = −ε n_i/|n|.  The same numbers
    as :func:`angles` (tests/dynamics/test_reduction.py), from two square roots of integers."""
    i = INDEX[letter]
    j, k = NEXT[i]
    nj, nk = n[j], n[k]
    if nk > 0 and nj < 0:
        pj, pk, ni = nk, -nj, -n[i]          # ε = 1
    elif nk < 0 and nj > 0:
        pj, pk, ni = -nk, nj, n[i]           # ε = −1
    else:
        raise Corner(f"the plane {n} meets the face {letter} outside its interior")
    s = nj * nj + nk * nk
    root_s, root_nn = arb(s).sqrt(), arb(s + n[i] * n[i]).sqrt()
    return letter, arb(pj) / root_s, arb(pk) / root_s, arb(ni) / root_nn, root_s / root_nn


# --- printed vector formulas ---------------------------------------------------

class _Matrix:
    """A, B or C at r acting by ``K*v`` (for :func:`formula`); with ``integral``, 2d·K for a
    rational r = m/d (:func:`certify.dynamics.model.collide_integral`)."""

    def __init__(self, letter: str, r, integral: bool = False):
        self.letter, self.r, self.act = letter, r, collide_integral if integral else collide

    def __mul__(self, v):
        return self.act(self.letter, v, self.r)


def formula(text: str, integral: bool = False):
    """A printed vector formula as transcribed in ``proofs/section4_*.py``,
    e.g. "cross(cross(u0, ey), B*cross(u0, cross(ex, u0)))" (l. 976), as a function
    (u, r) ↦ vector in the ring of u (exact on rationals).  The brackets of the print
    are kept: ∧ is not associative (l. 989).  With ``integral`` (a rational r = m/d), each
    K acts as 2d·K: integer u gives integer vectors, and the value is (2d)^k times the
    formula's when K is applied k times, a positive multiple (∧, · and K v are linear in
    each argument)."""
    code = compile(text, "<printed formula>", "eval")

    def evaluate(u, r):
        names = {"cross": cross, "dot": dot, "u0": tuple(u), "ex": E[0], "ey": E[1], "ez": E[2],
                 **{L.upper(): _Matrix(L, r, integral) for L in LETTERS}}
        return tuple(eval(code, {"__builtins__": {}}, names))
    return evaluate
