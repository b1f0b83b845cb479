"""Section 2 (l. 147-247): the collision law in relative coordinates.

M1  the law (momentum, restitution) gives exactly the printed A, B, C;
M2  AC = CA;
M3  a collision turns q_i < 0 into q_i > 0, so particles never cross;
M4  scaling p or q by a positive factor keeps the collisions and the time ratios.
"""
import random

import flint
import sympy as sp

from certify.algebra import parse, r, show, statements, to_field, to_fmpq
from certify.dynamics import INDEX, LETTERS, collision_matrix
from certify.dynamics import simulate as sim
from certify.run import (
    PASS,
    Check,
    certificate,
    conclude,
    for_a_run,
    overridden,
    replaced,
    reworded,
    unread,
)

A_PRINTED = "[[-r, 0, 0], [(1+r)/2, 1, 0], [0, 0, 1]]"
B_PRINTED = "[[1, (1+r)/2, 0], [0, -r, 0], [0, (1+r)/2, 1]]"
C_PRINTED = "[[1, 0, 0], [0, 1, (1+r)/2], [0, 0, -r]]"


def matrix(text: str) -> sp.Matrix:
    """A printed 3×3 matrix, rows as lists."""
    return sp.Matrix(parse(text))


def same_matrix(K, L) -> bool:
    """K = L entry by entry as rational functions of r (equal elements of Q(r))."""
    return K.shape == L.shape and all(to_field(a) == to_field(b) for a, b in zip(K, L))


@for_a_run
def law(letter: str) -> sp.Matrix:
    """The matrix K with q' = K q derived from the collision law itself: for the pair
    (i, i+1), v_i' + v_{i+1}' = v_i + v_{i+1} and v_i' - v_{i+1}' = -r(v_i - v_{i+1});
    the solved velocities satisfy both equations, and q' = K q with v written through q."""
    v = sp.symbols("v1:5")
    i = INDEX[letter]
    vp = list(v)
    a, b = sp.symbols("a b")
    (vp[i], vp[i + 1]), = sp.linsolve([a + b - (v[i] + v[i + 1]), a - b + r * (v[i] - v[i + 1])], [a, b])
    law_lhs = sp.Matrix([vp[i] + vp[i + 1], vp[i] - vp[i + 1]])
    law_rhs = sp.Matrix([v[i] + v[i + 1], -r * (v[i] - v[i + 1])])
    qp = sp.Matrix([vp[k + 1] - vp[k] for k in range(3)])
    # express q' in the basis q: v is determined by q up to a common shift
    shift = sp.Symbol("w")
    subs = {v[0]: shift}
    qs = sp.symbols("q1:4")
    for k in range(3):
        subs[v[k + 1]] = shift + sum(qs[: k + 1])
    qp = qp.subs(subs).applyfunc(sp.expand)
    K = sp.Matrix(3, 3, lambda row, col: sp.expand(qp[row]).coeff(qs[col]))
    Kq = K * sp.Matrix(qs)
    assert (law_lhs - law_rhs).applyfunc(sp.expand) == sp.zeros(2, 1)
    assert (qp - Kq).applyfunc(sp.expand) == sp.zeros(3, 1)
    return K.applyfunc(sp.factor)


@certificate("M1", printed=dict(A=A_PRINTED, B=B_PRINTED, C=C_PRINTED),
             expect=PASS,
             mutants=[replaced("B", "-r", "r", "the sign of B's restitution term")])
def collision_law_gives_A_B_C(A, B, C):
    """Derive q' = K q from momentum conservation and restitution, compare with the print."""
    checks = []
    for k, (letter, text) in enumerate(zip(LETTERS, (A, B, C))):
        K = law(letter)
        same = same_matrix(K, matrix(text))
        checks.append(Check(f"the law for a collision of type {letter} gives the printed {letter.upper()}",
                            same, [f"derived: `{show(K.tolist())}`"], ref=f"M1.{k + 1}"))
    checks.append(Check("the engine's collision matrices are the ones the law gives",
                        all(same_matrix(law(k), collision_matrix(k)) for k in LETTERS), counts=False))
    return conclude(checks)


