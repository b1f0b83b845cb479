"""Remark after Theorem 3.1 (l. 513-515): the pattern abcab has no self-similar datum.

As printed: "for the initial data that are the obvious candidates - that is, the
eigenvector of the corresponding matrix BACBA for the velocities and a fixed point
for the distance map f for the positions - the collision after the first b
collision is a, not c (and these collisions do not take place at the same time, so
that the order really is a and then, after a strictly positive time, c)".

The candidate, with the paper's normalisation for a word that starts with a and
ends with b (l. 270-280): q(0) = (-1, u, v), an eigenvector of M_w = K_b K_a K_c K_b K_a
for a real eigenvalue λ (any real branch), and p(0) = (1, 0, x) with x a fixed point
x₊ or x₋ of f(x) = p_3(t_5)/p_1(t_5) = (ax + b)/(cx + d).  The collisions are
*assumed* (times defined by p_i(t_k) = 0, as in l. 460-463) and then checked:

* the candidate realises a, b as its first two collisions iff u = q_2(0) > 0
  (p_2(0) = 0 right after the last b), x > 0, q_2(t_1) < 0 and p_3(t_2) > 0
  (see :func:`prefix_requirements` for why the other gaps need no condition);
* the claim: q_1(t_2) < 0 (a comes next) and, at the time t_3 of that a,
  p_3(t_3) > 0, i.e. the a collision happens strictly before any c:
  p_3(t_3) = p_3(t_2) + τ_a q_3(t_2) = -q_3(t_2)(τ_c - τ_a) when q_3(t_2) < 0.

Each condition is a rational function of r, λ and x; its sign on each real
eigenvalue branch is certified over whole r-intervals (critical values from
resultants and the discriminant, one exact sample per cell, the branches isolated
by Sturm sequences, signs proven by balls).  :class:`Analysis` imposes the
conditions one at a time and keeps, per branch and fixed point, the exact set of r
where all hold (open intervals with algebraic ends, and points).  At a critical
value the signs are decided by balls, or, where a quantity vanishes or has a pole,
by the engine's exact zero test in Q(r_c)[λ]; where c = 0 the map f is affine and
its fixed point b/(d - a) is used.  The dynamics itself (``certify.simulate``,
balls) is run from the candidate at one rational r per piece as a cross-check.

The helpers (symbolic runs of a word over Q(λ, r), conditions reduced modulo cp,
the region analysis) are shared with ``proofs/literature.py``.
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import flint
import sympy as sp

from certify.algebraic import Algebraic
from certify.branches import Cell, Condition, SignTable, Spectrum, evaluate_sign, simple_rational_between
from certify.model import INDEX, collision_matrix
from certify.poly import FIELD, RING, Lf, Rf, lam, primitive, r, show, to_field, to_ring, x
from certify import simulate as sim
from certify.runner import Check, certificate, conclude
from certify.sturm import count_roots, flint_real_roots

Q = flint.fmpq
K, _LAM, _R = FIELD, Lf, Rf          # the engine's sparse rational functions, λ first in lex order
BRANCH_NAMES = ("upper", "middle", "lower")


# ---------------------------------------------------------------- symbolic candidate
@dataclass
class Candidate:
    """The self-similar candidate of a word w starting with a and ending with b:
    q(0) and the run exact in K = Q(λ, r); a, b, c, d reduced modulo cp (monic in
    λ), which keeps their values on every eigenvalue branch."""

    word: str
    M: sp.Matrix                # M_w = K_{c_n} ... K_{c_1}
    cp: sp.Expr                 # det(λI - M_w)
    spectrum: Spectrum
    q0: tuple                   # (-1, u, v), elements of K (rows 1, 2 of the eigen-equation)
    q0_other: list              # the same from rows (1, 3) and (2, 3), for points where rows 1, 2 degenerate
    abcd: tuple                 # (a, b, c, d) polynomials in r, λ: f(x) = (ax + b)/(cx + d)
    steps: list                 # the symbolic run of the word from (p(0), q(0))

    def fixed_points(self) -> dict[str, "FixedPointData"]:
        """x₊ = (a - d + √Δ)/(2c) and x₋ = (a - d - √Δ)/(2c), reduced modulo cp."""
        return {fp.label: fp for fp in fixed_point_data(self.abcd, self.cp)}


def expr_of(e) -> sp.Expr:
    """An element of K (or a pair P0 + x P1) back as a SymPy expression."""
    if isinstance(e, tuple):
        return e[0].as_expr() + x * e[1].as_expr()
    return e.as_expr()


def collide_k(letter: str, q: tuple) -> tuple:
    """K q over Q(r, λ)."""
    h = (1 + _R) / 2
    q1, q2, q3 = q
    return {"a": (-_R * q1, q2 + h * q1, q3),
            "b": (q1 + h * q2, -_R * q2, q3 + h * q2),
            "c": (q1, q2 + h * q3, -_R * q3)}[letter]


@dataclass
class SymbolicStep:
    """The state right after a collision: p_i = P0_i + x P1_i, q_i over Q(r, λ)."""

    letter: str
    p: list                    # [(P0, P1)] * 3
    q: tuple


def run_letters(letters: str, q0: tuple) -> list[SymbolicStep]:
    """From p(0) = (1, 0, x), q(0) = q0, apply the collisions in ``letters`` with
    times *defined* by p_i(t_k) = 0 (l. 460-463): positions stay affine in x.
    (Exact in K; reducing modulo cp along the way would spoil K's cancellations
    and put spurious factors in the resultants, so conditions are reduced at the end.)"""
    p = [(K.one, K.zero), (K.zero, K.zero), (K.zero, K.one)]
    q = tuple(q0)
    out = []
    for letter in letters:
        i = INDEX[letter]
        if q[i] == K.zero:
            raise ZeroDivisionError(f"q_{i + 1} vanishes identically before {letter}")
        t = (-p[i][0] / q[i], -p[i][1] / q[i])
        p = [(P0 + t[0] * qj, P1 + t[1] * qj) for (P0, P1), qj in zip(p, q)]
        p[i] = (K.zero, K.zero)
        q = collide_k(letter, q)
        out.append(SymbolicStep(letter, p, q))
    return out


def word_matrix_k(word: str) -> list[list]:
    """M_w = K_{c_n} ... K_{c_1} with entries in K."""
    h = (1 + _R) / 2
    o, z = K.one, K.zero
    mats = {"a": [[-_R, z, z], [h, o, z], [z, z, o]], "b": [[o, h, z], [z, -_R, z], [z, h, o]],
            "c": [[o, z, z], [z, o, h], [z, z, -_R]]}
    M = [[o if i == j else z for j in range(3)] for i in range(3)]
    for letter in word:
        Kc = mats[letter]
        M = [[sum((Kc[i][k] * M[k][j] for k in range(3)), z) for j in range(3)] for i in range(3)]
    return M


def det3(A) -> object:
    return (A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) - A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0])
            + A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]))


def eigenvector_k(m, rows=(0, 1)) -> tuple:
    """q = (-1, u, v) solving two rows of (M - λI) q = 0 (Cramer's rule over K); the
    paper uses rows 1 and 2 (l. 366).  On the eigenvalue branches all three choices
    agree wherever their determinants do not vanish."""
    A = [[m[i][j] - (_LAM if i == j else K.zero) for j in range(3)] for i in range(3)]
    (a11, a12), (a21, a22) = [(A[i][1], A[i][2]) for i in rows]
    b1, b2 = (A[i][0] for i in rows)
    det = a11 * a22 - a12 * a21
    return (-K.one, (b1 * a22 - a12 * b2) / det, (a11 * b2 - b1 * a21) / det)


def polynomial_abcd(steps: list[SymbolicStep], cp_ring) -> tuple:
    """(a, b, c, d) with p_3(t_n) = ax + b, p_1(t_n) = cx + d, over a common
    denominator (a common factor does not change f; x₊ and x₋ may swap, and both
    are considered), reduced modulo cp (polynomials in Q[λ, r], not in K: K
    normalises constants and would scale a, b, c, d differently)."""
    (d0, c0), (b0, a0) = steps[-1].p[0], steps[-1].p[2]
    den = RING.one
    for e in (a0, b0, c0, d0):
        den = den.lcm(e.denom)
    return tuple((e.numer * den.quo(e.denom)).rem(cp_ring).as_expr() for e in (a0, b0, c0, d0))


@lru_cache(maxsize=None)
def candidate(word: str) -> Candidate:
    """M_w, cp, the branches, q(0) and the position map of a word (a ... b)."""
    if not word or word[0] != "a" or word[-1] != "b" or any(c not in "abc" for c in word):
        raise ValueError(f"the normalisation q(0) = (-1, u, v), p(0) = (1, 0, x) needs a word a...b, not {word!r}")
    Mk = word_matrix_k(word)
    cpk = det3([[(_LAM if i == j else K.zero) - Mk[i][j] for j in range(3)] for i in range(3)])
    if cpk.denom.is_ground is False:
        raise ArithmeticError("cp has a denominator in r")
    cp_ring = cpk.numer.quo_ground(cpk.denom.LC)          # monic in λ
    q0 = eigenvector_k(Mk)
    steps = run_letters(word, q0)
    if steps[-1].p[1] != (K.zero, K.zero):
        raise ArithmeticError("p_2 does not vanish after the last b")
    M = sp.Matrix(3, 3, lambda i, j: sp.factor(Mk[i][j].as_expr()))
    cp = cp_ring.as_expr()
    abcd = polynomial_abcd(steps, cp_ring)
    check_position_map(steps, abcd, cp_ring)
    q0_other = [eigenvector_k(Mk, rows) for rows in ((0, 2), (1, 2))]
    return Candidate(word, M, cp, Spectrum(cp), q0, q0_other, abcd, steps)


def check_position_map(steps, abcd, cp_ring):
    """(ax + b)/(cx + d) = p_3(t_n)/p_1(t_n) identically in x, modulo cp:
    a c₁ = c a₁, a d₁ + b c₁ = c b₁ + d a₁, b d₁ = d b₁ with p_1 = d₁ + c₁x, p_3 = b₁ + a₁x."""
    (d1, c1), (b1, a1) = steps[-1].p[0], steps[-1].p[2]
    a, b, c, d = (to_field(e) for e in abcd)
    for e in (a * c1 - c * a1, a * d1 + b * c1 - c * b1 - d * a1, b * d1 - d * b1):
        if e.numer.rem(cp_ring) != 0:
            raise ArithmeticError("the position map (a, b, c, d) does not reproduce p_3/p_1")


def matrix_of_name(name: str) -> sp.Matrix:
    """The product of collision matrices named left to right, e.g. "BACBA" = B·A·C·B·A."""
    out = sp.eye(3)
    for letter in name:
        out = out * collision_matrix(letter.lower())
    return out


# ---------------------------------------------------------------- conditions reduced modulo cp
@dataclass
class Requirement:
    """A condition g = G0 + x G1 (G0, G1 in Q(r, λ)) and the strict sign it must have."""

    name: str
    G: tuple
    sign: int
    other: tuple = ()          # other representations of the same function on the branches

    @property
    def has_x(self) -> bool:
        return self.G[1] != K.zero


def _ring(e):
    """A polynomial in λ, r as an element of the engine's ring (λ first in lex order)."""
    return to_ring(e)


@lru_cache(maxsize=None)
def _cp_ring(cp):
    return to_ring(cp)


def mod_cp(e, cp):
    """A polynomial in r, λ reduced modulo cp (monic in λ): the same values on
    every branch, λ-degree below 3."""
    return _ring(e).rem(_cp_ring(cp))


@dataclass
class FixedPointData:
    """x = (a - d + σ√Δ)/(2c), Δ = (a - d)² + 4bc, all reduced modulo cp."""

    label: str
    sigma: int
    amd: object                 # polynomials of the engine's ring
    c: object
    delta: object


def fixed_point_data(abcd, cp) -> list[FixedPointData]:
    a, b, c, d = (_ring(e) for e in abcd)
    amd = mod_cp(a - d, cp)
    delta = mod_cp((a - d) ** 2 + 4 * b * c, cp)
    cc = mod_cp(c, cp)
    return [FixedPointData("x₊", 1, amd, cc, delta), FixedPointData("x₋", -1, amd, cc, delta)]


def condition(req: Requirement, cp, fp: FixedPointData | None = None, x_value=None) -> Condition:
    """The engine's Condition for g = G0 + x G1, numerator and denominator reduced
    modulo cp, x the fixed point ``fp`` (x = (A + σ√Δ)/(2c), A = a - d) or the
    rational function ``x_value``."""
    C = _cp_ring(cp)
    G0, G1 = req.G
    n0, d0, n1, d1 = G0.numer, G0.denom, G1.numer, G1.denom
    zero = RING.zero
    if not req.has_x:
        N0, N1, D0, delta, c = n0, zero, d0, None, None
    elif x_value is not None:                               # x = X0/X1
        X = to_field(x_value)
        N0, N1, D0, delta, c = n0 * d1 * X.denom + n1 * d0 * X.numer, zero, d0 * d1 * X.denom, None, None
    else:                                                   # g = (n0 d1 + x n1 d0)/(d0 d1)
        A, c, delta = fp.amd, fp.c, fp.delta
        N0, N1, D0 = 2 * c * n0 * d1 + A * n1 * d0, fp.sigma * n1 * d0, 2 * c * d0 * d1
    return Condition(req.name, (N0.rem(C), N1.rem(C)), (D0.rem(C), zero), delta, c)


# ---------------------------------------------------------------- exact zero tests, fast sign tables
def vanishes_on_branch(spec: Spectrum, g: sp.Expr, rc: Algebraic, branch: int) -> bool:
    """Exact: the polynomial g(r, λ) vanishes at r = rc on the real branch ``branch``
    (the engine's gcd test in Q(rc)[λ]); False when it cannot be proven."""
    try:
        return spec.vanishes_at(g.as_expr() if hasattr(g, "as_expr") else g, rc, branch)
    except ArithmeticError:
        return False


def critical_values(spec: Spectrum, cond: Condition, lo, hi) -> list[Algebraic]:
    """The engine's critical values (zeros of Disc_λ(cp), of the leading coefficient
    and of the resultants of the norms of the condition with cp) in ]lo, hi[, found
    factor by factor: each resultant is factored over Q (python-flint) and every
    irreducible factor's roots isolated by Sturm sequences (its real roots counted a
    second time by python-flint's root isolation; disagreement raises).  Same set as
    ``Spectrum.critical_values``, much faster for resultants of high degree."""
    polys = [spec.disc] + ([spec.lc] if spec.lc.degree() > 0 else [])
    for e in cond.norms():
        R = spec.resultant(e)
        if R.is_zero():
            raise ArithmeticError(f"{cond.name}: a factor vanishes on a whole branch")
        polys.append(R)
    factors = {}
    for p in polys:
        for f, _m in primitive(p).factor()[1]:
            if f.degree() > 0:
                f = primitive(f)
                factors[str(f)] = f
    a = lo.lo if isinstance(lo, Algebraic) else Q(lo)
    b = hi.hi if isinstance(hi, Algebraic) else Q(hi)
    roots = []
    for f in factors.values():
        if count_roots(f) != len(flint_real_roots(f)):       # all real roots, both routes
            raise ArithmeticError(f"Sturm and python-flint disagree on the roots of {show(f)}")
        roots += Algebraic.roots(f, a, b)
    return sorted(z for z in roots if _alg(lo) < z < _alg(hi))


def _alg(a) -> Algebraic:
    return a if isinstance(a, Algebraic) else Algebraic.rational(a)


_EIGENVALUES: dict = {}


def _eigenvalues(spec: Spectrum, t) -> list[Algebraic]:
    """spec.real_eigenvalues(t), memoised (the same samples recur across tables)."""
    key = (id(spec), str(t))
    if key not in _EIGENVALUES:
        _EIGENVALUES[key] = (spec, spec.real_eigenvalues(t))
    return _EIGENVALUES[key][1]


def sign_table(spec: Spectrum, cond: Condition, lo, hi) -> SignTable:
    """``Spectrum.sign_table`` with the factor-by-factor critical values: one exact
    sample per cell, the branches isolated there, signs proven by balls; the signs
    at the critical values by ``Spectrum.sign_at_point``."""
    crit = critical_values(spec, cond, lo, hi)
    ends = [_alg(lo)] + crit + [_alg(hi)]
    cells = []
    for a, b in zip(ends, ends[1:]):
        t = simple_rational_between(a, b)
        lams = _eigenvalues(spec, t)
        cells.append(Cell(a, b, t, lams, [evaluate_sign(cond, t, L) for L in lams]))
    points = [spec.sign_at_point(cond, rc) for rc in crit]
    return SignTable(cond.name, (_alg(lo), _alg(hi)), crit, cells, points)


# ---------------------------------------------------------------- regions of r, branch by branch
@dataclass
class Piece:
    """An open interval ]lo, hi[ of r, or the single point lo (hi None).  At a point
    where f degenerates, ``x_value`` is the fixed point used there instead of x±."""

    lo: Algebraic
    hi: Algebraic | None = None
    x_value: sp.Expr | None = None
    note: str = ""

    @property
    def is_point(self) -> bool:
        return self.hi is None

    def __str__(self) -> str:
        if self.is_point:
            return "{" + _fmt(self.lo) + "}" + (f" ({self.note})" if self.note else "")
        return f"]{_fmt(self.lo)}, {_fmt(self.hi)}["


@dataclass
class Region:
    """The set of r where every requirement imposed so far holds, for one real
    branch and one fixed point; ``undecided`` lists the points no test settled."""

    branch: int
    fixed_point: str
    pieces: list
    undecided: list
    dropped: list                  # (point, reason) settled exactly as failing

    def describe(self) -> str:
        """The pieces, with ]a, b[ ∪ {b} ∪ ]b, c[ shown as ]a, c[."""
        intervals = sorted((p for p in self.pieces if not p.is_point), key=lambda p: p.lo)
        points = [p for p in self.pieces if p.is_point]
        merged = []
        for p in intervals:
            if merged and merged[-1][1] == p.lo:
                joint = [q for q in points if q.lo == p.lo and not q.note]
                if joint:
                    points.remove(joint[0])
                    merged[-1][1] = p.hi
                    continue
            merged.append([p.lo, p.hi])
        parts = [str(Piece(a, b)) for a, b in merged] + [str(q) for q in points]
        return " ∪ ".join(parts) or "∅"


def _fmt(a: Algebraic) -> str:
    return str(a.lo) if a.is_rational else "≈" + a.digits(6)


def _meets(sg, want) -> bool | None:
    if sg == "?":
        return None
    if sg in (None, "missing"):
        return False
    return sg == want


def sign_in_cell(T, branch: int, lo, hi):
    """The sign of table T on ``branch`` over ]lo, hi[, inside one cell of T."""
    signs = T.signs(branch, lo, hi, include_points=False)
    if len(signs) != 1:
        raise ArithmeticError(f"{T.condition}: signs {signs} on ]{lo}, {hi}[")
    return next(iter(signs))


def sign_at(T, rc: Algebraic, branch: int):
    """The sign of table T at rc on ``branch``: its point value when rc is one of
    T's critical values, else the sign of the cell holding rc."""
    for c, pt in zip(T.critical, T.points):
        if c == rc:
            if pt is None:
                return "?"
            return pt[branch] if branch < len(pt) else "missing"
    for cell in T.cells:
        if cell.lo < rc < cell.hi:
            return cell.signs[branch] if branch < len(cell.signs) else "missing"
    raise ArithmeticError(f"{rc} outside the table of {T.condition}")


def _hull(regions, lo0, hi0):
    """An interval ]L, H[ (rational or algebraic ends) containing every piece: an
    open end of a piece is used as it is, a point at an end is enclosed by a
    simple rational just outside it."""
    pieces = [p for R in regions for p in R.pieces]
    if not pieces:
        return None
    L = min(p.lo for p in pieces)
    H = max(p.lo if p.is_point else p.hi for p in pieces)
    eps = Q(1, 10 ** 4)
    if any(p.is_point and p.lo == L for p in pieces):
        L.refine(eps)
        top = L.lo if not L.is_rational else L.lo - eps / 2
        L = Algebraic.rational(simplest_between(max(Q(lo0), L.lo - eps), top))
    if any(p.is_point and p.lo == H for p in pieces):
        H.refine(eps)
        bottom = H.hi if not H.is_rational else H.hi + eps / 2
        H = Algebraic.rational(simplest_between(bottom, min(Q(hi0), H.hi + eps)))
    return (L.lo if L.is_rational else L), (H.lo if H.is_rational else H)


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
    # lo and hi share the integer part: recurse on the reciprocals of the fractional parts
    return Q(fl) + 1 / simplest_between(1 / (hi - fl), 1 / (lo - fl))


class Analysis:
    """Impose requirements one at a time on the candidate of a word and keep, per
    real branch and fixed point, the region of r where all hold (certified)."""

    def __init__(self, cand: Candidate, lo=0, hi=1):
        self.cand, self.spec, self.lo, self.hi = cand, cand.spectrum, lo, hi
        self.fps = cand.fixed_points()
        self.tables = {}
        base = sign_table(self.spec, Condition.of("λ", lam), lo, hi)
        nb = max(len(c.branches) for c in base.cells)
        self.regions = [Region(k, f, [], [], []) for k in range(nb) for f in self.fps]
        for R in self.regions:
            ends = [Algebraic.rational(lo)] + base.critical + [Algebraic.rational(hi)]
            for a, b in zip(ends, ends[1:]):
                if R.branch < len(next(c for c in base.cells if c.lo == a).branches):
                    R.pieces.append(Piece(a, b))
            for c, pt in zip(base.critical, base.points):
                if pt is None:
                    R.undecided.append((c, "branches not isolated"))
                elif R.branch < len(pt):
                    R.pieces.append(Piece(c))
            R.pieces.sort(key=lambda p: p.lo)

    def table(self, req: Requirement, fname: str):
        """The sign table of a requirement over the hull of the current regions."""
        regions = [R for R in self.regions if R.fixed_point == fname or not req.has_x]
        hull = _hull(regions, self.lo, self.hi)
        if hull is None:
            return None
        key = (req.name, fname if req.has_x else "", repr(hull))
        if key not in self.tables:
            self.tables[key] = sign_table(self.spec, condition(req, self.spec.cp,
                                                               self.fps[fname] if req.has_x else None), *hull)
        return self.tables[key]

    def impose(self, req: Requirement):
        """Keep only the r where req has its required sign."""
        tables = {f: self.table(req, f) for f in self.fps}       # over the hull before cutting
        for R in self.regions:
            if not R.pieces:
                continue
            T = tables[R.fixed_point]
            new = []
            for p, status, why in self._split(R, p_list=R.pieces, req=req, T=T):
                if status == "holds":
                    new.append(p)
                elif status == "undecided":
                    R.undecided.append((p.lo, why))
                elif p.is_point and why:
                    R.dropped.append((p.lo, why))
            R.pieces = sorted(new, key=lambda q: q.lo)

    def violations(self, req: Requirement) -> list[tuple[Region, Piece, str]]:
        """Where, in the current regions, req does not have its sign (or is undecided)."""
        bad = []
        tables = {f: self.table(req, f) for f in self.fps}
        for R in self.regions:
            if not R.pieces:
                continue
            T = tables[R.fixed_point]
            for p, status, why in self._split(R, R.pieces, req, T):
                if status != "holds":
                    bad.append((R, p, status + (f": {why}" if why else "")))
        return bad

    def _split(self, R: Region, p_list, req: Requirement, T):
        """Each piece cut at the critical values of T, with the status of req on each
        part: "holds", "fails" or "undecided" (and a reason at points)."""
        for p in p_list:
            if p.is_point:
                yield self._point(R, p, req, T)
                continue
            cuts = [c for c in T.critical if p.lo < c < p.hi]
            ends = [p.lo] + cuts + [p.hi]
            for a, b in zip(ends, ends[1:]):
                ok = _meets(sign_in_cell(T, R.branch, a, b), req.sign)
                yield Piece(a, b), "holds" if ok else "fails", ""
            for c in cuts:
                yield self._point(R, Piece(c), req, T)

    # -- a single point: balls first, exact zero tests where balls cannot decide
    def _point(self, R: Region, p: Piece, req: Requirement, T):
        rc, k = p.lo, R.branch
        sg = self._sign_with_x(req, rc, k, p.x_value) if (p.x_value is not None and req.has_x) else sign_at(T, rc, k)
        ok = _meets(sg, req.sign)
        if ok is not None:
            return p, "holds" if ok else "fails", "" if ok else \
                f"{req.name} {'= 0' if sg == 0 else 'is not real' if sg is None else 'has the wrong sign'}"
        a, b, c, d = self.cand.abcd
        if req.has_x and p.x_value is None and vanishes_on_branch(self.spec, c, rc, k):
            xv = sp.cancel(b / (d - a))
            if _meets(self._sign_with_x(Requirement("x", (K.zero, K.one), 1), rc, k, xv), 1):
                return self._point(R, Piece(rc, None, xv, "c = 0: f affine, fixed point b/(d-a)"), req, T)
            return p, "fails", "c = 0 there (exact): f is affine, its fixed point b/(d-a) is not positive"
        if not req.has_x or p.x_value is not None:
            # g = N/D without √Δ: N = 0 (g = 0) or D = 0 (g undefined: a collision time or
            # the normalisation q_1(0) = -1 breaks down) both defeat a strict inequality;
            # N = D = 0 stays undecided.
            cond = condition(req, self.spec.cp, x_value=p.x_value) if req.has_x else condition(req, self.spec.cp)
            zero_n = vanishes_on_branch(self.spec, cond.N[0], rc, k)
            zero_d = vanishes_on_branch(self.spec, cond.D[0], rc, k)
            if zero_n != zero_d:
                return p, "fails", f"{req.name} {'vanishes' if zero_n else 'has a pole'} there (exact)"
            # 0/0: another representation of the same function, with a denominator not vanishing there
            for G in req.other:
                alt = Requirement(req.name, G, req.sign)
                cond = condition(alt, self.spec.cp, x_value=p.x_value) if alt.has_x else condition(alt, self.spec.cp)
                if vanishes_on_branch(self.spec, cond.D[0], rc, k):
                    continue
                if vanishes_on_branch(self.spec, cond.N[0], rc, k):
                    return p, "fails", f"{req.name} vanishes there (exact, other rows of the eigen-equation)"
                sg = self.spec.sign_at_point(cond, rc)
                ok = None if sg is None else _meets(sg[k] if k < len(sg) else "missing", req.sign)
                if ok is not None:
                    return p, "holds" if ok else "fails", "" if ok else \
                        f"{req.name} has the wrong sign (other rows of the eigen-equation)"
        return p, "undecided", req.name

    def _sign_with_x(self, req, rc, k, xv):
        sg = self.spec.sign_at_point(condition(req, self.spec.cp, x_value=xv), rc)
        return "?" if sg is None else (sg[k] if k < len(sg) else "missing")
# ---------------------------------------------------------------- the candidate in balls
def arb_of(e):
    """A rational function of r, λ (SymPy) as a function of balls (R, L), exact
    rational coefficients."""
    num, den = sp.fraction(sp.together(sp.sympify(e)))
    terms = [[(i, j, Q(int(sp.numer(c)), int(sp.denom(c)))) for (i, j), c in sp.Poly(p, r, lam).terms()]
             for p in (num, den)]

    def value(R, L):
        n, d = (sum((flint.arb(c) * R ** i * L ** j for i, j, c in ts), flint.arb(0)) for ts in terms)
        return n / d
    return value


def candidate_balls(cand: Candidate, r0, branch: int, sigma: int, prec: int):
    """(p(0), q(0), r) of the candidate at a rational r0 on a real branch, x = x₊
    (sigma = 1) or x₋ (sigma = -1), as balls at ``prec`` bits."""
    lams = cand.spectrum.real_eigenvalues(r0)
    with sim.precision(prec + 30):
        R, L = flint.arb(Q(r0)), lams[branch].arb(prec + 30)
        u, v = (arb_of(expr_of(e))(R, L) for e in cand.q0[1:])
        a, b, c, d = (arb_of(e)(R, L) for e in cand.abcd)
        disc = (a - d) ** 2 + 4 * b * c
        if not disc > 0:
            raise sim.Undecided("Δ not proven positive")
        x_ = (a - d + sigma * disc.sqrt()) / (2 * c)
        return (flint.arb(1), flint.arb(0), x_), (flint.arb(-1), u, v), R


# ---------------------------------------------------------------- the requirements of a prefix
def prefix_requirements(word: str, m: int, q0, steps=None, q0_other=()) -> tuple[list[Requirement], list[SymbolicStep]]:
    """The candidate of ``word`` realises its first m collisions, strictly, iff

    * u = q_2(0) > 0 (p_2(0) = 0 right after the last b of the previous period), x > 0;
    * at each collision k the pair i_k approaches: q_{i_k}(t_{k-1}) < 0;
    * the gap i_k is open just before: p_{i_k}(t_{k-1}) > 0, so that τ_k > 0, except
      when it is automatic: k = 1 (p_1(0) = 1), or the pair collided at k - 2
      (p_{i_k}(t_{k-1}) = τ_{k-1} q_{i_k}(t_{k-2}) with q_{i_k}(t_{k-2}) > 0 after that
      collision);
    * every gap that does not collide at m is open at t_m (same exception for the gap
      that collided at m - 1).

    Why this is enough: each collision of type b adds (1+r)/2 q_2 < 0 to q_1 and q_3,
    a collision a or c adds (1+r)/2 q_1 < 0 or (1+r)/2 q_3 < 0 to q_2, so every gap
    p_j(t) is concave between two consecutive collisions of its own pair (the slopes
    only decrease; all τ_k > 0 by the above).  A concave function positive at both
    ends of an interval (or zero at the left end with a positive slope there) is
    positive inside, so the gap is open at every intermediate collision and no other
    pair collides in between (the paper's argument of l. 478-480, for every gap)."""
    steps = steps[:m] if steps is not None and len(steps) >= m else run_letters(word[:m], q0)
    reqs = [Requirement("u = q_2(0)", (q0[1], K.zero), 1, tuple((q[1], K.zero) for q in q0_other)),
            Requirement("x", (K.zero, K.one), 1)]
    letters = [INDEX[word[-1]]] + [INDEX[c] for c in word[:m]]        # letters[k] = i_k, i_0 = last b
    for k in range(1, m + 1):
        i = letters[k]
        before = q0 if k == 1 else steps[k - 2].q
        if not _positive_constant(-before[i]):
            reqs.append(Requirement(f"q_{i + 1}(t_{k - 1})", (before[i], K.zero), -1))
        automatic = k == 1 or letters[k - 2] == i
        if not automatic:
            reqs.append(Requirement(f"p_{i + 1}(t_{k - 1})", steps[k - 2].p[i], 1))
    for j in range(3):
        if j != letters[m] and j != letters[m - 1]:
            reqs.append(Requirement(f"p_{j + 1}(t_{m})", steps[m - 1].p[j], 1))
    return reqs, steps


def _positive_constant(e) -> bool:
    v = e.as_expr()
    return v.is_number and v > 0


# ---------------------------------------------------------------- T27
PRINTED_T27 = dict(word="abcab", matrix="BACBA", after="b", next="a", other="c")


@certificate("T27", "l. 513-515",
             "abcab (matrix BACBA) has no self-similar datum: for the candidate (eigenvector of BACBA, a fixed "
             "point of f), the collision after the first b is a, not c, at a strictly earlier time.",
             printed=PRINTED_T27)
def abcab_has_no_self_similar_datum(word, matrix, after, next, other):
    """On every real branch, for every r in ]0,1[ and both fixed points x±: wherever
    the candidate realises its first collisions up to the first b, the next
    collision is a (q_1 < 0 after b) and it comes strictly before c (p_3 > 0 at
    that a)."""
    cand = candidate(word)
    same = (matrix_of_name(matrix) - cand.M).applyfunc(sp.cancel) == sp.zeros(3, 3)
    checks = [Check(f"the matrix of the word {word} (collisions in time order) is {matrix}", same,
                    [f"M_w = `{show(cand.M.tolist())}`", f"cp(M_w) = `{show(sp.collect(cand.cp, lam))}`"])]
    m = word.index(after) + 1
    feas, steps = prefix_requirements(word, m, cand.q0, cand.steps, cand.q0_other)
    i, o = INDEX[next], INDEX[other]
    tail = run_letters(word[:m] + next, cand.q0)[-1]
    claim = [Requirement(f"q_{i + 1}(t_{m})", (steps[-1].q[i], K.zero), -1),
             Requirement(f"p_{o + 1}(t_{m + 1})", tail.p[o], 1)]
    an = Analysis(cand)
    for req in feas:
        an.impose(req)
    bad = [v for req in claim for v in an.violations(req)]
    undecided = [(R, u) for R in an.regions for u in R.undecided]
    feasible = [R for R in an.regions if R.pieces]
    a, b, c, d = cand.abcd
    ev = [f"q(0) = (-1, u, v), u = `{show(sp.factor(expr_of(cand.q0[1])))}`, "
          f"v = `{show(sp.factor(expr_of(cand.q0[2])))}`; p(0) = (1, 0, x)",
          f"f(x) = (ax + b)/(cx + d), a = `{show(sp.factor(a))}`, b = `{show(sp.factor(b))}`, "
          f"c = `{show(sp.factor(c))}`, d = `{show(sp.factor(d))}`; x± = (a - d ± √((a-d)² + 4bc))/(2c)",
          f"the candidate realises {', '.join(word[:m])} iff " + ", ".join(f"{q.name} {'>' if q.sign > 0 else '<'} 0"
                                                                        for q in feas),
          f"claim: {claim[0].name} < 0 ({next} approaches) and {claim[1].name} > 0 (at the time of that {next}, "
          f"the gap {other} is still open: τ_{next} < τ_{other})"]
    for R in an.regions:
        ev.append(f"{BRANCH_NAMES[R.branch]} branch, {R.fixed_point}: candidate realised on {R.describe()}"
                  + (f"; excluded exactly at {', '.join(f'{_fmt(rc)} ({why})' for rc, why in R.dropped)}"
                     if R.dropped else ""))
    for key, T in an.tables.items():
        if key[0] in ("x", claim[0].name, claim[1].name):
            ev.append(f"sign of {key[0]} {key[1]} over ]{_fmt(Algebraic.rational(T.interval[0]) if not isinstance(T.interval[0], Algebraic) else T.interval[0])}, "
                      f"{_fmt(T.interval[1] if isinstance(T.interval[1], Algebraic) else Algebraic.rational(T.interval[1]))}[:\n\n{T.markdown()}")
    q_other = Requirement(f"q_{o + 1}(t_{m})", (steps[-1].q[o], K.zero), -1)
    ev.append(f"{q_other.name} < 0 ({other} approaching after {after}) on the same region: "
              + ("yes" if not an.violations(q_other) else "no (where it is ≥ 0, c does not come next at all)"))
    dynamic = []
    for R in an.regions:
        for p in R.pieces:
            if p.is_point:
                continue
            p.lo.refine(Q(1, 10 ** 6)), p.hi.refine(Q(1, 10 ** 6))
            w = (p.hi.lo - p.lo.hi) / 8
            r0 = simplest_between(p.lo.hi + w, p.hi.lo - w)
            sigma = 1 if R.fixed_point == "x₊" else -1
            run, prec = sim.run_certified(lambda pr: candidate_balls(cand, r0, R.branch, sigma, pr), m + 1)
            dynamic.append((R, r0, run.word))
    want = word[:m] + next
    ev.append("the particle dynamics itself (certify.simulate, every collision proven in balls) from the candidate "
              "at one rational r per piece: " + "; ".join(f"{BRANCH_NAMES[R.branch]} {R.fixed_point} r = {r0}: "
                                                          f"{w}" for R, r0, w in dynamic))
    checks += [
        Check(f"cross-check on the dynamics: from the candidate, the first {m + 1} collisions are {want}",
              all(w == want for _, _, w in dynamic) and bool(dynamic)),
        Check("every cell and critical value of ]0,1[ decided on every branch, for x₊ and x₋", not undecided,
              [f"undecided: {BRANCH_NAMES[R.branch]} {R.fixed_point} at {_fmt(rc)} ({why})" for R, (rc, why) in undecided]),
        Check(f"wherever the candidate realises {', '.join(word[:m])}, the next collision is {next}, "
              f"strictly before {other}", not bad and not undecided,
              [f"fails on {BRANCH_NAMES[R.branch]} {R.fixed_point} {p}: {why}" for R, p, why in bad]),
        Check("and the candidate does realise them somewhere (the remark is not vacuous)", bool(feasible)),
    ]
    where = "; ".join(f"{BRANCH_NAMES[R.branch]} branch with {R.fixed_point} on {R.describe()}" for R in feasible)
    return conclude(checks, evidence=ev,
                    note=f"The printed reason is checked wherever it applies: the candidate realises "
                         f"{', '.join(word[:m])} exactly on: {where or 'nowhere'}; elsewhere (other branches, "
                         f"other fixed point, other r) it fails earlier, so there is no self-similar datum either.")
