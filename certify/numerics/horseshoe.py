"""Certified horseshoes of the b-to-b map: chaos proved by covering relations (issue 36).

**The map, projectively.**  A state at the contact b is an oriented normal n (n_z > 0 > n_x,
:mod:`certify.dynamics.reduction`), in the chart of :mod:`certify.dynamics.island`:
n = (u − 1, v, u + 1).  One step to the next contact j multiplies the normal by cof(K_j)
(Theorem 4.1), and the physical normal keeps the orientation e_t · n > 0 (t = i + 1 at the
contact i), so every rule of :func:`certify.dynamics.reduction.next_letter` is the sign of a
*linear* form of n: at the contact i, with m the product of the cofactors so far times n,
m_{i+1} > 0 (orientation), m_{i+2} < 0 (the position inside the face) and the next letter is
i + 1 where m_i > 0, i + 2 where m_i < 0.  Hence the states that follow a given word from b
to b (a *branch*) form an open convex polygon of the chart, cut by these linear inequalities
(:func:`branch_forms`), and on it the map is the projective map n ↦ M_w n, whose chart
denominator m_z − m_x is positive there (m_z > 0 > m_x at the final b): segments go to
segments, a quadrilateral inside a branch goes to the quadrilateral of its vertices' images.
(We checked the orientation rule on 10⁵ float steps at r = 0.11 and 0.09: the normal
cof(K_j) n never needs :func:`~certify.dynamics.reduction.canonical`'s flip; the proof below
does not rely on it, it requires m_{i+1} > 0 as one of the branch's inequalities.)

**The proof** (:func:`prove`), all in rationals: quadrilaterals N_i = c_i + [−1, 1] U_i +
[−1, 1] S_i with rational c, U, S, each given the word of G = f^k (k b-returns) it must follow.
(a) every vertex of N_i satisfies every strict inequality of its word's branch: by
convexity the whole N_i does, G is the projective map M_w on it and continuous.  (b) N_i ⇒ N_j
(Zgliczyński–Gidea's covering relation with one unstable direction): in N_j's affine
coordinates (x along U_j, y along S_j, N_j = [−1, 1]²) the images of N_i's four vertices have
|y| < 1, and the images of N_i's two exit edges x = −1, x = +1 (their two vertices each) lie in
x < −1 and x > 1, or the other way round.  The image of N_i is the quadrilateral of these
images, so the homotopy (1 − t) G_c + t·(x, y) ↦ (±2x, 0) never meets N_j's entry set nor
brings the exit set into N_j: the relation holds, with degree ±1.  (c) the boxes are pairwise
disjoint (a separating edge line, signs at the vertices).  Conclusion (Zgliczyński–Gidea,
J. Differential Equations 202 (2004), Theorems 9 and 11): for every path of the graph T
(T_ij = 1 iff N_i ⇒ N_j) there is an orbit of G following it, periodic for a periodic path;
on the compact invariant set of such orbits G is semi-conjugate to the subshift of finite
type of T, so h_top(f) ≥ log ρ(T) / k, and f has periodic orbits of infinitely many periods.
ρ(T) ≥ β is certified by Collatz–Wielandt: min_i (T x)_i / x_i ≥ β for a positive rational x.

The chaos proved is on this invariant set, a set of measure zero (a Cantor set of a
horseshoe): it says nothing of a given orbit the simulator calls unresolved.

**The search** (:func:`find`, floats, never trusted): a saddle periodic point p of f (a fixed
point of G = f^k, an eigenvector of M_w), its unstable line (straight: the branch is
projective), the first crossing of the stable line by the iterated unstable segment (a
homoclinic point), and a chain of boxes along that homoclinic orbit, sized by the derivative
cocycle with a margin; a box N_0 at p with N_0 ⇒ N_0.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from fractions import Fraction

import flint
import numpy as np

from certify.algebra.balls import precision
from certify.algebra.poly import to_fmpq
from certify.dynamics.model import INDEX, LETTERS
from certify.dynamics.reduction import cofactor

ORIENTATION_INDEX = {"a": 1, "b": 2, "c": 0}        # t = i + 1 (mod 3) at the contact i
BRANCHES = ("ab", "cb", "acb", "cab")              # the words of one b-to-b step (a step from b to b)
TRANSIENT_RETURNS = 100                            # b-returns before a visit to the boxes counts (:func:`visits`)


# --- exact: the branch of a word and its projective map ------------------------

def point_normal(u, v) -> tuple:
    """The normal n = (u − 1, v, u + 1) of the chart point (u, v) at b."""
    return (u - 1, v, u + 1)


def chart_of(n) -> tuple:
    """(u, v) of a normal at b with n_z − n_x ≠ 0 (any field)."""
    d = n[2] - n[0]
    return ((n[0] + n[2]) / d, 2 * n[1] / d)


def _apply(rows, n) -> tuple:
    return tuple(rows[k][0] * n[0] + rows[k][1] * n[1] + rows[k][2] * n[2] for k in range(3))


def branch_forms(word: str, r) -> list[tuple[tuple, str]]:
    """The linear forms of n (as integer rows) whose strict signs define the branch of ``word``
    (letters from b to b): [(row, why)], each form required > 0.  At each contact i with
    m = (product of cof(K) so far) n: m_{i+1} > 0, −m_{i+2} > 0, and ±m_i > 0 picking the next
    letter; at the end (contact b) m_z > 0 and −m_x > 0."""
    if not word or word[-1] != "b" or any(x not in LETTERS for x in word):
        raise ValueError(f"not a word from b to b: {word!r}")
    rows = ((1, 0, 0), (0, 1, 0), (0, 0, 1))
    forms, contact = [], "b"
    for k, letter in enumerate(word):
        i = INDEX[contact]
        j1, j2 = (i + 1) % 3, (i + 2) % 3
        if letter == contact:
            raise ValueError(f"{word!r}: the same collision twice in a row")
        forms.append((rows[j1], f"orientation before {letter} (step {k + 1})"))
        forms.append((tuple(-z for z in rows[j2]), f"inside the face {contact} (step {k + 1})"))
        pick = rows[i] if INDEX[letter] == j1 else tuple(-z for z in rows[i])
        forms.append((pick, f"next collision {letter} (step {k + 1})"))
        C = cofactor(letter, to_fmpq(r))
        rows = tuple(tuple(sum(C[a][c] * rows[c][b] for c in range(3)) for b in range(3)) for a in range(3))
        contact = letter
    forms.append((rows[2], "orientation at the return to b"))
    forms.append((tuple(-z for z in rows[0]), "inside the face b at the return"))
    return forms


def word_matrix(word: str, r) -> tuple:
    """The integer rows of M_w = cof(K_last) ⋯ cof(K_first) (each cofactor a positive multiple)."""
    rows = ((1, 0, 0), (0, 1, 0), (0, 0, 1))
    for letter in word:
        C = cofactor(letter, to_fmpq(r))
        rows = tuple(tuple(sum(C[a][c] * rows[c][b] for c in range(3)) for b in range(3)) for a in range(3))
    return rows


def follows(word: str, point, r) -> bool:
    """Whether the rational chart point follows ``word`` (every form of :func:`branch_forms`
    strictly positive at it)."""
    n = point_normal(*(to_fmpq(z) for z in point))
    return all(_dot(row, n) > 0 for row, _ in branch_forms(word, r))


def _dot(row, n):
    return row[0] * n[0] + row[1] * n[1] + row[2] * n[2]


def image(word: str, point, r) -> tuple:
    """The image of a rational chart point under the projective map of ``word`` (exact)."""
    return chart_of(_apply(word_matrix(word, r), point_normal(*(to_fmpq(z) for z in point))))


# --- exact: boxes and covering relations -------------------------------------

@dataclass(frozen=True)
class Box:
    """N = c + [−1, 1] U + [−1, 1] S in the chart (rationals), following ``word`` under G."""

    name: str
    word: str
    c: tuple
    U: tuple
    S: tuple

    def vertices(self) -> list[tuple]:
        """The corners c + sU + tS for (s, t) = (−1, −1), (−1, 1), (1, 1), (1, −1) (in order around)."""
        return [self.point(s, t) for s, t in ((-1, -1), (-1, 1), (1, 1), (1, -1))]

    def point(self, x, y) -> tuple:
        return (self.c[0] + x * self.U[0] + y * self.S[0], self.c[1] + x * self.U[1] + y * self.S[1])

    def coordinates(self, z) -> tuple:
        """(x, y) with z = c + xU + yS (exact)."""
        det = self.U[0] * self.S[1] - self.U[1] * self.S[0]
        dz = (z[0] - self.c[0], z[1] - self.c[1])
        return ((dz[0] * self.S[1] - dz[1] * self.S[0]) / det, (self.U[0] * dz[1] - self.U[1] * dz[0]) / det)

    def as_json(self) -> dict:
        return {"name": self.name, "word": self.word, "center": [str(z) for z in self.c],
                "unstable": [str(z) for z in self.U], "stable": [str(z) for z in self.S],
                "vertices": [[str(z) for z in p] for p in self.vertices()]}

    @classmethod
    def of_json(cls, d: dict) -> Box:
        """The box of :meth:`as_json` (its rationals read exactly)."""
        return cls(d["name"], d["word"], *(tuple(to_fmpq(z) for z in d[k]) for k in ("center", "unstable", "stable")))


@dataclass
class Proof:
    """What :func:`prove` decided: each box in its branch, each covering relation, disjointness,
    T, the certified lower bound β ≤ ρ(T) and the entropy bound log β / k."""

    r: object
    k: int
    boxes: list
    in_branch: dict = field(default_factory=dict)       # name -> (holds, evidence)
    covers: dict = field(default_factory=dict)          # (i, j) -> (holds, evidence)
    disjoint: tuple = (True, "")
    T: list = field(default_factory=list)
    beta: Fraction | None = None
    entropy: str = ""

    @property
    def holds(self) -> bool:
        """A horseshoe proved: every box in its branch, every claimed relation, disjoint boxes, β > 1."""
        return (all(h for h, _ in self.in_branch.values()) and all(h for h, _ in self.covers.values())
                and self.disjoint[0] and self.beta is not None and self.beta > 1)


def in_branch(box: Box, r) -> tuple[bool, str]:
    """Every form of the box's word is > 0 at its four vertices (so on the box, by convexity); a
    flat box (U, S dependent) is refused."""
    if box.U[0] * box.S[1] - box.U[1] * box.S[0] == 0:
        return False, "a flat box: U and S are dependent"
    forms = branch_forms(box.word, r)
    for row, why in forms:
        for p in box.vertices():
            if _dot(row, point_normal(*p)) <= 0:
                return False, f"{why}: not > 0 at the vertex ({p[0]}, {p[1]})"
    return True, f"{len(forms)} linear forms > 0 at the 4 vertices"


def covering(a: Box, b: Box, r) -> tuple[bool, str]:
    """N_a ⇒ N_b under a's projective map (a in its branch is the caller's): image vertices in
    b's coordinates; |y| < 1 at all four, the exit edge x = −1 beyond one side of b and x = +1
    beyond the other."""
    xy = {(s, t): b.coordinates(image(a.word, a.point(s, t), r)) for s in (-1, 1) for t in (-1, 1)}
    ys = [y for _, y in xy.values()]
    if not all(-1 < y < 1 for y in ys):
        return False, f"an image vertex has |y| ≥ 1 (y = {', '.join(f'{float(y):.4g}' for y in ys)})"
    left, right = [xy[(-1, t)][0] for t in (-1, 1)], [xy[(1, t)][0] for t in (-1, 1)]
    if (all(x < -1 for x in left) and all(x > 1 for x in right)) or \
            (all(x > 1 for x in left) and all(x < -1 for x in right)):
        return True, (f"|y| ≤ {float(max(abs(y) for y in ys)):.4g} < 1; exit edges at x ∈ "
                      f"[{float(min(left)):.4g}, {float(max(left)):.4g}] and "
                      f"[{float(min(right)):.4g}, {float(max(right)):.4g}]")
    return False, f"the exit edges' images at x = {[float(x) for x in left]}, {[float(x) for x in right]}"


def separated(a: Box, b: Box) -> bool:
    """Whether an edge line of a or of b has the other box strictly on its outer side."""
    for P, Q in ((a, b), (b, a)):
        V = P.vertices()
        for k in range(4):
            p, q = V[k], V[(k + 1) % 4]
            inner = V[(k + 2) % 4]

            def side(z, p=p, q=q):
                return (q[0] - p[0]) * (z[1] - p[1]) - (q[1] - p[1]) * (z[0] - p[0])
            s = side(inner)
            if all(side(z) * s < 0 for z in Q.vertices()):
                return True
    return False


def collatz_wielandt(T: list, x: list) -> Fraction:
    """min_i (T x)_i / x_i for a positive rational x: a lower bound of ρ(T) (T ≥ 0)."""
    return min(sum(Fraction(T[i][j]) * x[j] for j in range(len(x))) / x[i] for i in range(len(x)))


def prove(r, boxes: list, edges: list, k: int) -> Proof:
    """The exact proof of a horseshoe for G = f^k (module docstring): each box in its branch,
    each covering relation of ``edges`` (pairs of indices), the boxes pairwise disjoint, and
    ρ(T) ≥ β by Collatz–Wielandt on the Perron vector (rounded to rationals)."""
    P = Proof(r, k, boxes)
    for b in boxes:
        P.in_branch[b.name] = in_branch(b, r)
    m = len(boxes)
    P.T = [[0] * m for _ in range(m)]
    for i, j in edges:
        holds, why = (covering(boxes[i], boxes[j], r) if P.in_branch[boxes[i].name][0] and P.in_branch[boxes[j].name][0]
                      else (False, "a box not in its branch"))
        P.covers[(i, j)] = (holds, why)
        P.T[i][j] = 1 if holds else 0
    bad = [(a.name, b.name) for n, a in enumerate(boxes) for b in boxes[n + 1:] if not separated(a, b)]
    P.disjoint = (not bad, "pairwise disjoint (a separating edge line each)" if not bad
                  else f"not shown disjoint: {bad[:3]}")
    w, V = np.linalg.eig(np.array(P.T, dtype=float))
    top = int(np.argmax(w.real))
    x = [Fraction(max(abs(float(z)), 1e-6)).limit_denominator(10**6) for z in V[:, top].real]
    P.beta = collatz_wielandt(P.T, x)
    if P.beta > 1:
        P.entropy = entropy_bound(P.beta, k)
    return P


def entropy_bound(beta: Fraction, k: int, digits: int = 6) -> str:
    """A decimal ≤ log(β)/k with ``digits`` digits: the lower end of an arb ball, rounded down."""
    with precision(128):
        ball = flint.arb(flint.fmpq(beta.numerator, beta.denominator)).log() / k
        lo = _exact(ball.mid()) - _exact(ball.rad())
    return _decimal(math.floor(lo * 10**digits), digits)


def _exact(x) -> Fraction:
    man, exp = x.man_exp()
    return Fraction(int(man)) * Fraction(2) ** int(exp)


def _decimal(units: int, digits: int) -> str:
    sign, units = ("-" if units < 0 else ""), abs(units)
    return f"{sign}{units // 10**digits}.{units % 10**digits:0{digits}d}"


# --- floats: the search (never trusted; the proof above decides) -----------------

class FloatMap:
    """The b-to-b map f in floats in the chart: its branch word and projective matrix at a point."""

    def __init__(self, r):
        r = to_fmpq(r)
        self.r = r
        self.C = {L: np.array([[float(z) for z in row] for row in cofactor(L, r)]) for L in LETTERS}

    def step(self, z, returns: int = 1):
        """(image, word) of f^returns at the chart point z, or (None, word) at a corner/escape."""
        n = np.array([z[0] - 1.0, z[1], z[0] + 1.0])
        contact, word = "b", ""
        for _ in range(returns):
            for _ in range(400):
                i = INDEX[contact]
                j1, j2 = (i + 1) % 3, (i + 2) % 3
                if not (n[j1] > 0 > n[j2]) or n[i] == 0:
                    return None, word
                contact = LETTERS[j1] if n[i] > 0 else LETTERS[j2]
                n = self.C[contact] @ n
                n = n / np.abs(n).max()
                word += contact
                if contact == "b":
                    break
            else:
                return None, word
        if not (n[2] > 0 > n[0]):
            return None, word
        return np.array(chart_of(n)), word

    def matrix(self, word: str) -> np.ndarray:
        M = np.eye(3)
        for L in word:
            M = self.C[L] @ M
            M = M / np.abs(M).max()
        return M


def projective(M, z) -> np.ndarray:
    """The chart image of z under the normal map M (floats)."""
    n = M @ np.array([z[0] - 1.0, z[1], z[0] + 1.0])
    return np.array(chart_of(n))


def jacobian(M, z) -> np.ndarray:
    """The derivative of the chart map of M at z (floats, the quotient rule)."""
    N = M @ np.array([z[0] - 1.0, z[1], z[0] + 1.0])
    dN = [M @ np.array([1.0, 0.0, 1.0]), M @ np.array([0.0, 1.0, 0.0])]
    d = N[2] - N[0]
    J = np.zeros((2, 2))
    for c in range(2):
        dd = dN[c][2] - dN[c][0]
        J[0, c] = ((dN[c][0] + dN[c][2]) * d - (N[0] + N[2]) * dd) / d**2
        J[1, c] = (2 * dN[c][1] * d - 2 * N[1] * dd) / d**2
    return J


@dataclass
class Saddle:
    word: str
    returns: int
    p: np.ndarray
    M: np.ndarray
    eu: np.ndarray
    es: np.ndarray
    lam: float
    mu: float


def saddles(fm: FloatMap, max_returns: int = 3) -> list[Saddle]:
    """The saddle periodic points of f with at most ``max_returns`` returns (floats): for every
    word of branches, the eigenvectors of M_w whose chart point follows w, with one multiplier
    of modulus > 1 and one < 1; sorted by period, then by the weaker of log λ and −log μ (to 9
    digits: mirror images, such as abacb and cbcab, have the same multipliers, which floats
    tell apart only in their last bits, differently from one numpy to another), then by the
    word, the later in alphabetical order first."""
    import itertools
    out = []
    for k in range(1, max_returns + 1):
        for combo in itertools.product(range(len(BRANCHES)), repeat=k):
            if combo != min(combo[i:] + combo[:i] for i in range(k)):
                continue
            w = "".join(BRANCHES[c] for c in combo)
            M = fm.matrix(w)
            ev, V = np.linalg.eig(M)
            for idx in range(3):
                if abs(ev[idx].imag) > 1e-12:
                    continue
                n = V[:, idx].real
                n = n if n[2] - n[0] > 0 else -n
                if not (n[2] > 0 > n[0]):
                    continue
                p = np.array(chart_of(n))
                z, seen = fm.step(p, k)
                if z is None or seen != w or np.abs(z - p).max() > 1e-8 * (1 + np.abs(p).max()):
                    continue
                J = jacobian(M, p)
                lj, Vj = np.linalg.eig(J)
                if np.iscomplexobj(lj) and np.abs(lj.imag).max() > 0:
                    continue
                lj, Vj = lj.real, Vj.real
                a, b = (0, 1) if abs(lj[0]) > abs(lj[1]) else (1, 0)
                if not (abs(lj[a]) > 1.5 and abs(lj[b]) < 1 / 1.5):
                    continue
                out.append(Saddle(w, k, p, M, Vj[:, a] / np.linalg.norm(Vj[:, a]),
                                  Vj[:, b] / np.linalg.norm(Vj[:, b]), lj[a], lj[b]))
    out.sort(key=lambda s: (s.returns, float(f"{-min(math.log(abs(s.lam)), -math.log(abs(s.mu))):.9g}"),
                            tuple(-ord(x) for x in s.word)))
    return out


def _coords(s: Saddle, z) -> tuple:
    """(a, b) with z = p + a e_u + b e_s."""
    B = np.column_stack([s.eu, s.es])
    a, b = np.linalg.solve(B, np.asarray(z) - s.p)
    return a, b


def _local_range(fm: FloatMap, s: Saddle, e: np.ndarray) -> float:
    """The largest t (a power-of-two fraction of 4) with p ± t'e following s.word for every t' ≤ t
    on a grid (floats): the local straight piece of a manifold inside p's branch."""
    t = 4.0
    while t > 1e-9:
        if all(fm.step(s.p + sign * t * f * e, s.returns)[1] == s.word
               for sign in (-1, 1) for f in np.linspace(0.01, 1, 25)):
            return t
        t /= 2
    return 0.0