@certificate("M2", printed=dict(A=A_PRINTED, B=B_PRINTED, C=C_PRINTED, equality="AC = CA"),
             expect=PASS,
             mutants=[replaced("equality", "AC = CA", "AB = BA", "A and B do not commute"),
                      reworded("equality", "=", "≠"),
                      unread("equality", "AD = DA", "a matrix that is not printed")])
def a_and_c_commute(A, B, C, equality):
    """The printed equation between products of the printed A, B, C (AC = CA: simultaneous
    a and c collisions are well defined), read whole and checked identically in r."""
    K = {"A": matrix(A), "B": matrix(B), "C": matrix(C)}
    eq = statements.product_equation(equality)
    X, Y = (sp.prod((K[letter] for letter in word), start=sp.eye(3)) for word in (eq.lhs, eq.rhs))
    diff = (X - Y).applyfunc(sp.expand)
    same = diff == sp.zeros(3, 3)
    return conclude([Check(f"{equality} identically in r", same == eq.equal,
                           [f"{eq.lhs} - {eq.rhs} = `{show(diff.tolist())}`"], ref="M2.1")])


Q_I = sp.Symbol("q_i")


@certificate("M3", printed=dict(A=A_PRINTED, B=B_PRINTED, C=C_PRINTED, approaching="q_i < 0", separating="q_i > 0"),
             expect=PASS,
             mutants=[replaced("C", "-r", "-r/2", "another restitution in C"),
                      reworded("separating", ">", "<"),
                      reworded("approaching", "<", ">")])
def collisions_separate(A, B, C, approaching, separating):
    """Row i of K_i is -r e_i, so q_i' = -r q_i: with 0 < r < 1, sign q_i' = -sign q_i,
    and the printed conditions are read and checked: every sign of q_i allowed by the
    first (approaching, before) gives after the collision a sign allowed by the second.
    Between collisions p is affine in t and a gap closes only at a collision, after
    which it reopens: every gap p_i stays >= 0, so the order of the particles holds."""
    before, after = (statements.relation(t, {"q_i": Q_I}) for t in (approaching, separating))
    allowed = [s for s in (-1, 0, 1) if before.holds({Q_I: s})]
    turns = bool(allowed) and all(after.holds({Q_I: -s}) for s in allowed)
    checks = []
    for letter, text in zip(LETTERS, (A, B, C)):
        K, i = matrix(text), INDEX[letter]
        row = K.row(i).applyfunc(sp.expand)
        ref = f"M3.{i + 1}"
        expected = sp.Matrix([[-r if k == i else 0 for k in range(3)]])
        checks.append(Check(f"after {letter}: q_{i + 1}' = -r q_{i + 1}, so {approaching} before the collision gives "
                            f"{separating} after it (0 < r < 1)", row == expected and turns,
                            [f"row {i + 1} of {letter.upper()}: `{show(row.tolist())}`",
                             f"signs of q_i allowed before: {', '.join('+' if s > 0 else '−' for s in allowed)}; "
                             "the sign after (−sign) separating: "
                             + ", ".join("yes" if after.holds({Q_I: -s}) else "no" for s in allowed)], ref=ref))
    checks.append(Check("therefore the particles cannot cross each other: the order x_1 ≤ x_2 ≤ x_3 ≤ x_4 holds for "
                        "all times (by induction over the collisions: between two collisions p is affine in t, a gap "
                        "closes only at a collision and reopens after it, by the three rows above)",
                        all(c.holds for c in checks), ref="M3.4"))
    return conclude(checks)


@certificate("M4", printed=dict(A=A_PRINTED, B=B_PRINTED, C=C_PRINTED, time_factor="alpha/beta"),
             expect=PASS,
             mutants=[overridden({"time_factor": "beta/alpha"}, "the time factor inverted")])
