"""The five-particle reduction map iterated numerically (issue 39; beyond the paper).

The state right after a collision is the face i (0..3 for a, b, c, d: the gap p_i that has
just closed) and the bivector ω = p ∧ q of the plane Span(p, q) ⊂ R⁴ (gaps p, relative
velocities q), in the coordinates ω_kl, k < l, of :data:`PAIRS`, never normalised; the
oriented plane is a point of Gr⁺(2, 4) ≅ S² × S² (:func:`chart`).  Certificate B1 (the
N-particle reduction, docs/beyond.md) gives the map:

* **the position.** p ∝ −ι_i ω: −ω_ik = p_k q_i with p_i = 0, and q_i > 0 right after the
  collision, so the state lies inside the face iff −ω_ik > 0 for the three k ≠ i.
* **the next face.** Along the plane, from p towards q, every other gap x_j vanishes once
  (x_j = p_j > 0 at p, −p_j at −p); the first to vanish, j, is the next face, and j comes
  before k iff ω_jk > 0.  Proof: let x be the point of the arc where x_j = 0 and y its
  derivative, x ∧ y a positive multiple of ω; then ω_jk = x_j y_k − x_k y_j = −x_k y_j with
  y_j < 0 (x_j crosses 0 downwards, its only zero on the half-turn), so ω_jk has the sign
  of x_k there, positive iff x_k has not vanished yet.  So the next face is the j with
  ω_jk > 0 for the two other k ≠ i, j (a tournament decided by three signs).
* **the new plane.** ω ↦ Λ²K_j ω (free flight keeps p ∧ q; K_j fixes the face of j
  pointwise, so p ∧ q ↦ p ∧ K_j q), a positive multiple kept: no re-orientation.

Together the six entries of ω are all used: three say the state is in its face, three
decide the next face.  The map follows the plane for ever; a physical run stops when the
gaps all separate (q ≥ 0 before the arc leaves the orthant), which the plane does not see
(as the four-particle reduction, docs/particles.md).  Breaks are those of
:data:`.rules.BREAKS`, read for the bivector: 1 the tournament undecided (no face decided
first), 2 an in-face entry −ω_ik undecided (two gaps closing at once to working precision),
3 corner (ω = 0 or a decided wrong sign in the face), 4 non-finite, 5 the certified horizon
(``strict``).

The float64 engine (:mod:`.five_kernel`) carries, as the four-particle one, the margins of
the last step (TOL · |Ĉ||ω|) and the rigorous accumulated bound :func:`.rules.carry_bound`
at length 6 (g = ``rules.gamma_bound(53, 6)``); a collision is *certified* while that bound
decides it.  The datum of an orbit is (p0, q0) as float64 read exactly, its bivector
computed with the bound TOL · (|p_k q_l| + |p_l q_k|) (two products and a difference: at most
3 roundings, far below TOL = 64u).  :func:`exact_orbit` is the same map in exact rationals
(the tests' reference, against the particle simulator).
"""
from __future__ import annotations

import itertools
import math
from collections.abc import Callable
from dataclasses import dataclass

import flint
import numpy as np

from certify.dynamics.model import alphabet, collide_gaps

from . import rules

