"""The island theorem: around the symmetric orbit [ac]b the b-to-b map is an elliptic
rotation, and the orbits in the island U_r are quasi-periodic.  Every step is proved
here by exact computation, at a rational r (:func:`theorem`) or for r a symbol on
]3−2√2, 1[ (:func:`symbolic_theorem`), from the collision law and the reduction's own
sign rules; the objects it proves things about (the chart, A(r), Q, c_max) are those
of :mod:`certify.dynamics.island`, passed in as :class:`Claims` so that a test can
perturb any of them and see the theorem refuse.

The steps (each a :class:`Step`: a name, whether it holds, evidence):

(a) K_a K_c = K_c K_a (a and c act on the disjoint pairs 1-2 and 3-4).
(b) The branch region.  The reduction's rules (the orientation of :func:`reduction.canonical`,
    the face and next-letter rules of ``reduction._next_letter_exact``) are run on the
    normal n = (u−1, v, u+1) of the chart with entries that are linear forms in (u, v):
    every sign the rules ask for is branched on (+, −, 0).  The leaves partition the
    plane; the states whose next segment is ac or ca and then b are exactly the leaves
    that contain the walls |u| < 1, |u − (1+r)v/2| < 1 (and v > 0: cab, v < 0: acb), and
    every other leaf contradicts one of them.  On the tie v = 0 the rules stop (cos φ = 0):
    it is the double collision [ac], well defined because a and c commute (a).
(c) On R the b-to-b map is n ↦ cof(K_b) cof(K_a) cof(K_c) n (= cof(K_b) cof(K_c) cof(K_a) n
    by (a)); n_z − n_x is multiplied by a positive constant, so in the chart it is linear:
    A(r), det A = 1, tr A = −(1−r)²/(2r); elliptic iff r² − 6r + 1 < 0.
(d) Q∘A = Q, Q positive definite (and Q spans the invariant quadratic forms of A).
(e) 4γ·Q = (2γv + βu)² + (4αγ − β²)u² for Q = αu² + βuv + γv², so u² ≤ Q/c_max with
    c_max = (4αγ − β²)/(4γ): the island {Q < c_max} lies in |u| < 1, and, Q being
    A-invariant, in |first coordinate of A| < 1, the second wall; c_max is the largest
    such level (Q = c_max touches u = 1).
(f) At r = p/q the eigenvalue e^{iθ} is a root of 2pqν² + (q−p)²ν + 2pq, whose primitive
    form is not monic: e^{iθ} is not a root of unity (a root of unity is an algebraic
    integer), θ/2π is irrational, and every orbit in U_r is dense on its ellipse
    Q = const (Kronecker: A is a rotation by θ in coordinates where Q is Euclidean).

>>> from flint import fmpq
>>> T = theorem(fmpq(3, 10))
>>> T.holds, T.elliptic, T.c_max, T.quasi_periodic
(True, True, 71/120, True)
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from fractions import Fraction
from functools import cache
from pathlib import Path

import flint
import sympy as sp
from sympy.polys.matrices import DomainMatrix

from certify import caches
from certify.algebra import Algebraic, checked_real_root_count, ends, flint_real_roots, precision, sign_at, sturm_count
from certify.algebra.poly import parse, show, to_fmpq, to_fmpz_poly
from certify.dynamics import island, reduction
from certify.dynamics.model import INDEX, collide, collide_particles
from certify.dynamics.reduction import ORIENTATION, Corner

SCHEMA_PATH = Path(__file__).with_name("island.schema.json")
u, v, nu = sp.symbols("u v nu")
R_SYMBOL = sp.Symbol("r", positive=True)
WORDS = ("acb", "cab")
LOWER_END = Algebraic.surd(3, -2, 2)          # 3 − 2√2: the interval ]3−2√2, 1[ where A is elliptic


def default_walls(r) -> list:
    """The walls of R as :mod:`certify.dynamics.island` states them: forms
    positive on R = {|u| < 1, |u − (1+r)v/2| < 1}.  Only compared with the derived ones."""
    h = (1 + r) / 2
    return [1 - u, 1 + u, 1 - u + h * v, 1 + u - h * v]


@dataclass
class Claims:
    """What the theorem is about: the collision law, A, Q, c_max, the walls of R and the
    words of its two sides.  The defaults are the objects of :mod:`certify.dynamics.island`;
    a test replaces one to see a step refuse."""

    law: object = collide
    A: object = island.matrix_A
    Q: object = island.quadratic_form
    c_max: object = island.c_max
    walls: object = default_walls
    words: tuple = WORDS


@dataclass
class Step:
    """One step: its name, whether it holds, and its evidence, written when first read
    (``text``: the string, or a function of no argument that writes it; the verdict never
    waits for it, and most callers, ``certify identify`` and ``certify all``, never read it)."""

    name: str
    holds: bool
    text: object = ""

    @property
    def evidence(self) -> str:
        if callable(self.text):
            self.text = self.text()
        return str(self.text)

    def __getstate__(self) -> dict:
        """Pickled with its evidence written (a function that writes it is not picklable)."""
        return {"name": self.name, "holds": self.holds, "text": self.evidence}


@dataclass
class Theorem:
    """The island theorem at r (a rational, or the symbol r on ]3−2√2, 1[)."""

    r: object
    steps: list = field(default_factory=list)
    elliptic: bool = False
    c_max: object = None

    @property
    def holds(self) -> bool:
        return all(s.holds for s in self.steps)

    @property
    def quasi_periodic(self) -> bool:
        """Proved: every step holds, A is elliptic and θ/2π is irrational (step f)."""
        return self.holds and self.elliptic and any(s.name.startswith("(f)") for s in self.steps)

    def _repr_markdown_(self) -> str:
        """A notebook shows the theorem at r: its conclusion, then each step with ✓ or ✗."""
        head = (f"**The island at r = {self.r}**: "
                + ("every step proved; A elliptic, c_max = " + str(self.c_max)
                   + ("; every orbit in U_r is dense on its ellipse" if self.quasi_periodic else "")
                   if self.holds and self.elliptic else
                   "A is not elliptic: no island" if self.holds else "a step does not hold"))
        return "\n".join([head, ""] + [f"- {'✓' if s.holds else '✗'} {s.name}" for s in self.steps])


# --- signs of polynomials in r, at a rational r or on ]3−2√2, 1[ ----------------

def _fmpq_poly(expr) -> flint.fmpq_poly:
    P = sp.Poly(sp.expand(expr), R_SYMBOL)
    return flint.fmpq_poly([to_fmpq(c) for c in reversed(P.all_coeffs())])


def interval_sign(expr) -> int:
    """The sign of a rational function of r on ]3−2√2, 1[: ±1 when it keeps one sign there
    (no root of its numerator or denominator in the interval, counted by Sturm and
    python-flint's isolation), ValueError otherwise."""
    num, den = sp.fraction(sp.cancel(sp.together(expr)))
    return fraction_sign(_fmpq_poly(num), _fmpq_poly(den), lambda k: (num, den, expr)[k])


def fraction_sign(num: flint.fmpq_poly, den: flint.fmpq_poly, name=None) -> int:
    """The sign of num/den on ]3−2√2, 1[ (:func:`interval_sign`): ±1 when neither has a root
    inside (:func:`roots_inside`), their signs at r = 1/2; ValueError otherwise.  ``name(k)``:
    what the error names (k = 0, 1: num, den; 2: the fraction)."""
    s = 1
    for k, P in enumerate((num, den)):
        if P.degree() > 0 and roots_inside(P) != 0:
            raise ValueError(f"{name(k) if name else P} changes sign on ]3−2√2, 1[")
        s *= (P(flint.fmpq(1, 2)) > 0) - (P(flint.fmpq(1, 2)) < 0)
    if s == 0:
        raise ValueError(f"{name(2) if name else (num, den)} vanishes on ]3−2√2, 1[")
    return s


def roots_inside(P: flint.fmpq_poly) -> int:
    """The number of distinct roots of P in the open interval ]3−2√2, 1[, by two routes:
    Sturm isolation on ]0, 1[ compared exactly with 3−2√2, and python-flint's root
    balls (a ball meeting 3−2√2 is decided by the exact sign of P there); ArithmeticError
    when they disagree."""
    sturm = sum(1 for x in Algebraic.roots(P, 0, 1) if x > LOWER_END)
    zero_at_end = sign_at(P, LOWER_END) == 0
    end = LOWER_END.arb(128)
    flint_count = 0
    for b in flint_real_roots(P):
        if b.overlaps(end) and zero_at_end or b.overlaps(flint.arb(1)) and P(1) == 0:
            continue                        # the root is an end (decided exactly above)
        if b.overlaps(end) or b.overlaps(flint.arb(1)):
            raise ArithmeticError(f"a root ball of {P} meets an end of the interval")
        flint_count += bool(b > end and b < 1)
    if sturm != flint_count:
        raise ArithmeticError(f"Sturm ({sturm}) and python-flint ({flint_count}) disagree on the roots of {P}")
    return sturm


def sign_of(expr, symbolic: bool) -> int:
    """The sign of a constant of Q(r): exact at a rational r, certified on the interval
    for the symbol r."""
    expr = sp.cancel(sp.together(expr))
    if expr == 0:
        return 0
    if symbolic and expr.has(R_SYMBOL):
        return interval_sign(expr)
    return 1 if expr > 0 else -1


# --- exact arithmetic over Q (r rational) or Q(r) (r the symbol) -------------------
#
# The steps decide in the field of the coefficients: Q (python-flint's fmpq) at a rational
# r, Q(r) (SymPy's field of fractions in r, its elements kept cancelled) for the symbol r.
# A linear form a·u + b·v + c is the triple (a, b, c); a matrix, the tuple of its rows.
# SymPy expressions are read in once (the law's matrices, the claims) and written out
# only for the evidence.

class Coefficients:
    """The field of the forms' coefficients (Q at a rational r, Q(r) for the symbol r) and
    the sign of its elements: exact at a rational r, certified on ]3−2√2, 1[ for the symbol
    (:func:`fraction_sign`), as :func:`sign_of` decides them."""

    def __init__(self, symbolic: bool):
        self.symbolic = symbolic
        self.K = sp.QQ.frac_field(R_SYMBOL) if symbolic else sp.QQ

    def of(self, expr):
        """A SymPy constant (free of u, v) as an element."""
        return self.K.from_sympy(sp.sympify(expr))

    def to_sympy(self, x):
        return self.K.to_sympy(x)

    def sign(self, x) -> int:
        if x == 0:
            return 0
        if not self.symbolic:
            return 1 if x > 0 else -1
        num, den = _poly_in_r(x.numer), _poly_in_r(x.denom)
        if num.degree() <= 0 and den.degree() <= 0:
            return 1 if num[0] * den[0] > 0 else -1
        return fraction_sign(num, den, lambda k: (x.numer.as_expr(), x.denom.as_expr(), self.to_sympy(x))[k])

    def linear(self, expr) -> tuple:
        """The form (a, b, c) of a SymPy expression a·u + b·v + c; ValueError when it is not linear."""
        P = sp.Poly(sp.expand(expr), u, v, domain=self.K)
        if P.total_degree() > 1:
            raise ValueError(f"{expr} is not a linear form in (u, v)")
        d = P.as_dict(native=True)
        zero = self.K.zero
        return (d.get((1, 0), zero), d.get((0, 1), zero), d.get((0, 0), zero))

    def expr(self, form: tuple):
        """The SymPy expression of a form (as SymPy's Poly.as_expr writes it)."""
        return sp.Add(*[sp.Mul(self.to_sympy(z), x) for z, x in zip(form, (u, v, sp.Integer(1))) if z != 0])


def _poly_in_r(p) -> flint.fmpq_poly:
    """A polynomial of SymPy's ring Q[r] (its coefficients fmpq or integers) as an fmpq_poly."""
    coeffs = [flint.fmpq(0)] * (p.degree() + 1) if p else []
    for (k,), c in p.terms():
        coeffs[k] = flint.fmpq(c)
    return flint.fmpq_poly(coeffs)


def law_matrix(law, letter: str, r, F: Coefficients) -> tuple:
    """The rows of the matrix of the collision ``letter`` of ``law`` over F (:func:`matrix`)."""
    cols = [law(letter, e, r) for e in ((1, 0, 0), (0, 1, 0), (0, 0, 1))]
    return tuple(tuple(F.of(cols[j][i]) for j in range(3)) for i in range(3))


def cof_rows(K: tuple) -> tuple:
    """The rows of cof(K) = det(K) K^{-T} (:func:`cof`): its column m is K e_{m+1} ∧ K e_{m+2}
    (:func:`reduction.cofactor_columns`)."""
    cols = [tuple(row[j] for row in K) for j in range(3)]
    c = [reduction.cross(cols[(m + 1) % 3], cols[(m + 2) % 3]) for m in range(3)]
    return tuple(tuple(c[m][i] for m in range(3)) for i in range(3))


def mat_mul(X: tuple, Y: tuple) -> tuple:
    """The product of two 3×3 matrices given by their rows (also: rows of field elements times
    a vector of three forms, each form a row of its coefficients)."""
    return tuple(tuple(row[0] * Y[0][j] + row[1] * Y[1][j] + row[2] * Y[2][j] for j in range(3)) for row in X)


def sympy_matrix(X: tuple, F: Coefficients) -> sp.Matrix:
    """The matrix with these rows (elements of F) in SymPy, for the evidence."""
    return sp.Matrix([[F.to_sympy(x) for x in row] for row in X])


# --- (a) the commuting collisions --------------------------------------------------

def matrix(law, letter: str, r) -> sp.Matrix:
    """The matrix of the collision ``letter`` of ``law`` (its columns: the images of e_1, e_2, e_3)."""
    cols = [law(letter, e, r) for e in ((1, 0, 0), (0, 1, 0), (0, 0, 1))]
    return sp.Matrix(3, 3, lambda i, j: sp.sympify(cols[j][i]))


def cof(K: sp.Matrix) -> sp.Matrix:
    """cof(K) = det(K) K^{-T}: the map of the normals (reduction's docstring)."""
    return K.adjugate().T


def commuting_step(r, claims: Claims) -> Step:
    """K_a K_c = K_c K_a, and the same for the law on the four velocities (written
    independently, :func:`model.collide_particles`): a and c act on disjoint pairs."""
    F = Coefficients(not r.is_Rational)
    Ka, Kc = law_matrix(claims.law, "a", r, F), law_matrix(claims.law, "c", r, F)
    D = tuple(tuple(x - y for x, y in zip(p, q)) for p, q in zip(mat_mul(Ka, Kc), mat_mul(Kc, Ka)))
    w = sp.symbols("w1:5")
    ac = collide_particles("c", collide_particles("a", w, r), r)
    ca = collide_particles("a", collide_particles("c", w, r), r)
    particles = all(sp.expand(x - y) == 0 for x, y in zip(ac, ca))
    ok = all(x == 0 for row in D for x in row) and particles
    return Step("(a) K_a K_c = K_c K_a", bool(ok),
                lambda: f"K_a K_c − K_c K_a = {sympy_matrix(D, F).applyfunc(sp.simplify).tolist()} (exact); on the "
                f"four velocities the law gives a∘c = c∘a: {particles} (a acts on the pair 1-2, c on 3-4); the double "
                "collision [ac] acts by K_a K_c, and cof(K_a K_c) = cof(K_a) cof(K_c)"
                + ("" if ok else ": the collisions do not commute, the tie v = 0 has no single map"))


# --- (b) the branch region, from the reduction's sign rules ---------------------

class NeedSign(Exception):
    """The rules asked for the sign of a linear form not yet branched on."""

    def __init__(self, key):
        self.key = key


class Key(tuple):
    """A monic form (a, b, c), the key of a sign in an assignment: a tuple whose hash, taken
    once, is that of its coefficients' numerators and denominators when they are rationals
    (python-flint hashes an fmpq through a Fraction, slowly; the branching looks keys up
    thousands of times), else the tuple's.  Equal keys have equal hashes (an fmpq is
    reduced), so keys compare and look up as the tuples do among keys."""

    _hash: int

    def __new__(cls, items):
        self = super().__new__(cls, items)
        try:
            self._hash = hash(tuple((z.p, z.q) for z in self))
        except AttributeError:                  # Q(r) for the symbol r: SymPy's field elements
            self._hash = tuple.__hash__(self)
        return self

    def __hash__(self) -> int:
        return self._hash

    def __eq__(self, other) -> bool:
        return tuple.__eq__(self, other)

    def __ne__(self, other) -> bool:
        return tuple.__ne__(self, other)


def _key(form: tuple, F: Coefficients):
    """(sign factor, key) with form = factor · key, key the monic form (its first nonzero
    coefficient among those of u, v, 1 equal to 1, a :class:`Key`); None key for a constant."""
    a, b, c = form
    if a == 0 and b == 0:
        return F.sign(c), None
    lc = a if a != 0 else b
    return F.sign(lc), Key((a / lc, b / lc, c / lc))


def form_key(expr, symbolic: bool):
    """(sign factor, key) with expr = factor · key, key the monic linear form (first
    coefficient in u, v, 1 equal to 1) over Q(r), as a triple (a, b, c) of coefficients
    of u, v, 1; None key for a constant."""
    F = Coefficients(symbolic)
    return _key(F.linear(expr), F)


class Form:
    """A linear form in (u, v) whose comparisons with 0 are answered by the branch
    assignment (so that the reduction's own rules can run on it)."""

    def __init__(self, form: tuple, oracle):
        self.form, self.oracle, self._sign = form, oracle, None

    def sign(self) -> int:
        if self._sign is None:
            self._sign = self.oracle.sign(self.form)
        return self._sign

    def __gt__(self, other):
        return self.sign() > 0

    def __lt__(self, other):
        return self.sign() < 0


class Oracle:
    def __init__(self, assignment: dict, F: Coefficients):
        self.assignment, self.F = assignment, F

    def sign(self, form: tuple) -> int:
        factor, key = _key(form, self.F)
        if key is None:
            return factor
        if key not in self.assignment:
            raise NeedSign(key)
        return factor * self.assignment[key]


def walk(n: tuple, cofs: dict, oracle: Oracle) -> str:
    """From the state n at b, the letters up to the return to b (at most 3), by the
    reduction's rules: the orientation e_t · n > 0 of :func:`reduction.canonical` and the
    face / next-letter rule of ``reduction._next_letter_exact``; the landing at b must lie
    inside its face (the same face rule, its next-letter part set aside).  Corner → "corner".
    n: three forms; cofs: letter → the rows of cof(K), field elements."""
    letter, m, letters = "b", _orient("b", n, oracle), ""
    try:
        for _ in range(3):
            j = reduction._next_letter_exact(letter, INDEX[letter], tuple(Form(z, oracle) for z in m))
            m = _orient(j, mat_mul(cofs[j], m), oracle)
            letter, letters = j, letters + j
            if j == "b":
                K = oracle.F.K
                one = Form((K.zero, K.zero, K.one), oracle)
                reduction._next_letter_exact("b", INDEX["b"], (Form(m[0], oracle), one, Form(m[2], oracle)))
                break
    except Corner:
        return letters + "|corner"
    return letters


def _orient(letter: str, m, oracle: Oracle) -> tuple:
    s = oracle.sign(m[ORIENTATION[letter]])
    if s == 0:
        raise Corner("e_t · n = 0")
    return m if s > 0 else tuple(tuple(-x for x in z) for z in m)


def explore(n: tuple, cofs: dict, symbolic: bool) -> list[tuple[dict, str]]:
    """Every leaf of the sign branching: (assignment key → sign, outcome word).  n: the
    normal at b (SymPy expressions linear in u, v); cofs: letter → cof(K) (SymPy matrices)."""
    F = Coefficients(symbolic)
    rows = {L: tuple(tuple(F.of(K[i, k]) for k in range(3)) for i in range(3)) for L, K in cofs.items()}
    return branches(tuple(F.linear(z) for z in n), rows, F)


def branches(forms: tuple, rows: dict, F: Coefficients) -> list[tuple[dict, str]]:
    """:func:`explore` on the forms of n and the rows of the cofactors over F."""
    leaves, stack = [], [{}]
    while stack:
        a = stack.pop()
        try:
            leaves.append((a, walk(forms, rows, Oracle(a, F))))
        except NeedSign as need:
            stack.extend(b for b in ({**a, need.key: s} for s in (1, -1, 0)) if feasible(b, F))
            continue
        except Corner:
            leaves.append((a, "|corner"))
    return leaves


def feasible(assignment: dict, F: Coefficients) -> bool:
    """Whether some (u, v) gives every form of the assignment its sign: Fourier–Motzkin
    elimination of u, then v, exact (each coefficient's sign proved, on the interval for the
    symbol r); strict inequalities combine into strict ones, equalities are substituted."""
    cons = [(k, True) if s == 0 else (tuple(s * z for z in k), False) for k, s in assignment.items()]
    for var in (0, 1):
        eq = next((i for i, (e, z) in enumerate(cons) if z and e[var] != 0), None)
        if eq is not None:                          # var = −(the rest of e)/a: f − (f_var/a)·e
            e = cons[eq][0]
            a = e[var]
            cons = [(_minus(f, f[var] / a, e), z) for i, (f, z) in enumerate(cons) if i != eq]
            continue
        keep, low, up = [], [], []
        for e, z in cons:
            a = e[var]
            if a == 0:
                keep.append((e, z))
            else:                                   # a·var + rest > 0: var > −rest/a when a > 0
                bound = tuple(-x / a for x in e)    # its var coefficient −1, the same in every bound
                (low if F.sign(a) > 0 else up).append(bound)
        cons = keep + [(tuple(x - y for x, y in zip(U, L)), False) for L in low for U in up]
    for (_, _, c), z in cons:
        if z and c != 0:
            return False
        if not z and F.sign(c) <= 0:
            return False
    return True


def _minus(f: tuple, t, e: tuple) -> tuple:
    """f − t·e."""
    return tuple(x - t * y for x, y in zip(f, e))


def region_step(r, claims: Claims, symbolic: bool) -> Step:
    F = Coefficients(symbolic)
    rows = {L: cof_rows(law_matrix(claims.law, L, r, F)) for L in "abc"}
    leaves = branches(tuple(F.linear(z) for z in island.normal(u, v)), rows, F)
    walls = [form_key(w, symbolic) for w in claims.walls(r)]
    side = form_key(v, symbolic)
    sides = {claims.words[1]: 1, claims.words[0]: -1}          # cab on v > 0, acb on v < 0
    bad = []
    success = [(a, w) for a, w in leaves if w in sides]
    for a, w in success:
        need = [(k, s) for s, k in walls] + [(side[1], side[0] * sides[w])]
        if any(a.get(k) != s for k, s in need):
            bad.append(f"the leaf {w} misses a wall: {_show(a, symbolic)}")
    for a, w in leaves:
        if w in sides:
            continue
        contradicts = any(k in a and a[k] != s for s, k in walls) or a.get(side[1]) == 0
        if not contradicts:
            bad.append(f"the leaf {w or '(none)'} meets the claimed R: {_show(a, symbolic)}")
    found = sorted({w for _, w in success})
    if found != sorted(sides):
        bad.append(f"the words through R are {found}, not {sorted(sides)}")
    keys = {k for a, _ in leaves for k in a}

    def evidence() -> str:
        text = (f"{len(leaves)} leaves of the sign branching on {len(keys)} linear forms in (u, v), from n = "
                "(u−1, v, u+1) at b by the reduction's orientation, face and next-letter rules; the leaves through "
                "ac/ca then b: " + "; ".join(f"{w}: {_show(a, symbolic)}" for a, w in success)
                + f"; walls claimed: {', '.join(str(sp.factor(w)) + ' > 0' for w in claims.walls(r))}; "
                "the tie v = 0 stops the rules (cos φ = 0): the double collision [ac], one map by (a)")
        return text + ("" if not bad else "; REFUSED: " + "; ".join(bad[:3]))
    return Step("(b) the branch region R = {|u| < 1, |u − (1+r)v/2| < 1}, from the reduction's sign rules",
                not bad, evidence)


def _show(a: dict, symbolic: bool) -> str:
    F = Coefficients(symbolic)
    return ", ".join(f"{sp.factor(F.expr(k))} {'>' if s > 0 else '<' if s < 0 else '='} 0" for k, s in a.items())


# --- (c) the linear map -------------------------------------------------------------

def derived_A(r, claims: Claims, F: Coefficients | None = None) -> tuple[tuple | None, object]:
    """A in the chart (its rows over F) from cof(K_b) cof(K_a) cof(K_c) (and the other order),
    or None; with why (a string, or a function of no argument that writes it: :func:`_written`)."""
    F = F or Coefficients(not r.is_Rational)
    K = {L: cof_rows(law_matrix(claims.law, L, r, F)) for L in "abc"}
    M_cab, M_acb = mat_mul(K["b"], mat_mul(K["a"], K["c"])), mat_mul(K["b"], mat_mul(K["c"], K["a"]))
    if M_cab != M_acb:
        return None, "cof(K_b)cof(K_a)cof(K_c) ≠ cof(K_b)cof(K_c)cof(K_a): two maps on the two sides"
    m = mat_mul(M_cab, tuple(F.linear(z) for z in island.normal(u, v)))
    d = tuple(x - y for x, y in zip(m[2], m[0]))
    if d[0] != 0 or d[1] != 0 or d[2] == 0:
        return None, f"n_z − n_x ↦ {sp.cancel(F.expr(d))}: the map is projective, not linear, in the chart"
    U, V = tuple((x + y) / d[2] for x, y in zip(m[0], m[2])), tuple(2 * y / d[2] for y in m[1])
    if U[2] != 0 or V[2] != 0:
        return None, f"the image has a constant part {[F.to_sympy(U[2]), F.to_sympy(V[2])]}: affine, not linear"
    return (U[:2], V[:2]), lambda: (f"n_z − n_x ↦ {sp.factor(F.to_sympy(d[2]))}·(n_z − n_x)/2; "
                                    "M = cof(K_b)cof(K_a)cof(K_c)")


def _written(text) -> str:
    """A text given as a string or as a function of no argument that writes it."""
    return text() if callable(text) else text


def map_step(r, claims: Claims, symbolic: bool) -> tuple[Step, sp.Matrix | None]:
    F = Coefficients(symbolic)
    AF, why = derived_A(r, claims, F)
    claimed = tuple(tuple(F.of(z) for z in row) for row in claims.A(r))
    A = sympy_matrix(AF, F) if AF is not None else None
    ok = AF is not None and AF == claimed
    det = AF[0][0] * AF[1][1] - AF[0][1] * AF[1][0] if AF is not None else None
    ok = ok and det == 1 and AF[0][0] + AF[1][1] + F.of((1 - r) ** 2 / (2 * r)) == 0
    if A is not None and not symbolic:
        ok = ok and _matches_reduction(A, r)

    def text() -> str:
        claimed_A = sp.Matrix([[sp.sympify(z) for z in row] for row in claims.A(r)])
        if A is None:
            return f"{_written(why)}; derived A = None, claimed {claimed_A.tolist()}; det A = None, tr A = None"
        return (f"{_written(why)}; derived A = {A.applyfunc(sp.factor).tolist()}, claimed {claimed_A.tolist()}; "
                f"det A = {F.to_sympy(det)}, tr A = {sp.factor(A.trace())}")
    return Step("(c) on R the b-to-b map is A(r) in the chart, det A = 1, tr A = −(1−r)²/(2r)", bool(ok), text), A


def _matches_reduction(A: sp.Matrix, r) -> bool:
    """Route 2 at a rational r: reduction.step from the state with chart (1/3, 1/5) (in R
    for every r in ]0, 1[) lands on A(1/3, 1/5)."""
    x = (flint.fmpq(1, 3), flint.fmpq(1, 5))
    P = reduction.canonical("b", island.normal(*x))
    rq = to_fmpq(r)
    for _ in range(3):
        P = reduction.step(P, rq)
        if P.letter == "b":
            break
    got = island.chart(P.n)
    want = A * sp.Matrix([sp.Rational(1, 3), sp.Rational(1, 5)])
    return all(to_fmpq(w) == g for w, g in zip(want, got))


def elliptic_step(r, A: sp.Matrix | None, symbolic: bool) -> tuple[Step, bool]:
    """det A = 1, so A is elliptic iff tr² A − 4 < 0; then it turns every state one way, that
    of det[e1, A e1] (no real eigenvector: det[w, Aw] never vanishes for w ≠ 0)."""
    if A is None:
        return Step("(c′) elliptic", False, "no linear map"), False
    s = sign_of(A.trace() ** 2 - 4, symbolic)
    ell = s < 0
    turn = sign_of(A[1, 0], symbolic) if ell else 0
    where = ("on ]3−2√2, 1[ (no root inside: Sturm and python-flint; negative at r = 1/2)" if symbolic
             else f"at r = {r}")

    def text() -> str:
        out = f"tr² A − 4 = {sp.factor(A.trace() ** 2 - 4)} {'<' if s < 0 else '>' if s > 0 else '='} 0 {where}"
        if ell:
            out += (f"; det[e1, A e1] = {sp.factor(A[1, 0])} {'>' if turn > 0 else '<'} 0: A turns every state "
                    f"{'counter' if turn > 0 else ''}clockwise in the (u, v) chart")
        return out
    if symbolic:
        return Step("(c′) A is elliptic on ]3−2√2, 1[ (r² − 6r + 1 < 0)", ell, text), ell
    name = "(c′) A is elliptic (r² − 6r + 1 < 0)" if ell else \
        "(c′) A is not elliptic (r² − 6r + 1 ≥ 0): hyperbolic or parabolic, no invariant ellipse, no island"
    return Step(name, True, text), ell


# --- (d) the invariant form, (e) the island inside R --------------------------------

def _quadratic(F: Coefficients, q) -> sp.Poly:
    """A polynomial in (u, v) (a SymPy expression or Poly) as a Poly over F."""
    return sp.Poly(q, u, v, domain=F.K)


def _coefficient(P: sp.Poly, monomial: tuple, F: Coefficients):
    return P.as_dict(native=True).get(monomial, F.K.zero)


def _ellipse(claims: Claims, r, F: Coefficients) -> tuple:
    """(Q as a Poly over F, α, β, γ: its coefficients of u², uv, v², elements of F)."""
    Q = _quadratic(F, claims.Q(u, v, r))
    return (Q,) + tuple(_coefficient(Q, m, F) for m in ((2, 0), (1, 1), (0, 2)))


def invariant_step(r, claims: Claims, symbolic: bool) -> Step:
    F = Coefficients(symbolic)
    A = tuple(tuple(F.of(z) for z in row) for row in claims.A(r))
    Q, al, be, ga = _ellipse(claims, r, F)
    Au, Av = (_quadratic(F, sp.Poly.from_dict({(1, 0): a, (0, 1): b}, u, v, domain=F.K)) for a, b in A)
    diff = _quadratic(F, claims.Q(Au, Av, r)) - Q
    pos = F.sign(al) > 0 and F.sign(4 * al * ga - be ** 2) > 0
    # x Au² + y Au Av + z Av² − (x u² + y uv + z v²) = 0: a linear system in (x, y, z)
    images = [Au * Au - _quadratic(F, u * u), Au * Av - _quadratic(F, u * v), Av * Av - _quadratic(F, v * v)]
    system = [[_coefficient(g, m, F) for g in images] for m in ((2, 0), (1, 1), (0, 2))]
    dim = 3 - DomainMatrix(system, (3, 3), F.K).rank()
    ok = diff.is_zero and pos and dim == 1
    return Step("(d) Q∘A = Q, Q positive definite, and Q spans the A-invariant quadratic forms", bool(ok),
                lambda: f"Q = {sp.factor(Q.as_expr())}; Q∘A − Q = {sp.cancel(diff.as_expr())}; α = {F.to_sympy(al)} "
                f"> 0, 4αγ − β² = {sp.factor(F.to_sympy(4 * al * ga - be ** 2))} {'> 0' if pos else '≯ 0'}; "
                f"invariant forms: a space of dimension {dim}")


def island_step(r, claims: Claims, symbolic: bool) -> Step:
    F = Coefficients(symbolic)
    Q, al, be, ga = _ellipse(claims, r, F)
    if ga == 0:
        return Step("(e) the island U_r = {Q < c_max} lies in R, c_max the largest such level", False,
                    "γ = 0: Q is not positive definite")
    level = (4 * al * ga - be ** 2) / (4 * ga)
    square = sp.Poly.from_dict({(1, 0): be, (0, 1): 2 * ga}, u, v, domain=F.K)        # 2γv + βu
    identity = Q.mul_ground(4 * ga) - square * square - sp.Poly.from_dict({(2, 0): 4 * al * ga - be ** 2}, u, v,
                                                                            domain=F.K)
    claimed = F.of(claims.c_max(r))
    a, b = (F.of(z) for z in claims.A(r)[0])
    first = (a, b, F.K.zero)
    walls = {form_key(w, symbolic)[1] for w in claims.walls(r)}
    one, zero = F.K.one, F.K.zero
    expect = {_key(w, F)[1] for w in ((-one, zero, one), (one, zero, one), (-a, -b, one), (a, b, one))}
    x = -be / (2 * ga)                           # Q = c_max at (1, x): the wall u = 1 is touched
    touch = sum((c * x ** j for (i, j), c in Q.as_dict(native=True).items()), start=zero) - level
    ok = (identity.is_zero and level == claimed and F.sign(ga) > 0
          and F.sign(level) > 0 and walls == expect and touch == 0)
    return Step("(e) the island U_r = {Q < c_max} lies in R, c_max the largest such level", bool(ok),
                lambda: f"4γQ = (2γv + βu)² + (4αγ − β²)u² (identity: remainder {identity.as_expr()}), so u² ≤ "
                f"Q/c_max with c_max = (4αγ − β²)/(4γ) = {sp.factor(F.to_sympy(level))} (claimed "
                f"{sp.factor(F.to_sympy(claimed))}); γ = {F.to_sympy(ga)} > 0; the second wall is |first coordinate of "
                f"A| = |{sp.expand(F.expr(first))}| < 1, which Q∘A = Q gives; the walls of R are 1 ± u, 1 ± A₁(u, v): "
                f"{walls == expect}; "
                f"Q(1, −β/2γ) − c_max = {F.to_sympy(touch)} (touches u = 1)")


# --- (f) not a root of unity ---------------------------------------------------------

def irrational_step(r, A: sp.Matrix | None) -> Step:
    if A is None:
        return Step("(f) e^{iθ} is not a root of unity", False, "no linear map")
    rq = to_fmpq(r)
    p, q = int(rq.p), int(rq.q)
    cp = sp.Poly(sp.expand(2 * p * q * (nu ** 2 - A.trace() * nu + A.det())), nu)
    coeffs = [int(c) for c in cp.all_coeffs()]
    printed = [2 * p * q, (q - p) ** 2, 2 * p * q]
    f = flint.fmpz_poly(list(reversed(coeffs)))
    content = f.content()
    prim = flint.fmpz_poly([c // content for c in f.coeffs()])
    disc = coeffs[1] ** 2 - 4 * coeffs[0] * coeffs[2]
    ok = coeffs == printed and disc < 0 and abs(prim.coeffs()[-1]) > 1
    return Step("(f) e^{iθ} is not a root of unity: θ/2π irrational, every orbit in U_r dense on its ellipse", bool(ok),
                f"2pq·(ν² − tr A ν + det A) = {_nu(prim * content)} at r = {p}/{q}; content {content}, primitive form "
                f"{_nu(prim)} (irreducible: discriminant {disc} < 0), leading coefficient {prim.coeffs()[-1]} ≠ ±1: "
                "not monic, so e^{iθ} is not an algebraic integer, not a root of unity; A is a rotation by θ in "
                "coordinates where Q is Euclidean (det A = 1, Q∘A = Q), so each orbit is dense on its ellipse "
                "(Kronecker)")


def _nu(f: flint.fmpz_poly) -> str:
    return str(f).replace("x", "ν")


def symbolic_irrational_step() -> Step:
    """(f) for every rational r = p/q in the interval: the identity in p, q, and the content."""
    p, q = sp.symbols("p q", positive=True)
    tr = -(1 - p / q) ** 2 / (2 * p / q)
    lhs = sp.expand(sp.cancel(2 * p * q * (nu ** 2 - tr * nu + 1)))
    ok = sp.expand(lhs - (2 * p * q * nu ** 2 + (q - p) ** 2 * nu + 2 * p * q)) == 0
    return Step("(f) at every rational r = p/q (gcd 1) in the interval, e^{iθ} is not a root of unity", bool(ok),
                f"2pq(ν² − tr A ν + 1) = {sp.factor(lhs)} (identity in p, q); a prime dividing pq and q − p divides "
                "p and q, so the content is gcd(2, (q−p)²) ≤ 2 < 2pq: the primitive form is not monic, e^{iθ} is no "
                "algebraic integer, no root of unity.  At an irrational algebraic r it can be one: the resonances")


# --- the theorem -----------------------------------------------------------------

def theorem(r, claims: Claims | None = None) -> Theorem:
    """The island theorem at a rational r in ]0, 1[, every step proved exactly (module docstring);
    with the default claims once per run and r (:func:`certify.caches.for_a_run`: ``certify
    identify`` asks at every r it classifies, ``certify all`` at the r of N2, N5, N6 and N7.1)."""
    rq = to_fmpq(r)
    if not 0 < rq < 1:
        raise ValueError(f"r = {rq} is not in ]0, 1[")
    return _theorem(rq) if claims is None else prove(rq, claims)


def prove(rq: flint.fmpq, claims: Claims) -> Theorem:
    """The steps of :func:`theorem` at r = rq about ``claims``."""
    rs = sp.Rational(int(rq.p), int(rq.q))
    T = Theorem(rq)
    T.steps.append(commuting_step(rs, claims))
    T.steps.append(region_step(rs, claims, False))
    step, A = map_step(rs, claims, False)
    T.steps.append(step)
    step, T.elliptic = elliptic_step(rs, A, False)
    T.steps.append(step)
    if T.elliptic:
        T.steps.append(invariant_step(rs, claims, False))
        T.steps.append(island_step(rs, claims, False))
        T.steps.append(irrational_step(rs, A))
        c = sp.cancel(sp.sympify(claims.c_max(rs)))
        T.c_max = flint.fmpq(int(sp.numer(c)), int(sp.denom(c)))
    return T


@caches.for_a_run
def _theorem(rq: flint.fmpq) -> Theorem:
    return prove(rq, Claims())


@cache
def symbolic_theorem() -> Theorem:
    """The theorem for r a symbol on ]3−2√2, 1[: the same steps as identities in Q(r), every
    sign of a polynomial in r certified on the interval (Sturm and python-flint)."""
    claims, rs = Claims(), R_SYMBOL
    T = Theorem(rs)
    T.steps.append(commuting_step(rs, claims))
    T.steps.append(region_step(rs, claims, True))
    step, A = map_step(rs, claims, True)
    T.steps.append(step)
    step, T.elliptic = elliptic_step(rs, A, True)
    T.steps.append(step)
    T.steps.append(invariant_step(rs, claims, True))
    T.steps.append(island_step(rs, claims, True))
    T.steps.append(symbolic_irrational_step())
    T.c_max = sp.factor(claims.c_max(rs))
    return T


# --- the rotation number ----------------------------------------------------------

CONVENTION = ("ρ = θ/2π with cos θ = tr A/2 = −(1−r)²/(4r), θ ∈ ]0, π[: A turns every state counterclockwise "
              "in the (u, v) chart (det[w, Aw] > 0) by the angle θ, measured in coordinates where Q is Euclidean")


def rotation_ball(r, prec: int = 128) -> flint.arb:
    """ρ(r) as an arb ball (r rational with r² − 6r + 1 < 0)."""
    rq = r if isinstance(r, flint.arb) else to_fmpq(r)
    with precision(prec):
        c = flint.arb(-(1 - rq) ** 2 / (4 * rq))
        return c.acos() / (2 * flint.arb.pi())


def rotation_number(r, digits: int = 20) -> str:
    """ρ(r) rounded to ``digits`` significant digits, every one certified: the ball is made
    narrow enough that both of its ends round alike (increasing the precision)."""
    prec = 4 * digits + 40
    while True:
        z = rotation_ball(r, prec)
        lo, hi = ends(z)
        a, b = _round(lo, digits), _round(hi, digits)
        if a == b:
            return a
        prec *= 2


def _round(x: flint.fmpq, digits: int) -> str:
    from certify.dynamics.particles import decimal_digits
    return decimal_digits(x, digits)[0]


# --- resonances -----------------------------------------------------------------------

def cos_minimal_polynomial(q: int) -> flint.fmpz_poly:
    """The minimal polynomial of cos(2πp/q), gcd(p, q) = 1 (the same for every such p): the
    factor of T_q(x) − 1 that vanishes at cos(2π/q) (decided by ball evaluation at a point
    of the factor's isolated roots, and by degree φ(q)/2)."""
    T = sp.chebyshevt_poly(q, sp.Symbol("x"), polys=True) - 1
    f = flint.fmpz_poly([int(c) for c in reversed(T.all_coeffs())])
    with precision(200):
        c = (2 * flint.arb.pi() / q).cos()
    want = max(1, sp.totient(q) // 2) if q > 2 else 1
    for g, _m in f.factor()[1]:
        if g.degree() == want and flint.arb_poly([flint.arb(x) for x in g.coeffs()])(c).contains(0):
            return g
    raise ArithmeticError(f"no factor of T_{q} − 1 vanishes at cos(2π/{q})")


def resonance_polynomial(q: int) -> flint.fmpz_poly:
    """The polynomial in r whose roots in ]0, 1[ are the r with cos θ(r) = cos(2πp/q) for some
    p prime to q, computed by two routes: the substitution c = −(1−r)²/(4r) cleared of
    denominators, and SymPy's resultant in c of Ψ_q(c) and r² − (2 − 4c) r + 1; ArithmeticError
    when they differ (up to a constant)."""
    psi = cos_minimal_polynomial(q)
    d = psi.degree()
    R = flint.fmpz_poly([0, 1])
    num = -(1 - R) ** 2
    sub = sum((psi.coeffs()[k] * num ** k * (4 * R) ** (d - k) for k in range(d + 1)), flint.fmpz_poly(0))
    c, rr = sp.symbols("c r")
    res = sp.Poly(sp.resultant(sum(int(a) * c ** k for k, a in enumerate(psi.coeffs())),
                               rr ** 2 - (2 - 4 * c) * rr + 1, c), rr)
    res = flint.fmpz_poly([int(a) for a in reversed(res.all_coeffs())])
    if sub * res.coeffs()[-1] != res * sub.coeffs()[-1]:
        raise ArithmeticError(f"the two eliminations differ at q = {q}")
    return sub


@dataclass
class Resonance:
    p: int
    q: int
    r: Algebraic

    def interval(self, k: int = 20) -> tuple[str, str]:
        """An isolating interval with decimal ends ]L/10^k, (L+1)/10^k[ (checked: one root
        of the minimal polynomial inside, none at the ends)."""
        m = self.r.minimal_polynomial()
        L = self.r.floor_scaled(10 ** k)
        lo, hi = flint.fmpq(L, 10 ** k), flint.fmpq(L + 1, 10 ** k)
        if m(lo) == 0 or m(hi) == 0 or sturm_count(m, lo, hi) != 1:
            raise ArithmeticError(f"]{lo}, {hi}[ does not isolate {self.r}")
        return _decimal(L, k), _decimal(L + 1, k)

    def as_json(self) -> dict:
        return {"p": self.p, "q": self.q, "minimal_polynomial": show(self.r.minimal_polynomial()),
                "isolating_interval": list(self.interval()), "digits": self.r.digits(20)}


def _decimal(n: int, k: int) -> str:
    return f"{n // 10 ** k}.{str(n % 10 ** k).zfill(k)}"


@cache
def resonances_of_q(q: int) -> tuple:
    """The r in ]3−2√2, 1[ where ρ(r) = p/q, gcd(p, q) = 1 (q ≥ 3): roots in ]0, 1[ of the
    resonance polynomial's factors, counted by Sturm and python-flint alike; p = the integer
    in q·ρ(r) (a certified ball narrower than 1/2)."""
    out = []
    P = resonance_polynomial(q)
    for g, _m in P.factor()[1]:
        g = flint.fmpz_poly(g)
        checked_real_root_count(g)                  # Sturm and python-flint on the line
        roots = [x for x in Algebraic.roots(g, 0, 1) if x > LOWER_END]
        if len(roots) != roots_inside(flint.fmpq_poly(g)):
            raise ArithmeticError(f"root counts disagree for {g}")
        for x in roots:
            with precision(200):
                z = rotation_ball(x.arb(200), 200) * q
            k = round(float(z.mid()))
            if not abs(z - k) < flint.arb(1) / 4 or math.gcd(k, q) != 1:
                raise ArithmeticError(f"no p/q for the root {x} of {g}")
            out.append(Resonance(k, q, x))
    return tuple(sorted(out, key=lambda s: s.r))


def resonances(Q: int) -> list[Resonance]:
    """Every r in ]3−2√2, 1[ where the rotation number is p/q with q ≤ Q, increasing in r
    (ρ decreases from 1/2 to 1/4 as r goes from 3−2√2 to 1, so each p/q ∈ ]1/4, 1/2[ once)."""
    out = [s for q in range(3, Q + 1) for s in resonances_of_q(q)]
    return sorted(out, key=lambda s: s.r)


@dataclass(frozen=True)
class EndRotation:
    """The island's rotation number at a window end x ∈ [3 − 2√2, 1] (:func:`end_rotation`):
    ``island_end`` when x is one of the island's own ends (3 − 2√2, ρ = 1/2; r = 1, ρ → 1/4),
    ``ball`` ρ(x)'s certified enclosure [lo, hi] (x strictly inside; None at the ends), and
    ``resonance`` (p, q) when ρ(x) = p/q exactly with q ≤ the Q asked (at an end: its own)."""
    island_end: bool
    ball: tuple | None
    resonance: tuple[int, int] | None


def end_rotation(alg: Algebraic, Q: int) -> EndRotation | None:
    """The one place where a window end's resonance is decided (None below 3 − 2√2 or above
    1): at the island's ends ρ = 1/2 (3 − 2√2, A parabolic) and 1/4 (r = 1, the elastic end);
    strictly inside, ρ(alg)'s ball is computed once, narrower than 1/(2Q²) (from 200 bits,
    doubled), and only one p/q is tried: two fractions of denominators ≤ Q are at least 1/Q²
    apart, so if ρ(alg) = p/q with q ≤ Q, p/q is the fraction of denominator ≤ Q nearest the
    ball's midpoint; it is a resonance when alg is the same number as a resonance r_{p/q} of
    :func:`resonances_of_q` (the same minimal polynomial, and isolating intervals that overlap
    however far refined: Algebraic's exact equality)."""
    one = Algebraic.rational(flint.fmpq(1))
    if alg < LOWER_END or one < alg:
        return None
    if alg == LOWER_END:
        return EndRotation(True, None, (1, 2))
    if alg == one:
        return EndRotation(True, None, (1, 4))
    prec = 200
    while True:
        with precision(prec):
            lo, hi = ends(rotation_ball(alg.arb(prec), prec))
        if (hi - lo) * 2 * Q * Q < 1:
            break
        prec *= 2
    mid = (lo + hi) / 2
    cand = Fraction(int(mid.p), int(mid.q)).limit_denominator(Q)
    found = None
    if cand.denominator >= 3:
        m = alg.minimal_polynomial()
        for s in resonances_of_q(cand.denominator):
            mp = s.r.minimal_polynomial()
            if s.p == cand.numerator and (mp == m or mp == -m) and s.r == alg:
                found = (s.p, s.q)
                break
    return EndRotation(False, (lo, hi), found)


def resonance_of(alg: Algebraic, Q: int) -> tuple[int, int] | None:
    """(p, q) when the algebraic number alg, strictly inside ]3 − 2√2, 1[, is a resonance
    with q ≤ Q, else None (:func:`end_rotation`)."""
    e = end_rotation(alg, Q)
    return None if e is None or e.island_end else e.resonance


def algebraic_of(end: dict) -> Algebraic:
    """The Algebraic of an end point as the census and ``orbit --json`` print it
    ({"minimal_polynomial": "r^2 - 4r + 1", "interval": ["0.2679…", "0.2679…"], "exact": …})."""
    if end.get("exact") is not None:
        return Algebraic.rational(to_fmpq(end["exact"]))
    p = to_fmpz_poly(parse(re.sub(r"(\d)r", r"\1*r", end["minimal_polynomial"])))     # "12r^3" as printed
    lo, hi = (to_fmpq(x) for x in end["interval"])
    return Algebraic(p, lo, hi)


RESONANCE_Q = 12      # window ends compared with the resonances p/q, q ≤ RESONANCE_Q (orbit, CENSUS.md, island)


def resonance_phrase(side: str, digits: str, p: int, q: int) -> str:
    """How every output words a window end at a resonance (:func:`window_resonances`)."""
    return (f"its {'upper' if side == 'hi' else 'lower'} end ≈ {digits} is where the island's rotation number "
            f"is ρ = {p}/{q}")


def window_resonances(windows: dict, Q: int = RESONANCE_Q) -> list[tuple[str, str, str, tuple[int, int]]]:
    """(word, "lo" or "hi", digits, (p, q)) for every end of the attracting windows
    ({word: [{"lo": end, "hi": end}, ...]}, as census.json holds them) that is a resonance
    of the island with q ≤ Q, exactly (:func:`resonance_of`); an end at 3 − 2√2 is listed
    with (1, 2): ρ = 1/2 there, the end of the elliptic interval (A parabolic); an end at
    r = 1 with (1, 4) (ρ → 1/4, the elastic end)."""
    out = []
    for word, spans in windows.items():
        for span in spans:
            for side in ("lo", "hi"):
                e = end_rotation(algebraic_of(span[side]), Q)
                if e is not None and e.resonance is not None:
                    out.append((word, side, span[side]["digits"], e.resonance))
    return out


# --- the share of the b-section inside the island -------------------------------------

def island_fraction(r, depth: int = 8, prec: int = 64) -> tuple[flint.fmpq, flint.fmpq]:
    """[lo, hi] ∋ the share of the b-section (θ, φ) ∈ ]0, π/2[ × ]0, π[ (uniform measure)
    inside U_r: boxes (fractions s, t of the rectangle, θ = πs/2, φ = πt) are classified by arb
    balls containing them (p, q from reduction.P0/Q0 at b, n = p ∧ q, Q and c_max at its chart);
    undecided ones are bisected up to ``depth`` times.  lo = the area proved inside, hi = lo +
    the area undecided; exact rationals."""
    rq = to_fmpq(r)
    if rq * rq - 6 * rq + 1 >= 0:
        return flint.fmpq(0), flint.fmpq(0)
    inside, undecided = flint.fmpq(0), flint.fmpq(0)
    boxes = [(flint.fmpq(0), flint.fmpq(1), flint.fmpq(0), flint.fmpq(1))]
    with precision(prec):
        sides = Sides(rq)
        for level in range(depth + 1):
            nxt = []
            for box in boxes:
                s = box_sign(box, rq, sides)
                area = (box[1] - box[0]) * (box[3] - box[2])
                if s > 0:
                    inside += area
                elif s == 0:
                    if level == depth:
                        undecided += area
                    else:
                        nxt.extend(_split(box))
            boxes = nxt
    return inside, inside + undecided


def _split(box):
    s0, s1, t0, t1 = box
    sm, tm = (s0 + s1) / 2, (t0 + t1) / 2
    return [(s0, sm, t0, tm), (sm, s1, t0, tm), (s0, sm, tm, t1), (sm, s1, tm, t1)]


class Sides:
    """What :func:`box_sign` reads at the sides of the boxes, at r and the working precision,
    each computed once: the exact ends of the balls tan(θ − π/4) and w = 1/(sin θ + cos θ) at
    θ = πs/2 (:meth:`at_s`), of cot φ at φ = πt (:meth:`at_t`); r and c_max as balls."""

    def __init__(self, r: flint.fmpq):
        self.r, self.pi = r, flint.arb.pi()
        self.R, self.c = flint.arb(r), flint.arb(island.c_max(r))
        self.K = 1 + self.R                                   # 1 + r and −(1 + r), as box_sign forms them
        self.minus_K = -(1 + self.R)
        self.w_min = _lower(1 / flint.arb(2).sqrt())          # w at θ = π/4
        self.s, self.t, self.pairs = {}, {}, {}

    def at_s(self, s: flint.fmpq) -> tuple:
        """(lower, upper end of tan(θ − π/4), lower, upper end of w(θ)) at θ = πs/2."""
        key = (s.p, s.q)                  # python-flint hashes an fmpq slowly, an fmpz fast
        got = self.s.get(key)
        if got is None:
            th = s * self.pi / 2
            got = self.s[key] = ends((th - self.pi / 4).tan()) + ends(1 / (th.sin() + th.cos()))
        return got

    def at_pair(self, s0: flint.fmpq, s1: flint.fmpq) -> tuple:
        """((x, 2x·x, (1+r)x) for x the ball of u's lower end at s0, the same for its upper end
        at s1, the lower and upper end of w on [s0, s1]: its minimum w(π/4) when π/4 is in the
        interval) for the boxes of columns [s0, s1], once a pair and working precision."""
        key = (s0.p, s0.q, s1.p, s1.q, flint.ctx.prec)
        got = self.pairs.get(key)
        if got is None:
            (ua, _, w0_lo, w0_hi), (_, ub, w1_lo, w1_hi) = self.at_s(s0), self.at_s(s1)
            w_lo = self.w_min if s0 <= flint.fmpq(1, 2) <= s1 else min(w0_lo, w1_lo)
            ua, ub = flint.arb(ua), flint.arb(ub)
            got = self.pairs[key] = ((ua, 2 * ua * ua, self.K * ua), (ub, 2 * ub * ub, self.K * ub),
                                     w_lo, max(w0_hi, w1_hi))
        return got

    def at_t(self, t: flint.fmpq) -> tuple:
        """(lower, upper end of cot φ) at φ = πt."""
        key = (t.p, t.q)
        got = self.t.get(key)
        if got is None:
            ph = t * self.pi
            got = self.t[key] = ends(ph.cos() / ph.sin())
        return got


def box_sign(box, r: flint.fmpq, sides: Sides | None = None) -> int:
    """+1 when the whole box is in U_r, −1 when none of it is, 0 undecided: the chart of
    the box enclosed in a rectangle [u] × [v] by monotonicity, then Q bounded on it exactly
    as balls.  At b, n = p ∧ q = (−cos θ sin φ, cos φ, sin θ sin φ) (reduction.Angles), so
    u = tan(θ − π/4), increasing in θ, and v = 2 cot φ · w(θ) with w = 1/(sin θ + cos θ) > 0,
    cot φ decreasing, w smallest at θ = π/4 and largest at an end.  Q is convex (positive
    definite): its maximum on the rectangle is at a corner, its minimum at the origin or
    on an edge (a quadratic in one variable, minimised in closed form); each bound is
    computed only when the previous ones have not decided.  Boxes touching φ = 0 or π
    (v unbounded) are undecided: the chart's denominator n_z − n_x = sin φ (sin θ + cos θ)
    vanishes on their side, so :func:`box_sign_balls`, whose ball of it contains that 0,
    says 0 there too (a test)."""
    s0, s1, t0, t1 = box
    if t0 == 0 or t1 == 1:
        return 0
    sides = sides if sides is not None and sides.r == r else Sides(r)
    (ua, Aa, Ba), (ub, Ab, Bb), w_lo, w_hi = sides.at_pair(s0, s1)
    c_lo, c_hi = sides.at_t(t1)[0], sides.at_t(t0)[1]
    va, vb = 2 * min(c_lo * w_lo, c_lo * w_hi), 2 * max(c_hi * w_lo, c_hi * w_hi)
    va, vb = flint.arb(va), flint.arb(vb)
    R, c = sides.R, sides.c
    Ca, Cb = R * va * va, R * vb * vb
    # Q at the corners, island.quadratic_form(x, y, R) = (2x·x − (1+R)x·y) + R y·y, operation for operation
    if (c - ((Aa - Ba * va) + Ca) > 0 and c - ((Aa - Ba * vb) + Cb) > 0
            and c - ((Ab - Bb * va) + Ca) > 0 and c - ((Ab - Bb * vb) + Cb) > 0):
        return 1
    if ua <= 0 <= ub and va <= 0 <= vb:
        return 0
    minus = sides.minus_K                    # the edges u = ua, ub, then v = va, vb
    if _edge_min(R, minus * ua, Aa, va, vb) - c > 0 and _edge_min(R, minus * ub, Ab, va, vb) - c > 0:
        two = flint.arb(2)
        if _edge_min(two, minus * va, Ca, ua, ub) - c > 0 and _edge_min(two, minus * vb, Cb, ua, ub) - c > 0:
            return -1
    return 0


def _lower(z: flint.arb) -> flint.fmpq:
    """The exact lower end of a ball (so that min and max below are exact)."""
    return ends(z)[0]


def _upper(z: flint.arb) -> flint.fmpq:
    return ends(z)[1]


def _edge_min(a2, a1, a0, lo, hi) -> flint.arb:
    """A lower bound (a ball) of a2 x² + a1 x + a0 (a2 > 0) on [lo, hi]: the value at the
    nearer end when the vertex −a1/(2a2) is proved outside, else the vertex value."""
    x = -a1 / (2 * a2)
    if x < lo:
        return a2 * lo * lo + a1 * lo + a0
    if x > hi:
        return a2 * hi * hi + a1 * hi + a0
    return a0 - a1 * a1 / (4 * a2)


def box_sign_balls(box, r: flint.fmpq) -> int:
    """:func:`box_sign` by plain ball arithmetic on the box (balls containing θ and φ through
    reduction.Angles, n = p ∧ q, its chart and Q): coarser, the second route."""
    s0, s1, t0, t1 = box
    pi = flint.arb.pi()
    th = flint.arb((s0 + s1) / 2, (s1 - s0) / 2) * pi / 2
    ph = flint.arb((t0 + t1) / 2, (t1 - t0) / 2) * pi
    T = reduction.Angles("b", th.cos(), th.sin(), ph.cos(), ph.sin())
    n = T.u()
    d = n[2] - n[0]
    if not d > 0:
        return 0
    U, V = (n[0] + n[2]) / d, 2 * n[1] / d
    gap = flint.arb(island.c_max(r)) - island.quadratic_form(U, V, flint.arb(r))
    return 1 if gap > 0 else -1 if gap < 0 else 0


# --- JSON -------------------------------------------------------------------------------

def report(r, depth: int = 8, digits: int = 20) -> dict:
    """The JSON record of the island at a rational r (schema island.schema.json)."""
    T = theorem(r)
    rq = T.r
    out = {"r": str(rq), "elliptic": T.elliptic, "holds": T.holds,
           "c_max": str(T.c_max) if T.c_max is not None else None,
           "rotation_number": None, "quasi_periodic": T.quasi_periodic, "island_fraction": None,
           "steps": [{"name": s.name, "holds": s.holds, "evidence": s.evidence} for s in T.steps]}
    if T.elliptic:
        out["rotation_number"] = {"value": rotation_number(rq, digits), "digits": digits, "convention": CONVENTION}
        lo, hi = island_fraction(rq, depth)
        out["island_fraction"] = {"lo": str(lo), "hi": str(hi), "depth": depth}
    return out