@dataclass
class Homoclinic:
    t: float            # the point p + t e_u of the local unstable line
    m: int              # G^m(p + t e_u) lies on the local stable line
    b: float            # at p + b e_s


def homoclinic_points(fm: FloatMap, s: Saddle, Tu: float, Ts: float, max_iter: int = 10,
                      samples: int = 600) -> list[Homoclinic]:
    """Crossings of the local stable segment {p + b e_s : |b| < Ts/2} by the iterated local
    unstable segment (floats): G^m of consecutive samples of a fundamental domain on both sides
    of p, with the same words (one projective piece) and a change of side, refined by bisection."""
    lam = abs(s.lam)
    t1 = Tu / lam / 2
    found = []
    for side in (-1.0, 1.0):
        ts = side * t1 * np.exp(np.linspace(0, math.log(lam), samples))
        prev = None
        for t in ts:
            z, hist = s.p + t * s.eu, []
            track = []
            for m in range(1, max_iter + 1):
                z, w = fm.step(z, s.returns)
                if z is None:
                    break
                hist.append(w)
                track.append((m, "".join(hist), _coords(s, z)))
            if prev is not None:
                old = {m: (h, ab) for m, h, ab in prev[1]}
                for m, h, (a, b) in track:
                    if m in old and old[m][0] == h and m >= 1:
                        a0, b0 = old[m][1]
                        if a0 * a < 0 and abs(b) < Ts / 2 and abs(b0) < Ts / 2 and min(abs(b), abs(b0)) > 1e-6 * Ts:
                            found.append(_refine(fm, s, prev[0], t, m, h))
                            break
            prev = (t, track)
    return [h for h in found if h is not None]