def scaling_invariance(A, B, C, time_factor):
    """With p ↦ αp, q ↦ βq (α, β > 0): every candidate time -p_i/q_i is multiplied by α/β,
    so the next collision is the same; K(βq) = βK q, and p(t_k) scales by α; by
    induction all collisions agree and every time is multiplied by α/β.  Exact runs of
    the particle system are supporting evidence."""
    al, be = sp.symbols("alpha beta", positive=True)
    p = sp.Matrix(sp.symbols("p1:4", positive=True))
    q = sp.Matrix(sp.symbols("q1:4"))
    checks = []
    for letter, text in zip(LETTERS, (A, B, C)):
        K, i = matrix(text), INDEX[letter]
        t, ts = -p[i] / q[i], -(al * p[i]) / (be * q[i])
        new_p, new_ps = p + t * q, al * p + ts * be * q
        factor = sp.sympify(time_factor, locals={"alpha": al, "beta": be})
        parts = [sp.cancel(ts - factor * t) == 0,        # rational functions: 0 iff canceled to 0
                 (new_ps - al * new_p).applyfunc(sp.cancel) == sp.zeros(3, 1),
                 (K * (be * q) - be * (K * q)).applyfunc(sp.expand) == sp.zeros(3, 1)]
        checks.append(Check(f"collision {letter}: time ×α/β, p(t) ×α, K q ×β", all(parts), ref=f"M4.{i + 1}"))
    runs = scaled_runs_agree(sp.sympify(time_factor, locals={"alpha": al, "beta": be}), al, be)
    return conclude(checks, evidence=[f"Supporting evidence, not proof: {runs.statement}: "
                                      f"{'yes' if runs.holds else 'NO'}, {runs.evidence[0]}."])


def scaled_runs_agree(factor: sp.Expr, al: sp.Symbol, be: sp.Symbol, n_data: int = 40, n: int = 100) -> Check:
    """On the exact dynamics: random rational (p, q) and (αp, βq) at random r give the
    same collisions, and every collision time of the second is ``factor`` times the first."""
    rng = random.Random(2024)
    agree = total = 0
    at = exact_values(factor, al, be)
    for _ in range(n_data):
        rr = flint.fmpq(1, rng.randint(4, 40))
        p = tuple(flint.fmpq(rng.randint(0, 50), rng.randint(1, 50)) for _ in range(3))
        q = tuple(flint.fmpq(rng.randint(-50, 20), rng.randint(1, 50)) for _ in range(3))
        a, b = (flint.fmpq(rng.randint(1, 30), rng.randint(1, 30)) for _ in range(2))
        f = at(a, b)
        one, two = sim.follow(p, q, rr, n), sim.follow(tuple(a * z for z in p), tuple(b * z for z in q), rr, n)
        total += 1
        agree += one.events == two.events and all(s2.t == f * s1.t for s1, s2 in zip(one.states, two.states))
    return Check(f"exact runs: (αp, βq) has the collisions of (p, q) at {factor} times its times",
                 agree == total, [f"{agree} of {total} random rational data, up to {n} collisions each"])


def exact_values(e: sp.Expr, al: sp.Symbol, be: sp.Symbol):
    """(a, b) ↦ e at α = a, β = b (rationals, fmpq), exactly: a quotient of polynomials over Q
    evaluated in fmpq; SymPy's subs for any other ``e``."""
    try:
        num, den = (sp.Poly(part, al, be, domain="QQ") for part in sp.fraction(sp.together(e)))
    except sp.PolynomialError:
        return lambda a, b: to_fmpq(e.subs({al: sp.Rational(int(a.p), int(a.q)), be: sp.Rational(int(b.p), int(b.q))}))

    def value(P, a, b):
        return sum((to_fmpq(c) * a ** i * b ** j for (i, j), c in P.terms()), flint.fmpq(0))
    return lambda a, b: value(num, a, b) / value(den, a, b)
