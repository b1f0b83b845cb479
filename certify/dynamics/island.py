"""The elliptic island of the b-to-b map around the symmetric orbit [ac]b.

The objects (the proofs that they are what they claim live with the ``certify
island`` command and its tests; this module only defines them, in any ring):

* **the chart at b.**  A state at the contact b is an oriented normal n (n_z > 0, and
  n_x < 0 for the position inside the face b, :mod:`.reduction`), so n_z − n_x > 0 and

      u = (n_x + n_z)/(n_z − n_x),     v = 2 n_y/(n_z − n_x)

  is an affine chart of the states at b; n* = (−1, 0, 1) (the plane p_a = p_c,
  q_a = q_c of the double collision [ac]) is its origin.
* **the linear map.**  From b the next segment is ac (n_y < 0) or ca (n_y > 0), then b;
  K_a K_c = K_c K_a, so on both sides of the tie n_y = 0 the b-to-b map is the one
  projective map n ↦ cof(K_b) cof(K_a) cof(K_c) n, which in the chart is linear:

      A(r) = [[1, −(1+r)/2], [(1+r)/r, −(1+r²)/(2r)]],   det A = 1,  tr A = −(1−r)²/(2r).

* **the invariant form** Q(u, v) = 2u² − (1+r)uv + r v², with Q∘A = Q; positive definite
  iff r² − 6r + 1 < 0, i.e. on ]3−2√2, 1[, where A is elliptic.
* **the island** U_r = {Q < c_max}, c_max = 1 − (1−r)²/(4r) = −(r² − 6r + 1)/(4r): the
  largest sublevel set of Q inside the region R = {|u| < 1, |u − (1+r)v/2| < 1} where
  the b-to-b map is A.

>>> from flint import fmpq
>>> r = fmpq(3, 10)
>>> print(c_max(r))
71/120
>>> island_sign((-1, 0, 1), r)      # the symmetric state [ac]b is the island's centre
1
>>> island_sign((-3, 1, 1), r)      # u = -1/2, v = 1/2: Q = 9/10 > c_max
-1

A ball of states is in the island only when all of it is (:func:`inside`): on v = 0 the
boundary ellipse crosses u = √(71/240) ≈ 0.5439, inside the ball u = 0.54 ± 0.01, whose
midpoint is in the island:

>>> from flint import arb
>>> across = normal(arb("0.54 +/- 0.01"), arb(0))
>>> inside(across, r), inside(tuple(z.mid() for z in across), r)
(False, True)
>>> inside(normal(arb("0.2 +/- 0.01"), arb(0)), r)
True
"""
from __future__ import annotations

import flint

from certify.errors import UNDECIDED

from .simulate import Undecided, sign


def chart(n) -> tuple:
    """(u, v) of an oriented normal n at b, in the ring of n (fmpq for an integer or
    rational n, arb for a ball)."""
    if not (type(n[0]) is type(n[1]) is type(n[2]) is flint.arb):    # a ball normal as it is (the scans' case)
        n = tuple(flint.fmpq(z) if isinstance(z, (int, flint.fmpz)) else z for z in n)
    d = n[2] - n[0]
    if sign(d) <= 0:
        raise ValueError(f"n = {n} is not an oriented normal inside the face b (n_z − n_x ≤ 0)")
    return ((n[0] + n[2]) / d, 2 * n[1] / d)


def normal(u, v) -> tuple:
    """The normal at b with chart coordinates (u, v) (n_z − n_x = 2)."""
    return (u - 1, v, u + 1)


def quadratic_form(u, v, r):
    """Q(u, v) = 2u² − (1+r)uv + r v², in any ring."""
    return 2 * u * u - (1 + r) * u * v + r * v * v


def c_max(r):
    """c_max = 1 − (1−r)²/(4r), the level of the island's boundary ellipse (the last exact r's
    kept: the scans ask it of one fmpq object at every state at b; an fmpq is immutable)."""
    global _LAST
    if type(r) is flint.fmpq:
        last = _LAST                 # one read of an immutable pair: safe between threads
        if last[0] is not r:
            last = _LAST = (r, 1 - (1 - r) * (1 - r) / (4 * r))
        return last[1]
    return 1 - (1 - r) * (1 - r) / (4 * r)        # x * x: an arb x ** 2 is nan when x holds 0


_LAST: tuple = (None, None)      # (r, c_max(r)) of the last exact r asked


def matrix_A(r) -> tuple:
    """The b-to-b map in the chart, as rows: A(r) (module docstring)."""
    return ((1, -(1 + r) / 2), ((1 + r) / r, -(1 + r * r) / (2 * r)))


def apply_A(u, v, r) -> tuple:
    """A(r)(u, v)."""
    (a, b), (c, d) = matrix_A(r)
    return (a * u + b * v, c * u + d * v)


def elliptic_polynomial(r):
    """r² − 6r + 1: A(r) is elliptic (and Q positive definite) where it is negative."""
    return r * r - 6 * r + 1


def island_sign(n, r) -> int | str:
    """The sign of c_max − Q(u, v) at the state n at b: +1 when the state lies in the
    island U_r, −1 outside its closure, 0 on the boundary ellipse; UNDECIDED when n is
    a ball that does not decide it.  r exact (fmpq) or a ball."""
    try:
        u, v = chart(n)
        return sign(c_max(r) - quadratic_form(u, v, r))
    except Undecided:
        return UNDECIDED


def inside(n, r) -> bool:
    """Whether the state n at b is proved inside the island U_r = {Q < c_max}: c_max − Q(u, v) > 0
    decided for the whole of n (for a ball normal, at every normal it holds: a ball that
    straddles the boundary ellipse is not inside, wherever its midpoint lies).  False outside,
    on the boundary, where n's balls do not decide the sign, and for a state not proved inside
    the face b (n_z − n_x not proved positive).  r exact (fmpq) or a ball.  The one membership
    test of ``certify identify`` and of the certified points of Section 5's figures; that the
    island is invariant (r in ]3−2√2, 1[) is the caller's to prove."""
    try:
        return island_sign(n, r) == 1
    except ValueError:                      # n_z − n_x ≤ 0: not a state inside the face b
        return False