def _refine(fm, s, t0, t1, m, hist) -> Homoclinic | None:
    """Bisection on t for the crossing a = 0 of G^m(p + t e_u) (the same words throughout)."""
    def a_of(t):
        z = s.p + t * s.eu
        for _ in range(m):
            z, _w = fm.step(z, s.returns)
        return _coords(s, z)
    a0 = a_of(t0)[0]
    for _ in range(60):
        tm = (t0 + t1) / 2
        am = a_of(tm)[0]
        if (am < 0) == (a0 < 0):
            t0, a0 = tm, am
        else:
            t1 = tm
    a, b = a_of((t0 + t1) / 2)
    return Homoclinic((t0 + t1) / 2, m, b)


def _preimage_on_line(s: Saddle, t: float, j: int) -> float:
    """The coordinate t' on the local unstable line with G^j(p + t' e_u) = p + t e_u (floats):
    G is the projective map M on p's branch and keeps the line."""
    Minv = np.linalg.inv(s.M)
    z = s.p + t * s.eu
    for _ in range(j):
        z = projective(Minv, z)
    return float(np.dot(z - s.p, s.eu))


def _rational(x: float, decimals: int) -> flint.fmpq:
    """The float x rounded to ``decimals`` decimals, as an exact rational (a short decimal: the boxes
    read as printed; the proof decides the rounded boxes)."""
    f = Fraction(f"{float(x):.{decimals}f}")
    return flint.fmpq(f.numerator, f.denominator)