GAPS = 4
LETTERS = alphabet(5)                                       # a, b, c, d
PAIRS = list(itertools.combinations(range(GAPS), 2))       # ω_kl, k < l: (0,1) (0,2) (0,3) (1,2) (1,3) (2,3)
SLOT = {pair: m for m, pair in enumerate(PAIRS)}
START = "b"                                                 # the face of the random initial data
KEYS = ("r", "p0", "q0", "breaks", "collisions", "certified", "face", "omega", "angles")
G64_6 = float(rules.gamma_bound(53, GAPS * (GAPS - 1) // 2))
BREAKS = {
    rules.COMPLETED: "completed",
    rules.UNDECIDED: "undecided: no face decided first (a sign ω_jk below the rounding bound)",
    rules.SHORT_STEP: "two gaps closing at once to working precision (an in-face entry undecided)",
    rules.CORNER: "corner: zero bivector, or the state outside its face",
    rules.NONFINITE: "non-finite number",
    rules.HORIZON: "certified horizon: the accumulated error bound no longer decides the face (strict)",
}


def entry(w, k: int, m: int):
    """ω_km for any k ≠ m (ω_mk = −ω_km) and the index of its slot."""
    return (w[SLOT[k, m]], SLOT[k, m]) if k < m else (-w[SLOT[m, k]], SLOT[m, k])


def classify(i: int, w, bounds, sign=rules.margin_sign, finite=math.isfinite) -> tuple[int, int]:
    """(break code, next face) of the state (i, ω) whose entries carry ``bounds`` (the
    module docstring): (0, j) when the face j is decided first."""
    if not all(finite(z) for z in w):
        return rules.NONFINITE, -1
    if all(z == 0 for z in w):
        return rules.CORNER, -1
    others = [k for k in range(GAPS) if k != i]
    inside = []
    for k in others:
        x, m = entry(w, i, k)
        inside.append(sign(-x, bounds[m]))
    if any(s < 0 for s in inside):
        return rules.CORNER, -1
    if any(s == 0 for s in inside):
        return rules.SHORT_STEP, -1
    for j in others:
        if all(sign(x, bounds[m]) > 0 for x, m in (entry(w, j, k) for k in others if k != j)):
            return rules.COMPLETED, j
    return rules.UNDECIDED, -1


def compound(K) -> list[list]:
    """Λ²K on the basis e_k ∧ e_l of :data:`PAIRS`: the 2×2 minors of K."""
    return [[K[i][k] * K[j][m] - K[i][m] * K[j][k] for (k, m) in PAIRS] for (i, j) in PAIRS]


def collision_matrix(j: int, r) -> list[list]:
    """K_j at r (the columns K_j e_c by :func:`certify.dynamics.model.collide_gaps`)."""
    one, zero = r ** 0, r * 0
    cols = [collide_gaps(LETTERS[j], tuple(one if m == c else zero for m in range(GAPS)), r) for c in range(GAPS)]
    return [[cols[c][m] for c in range(GAPS)] for m in range(GAPS)]


def integer_rows(r) -> list[list[list[int]]]:
    """Λ²(2d K_j) for j = a, b, c, d at r = n/d exact (``rules.exact_r``): integer matrices,
    4d² times Λ²K_j, a positive multiple (the orientation kept)."""
    q = rules.exact_r(r)
    out = []
    for j in range(GAPS):
        K = [[int(z * 2 * q.q) for z in row] for row in collision_matrix(j, q)]
        out.append(compound(K))
    return out


def float_rows(r) -> list[list[list[float]]]:
    """:func:`integer_rows` rounded to float64, each scaled into [1, 2) (``rules.scaled_rows``)."""
    return rules.scaled_rows(integer_rows(r), r)


def advance(j: int, w, rows) -> tuple:
    """Λ²K_j ω with the matrices ``rows`` (exact or float), left to right."""
    out = []
    for row in rows[j]:
        s = row[0] * w[0]
        for c in range(1, len(w)):
            s = s + row[c] * w[c]
        out.append(s)
    return tuple(out)


def bivector(p, q) -> tuple:
    """p ∧ q in the coordinates of :data:`PAIRS`."""
    return tuple(p[k] * q[m] - p[m] * q[k] for k, m in PAIRS)


def start(p, q, tol: float = rules.TOL64) -> tuple[tuple, tuple]:
    """The float bivector of the datum (p, q) and its bound TOL · (|p_k q_l| + |p_l q_k|)."""
    w = bivector([float(z) for z in p], [float(z) for z in q])
    err = tuple(tol * (abs(p[k] * q[m]) + abs(p[m] * q[k])) + rules.TINY64 for k, m in PAIRS)
    return w, err


def random_data(count: int, seed: int = 0, face: str = START) -> tuple[np.ndarray, np.ndarray]:
    """``count`` seeded random states on ``face``: p = |Gaussian| in the face (p_i = 0), q
    Gaussian with q_i = |Gaussian| > 0 (the gap opening): (p0, q0), each (count, 4)."""
    rng = np.random.default_rng(seed)
    i = LETTERS.index(face)
    p, q = np.abs(rng.standard_normal((count, GAPS))), rng.standard_normal((count, GAPS))
    p[:, i], q[:, i] = 0.0, np.abs(q[:, i])
    return p, q


# --- the chart of Gr⁺(2, 4) ≅ S² × S² ------------------------------------------

def self_dual_parts(w) -> tuple[tuple, tuple]:
    """(u, v): the self-dual and anti-self-dual parts of ω (Hodge star *e01 = e23,
    *e02 = −e13, *e03 = e12), u = (ω01 + ω23, ω02 − ω13, ω03 + ω12), v = (ω01 − ω23,
    ω02 + ω13, ω03 − ω12); |u| = |v| iff ω ∧ ω = 0 (ω01 ω23 − ω02 ω13 + ω03 ω12 = 0), i.e.
    iff ω is a plane."""
    w01, w02, w03, w12, w13, w23 = w
    return (w01 + w23, w02 - w13, w03 + w12), (w01 - w23, w02 + w13, w03 - w12)


def chart(w) -> tuple[float, float, float, float]:
    """The angles (α, β, γ, δ) of the oriented plane ω (docs/particles.md): u/|u| =
    (cos α, sin α cos β, sin α sin β), v/|v| = (cos γ, sin γ cos δ, sin γ sin δ), α, γ ∈ [0, π],
    β, δ ∈ ]−π, π]."""
    u, v = self_dual_parts([float(z) for z in w])

    def sphere(x):
        return math.atan2(math.hypot(x[1], x[2]), x[0]), math.atan2(x[2], x[1])
    return (*sphere(u), *sphere(v))


def from_chart(alpha, beta, gamma, delta) -> tuple:
    """The bivector of the angles (|u| = |v| = 1): the inverse of :func:`chart` up to a
    positive factor."""
    u = (math.cos(alpha), math.sin(alpha) * math.cos(beta), math.sin(alpha) * math.sin(beta))
    v = (math.cos(gamma), math.sin(gamma) * math.cos(delta), math.sin(gamma) * math.sin(delta))
    return ((u[0] + v[0]) / 2, (u[1] + v[1]) / 2, (u[2] + v[2]) / 2,
            (u[2] - v[2]) / 2, (v[1] - u[1]) / 2, (u[0] - v[0]) / 2)


# --- exact reference --------------------------------------------------------------

def exact_orbit(i: int, w, r, collisions: int) -> tuple[str, int]:
    """The map in exact rationals from the face i and the exact bivector ω (fmpq or int
    entries), at the exact r: (word, break code; 0 after ``collisions`` collisions)."""
    rows = [[[flint.fmpq(z) for z in row] for row in K] for K in integer_rows(r)]
    w = tuple(flint.fmpq(z) for z in w)
    word = []
    for _ in range(collisions):
        code, j = classify(i, w, (0,) * len(w), rules.ball_sign, lambda z: True)
        if code:
            return "".join(word), code
        w, i = advance(j, w, rows), j
        word.append(LETTERS[j])
    return "".join(word), 0


# --- the sweep ----------------------------------------------------------------------

@dataclass
class FiveOrbits:
    """The result of :func:`iterate`: r (n_r,), p0 and q0 (n_orbits, 4) the data on face
    b, breaks, collisions, certified (n_r, n_orbits) as in ``numerics.Orbits``, face
    (n_r, n_orbits) the last face (0..3), omega (n_r, n_orbits, 6) the last bivector
    (rescaled by powers of 2), angles (n_r, n_orbits, 4) its chart (α, β, γ, δ); word the
    collision words when asked."""

    r: np.ndarray
    p0: np.ndarray
    q0: np.ndarray
    breaks: np.ndarray
    collisions: np.ndarray
    certified: np.ndarray
    face: np.ndarray
    omega: np.ndarray
    angles: np.ndarray
    word: np.ndarray | None = None

    def save(self, handle) -> None:
        """The arrays of :data:`KEYS` (and ``word``) into an .npz (``numpy.savez``)."""
        arrays = {k: getattr(self, k) for k in KEYS}
        if self.word is not None:
            arrays["word"] = self.word
        np.savez(handle, **arrays)

    def summary(self) -> str:
        """A few lines: sizes, breaks by name, the certified collisions (observed beyond)."""
        n_r, n_o = self.breaks.shape
        done = int(self.collisions.sum())
        lines = [f"float64, five particles: {n_r} value(s) of r × {n_o} orbit(s), "
                 f"{int(self.collisions.max(initial=0))} collisions at most"]
        for code, name in BREAKS.items():
            count = int((self.breaks == code).sum())
            if count:
                lines.append(f"  {count:>7} {name} (break {code})")
        lines.append(f"  certified: {int(self.certified.sum())} of {done} collisions "
                     f"({(self.certified.sum() / done if done else 1):.2%}); certified horizon per orbit from "
                     f"{int(self.certified.min()) if self.certified.size else 0} to "
                     f"{int(self.certified.max(initial=0))}; the rest observed")
        if self.word is not None:
            tails: dict = {}
            for w in self.word.ravel():
                key = periodic_tail(str(w)) or "no periodic tail"
                tails[key] = tails.get(key, 0) + 1
            lines.append("  the words' tails (observed): " + ", ".join(
                f"{k} ×{n}" for k, n in sorted(tails.items(), key=lambda x: (-x[1], x[0]))))
        return "\n".join(lines)


def iterate(r, p0, q0, collisions: int = 10_000, strict: bool = False, words: bool = False,
            progress: Callable[[int, int, str], None] | None = None, face: str = START) -> FiveOrbits:
    """The five-particle reduction map from every datum (p0, q0) on ``face`` (rows of
    (n_orbits, 4) arrays), for every r, on the float64 engine: up to ``collisions``
    collisions or a break; ``strict`` stops each orbit at its certified horizon."""
    from . import five_kernel  # numba, where the engine first runs
    r = np.atleast_1d(np.asarray(r, dtype=float))
    p0, q0 = np.atleast_2d(np.asarray(p0, dtype=float)), np.atleast_2d(np.asarray(q0, dtype=float))
    if r.ndim != 1 or not np.all((r > 0) & (r < 1)):
        raise ValueError("r must be a 1-d array in ]0, 1[")
    if p0.shape != q0.shape or p0.shape[1:] != (GAPS,):
        raise ValueError("p0 and q0 must be (n, 4) arrays of one shape")
    n_r, n_o = len(r), len(p0)
    starts = [start(p, q) for p, q in zip(p0, q0)]
    shape = (n_r, n_o)
    breaks, counts, cert = np.zeros(shape, np.int8), np.zeros(shape, np.int64), np.zeros(shape, np.int64)
    last, omega = np.zeros(shape, np.int8), np.zeros(shape + (6,))
    word = [[""] * n_o for _ in range(n_r)]
    letters = np.zeros(collisions if words else 1, dtype=np.int8)
    i0 = LETTERS.index(face)
    for a, x in enumerate(r):
        rows = np.array(float_rows(x)).reshape(GAPS * 36)
        for b, (w0, e0) in enumerate(starts):
            out = np.array(w0)
            code, done, c, i = five_kernel.orbit(i0, np.array(w0), np.array(e0), rows, rules.TOL64, G64_6,
                                                 rules.K64, rules.TINY64, collisions, strict, words, letters, out)
            breaks[a, b], counts[a, b], cert[a, b], last[a, b], omega[a, b] = code, done, c, i, out
            if words:
                word[a][b] = "".join(LETTERS[z] for z in letters[:done])
        if progress is not None:
            progress(a + 1, n_r, f"r = {x:.6g}")
    angles = np.array([[chart(w) for w in row] for row in omega]).reshape(n_r, n_o, 4)
    return FiveOrbits(r, p0, q0, breaks, counts, cert, last, omega, angles,
                      np.array(word, dtype=str).reshape(shape) if words else None)


# --- the periodic tail of a word (observed) -----------------------------------------

def canonical(word: str) -> str:
    """The least rotation of the word or of its mirror image (a ↔ d, b ↔ c)."""
    mirror = word.translate(str.maketrans(LETTERS, LETTERS[::-1]))
    return min(w[k:] + w[:k] for w in (word, mirror) for k in range(len(word)))


def periodic_tail(word: str, longest: int = 200, repeats: int = 5) -> str | None:
    """The shortest period P ≤ ``longest`` with which the last ``repeats`` · P letters of the
    word repeat, as its :func:`canonical` form, or None (observed: a float run's tail)."""
    for P in range(2, longest + 1):
        n = repeats * P
        if n > len(word):
            return None
        tail = word[-n:]
        if tail == tail[:P] * repeats:
            return canonical(tail[:P])
    return None