def chain(fm: FloatMap, s: Saddle, h: Homoclinic, back: int, forward: int, alpha: float):
    """The boxes N_0 (at p) and B_0 … B_L along the homoclinic orbit (floats rounded to rationals),
    with the edges N_0 → N_0, N_0 → B_0, B_j → B_(j+1), B_L → N_0; or None where the sizes
    cannot satisfy the linearised covering conditions with margin ``alpha``."""
    t0 = _preimage_on_line(s, h.t, back)
    q = [s.p + t0 * s.eu]
    for _ in range(back + h.m):                # away from p: G itself (rounding grows like λ^(back+m))
        z, _w = fm.step(q[-1], s.returns)
        if z is None:
            return None
        q.append(z)
    q[-1] = s.p + _coords(s, q[-1])[1] * s.es  # the homoclinic point, on the stable line
    for _ in range(forward):                   # back to p along the stable line: p's projective map
        q.append(projective(s.M, q[-1]))
    words = []
    for z in q:
        image_, w = fm.step(z, s.returns)
        if image_ is None:
            return None
        words.append(w)
    L = len(q) - 1
    lam, mu = abs(s.lam), abs(s.mu)
    d0 = abs(t0)
    sL = abs(_coords(s, q[-1])[1])
    w0, h0 = d0 / math.sqrt(lam), sL * math.sqrt(mu)
    eu, es = [s.eu], [None] * (L + 1)
    lams, mus = [], [0.0] * (L + 1)
    for j in range(L + 1):
        v = jacobian(fm.matrix(words[j]), q[j]) @ eu[-1]
        lams.append(float(np.linalg.norm(v)))
        if j < L:
            eu.append(v / lams[-1])
    es[L] = s.es
    mus[L] = mu
    for j in range(L - 1, -1, -1):
        v = np.linalg.solve(jacobian(fm.matrix(words[j]), q[j]), es[j + 1])
        mus[j] = 1 / float(np.linalg.norm(v))
        es[j] = v * mus[j]
    W = [min(lam * w0 - d0, d0 - w0) / alpha]
    for j in range(L):
        W.append(W[-1] * lams[j] / alpha)
    H = [alpha * mu * h0]
    for j in range(L):
        H.append(H[-1] * mus[j] * alpha)
    Sw = W[L] * lams[L] / (alpha * w0)
    Sh = min(h0 / (alpha * mu) - sL, (sL - h0) / alpha) / H[L]
    if Sw < 1 or Sh < 1:
        return None
    widths = [W[j] * Sw ** (-(j + 1) / (L + 2)) for j in range(L + 1)]
    heights = [H[j] * Sh ** ((j + 1) / (L + 2)) for j in range(L + 1)]

    def box(name, word, c, U, S):
        scale = min(float(np.linalg.norm(U)), float(np.linalg.norm(S)))
        if not scale > 0:
            return Box(name, word, (flint.fmpq(0),) * 2, (flint.fmpq(0),) * 2, (flint.fmpq(0),) * 2)
        d = max(8, 6 - math.floor(math.log10(scale)))      # 10^-6 of the box's smaller side
        return Box(name, word, tuple(_rational(x, d) for x in c), tuple(_rational(x, d) for x in U),
                   tuple(_rational(x, d) for x in S))
    boxes = [box("N0", s.word, s.p, w0 * s.eu, h0 * s.es)]
    boxes += [box(f"B{j}", words[j], q[j], widths[j] * eu[j], heights[j] * es[j]) for j in range(L + 1)]
    edges = [(0, 0), (0, 1)] + [(j, j + 1) for j in range(1, L + 1)] + [(L + 1, 0)]
    return boxes, edges


@dataclass
class Horseshoe:
    """A proved horseshoe (or the reason none was found) at r."""

    r: object
    proof: Proof | None
    saddle: str = ""
    saddle_point: tuple = ()
    multipliers: tuple = ()
    homoclinic_iterates: int = 0
    tried: int = 0


def find(r, max_returns: int = 2, alphas=(2.0, 1.5, 3.0), tries: int = 40) -> Horseshoe:
    """Search a horseshoe at r (floats) and prove it (exact): for each saddle of at most
    ``max_returns`` returns, each homoclinic point (fewest iterates first), a few lengths of
    the chain and margins; the first chain whose exact proof holds.  ``tries``: proofs attempted
    at most."""
    fm = FloatMap(r)
    tried = 0
    for s in saddles(fm, max_returns):
        Tu, Ts = _local_range(fm, s, s.eu), _local_range(fm, s, s.es)
        if Tu == 0 or Ts == 0:
            continue
        hs = sorted(homoclinic_points(fm, s, Tu, Ts), key=lambda h: (h.m, abs(h.b)))
        for h in hs[:6]:
            for back in (1, 2, 3):
                for forward in (1, 2, 3):
                    for alpha in alphas:
                        built = chain(fm, s, h, back, forward, alpha)
                        if built is None:
                            continue
                        tried += 1
                        P = prove(r, built[0], built[1], s.returns)
                        if P.holds:
                            return Horseshoe(r, P, s.word, tuple(map(float, s.p)), (float(s.lam), float(s.mu)),
                                             h.m, tried)
                        if tried >= tries:
                            return Horseshoe(r, None, tried=tried)
                        break       # another margin rarely mends a failed proof: lengthen the chain
    return Horseshoe(r, None, tried=tried)


CONCLUSION = ("an invariant set of G = f^{k} (k = {k} b-returns) on which G is semi-conjugate to the "
              "subshift of finite type of T; topological entropy of the b-to-b map ≥ log ρ(T)/k ≥ {h}; "
              "periodic orbits of infinitely many periods")
MEASURE_ZERO = ("the horseshoe is a set of measure zero: it proves chaos on it, not that a given "
                "unresolved orbit of the simulator is chaotic")


def as_json(H: Horseshoe, seconds: float | None = None) -> dict:
    """The JSON record of ``certify chaos`` (certify/schemas/chaos.schema.json)."""
    doc: dict = {"schema": "certify-chaos", "version": 1, "r": str(H.r),
                 "certified": bool(H.proof is not None and H.proof.holds)}
    if seconds is not None:
        doc["seconds"] = round(seconds, 2)
    P = H.proof
    if P is None or not P.holds:
        doc["why"] = (f"no horseshoe found: {H.tried} chains of boxes tried, none proved "
                      "(saddles of at most 2 returns and their homoclinic points); nothing is claimed")
        return doc
    doc.update({
        "saddle": {"word": H.saddle, "returns": P.k, "point": list(H.saddle_point),
                   "multipliers": list(H.multipliers), "homoclinic_iterates": H.homoclinic_iterates},
        "boxes": [b.as_json() | {"in_branch": P.in_branch[b.name][1]} for b in P.boxes],
        "coverings": [{"from": P.boxes[i].name, "to": P.boxes[j].name, "evidence": why}
                      for (i, j), (_, why) in P.covers.items()],
        "disjoint": P.disjoint[1],
        "T": P.T, "rho_lower": str(P.beta), "entropy_lower": P.entropy,
        "conclusion": CONCLUSION.format(k=P.k, h=P.entropy), "measure": MEASURE_ZERO})
    return doc


def text_lines(doc: dict):
    """The text output of ``certify chaos``."""
    if not doc["certified"]:
        yield f"chaos at r = {doc['r']}: NOT certified: {doc['why']}"
        return
    s = doc["saddle"]
    yield f"chaos at r = {doc['r']}: a horseshoe, proved in exact rational arithmetic"
    yield (f"  saddle: word {s['word']} ({s['returns']} b-return(s)) at (u, v) ≈ ({s['point'][0]:.6f}, "
           f"{s['point'][1]:.6f}), multipliers ≈ {s['multipliers'][0]:.4g}, {s['multipliers'][1]:.4g} "
           "(floats, the search)")
    yield f"  homoclinic orbit: the unstable line reaches the stable line after {s['homoclinic_iterates']} iterates"
    yield f"  G = f^{s['returns']}; boxes N = c + [-1,1]U + [-1,1]S in the chart (u, v) of the b-section, rational:"
    for b in doc["boxes"]:
        c = ", ".join(f"{float(_q(z)):.6g}" for z in b["center"])
        yield f"    {b['name']:>4}  word {b['word']:<12} centre ≈ ({c})  ✓ in its branch: {b['in_branch']}"
    yield "  covering relations N_i ⇒ N_j (images of the vertices in N_j's coordinates):"
    for e in doc["coverings"]:
        yield f"    ✓ {e['from']} ⇒ {e['to']}: {e['evidence']}"
    yield f"  ✓ {doc['disjoint']}"
    yield "  T = " + " ".join("".join(map(str, row)) for row in doc["T"])
    yield f"  ρ(T) ≥ {doc['rho_lower']} ≈ {float(_q(doc['rho_lower'])):.6f} (Collatz–Wielandt, exact)"
    yield f"  proved: {doc['conclusion']}"
    yield f"  note: {doc['measure']}"
    if "visits" in doc:
        v = doc["visits"]
        yield (f"  visits ({v['kind']}): {v['visiting']} of {v['orbits']} random orbits enter a box within "
               f"{v['returns']} returns; share of returns in the boxes {v['share_of_returns']:.2e}")


def _q(text: str) -> Fraction:
    return Fraction(text)


def box_frames(boxes: list) -> list:
    """Each box as (centre, the inverse of [U S]) in floats, for :func:`in_boxes`."""
    return [(np.array([float(z) for z in b.c]),
             np.linalg.inv(np.column_stack([[float(z) for z in b.U], [float(z) for z in b.S]]))) for b in boxes]


def in_boxes(frames: list, z) -> bool:
    """Whether the chart point z lies in one of the boxes (floats: observed)."""
    return bool(any_in_boxes(frames, np.asarray(z, dtype=float).reshape(1, 2)))


def any_in_boxes(frames: list, points: np.ndarray) -> bool:
    """Whether one of the chart points (an n × 2 array) lies in one of the boxes (floats: observed)."""
    return any(bool((np.abs((points - c) @ B.T).max(axis=1) <= 1).any()) for c, B in frames) if len(points) else False


def visits(r, boxes: list, orbits: int = 100, returns: int = 2000, seed: int = 0) -> dict:
    """Observed (float64, not a proof): of ``orbits`` random orbits of f (u uniform in ]−1, 1[,
    v normal with deviation 3, seeded), how many enter some box within ``returns`` b-returns
    (after 100 transient ones), and the share of their returns spent in the boxes."""
    fm = FloatMap(r)
    rng = np.random.default_rng(seed)
    frames = box_frames(boxes)
    visiting = inside = counted = 0
    for _ in range(orbits):
        z = np.array([rng.uniform(-1, 1), 3 * rng.normal()])
        hit = False
        for k in range(returns + TRANSIENT_RETURNS):
            z, _w = fm.step(z)
            if z is None:
                break
            if k >= TRANSIENT_RETURNS:
                counted += 1
                if in_boxes(frames, z):
                    inside += 1
                    hit = True
        visiting += hit
    return {"orbits": orbits, "returns": returns, "visiting": visiting,
            "share_of_returns": inside / counted if counted else 0.0,
            "kind": "observed (float64 orbits, not a proof)"}


def facts(P: Proof) -> list[tuple[str, str, bool, object]]:
    """The proof's facts in the order of the statements N2.7.2, N2.7.3, ... (one per box in its branch,
    one per covering relation, one per box for its disjointness from the later boxes, the
    Collatz–Wielandt bound): (kind, text, holds, what: a box index, an edge (i, j) or None)."""
    out: list[tuple[str, str, bool, object]] = []
    for n, b in enumerate(P.boxes):
        out.append(("branch", f"{b.name} lies in the branch of {b.word}", P.in_branch[b.name][0], n))
    for (i, j), (holds, _) in P.covers.items():
        out.append(("cover", f"{P.boxes[i].name} ⇒ {P.boxes[j].name}", holds, (i, j)))
    for n, a in enumerate(P.boxes[:-1]):
        later = P.boxes[n + 1:]
        out.append(("disjoint", f"{a.name} is disjoint from {', '.join(b.name for b in later)}",
                    all(separated(a, b) for b in later), n))
    out.append(("beta", f"ρ(T) ≥ {P.beta} > 1 (Collatz–Wielandt)", P.beta is not None and P.beta > 1, None))
    return out
