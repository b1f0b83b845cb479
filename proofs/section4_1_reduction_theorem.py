"""Section 4 up to 4.1 (l. 518-875): the spherical reduction and the spherical reduction theorem.

S1  the tangent bases at the contacts a and b (l. 528-531, 744-752);
S2  the first collision after a contact a (t_b, t_c, their order) and after b (l. 617-630, 686-690, 787-789);
S3, S4, S5  the cases ab, ac, bc of the proof: t_λ, p_λ(1) and the reduction (l. 630-845);
S6  Theorem 4.1: one plane, one sequence of collisions (l. 839-868);
S11 Remark 4.2: every orbit off the corners has infinitely many collisions, and the
    particles realise a prefix of it (l. 869-875).

Every printed vector, time and chain of equalities is transcribed below as text, as it
stands in the paper, and checked by :mod:`certify.algebra.trig` (each identity by a Gröbner
normal form modulo cos²+sin²−1 and by the Weierstrass substitution; signs by
inspection of the factors under θ ∈ ]0, π/2[, sin φ > 0, 0 < r < 1 and the sign of
cos φ).  Chains are written one member per line, each further line starting with
``=``; every ``=`` is a separate check.  In the texts, ``V(a, b, c)`` is a column
vector, ``M([[...]])`` a printed matrix, ``A``, ``B``, ``C`` the matrices of Section 2
(l. 209-232), ``er`` = e_r = p(0), ``q0`` = q_λ(0) at λ = 0, ``p1`` = p_λ(1) at λ = 0.
Line numbers in the checks are those of the paper's file.

The claims about every trajectory rest on a proof for every state: the step lemma of the
map and the particle lemma on the six cones of states (:mod:`certify.dynamics.cones`).
The particle system is :mod:`certify.dynamics.simulate` in exact rationals (fmpq); the
reduction map is :mod:`certify.dynamics.reduction`.  The exact runs and the scan of 10^5
collisions are reported as supporting evidence, never as a check.  Random data are drawn
from a fixed seed, so the report is reproducible.  A datum is a state right after a
collision: the contact letter i, p with p_i = 0 and the other gaps positive, q with
q_i > 0 (the pair separates), and a second datum (α p, β q + γ p) spanning the same plane
(α, β > 0, γ of any sign).
"""
from __future__ import annotations

import random
import re
from dataclasses import dataclass

import flint
import sympy as sp

from certify.algebra import Q, lam, r, show, statements
from certify.algebra import trig as T
from certify.dynamics import INDEX, LETTERS, collision_matrix
from certify.dynamics import cones as RC
from certify.dynamics import reduction as R
from certify.dynamics import simulate as sim
from certify.run import (
    ERRATUM,
    MISPRINT,
    PASS,
    Check,
    certificate,
    check_of,
    combined,
    conclude,
    concluded,
    identity,
    kept_witnesses,
    named,
    overridden,
    quantity,
    replaced,
    result_check,
    reworded,
    unread,
    witnesses_of,
)
from proofs.section2_model import A_PRINTED, B_PRINTED, C_PRINTED, matrix

# ================================================================ as printed (l. 518-845)
cθ, cφ, sθ, sφ = T.cθ, T.cφ, T.sθ, T.sφ  # cos θ, cos φ, sin θ, sin φ


SECTION2 = {"A": matrix(A_PRINTED), "B": matrix(B_PRINTED), "C": matrix(C_PRINTED)}


UNIT = {"ex": T.E_X, "ey": T.E_Y, "ez": T.E_Z}


PAIR = {"1-2": "a", "2-3": "b", "3-4": "c"}


# ---------------------------------------------------------------- as printed: contacts a and b
P0_A = "(0, cos(θ), sin(θ))"                                                   # l. 594-600


E_X = "(1, 0, 0)"                                                               # l. 545, 605


E_THETA_A = "(0, -sin(θ), cos(θ))"                                              # l. 545, 605


LIMIT_0 = "[(1, 0, 0), (0, 1, 0), (0, 0, 1)]"                                   # l. 545


LIMIT_PI2 = "[(1, 0, 0), (0, 0, 1), (0, -1, 0)]"                                # l. 545


Q_A_SUM = "cos(φ)*eθ + sin(φ)*ex + λ*er"                                        # l. 614


Q_A = "(sin(φ), -cos(φ)*sin(θ) + λ*cos(θ), cos(φ)*cos(θ) + λ*sin(θ))"           # l. 614, 634


P0_B = "(sin(θ), 0, cos(θ))"                                                    # l. 768


E_THETA_B = "(cos(θ), 0, -sin(θ))"                                              # l. 775


E_Y = "(0, 1, 0)"                                                               # l. 775


Q_B_SUM = "cos(φ)*eθ + sin(φ)*ey + λ*er"                                        # l. 779


Q_B = "(cos(φ)*cos(θ) + λ*sin(θ), sin(φ), -cos(φ)*sin(θ) + λ*cos(θ))"           # l. 779-783


# ---------------------------------------------------------------- as printed: the first collision times
T_B_AB = "cos(θ)/(sin(θ)*cos(φ) - λ*cos(θ))\n= 1/(tan(θ)*cos(φ) - λ)"             # l. 620


T_C_AB = "sin(θ)/(-cos(θ)*cos(φ) - λ*sin(θ))\n= 1/(-cos(φ)/tan(θ) - λ)"           # l. 620


T_C_MINUS_T_B = "(cos(φ)*tan(θ) + cos(φ)/tan(θ))/((-cos(φ)/tan(θ) - λ)*(tan(θ)*cos(φ) - λ))"  # l. 625


ORDER = "t_c is smaller than t_b"      # l. 628: "t_c is positive but then smaller than t_b"


ORDER_CORRECTION = ("smaller", "larger")


T_C, T_B = sp.symbols("t_c t_b")       # what the printed order is about


T_C_BC = "cos(θ)/(sin(θ)*cos(φ) - λ*cos(θ))\n= 1/(tan(θ)*cos(φ) - λ)"             # l. 787


T_A_BC = "sin(θ)/(-cos(θ)*cos(φ) - λ*sin(θ))\n= 1/(-cos(φ)/tan(θ) - λ)"           # l. 787


SMALLEST_BC = "cos(φ) > 0"             # l. 789: "t_c is always the smallest positive ... iff cos φ > 0"


# ---------------------------------------------------------------- as printed: case ab (l. 632-701)
AB = dict(
    condition="cos(θ) + t*(λ*cos(θ) - cos(φ)*sin(θ))",                          # l. 641
    t_lambda="cos(θ)/(cos(φ)*sin(θ) - λ*cos(θ))",                               # l. 645
    p_chain="""
V(0, cos(θ), sin(θ)) + cos(θ)/(cos(φ)*sin(θ) - λ*cos(θ))*V(sin(φ), -cos(φ)*sin(θ) + λ*cos(θ), cos(φ)*cos(θ) + λ*sin(θ))
= V(sin(φ)*cos(θ)/(cos(φ)*sin(θ) - λ*cos(θ)), 0,
    (cos(φ)*sin(θ)^2 - λ*cos(θ)*sin(θ) + cos(φ)*cos(θ)^2 + λ*cos(θ)*sin(θ))/(cos(φ)*sin(θ) - λ*cos(θ)))
= 1/(cos(φ)*sin(θ) - λ*cos(θ))*V(sin(φ)*cos(θ), 0, cos(φ))""",                # l. 649-656
    cross_chain="""
cross(V(sin(φ)*cos(θ), 0, cos(φ)), B*q0)
= cross(V(sin(φ)*cos(θ), 0, cos(φ)), M([[1, (1+r)/2, 0], [0, -r, 0], [0, (1+r)/2, 1]])*V(sin(φ), -cos(φ)*sin(θ), cos(φ)*cos(θ)))
= cross(V(sin(φ)*cos(θ), 0, cos(φ)), V(sin(φ) - (1+r)/2*cos(φ)*sin(θ), r*cos(φ)*sin(θ), -(1+r)/2*cos(φ)*sin(θ) + cos(φ)*cos(θ)))
= V(-r*cos(φ)^2*sin(θ),
    cos(φ)*sin(φ) - (1+r)/2*cos(φ)^2*sin(θ) + (1+r)/2*cos(φ)*sin(φ)*cos(θ)*sin(θ) - cos(φ)*sin(φ)*cos(θ)^2,
    r*cos(φ)*sin(φ)*cos(θ)*sin(θ))""",                                         # l. 676-682
    K_er_chain="""
B*er
= M([[1, (1+r)/2, 0], [0, -r, 0], [0, (1+r)/2, 1]])*V(0, cos(θ), sin(θ))
= V((1+r)/2*cos(θ), -r*cos(θ), (1+r)/2*cos(θ) + sin(θ))""",                    # l. 686
    dot_chain="""
dot(B*er, (cos(φ)*sin(θ))*cross(p1, B*q0))
= dot(V((1+r)/2*cos(θ), -r*cos(θ), (1+r)/2*cos(θ) + sin(θ)),
      V(-r*cos(φ)^2*sin(θ),
        cos(φ)*sin(φ) - (1+r)/2*cos(φ)^2*sin(θ) + (1+r)/2*cos(φ)*sin(φ)*cos(θ)*sin(θ) - cos(φ)*sin(φ)*cos(θ)^2,
        r*cos(φ)*sin(φ)*cos(θ)*sin(θ)))
= (-r*(1+r)/2*cos(φ)^2*cos(θ)*sin(θ))
  + (-r*cos(φ)*sin(φ)*cos(θ) + r*(1+r)/2*cos(φ)^2*cos(θ)*sin(θ)
     - r*(1+r)/2*cos(φ)*sin(φ)*cos(θ)^2*sin(θ) + r*cos(φ)*sin(φ)*cos(θ)^3)
  + (r*(1+r)/2*cos(φ)*sin(φ)*cos(θ)^2*sin(θ) + r*cos(φ)*sin(φ)*cos(θ)*sin(θ)^2)
= -r*cos(φ)*sin(φ)*cos(θ) + r*cos(φ)*sin(φ)*cos(θ)*(cos(θ)^2 + sin(θ)^2)
= 0""",                                                                         # l. 690-701
)


# ---------------------------------------------------------------- as printed: case ac (l. 705-761)
AC = dict(
    condition="sin(θ) + t*(cos(φ)*cos(θ) + λ*sin(θ))",                          # l. 708
    t_lambda="-sin(θ)/(cos(φ)*cos(θ) + λ*sin(θ))",                              # l. 712
    p_chain="""
V(0, cos(θ), sin(θ)) + -sin(θ)/(cos(φ)*cos(θ) + λ*sin(θ))*V(sin(φ), -cos(φ)*sin(θ) + λ*cos(θ), cos(φ)*cos(θ) + λ*sin(θ))
= V(-sin(φ)*sin(θ)/(cos(φ)*cos(θ) + λ*sin(θ)),
    (cos(φ)*cos(θ)^2 + λ*cos(θ)*sin(θ) + cos(φ)*sin(θ)^2 - λ*cos(θ)*sin(θ))/(cos(φ)*cos(θ) + λ*sin(θ)), 0)
= 1/(cos(φ)*cos(θ) + λ*sin(θ))*V(-sin(φ)*sin(θ), cos(φ), 0)""",               # l. 716-726
    cross_chain="""
cross(V(-sin(φ)*sin(θ), cos(θ), 0), C*q0)
= cross(V(-sin(φ)*sin(θ), cos(φ), 0), M([[1, 0, 0], [0, 1, (1+r)/2], [0, 0, -r]])*V(sin(φ), -cos(φ)*sin(θ), cos(φ)*cos(θ)))
= cross(V(-sin(φ)*sin(θ), cos(φ), 0), V(sin(φ), -cos(φ)*sin(θ) + (1+r)/2*cos(φ)*cos(θ), -r*cos(φ)*cos(θ)))
= V(-r*cos(φ)^2*cos(θ), -r*cos(φ)*sin(φ)*cos(θ)*sin(θ),
    cos(φ)*sin(φ)*sin(θ)^2 - (1+r)/2*cos(φ)*sin(φ)*cos(θ)*sin(θ) - cos(φ)*sin(φ))""",  # l. 734-744
    K_er_chain="""
C*er
= M([[1, 0, 0], [0, 1, (1+r)/2], [0, 0, -r]])*V(0, cos(θ), sin(θ))
= V(0, cos(θ) + (1+r)/2*sin(θ), -r*sin(θ))""",                                 # l. 748
    dot_chain="""
dot(C*er, (cos(φ)*cos(θ))*cross(p1, C*q0))
= dot(V(0, cos(θ) + (1+r)/2*sin(θ), -r*sin(θ)),
      V(-r*cos(φ)^2*cos(θ), -r*cos(φ)*sin(φ)*cos(θ)*sin(θ),
        cos(φ)*sin(φ)*sin(θ)^2 - (1+r)/2*cos(φ)*sin(φ)*cos(θ)*sin(θ) - cos(φ)*sin(φ)))
= (-r*cos(φ)*sin(φ)*cos(θ)^2*sin(θ) - r*(1+r)/2*cos(φ)*sin(φ)*cos(θ)*sin(θ)^2)
  + (-r*cos(φ)*sin(φ)*sin(θ)^3 + r*(1+r)/2*cos(φ)*sin(φ)*cos(θ)*sin(θ)^2 + r*cos(φ)*sin(φ)*sin(θ))
= -r*cos(φ)*sin(φ)*(cos(θ)^2 + sin(θ)^2)*sin(θ) + r*cos(φ)*sin(φ)*sin(θ)
= 0""",                                                                         # l. 752-761
)


# The one correction of case ac, stated: l. 734 prints cos θ where l. 735 and l. 722-726 have cos φ
# (member 1 of the cross-product chain, old text → new text).
AC_CORRECTION = {("cross_chain", 0): ("cos(θ), 0)", "cos(φ), 0)")}


AC_CORRECTED_ROLES = ("colinear", "x 1=2", "first factor")     # the checks that read member 1 of the cross product


# ---------------------------------------------------------------- as printed: case bc (l. 765-843)
BC = dict(
    t_lambda="cos(θ)/(cos(φ)*sin(θ) - λ*cos(θ))",                               # l. 792
    p_chain="""
V(sin(θ), 0, cos(θ)) + cos(θ)/(cos(φ)*sin(θ) - λ*cos(θ))*V(cos(φ)*cos(θ) + λ*sin(θ), sin(φ), -cos(φ)*sin(θ) + λ*cos(θ))
= V((cos(φ)*sin(θ)^2 - λ*cos(θ)*sin(θ) + cos(φ)*cos(θ)^2 + λ*cos(θ)*sin(θ))/(cos(φ)*sin(θ) - λ*cos(θ)),
    sin(φ)*cos(θ)/(cos(φ)*sin(θ) - λ*cos(θ)), 0)
= 1/(cos(φ)*sin(θ) - λ*cos(θ))*V(cos(φ), sin(φ)*cos(θ), 0)""",                # l. 796-808
    cross_chain="""
cross(V(cos(φ), sin(φ)*cos(θ), 0), C*q0)
= cross(V(cos(φ), sin(φ)*cos(θ), 0), M([[1, 0, 0], [0, 1, (1+r)/2], [0, 0, -r]])*V(cos(φ)*cos(θ), sin(φ), -cos(φ)*sin(θ)))
= cross(V(cos(φ), sin(φ)*cos(θ), 0), V(cos(φ)*cos(θ), sin(φ) - (1+r)/2*cos(φ)*sin(θ), r*cos(φ)*sin(θ)))
= V(r*cos(φ)*sin(φ)*cos(θ)*sin(θ), -r*cos(φ)^2*sin(θ),
    cos(φ)*sin(φ) - (1+r)/2*cos(φ)^2*sin(θ) - cos(φ)*sin(φ)*cos(θ)^2)""",     # l. 816-826
    K_er_chain="""
C*er
= M([[1, 0, 0], [0, 1, (1+r)/2], [0, 0, -r]])*V(sin(θ), 0, cos(θ))
= V(sin(θ), (1+r)/2*cos(θ), -r*cos(θ))""",                                     # l. 830
    dot_chain="""
dot(C*er, (cos(φ)*sin(θ))*cross(p1, C*q0))
= dot(V(sin(θ), (1+r)/2*cos(θ), -r*cos(θ)),
      V(r*cos(φ)*sin(φ)*cos(θ)*sin(θ), -r*cos(φ)^2*sin(θ),
        cos(φ)*sin(φ) - (1+r)/2*cos(φ)^2*sin(θ) - cos(φ)*sin(φ)*cos(θ)^2))
= (r*cos(φ)*sin(φ)*cos(θ)*sin(θ)^2)
  + (-r*(1+r)/2*cos(φ)^2*cos(θ)*sin(θ))
  + (-r*cos(φ)*sin(φ)*cos(θ) + r*(1+r)/2*cos(φ)^2*cos(θ)*sin(θ) + r*cos(φ)*sin(φ)*cos(θ)^3)
= r*cos(φ)*sin(φ)*cos(θ)*(sin(θ)^2 + cos(θ)^2) - r*cos(φ)*sin(φ)*cos(θ)
= 0""",                                                                         # l. 834-843
)


# ================================================================ helpers of the proofs of Section 4 (also used in section4_2, section4_3)
def vec(text: str, **names) -> sp.Matrix:
    """A printed vector."""
    return T.vector(text, **names)


def links(name: str, members: list, lines: str) -> list[Check]:
    """One check per printed '=' of a chain."""
    return [identity(f"l. {lines}, {name}: member {k + 1} = member {k + 2}", members[k], members[k + 1])
            for k in range(len(members) - 1)]


def recording_matrices():
    """``M`` for the chains: builds the printed matrix and keeps it for comparison."""
    seen = []

    def M(rows):
        seen.append(sp.Matrix(rows))
        return seen[-1]
    return M, seen


def matrices_are(letter: str, seen: list, lines: str) -> Check:
    """Every matrix printed inline equals the engine's collision matrix of ``letter``."""
    K = collision_matrix(letter)
    diffs = [(m - K).applyfunc(sp.expand) for m in seen]
    return Check(f"l. {lines}: every matrix printed inline ({len(seen)}) is {letter.upper()} "
                 "(certify.dynamics.model.collision_matrix)", bool(seen) and all(d.is_zero_matrix for d in diffs),
                 [f"printed: `{T.show(sp.Matrix(m).tolist())}`" for m in seen[:1]])


def call_factors(text: str, fn: str, names: dict) -> list[list[tuple]]:
    """For each member of a printed chain, the arguments of its calls of ``fn`` (cross or dot)."""
    out = []
    for member in T.members(text):
        calls = []

        def record(u, v, calls=calls):
            calls.append((u, v))
            return T.NAMES[fn](u, v)
        T.parse(member, **{**names, fn: record})
        out.append(calls)
    return out


def same_factors(statement: str, calls: list[list[tuple]], members: list[int], position: int) -> Check:
    """Factor ``position`` of the one call of each listed member is the same vector."""
    vs = [calls[m][0][position] for m in members if len(calls[m]) == 1]
    if len(vs) != len(members):
        return Check(statement, False, ["a member is not a single product"])
    return combined(statement, [T.equal(vs[0], v) for v in vs[1:]])


def hit_point(p0, q0, k: int):
    """p(0) + t q(0) at the time t = −p_k/q_k where the gap k closes."""
    return p0 - p0[k] / q0[k] * q0


# ================================================================ the setting and the proof of Theorem 4.1, cases ab, ac, bc (l. 518-845): S1-S5
# ================================================================ S1
@certificate("S1", printed=dict(p0_a=P0_A, e_x=E_X, e_theta_a=E_THETA_A, limit_0=LIMIT_0, limit_pi2=LIMIT_PI2,
                          q_a_sum=Q_A_SUM, q_a=Q_A, p0_b=P0_B, e_theta_b=E_THETA_B, e_y=E_Y, q_b_sum=Q_B_SUM, q_b=Q_B),
             expect=PASS,
             mutants=[replaced("e_theta_a", "-sin(θ)", "sin(θ)", "a sign of e_θ")])
def tangent_bases(p0_a, e_x, e_theta_a, limit_0, limit_pi2, q_a_sum, q_a, p0_b, e_theta_b, e_y, q_b_sum, q_b):
    """Gram matrices and determinants as identities in θ; the limit bases by substitution."""
    pa, ex, eta = vec(p0_a), vec(e_x), vec(e_theta_a)
    pb, etb, ey = vec(p0_b), vec(e_theta_b), vec(e_y)
    frame = sp.Matrix.hstack(ex, pa, eta).T                 # rows e_x, p(0), e_θ
    checks = [named("S1.1", identity("l. 545: (e_x, p(0), e_θ) is orthonormal: its Gram matrix is I", frame * frame.T,
                                     sp.eye(3))),
              named("S1.2", identity("l. 545: det(e_x, p(0), e_θ) = +1 for every θ (direct)", frame.det(), 1))]
    for ref, angle, text in (("S1.3", "0", limit_0), ("S1.4", "π/2", limit_pi2)):
        L = T.parse(text)
        at = frame.xreplace(T.ANGLE[angle])
        same, det = (at - L).is_zero_matrix, L.det()
        checks.append(Check(f"l. 545: at θ = {angle} the basis is the printed {T.show(L.tolist())}, det = +1",
                            same and det == 1, [f"(e_x, p(0), e_θ) at θ = {angle}: "
                                                f"`{T.show(at.tolist())}`, det {det}"], ref=ref))
    checks.append(named("S1.5", identity("l. 614: cos φ e_θ + sin φ e_x + λ e_r is the printed vector q(0) (e_r = p(0))",
                                         T.parse(q_a_sum, eθ=eta, ex=ex, er=pa), vec(q_a))))
    frame_b = sp.Matrix.hstack(etb, ey, pb).T
    checks += [named("S1.6", identity("l. 775: the printed basis of contact b and p(0) are orthonormal: Gram matrix I",
                                      frame_b * frame_b.T, sp.eye(3))),
               named("S1.7", identity("l. 779: cos φ e_θ + sin φ e_y + λ e_r is the printed q_λ(0) of contact b "
                                      "(e_r = p(0))", T.parse(q_b_sum, eθ=etb, ey=ey, er=pb), vec(q_b)))]
    return conclude(checks, note="e_r is p(0) (l. 617: 'e_r and p(0) are colinear'); the paper states no "
                    "orientation for the basis of contact b, and none is checked.")


# ================================================================ S2
t = sp.Symbol("t")


TAN = sθ / cθ


def solves(name: str, members: list, p0, q, k: int, lines: str) -> Check:
    """Every printed form of a time solves p_k(0) + t q_k(0) = 0."""
    parts = [T.is_zero((p0 + m * q)[k]) for m in members]
    return combined(f"l. {lines}: both printed forms of {name} solve p_{k + 1}(0) + t q_{k + 1}(0) = 0", parts)


def order_claim(ti, tj, li: str, lj: str, cos_phi: int, expected: int) -> T.Result:
    """t_i, t_j > 0 and the sign of cos φ give sign(t_j − t_i) = ``expected``, through the
    identity t_j − t_i = cos φ (tanθ + 1/tanθ) t_i t_j."""
    Ti, Tj = sp.symbols(f"t_{li} t_{lj}")
    H = T.hypotheses(cos_phi).assume(Ti, 1, ti).assume(Tj, 1, tj)
    return T.has_sign(tj - ti, expected, H, witness=cφ * (TAN + 1 / TAN) * Ti * Tj)


def race(ti, tj, li: str, lj: str) -> dict:
    """The gaps i, j of the ray p(0) + t q_λ(0) with times ti = 1/(tanθ cos φ − λ),
    tj = 1/(−cos φ/tanθ − λ): the implications of the printed case analysis, each an
    identity with a witness whose sign is read from its factors (L = λ − tanθ cos φ,
    N = λ + cos φ/tanθ).  First for cos φ > 0, then the mirror steps for cos φ < 0."""
    Ti, Tj, L, N = sp.symbols(f"t_{li} t_{lj} L N")
    low, high = lam - TAN * cφ, lam + cφ / TAN
    pos, neg = T.hypotheses(1), T.hypotheses(-1)
    return {
        "tan>0": T.has_sign(TAN * cφ, 1, pos),
        "i<0 ⇒ λ": T.has_sign(low, 1, pos.assume(Ti, -1, ti), witness=-1 / Ti),
        "λ ⇒ λ2": T.has_sign(high, 1, pos.assume(L, 1, low), witness=L + TAN * cφ + cφ / TAN),
        "⇒ j<0": T.has_sign(tj, -1, pos.assume(N, 1, high), witness=-1 / N),
        "order+": order_claim(ti, tj, li, lj, 1, 1),
        "order−": order_claim(ti, tj, li, lj, -1, -1),
        "j<0 ⇒ λ2": T.has_sign(high, 1, neg.assume(Tj, -1, tj), witness=-1 / Tj),
        "λ2 ⇒ λ": T.has_sign(low, 1, neg.assume(N, 1, high), witness=N - cφ / TAN - TAN * cφ),
        "⇒ i<0": T.has_sign(ti, -1, neg.assume(L, 1, low), witness=-1 / L),
    }


MU, NU, TAU = sp.symbols("μ ν τ")
LO, HI = -cφ / TAN, TAN * cφ      # l. 628: the values of λ where t_c and t_b change sign


def at_lambda(e, value):
    return e.subs(lam, value)


def ranges(ti, tj, s: int) -> list[T.Result]:
    """The case analysis in λ as the formal statements S2.10, S2.11, S2.14 read it
    (statements/4_reduction.txt), each sign with its witness: ti = 1/(tanθ cos φ − λ), tj =
    1/(−cos φ/tanθ − λ) (second forms); for cos φ > 0 (s = 1) λ = LO − ν (both positive, tj > ti),
    λ = (LO + HI ν)/(1 + ν) between LO and HI (ti > 0 > tj), λ = HI + ν (both negative) and the
    ends; for cos φ < 0 the mirror (ν > 0)."""
    H, Hn = T.hypotheses(s), T.hypotheses(s).assume(NU, 1)
    if s > 0:
        mid = (LO + HI * NU) / (1 + NU)
        return [T.has_sign(HI - LO, 1, H), T.has_sign(at_lambda(ti, LO), 1, H), T.has_sign(at_lambda(tj, HI), -1, H),
                T.has_sign(at_lambda(ti, LO - NU), 1, Hn), T.has_sign(at_lambda(tj - ti, LO - NU), 1, Hn),
                T.has_sign(at_lambda(ti, mid), 1, Hn), T.has_sign(at_lambda(tj, mid), -1, Hn),
                T.has_sign(at_lambda(ti, HI + NU), -1, Hn), T.has_sign(at_lambda(tj, HI + NU), -1, Hn)]
    mid = (HI + LO * NU) / (1 + NU)
    return [T.has_sign(LO - HI, 1, H), T.has_sign(at_lambda(tj, HI), 1, H), T.has_sign(at_lambda(ti, LO), -1, H),
            T.has_sign(at_lambda(tj, HI - NU), 1, Hn), T.has_sign(at_lambda(ti - tj, HI - NU), 1, Hn),
            T.has_sign(at_lambda(tj, mid), 1, Hn), T.has_sign(at_lambda(ti, mid), -1, Hn),
            T.has_sign(at_lambda(ti, LO + NU), -1, Hn), T.has_sign(at_lambda(tj, LO + NU), -1, Hn)]


def witness_point(ti, tj, cos_phi: int) -> tuple[bool, str]:
    """A rational point with cos φ of the given sign where both times are positive."""
    pt = T.point("1/2", "1/2" if cos_phi > 0 else "2", λ=-2)
    vals = [T.at(ti, pt), T.at(tj, pt)]
    ok = all(v > 0 for v in vals) and (pt[cφ] > 0) == (cos_phi > 0)
    return ok, f"at cos θ = {pt[cθ]}, sin θ = {pt[sθ]}, cos φ = {pt[cφ]}, sin φ = {pt[sφ]}, λ = -2 the times are {vals[0]}, {vals[1]}"


@certificate("S2", printed=dict(p0_a=P0_A, q_a=Q_A, t_b=T_B_AB, t_c=T_C_AB, difference=T_C_MINUS_T_B, order=ORDER,
                          p0_b=P0_B, q_b=Q_B, t_c_bc=T_C_BC, t_a_bc=T_A_BC, smallest_bc=SMALLEST_BC),
             expect=ERRATUM,
             mutants=[replaced("t_b", "- λ*cos(θ))", "+ λ*cos(θ))", "a sign of t_b"),
                      overridden({"smallest_bc": "cos(φ) < 0"}, "the condition reversed"),
                      reworded("smallest_bc", "cos(φ)", "sin(φ)", "sin φ > 0 always: t_c would always come first"),
                      reworded("smallest_bc", ">", "<"),
                      reworded("smallest_bc", ">", "≥", "cos φ = 0: t_c = t_a, not the smallest"),
                      reworded("order", "smaller than", "less than", "still false, and the stated correction no longer applies"),
                      reworded("order", "t_c is", "t_b is", "t_b is smaller than t_b"),
                      unread("smallest_bc", "cos φ > 0", "not the printed notation cos(φ)"),
                      unread("order", "smaller", "a phrase without its subject")])
def first_collision_after_a(p0_a, q_a, t_b, t_c, difference, order, p0_b, q_b, t_c_bc, t_a_bc, smallest_bc):
    """The printed times solve the collision equations; each implication of l. 628-629 is an
    exact identity between the target and a witness whose factors have known signs.  The
    printed order of t_c and t_b (l. 628) is read and evaluated on the certified sign of
    t_c - t_b; the printed condition of l. 789 is read and its truth, for each sign of
    cos φ, compared with whether t_c is the smallest collision time.  The corrected
    statement is the printed one with the stated correction smaller → larger."""
    pa, qa, pb, qb = vec(p0_a), vec(q_a), vec(p0_b), vec(q_b)
    TB, TC, TCB, TAB = (T.chain(x) for x in (t_b, t_c, t_c_bc, t_a_bc))
    R = race(TB[0], TC[0], "b", "c")
    ok_pt, pt_ev = witness_point(TB[0], TC[0], 1)
    b_first = [R["i<0 ⇒ λ"], R["λ ⇒ λ2"], R["⇒ j<0"], R["order+"]] + ranges(TB[1], TC[1], 1)
    c_first = [R["j<0 ⇒ λ2"], R["λ2 ⇒ λ"], R["⇒ i<0"], R["order−"]] + ranges(TB[1], TC[1], -1)
    # the signs as the formal statements S2.4-S2.9 read them (parametrised λ), each with its witness
    pos, neg = T.hypotheses(1), T.hypotheses(-1)
    K = cφ * (TAN + 1 / TAN) * MU * NU
    signs = {"S2.4": [T.has_sign(K, 1, pos.assume(MU, 1).assume(NU, 1)), T.has_sign(K, -1, neg.assume(MU, 1).assume(NU, 1))],
             "S2.5": [T.has_sign(HI, 1, pos), T.has_sign(HI - 1 / TAU - HI, 1, pos.assume(TAU, -1))],
             "S2.6": [T.has_sign(LO - (HI + MU), -1, pos.assume(MU, 1))],
             "S2.7": [T.has_sign(at_lambda(TC[1], LO + MU), -1, pos.assume(MU, 1))],
             "S2.8": [T.has_sign(at_lambda(TB[1], LO - NU), 1, pos.assume(NU, 1)),
                      T.has_sign(at_lambda(TC[1], LO - NU), 1, pos.assume(NU, 1)),
                      T.has_sign(at_lambda(TC[1] - TB[1], LO - NU), 1, pos.assume(NU, 1))]}
    common = [
        named("S2.1", solves("t_b", TB, pa, qa, 1, "620")), named("S2.2", solves("t_c", TC, pa, qa, 2, "620")),
        named("S2.3", identity("l. 625: the printed t_c - t_b is the difference of the printed times", T.parse(difference),
                               TC[0] - TB[0])),
        named("S2.4", combined("l. 626: if t_b, t_c > 0 then sign(t_c - t_b) = sign(cos φ), as t_c - t_b = cos φ "
                               "(tanθ + 1/tanθ) t_b t_c", [R["order+"], R["order−"]] + signs["S2.4"])),
        named("S2.5", combined("l. 628: cos φ > 0 and t_b < 0 give 0 < tanθ cos φ < λ",
                               [R["tan>0"], R["i<0 ⇒ λ"]] + signs["S2.5"])),
        named("S2.6", combined("l. 628: then -cos φ/tanθ < λ", [R["λ ⇒ λ2"]] + signs["S2.6"])),
        named("S2.7", combined("l. 628: and so t_c < 0", [R["⇒ j<0"]] + signs["S2.7"])),
    ]
    conclusion = [named("S2.10", combined("l. 628: when cos φ > 0 the first collision after a, if any, is b "
                                          "(t_b < 0 ⇒ t_c < 0; t_b > 0 ⇒ t_c < 0 or t_c > t_b)", b_first)),
                  named("S2.11", combined("l. 629: when cos φ < 0 it is c (t_c < 0 ⇒ t_b < 0; both positive ⇒ "
                                          "t_c < t_b)", c_first))]
    RB = race(TCB[0], TAB[0], "c", "a")
    ok2, ev2 = witness_point(TCB[0], TAB[0], -1)
    tie = T.is_zero((TCB[0] - TAB[0]).subs(cφ, 0))                  # cos φ = 0: t_c = t_a
    first = {1: True, -1: False, 0: False}                           # t_c strictly the smallest, by the sign of cos φ
    # l. 789, "iff": the three signs of cos φ, each with the printed condition read at that sign
    Hn = neg.assume(NU, 1)
    proofs = {1: [RB[k] for k in ("i<0 ⇒ λ", "λ ⇒ λ2", "⇒ j<0", "order+")] + ranges(TCB[1], TAB[1], 1),
              -1: [RB["order−"], T.Result(ok2, [ev2]), T.has_sign(at_lambda(TCB[1], HI - NU), 1, Hn),
                   T.has_sign(at_lambda(TAB[1], HI - NU), 1, Hn), T.has_sign(at_lambda(TCB[1] - TAB[1], HI - NU), 1, Hn)],
              0: [tie]}
    condition = statements.relation(smallest_bc, {"cos(φ)": cφ, "sin(φ)": sφ})
    read = {s: condition.holds({cφ: s, sφ: 1}) for s in first}
    case = {1: "cos φ > 0: t_c < 0 ⇒ t_a < 0, both positive ⇒ t_c < t_a",
            -1: "cos φ < 0: both positive ⇒ t_a < t_c, which happens", 0: "cos φ = 0: t_c = t_a"}
    bc = [named("S2.12", solves("t_c", TCB, pb, qb, 2, "787")), named("S2.13", solves("t_a", TAB, pb, qb, 0, "787"))]
    bc += [named(ref, combined(f"l. 789: t_c is the smallest positive collision time iff {smallest_bc}; {case[s]}",
                               proofs[s] + [T.Result(read[s] == first[s], [
                                   f"the printed condition at {case[s].split(':')[0]}: {'yes' if read[s] else 'no'}"])]))
           for ref, s in (("S2.14", 1), ("S2.15", -1), ("S2.16", 0))]
    known = {T_C - T_B: 1} if R["order+"].holds else {}              # certified: t_c - t_b > 0

    def order_check(label, text):
        if text is None:
            return Check(f"l. 628 corrected: the stated correction {' → '.join(ORDER_CORRECTION)} applies to the "
                         f"printed `{order}`", False)
        # the implication rests on the certified sign of t_c - t_b; refuting it needs the hypotheses to hold
        # somewhere, shown at a rational point
        holds = bool(known) and statements.relation(text, {"t_c": T_C, "t_b": T_B}).holds(known)
        holds = holds and all(signs["S2.8"])      # and the signs the formal statement reads (S2.8, S2.9)
        return Check(f"{label}: cos φ > 0, t_b > 0, t_c > 0 ⇒ {text}", holds, R["order+"].evidence + (
            [] if holds else [f"false whenever its hypotheses hold, and they do hold: {pt_ev}" if ok_pt else
                              f"false whenever its hypotheses hold; NO witness that they hold: {pt_ev}"]),
            witnesses=witnesses_of(R["order+"], *signs["S2.8"]))
    as_printed = named("S2.8", order_check("l. 628", order))
    corrected_order = named("S2.9", order_check("l. 628 corrected", statements.corrected(order, *ORDER_CORRECTION)))
    return concluded(common + [as_printed] + conclusion + bc, common + [corrected_order] + conclusion + bc,
                     kind=MISPRINT, misprint="l. 628: 'smaller' printed for 'larger' (t_c and t_b when cos φ > 0)",
                    note="With 'smaller', c would come first and the conclusion 'the first collision is b' would not "
                         "follow; with 'larger' the case analysis proves it.")


# ================================================================ S3, S4, S5
def with_member(text: str, index: int, member: str) -> str:
    """A printed chain with its member ``index`` replaced (a stated correction)."""
    members = T.members(text)
    members[index] = member
    return "\n= ".join(members)


# The roles of the checks of one case, in the order of the formal statements (statements/4_reduction.txt).
ROLES = ("condition", "solves", "member 1", "p 1=2", "p 2=3", "linearity", "colinear", "x 1=2", "x 2=3", "x 3=4",
         "first factor", "second factor", "e 1=2", "e 2=3", "matrices", "d 1=2", "d factors", "d 2=3", "d 3=4",
         "d 4=5", "conclusion", "hence")


def case_refs(certificate: str, roles=ROLES, corrected: tuple = ()) -> dict:
    """role -> the id of its formal statement: numbered in the order of ``roles``; each role of
    ``corrected`` is followed by its correction (role + "'")."""
    out, k = {}, 0
    for role in roles:
        for name in (role, role + "'") if role in corrected else (role,):
            k += 1
            out[name] = f"{certificate}.{k}"
    return out


def reduction_case(chains: dict, p0_text: str, q_text: str, letter: str, lines: dict, refs: dict) -> list[Check]:
    """The printed computation of one case of Theorem 4.1 (contact, next collision ``letter``):
    the collision time, the chain for p_λ(1), the cross product, K e_r and the dot product,
    every '=' separately; then the conclusion, computed directly.  ``refs``: role -> the id of
    the formal statement the check decides (:func:`case_refs`)."""
    k, K = INDEX[letter], SECTION2[letter.upper()]
    p0, q = vec(p0_text), vec(q_text)
    q0, tl = q.subs(lam, 0), T.parse(chains["t_lambda"])
    p1 = (p0 + tl * q).subs(lam, 0)
    M, seen = recording_matrices()
    names = dict(M=M, er=p0, q0=q0, p1=p1, **SECTION2)
    P, X, KE, D = (T.chain(chains[n], **names) for n in ("p_chain", "cross_chain", "K_er_chain", "dot_chain"))
    L = letter.upper()

    def ref(role, check):
        return named(refs[role], check) if role in refs else check

    def chain_links(name, members, where, roles):
        return [ref(role, c) for role, c in zip(roles, links(name, members, where))]
    checks = []
    if "condition" in chains:
        checks.append(ref("condition", identity(f"l. {lines['t']}: the printed condition is p_{k + 1}(0) + t q_{k + 1}(0) = 0",
                                                T.parse(chains["condition"]), (p0 + t * q)[k])))
    checks.append(ref("solves", identity(f"l. {lines['t']}: the printed t_λ solves it", (p0 + tl * q)[k], 0)))
    checks.append(ref("member 1", identity(f"l. {lines['p']}: p(0) + t_λ q_λ(0) is member 1 of the chain for p_λ(1)",
                                           p0 + tl * q, P[0])))
    checks += chain_links("p_λ(1) for every λ", P, lines["p"], ("p 1=2", "p 2=3"))
    normal = p1.cross(K * q0)
    checks.append(ref("linearity", identity(f"l. {lines['lin']}: by linearity, q_λ(1)·[p(1) ∧ q(1)] = λ ({L} e_r)·[p(1) ∧ "
                                            f"q(1)] (q_λ(1) = {L} q_λ(0))", (K * q).dot(normal), lam * (K * p0).dot(normal))))
    checks.append(ref("colinear", result_check(f"l. {lines['x']}: p(1) ∧ q(1) = p(1) ∧ {L}q(0) is colinear to member 1, "
                                               f"`{T.members(chains['cross_chain'])[0]}`", T.parallel(normal, X[0]))))
    checks += chain_links("cross product", X, lines["x"], ("x 1=2", "x 2=3", "x 3=4"))
    fx = call_factors(chains["cross_chain"], "cross", names)
    checks += [ref("first factor", same_factors(f"l. {lines['x']}: the first factor of the cross product is the same in "
                                                "members 1-3", fx, [0, 1, 2], 0)),
               ref("second factor", same_factors(f"l. {lines['x']}: the second factor {L}q(0) = printed matrix × printed "
                                                 "q(0) = printed vector (members 1-3)", fx, [0, 1, 2], 1))]
    checks.append(identity(f"l. {lines['e']}: {L} e_r is member 1 of its chain (e_r = p(0))", K * p0, KE[0]))
    checks += chain_links(f"{L} e_r", KE, lines["e"], ("e 1=2", "e 2=3"))
    checks += chain_links(f"({L} e_r)·[p(1) ∧ q(1)]", D, lines["d"], ("d 1=2", "d 2=3", "d 3=4", "d 4=5"))
    fd = call_factors(chains["dot_chain"], "dot", names)
    checks += [ref("d factors", same_factors(f"l. {lines['d']}: member 2 of the dot product has the factors of member 1: "
                                             f"{L} e_r", fd, [0, 1], 0)),
               ref("d factors", same_factors(f"l. {lines['d']}: and the scaled p(1) ∧ q(1)", fd, [0, 1], 1))]
    checks.append(ref("matrices", matrices_are(letter, seen, f"{lines['x']}, {lines['e']}")))
    return checks


def reduction_conclusion(chains: dict, p0_text: str, q_text: str, letter: str, refs: dict) -> list[Check]:
    """(K e_r)·[p(1) ∧ q(1)] = 0, and directly: p_λ(1) ∧ K q_λ(0) ∥ p(1) ∧ K q(0) for every λ."""
    K = SECTION2[letter.upper()]
    p0, q = vec(p0_text), vec(q_text)
    n, d = T.fraction(T.parse(chains["t_lambda"]))
    pl = d * p0 + n * q                                  # d · p_λ(1): d ≢ 0 does not change the direction
    p1, q0 = pl.subs(lam, 0), q.subs(lam, 0)
    return [named(refs["conclusion"], identity(f"conclusion: ({letter.upper()} e_r)·[p(1) ∧ q(1)] = 0",
                                               (K * p0).dot(p1.cross(K * q0)), 0)),
            named(refs["hence"], result_check("hence P_λ(1) = Span(p_λ(1), q_λ(1)) does not depend on λ: p_λ(1) ∧ "
                                              "q_λ(1) ∥ p(1) ∧ q(1) (p_λ(1) times the denominator of t_λ)",
                                              T.parallel(pl.cross(K * q), p1.cross(K * q0))))]


def certify_case(chains, p0, q, letter, lines, refs, corrections=None, note="", misprint=""):
    """Printed checks; corrected checks = the same with the stated corrections (old text →
    new text in one member of a chain) applied.  A check that reads the same words in
    both names the member it was computed with, so that the errata show the change; a
    stated correction whose old text is not in the printed member fails.  A printed check
    that the correction changes decides the formal statement of its role, the corrected
    one that of its correction (role + "'"); the others decide the same statement twice."""
    printed = reduction_case(chains, p0, q, letter, lines, refs) + reduction_conclusion(chains, p0, q, letter, refs)
    if not corrections:
        return concluded(printed, note=note)
    fixed, changed = dict(chains), []
    for (name, index), (old, new) in corrections.items():
        member = T.members(chains[name])[index]
        new_member = statements.corrected(member, old, new)
        if new_member is None:
            return conclude(printed, [Check(f"the stated correction `{old}` → `{new}` applies to member {index + 1} "
                                            f"of the printed chain, `{member}`", False)], note=note)
        fixed[name] = with_member(fixed[name], index, new_member)
        changed.append((index, member, new_member))
    corrected = reduction_case(fixed, p0, q, letter, lines, refs) + reduction_conclusion(fixed, p0, q, letter, refs)
    by_ref = {v: k for k, v in refs.items()}
    for wrong, fix in zip(printed, corrected):
        if not wrong.holds and wrong.statement == fix.statement:
            for index, member, new_member in changed:
                wrong.statement += f", with member {index + 1} as printed, `{member}`"
                fix.statement += f", with member {index + 1} corrected, `{new_member}`"
        if not wrong.holds and by_ref.get(wrong.ref, "") + "'" in refs:
            fix.ref = refs[by_ref[wrong.ref] + "'"]
    return concluded(printed, corrected, note=note, kind=MISPRINT, misprint=misprint)


@certificate("S3", printed=dict(p0=P0_A, q=Q_A, **AB),
             expect=PASS,
             mutants=[replaced("cross_chain", "V(-r*cos(φ)^2*sin(θ)", "V(r*cos(φ)^2*sin(θ)", "a sign of the cross product"),
                      replaced("t_lambda", "- λ*cos(θ)", "+ λ*cos(θ)", "a sign of t_λ")])
def case_ab(p0, q, **chains):
    """Identities in θ, φ, r, λ modulo the circle relations."""
    return certify_case(chains, p0, q, "b", dict(t="641-645", p="649-656", lin="666-672", x="676-682", e="686",
                                                 d="690-701"), case_refs("S3"))


@certificate("S4", printed=dict(p0=P0_A, q=Q_A, **AC),
             expect=ERRATUM,
             mutants=[replaced("K_er_chain", "-r*sin(θ))", "-r*cos(θ))", "C e_r with cos θ for sin θ")])
def case_ac(p0, q, **chains):
    """Identities in θ, φ, r, λ modulo the circle relations; l. 734 (left) corrected."""
    return certify_case(chains, p0, q, "c", dict(t="708-712", p="716-726", lin="728-731", x="734-744", e="748",
                                                 d="752-761"), case_refs("S4", corrected=AC_CORRECTED_ROLES),
                        AC_CORRECTION, misprint="l. 734: cos θ printed for cos φ in p(1)",
                        note="l. 734 prints (-sinφ sinθ, cosθ, 0) ∧ (C q(0)) where p(1) ∝ "
                        "(-sinφ sinθ, cosφ, 0) (l. 722-726, and l. 735): a misprint; the rest of the "
                        "computation uses cos φ and the conclusion (C e_r)·[p(1) ∧ q(1)] = 0 holds.")


@certificate("S5", printed=dict(p0=P0_B, q=Q_B, **BC),
             expect=PASS,
             mutants=[replaced("dot_chain", "(sin(θ)^2 + cos(θ)^2) - r", "(sin(θ)^2 + cos(θ)^2) + r", "a sign of the dot product")])
def case_bc(p0, q, **chains):
    """Identities in θ, φ, r, λ modulo the circle relations."""
    return certify_case(chains, p0, q, "c", dict(t="790-792", p="796-808", lin="810-813", x="816-826", e="830",
                                                 d="834-843"), case_refs("S5", ROLES[1:]))


# ================================================================ Theorem 4.1, the spherical billiard reduction (l. 569-868): S6, on the dynamics and on cones
SEED = 4_1_2024


N_DATA = 300                 # random initial data (each with a second datum on its plane)


N_COLLISIONS = 200           # collisions asked of the particle system


N_REDUCTION = 250            # collisions of the reduction map per datum


SCAN_ORBITS, SCAN_LENGTH = 100, 1000      # the scan of Proposition 4.4: 10^5 collisions


# ---------------------------------------------------------------- random data
def rational(rng: random.Random, lo: int = 1, hi: int = 99) -> flint.fmpq:
    """A random fraction with numerator in [lo, hi] and denominator in [1, hi]."""
    return Q(rng.randint(lo, hi), rng.randint(1, hi))


def restitution(rng: random.Random) -> flint.fmpq:
    """r in ]0,1[: mostly small (long collapsing runs), 15 % anywhere in ]0,1[."""
    if rng.random() < 0.85:
        return Q(1, rng.randint(4, 60))
    return Q(rng.randint(1, 98), 99)


@dataclass
class Datum:
    """Two physical runs from data spanning the same plane, and the reduction orbit."""

    r: flint.fmpq
    letter: str
    start: tuple         # (p, q) of the first run
    runs: tuple          # (run from (p, q), run from (αp, βq + γp)), exact, on the directions of p and q (sim.Rays)
    normals: list        # run 1: p ∧ q (primitive, orientation kept) at its start and after each collision
    planes: tuple        # per run: the Plane of (p, q) at its start and after each collision
    orbit: list          # Planes: the reduction from P(0)

    @property
    def realised(self) -> int:
        return min(len(run.events) for run in self.runs)


def datum(rng: random.Random) -> Datum:
    """A state right after a collision, a second one on the same plane, their exact
    runs (at most N_COLLISIONS collisions) and N_REDUCTION steps of the reduction."""
    r, letter = restitution(rng), rng.choice(LETTERS)
    i = INDEX[letter]
    p = tuple(Q(0) if k == i else rational(rng) for k in range(3))
    lam = -1 - rational(rng, 0, 40) / 10             # a radial part towards the origin
    q = tuple((rational(rng) if k == i else rng.choice((1, -1)) * rational(rng)) + lam * p[k]
              for k in range(3))
    al, be, ga = rational(rng), rational(rng), rng.choice((1, -1)) * rational(rng) / 100
    p2 = tuple(al * z for z in p)
    q2 = tuple(be * qk + ga * pk for qk, pk in zip(q, p))
    runs = (sim.follow_rays(p, q, r, N_COLLISIONS), sim.follow_rays(p2, q2, r, N_COLLISIONS))
    contacts = [letter] + runs[0].events
    n0 = R.normal(*runs[0].rays[0])
    orbit = R.orbit(R.oriented(letter, n0), r, N_REDUCTION)
    # the runs' normals, each read first as a multiple of the orbit's there (the same primitive normal, else the gcd)
    hints = [P.n for P in orbit[1:]] + [None] * len(runs[0].rays)
    normals = [n0] + [R.normal(P, Q, n) for (P, Q), n in zip(runs[0].rays[1:], hints)]
    planes = ([R.oriented(L, n) for L, n in zip(contacts, normals)],
              [R.plane(letter, p2, q2)] + [R.plane(e, P, Q, n) for e, (P, Q), n in
                                           zip(runs[1].events, runs[1].rays[1:], hints)])
    return Datum(r, letter, (p, q), runs, normals, planes, orbit)


@quantity("section4_data")
def section4_data() -> list[Datum]:
    """N_DATA random data with their exact runs and reduction orbits (fixed seed)."""
    rng = random.Random(SEED)
    return [datum(rng) for _ in range(N_DATA)]


def growth(data: list[Datum]) -> list[str]:
    """Bit sizes along the first run that reaches N_COLLISIONS: the physical state
    (p, q, t) and the normal of its plane."""
    def bits(z):
        return max(int(z.p).bit_length(), int(z.q).bit_length())
    long_runs = [d for d in data if len(d.runs[0].events) >= N_COLLISIONS]
    if not long_runs:
        return []
    d = long_runs[0]
    run = sim.follow(*d.start, d.r, N_COLLISIONS)        # the physical states themselves, with t
    rows = ["| collisions | bits of p, q (physical, exact) | bits of t | bits of the normal n (projective) |",
            "|---:|---:|---:|---:|"]
    for k in (1, 10, 50, 100, 200):
        s = run.states[k]
        rows.append(f"| {k} | {max(bits(z) for z in s.p + s.q)} | {bits(s.t)} | {d.orbit[k].bits} |")
    return [f"Growth of the exact numbers along one run (r = {d.r}):", "\n".join(rows)]


# ---------------------------------------------------------------- the proofs on cones (S6-S11)
SECTION2_K = {L: SECTION2[L.upper()] for L in LETTERS}


@quantity("reduction_cones")
def reduction_cones() -> dict:
    """The step lemma of the reduction on the six cones of states (contact, sign of cos φ),
    with the collision matrices of Section 2 (certify.dynamics.cones)."""
    return RC.steps(SECTION2_K)


def printed_cones(cones: dict, A: str, B: str, C: str) -> dict:
    """The step lemmas with the printed matrices A, B, C: the shared ones when these are
    the matrices of Section 2, else computed afresh (a mutated print)."""
    K = {L: matrix(text) for L, text in zip(LETTERS, (A, B, C))}
    return cones if all(K[L] == SECTION2_K[L] for L in LETTERS) else RC.steps(K)


def cone_witnesses(cones, motion: bool = False) -> list[str]:
    """The witnesses of the step lemmas on ``cones`` (and of the particle lemmas with ``motion``),
    kept by certify.dynamics.cones, recorded for the check that reads them; the ids."""
    return kept_witnesses(RC.witnesses(cones, motion))


def lemma_check(s: RC.Step) -> Check:
    """The step lemma on one cone as one check; its parts as evidence (✓/✗)."""
    nxt = (f"the next collision is {s.following}; the next state lies in a cone of {s.following}, with "
           f"cos φ' {RC.SIGN[s.cos_next]}") if s.following else "no next collision proven"
    ev = [f"{'✓' if c.holds else '✗'} {c.statement}" for c in s.checks]
    ev += [e for c in s.checks if not c.holds for e in c.evidence]
    return Check(f"step lemma on the cone {s.label} (every state there, exact): {nxt}", s.holds, ev,
                 witnesses=cone_witnesses([s]))


def supporting(text: str) -> str:
    return f"Supporting evidence, not proof: {text}"


# ---------------------------------------------------------------- S6
def multiple(rows, M: sp.Matrix):
    """k > 0 with rows = k·M (an integer matrix and a rational one), or None."""
    N = sp.Matrix([[int(z) for z in row] for row in rows])
    ratios = {a / b for a, b in zip(N, M) if b != 0}
    if len(ratios) != 1 or any(a != 0 for a, b in zip(N, M) if b == 0):
        return None
    k = ratios.pop()
    return k if k > 0 else None


def multiples(rows: list, M: sp.Matrix, rates: list) -> list:
    """[multiple(rows[m], M at r = rates[m])]: with M's entries polynomials in r over Q, each
    evaluated exactly at the rational rates (fmpq_poly), the ratios compared in fmpq, k returned
    as the SymPy Rational :func:`multiple` gives; by :func:`multiple` for any other M."""
    try:
        polys = [flint.fmpq_poly([flint.fmpq(int(c.p), int(c.q)) for c in sp.Poly(e, r, domain="QQ").all_coeffs()[::-1]])
                 for e in M]
    except (sp.PolynomialError, sp.CoercionFailed, sp.GeneratorsNeeded):
        return [multiple(N_, M.xreplace({r: sp.Rational(int(v.p), int(v.q))})) for N_, v in zip(rows, rates)]
    return [_multiple_at(N_, [P(v) for P in polys]) for N_, v in zip(rows, rates)]


def _multiple_at(rows, values: list):
    """:func:`multiple` for the values of M (fmpq, row by row) at one rate."""
    k = None
    for a, b in zip((z for row in rows for z in row), values):
        if b == 0:
            if a != 0:
                return None
            continue
        ratio = flint.fmpq(a) / b
        if k is None:
            k = ratio
        elif ratio != k:
            return None
    return sp.Rational(int(k.p), int(k.q)) if k is not None and k > 0 else None


CASES = (("a", "b", "S6.1"), ("a", "c", "S6.2"), ("b", "c", "S6.3"), ("b", "a", "S6.4"), ("c", "a", "S6.5"),
         ("c", "b", "S6.6"))


def plane_identities(K: dict) -> list[Check]:
    """The proof's identity (K_j e_r)·[p(1) ∧ q(1)] = 0 (l. 672, 730, 812) in each of the six cases
    (contact i, next j), for every state: e_r ∝ p(0) = e_i ∧ u, q(0) = u ∧ p(0) (l. 969-971), p(1)
    in the printed direction u ∧ e_j (l. 958, 962, relabelled), q(1) = K_j q(0); so Span(p(1),
    K_j q_λ(0)) does not depend on the radial part λ."""
    u, out = RC.N, []
    for i, j, ref in CASES:
        p = RC.UNIT[INDEX[i]].cross(u)
        q = u.cross(p)
        Kj = K[j]
        lhs = (Kj * p).dot(u.cross(RC.UNIT[INDEX[j]]).cross(Kj * q))
        out.append(identity(f"case {i}{j}: ({j.upper()} e_r)·[p(1) ∧ q(1)] = 0 for every normal u (e_r ∝ e_{INDEX[i] + 1} "
                            f"∧ u, p(1) ∝ u ∧ e_{INDEX[j] + 1}, q(1) = {j.upper()}(u ∧ e_r))", sp.Matrix([lhs]),
                            sp.zeros(1, 1)))
        out[-1].ref = ref
    return out


@certificate("S6", needs=["section4_data", "reduction_cones"], printed=dict(A=A_PRINTED, B=B_PRINTED, C=C_PRINTED),
             expect=PASS,
             mutants=[replaced("B", "[[1, (1+r)/2, 0]", "[[2, (1+r)/2, 0]", "B no longer fixes {y = 0}"),
                      replaced("C", "[0, 0, -r]", "[0, 1, -r]", "C moves {z = 0}"),
                      replaced("A", "[[-r, 0, 0]", "[[r, 0, 0]", "a column that A does not fix"),
                      replaced("A", "[(1+r)/2, 1, 0]", "[(1+3*r)/3, 1, 0]", "the same A at r = 1/3, another one over Q(r)")])
def spherical_reduction_theorem(section4_data, reduction_cones, A, B, C):
    """Proof: K_j fixes the plane {x_j = 0} pointwise, so with p' = p + t q,
    Span(p', K_j q) = K_j Span(p', q) = K_j Span(p, q): the new plane is K_j P whatever
    the radial part of q, and its normal is cof(K_j) n (cof(K) (a ∧ b) = Ka ∧ Kb).
    The engine's cof(K_j) (:func:`certify.dynamics.reduction.cofactor_columns` at a symbolic r)
    is the printed matrix's, as matrices over Q(r); the integer matrices the map steps
    with are positive multiples of it at every r of the runs.  Which collision comes
    next depends on the plane only: on the six cones of states (certify.dynamics.cones)
    the particles, whatever the radial part of their velocity, collide next at the map's
    j or never.  By induction, two trajectories on one plane have the same collisions
    while both last, and the same planes.  The printed route, for every state: the identity
    (K_j e_r)·[p(1) ∧ q(1)] = 0 in the six cases (:func:`plane_identities`, S6.1-S6.6), so the
    plane after the collision does not depend on the radial part.  The exact runs of two data per plane, compared
    collision by collision with each other and with the projective map, are supporting
    evidence."""
    checks, rates = [], sorted({d.r for d in section4_data} | {Q(1, 3)})
    for letter, text in zip(LETTERS, (A, B, C)):
        K, j = matrix(text), INDEX[letter]
        kept = [(K * sp.eye(3).col(m) - sp.eye(3).col(m)).applyfunc(sp.expand) == sp.zeros(3, 1)
                for m in range(3) if m != j]
        fixed = all(kept)
        cof = K.adjugate().T                     # cof(K)(a ∧ b) = Ka ∧ Kb for every K
        det = sp.expand(K.det())
        adjugate = (K.T * cof - det * sp.eye(3)).applyfunc(sp.expand).is_zero_matrix     # K^T cof(K) = det(K) I
        engine = sp.Matrix.hstack(*(sp.Matrix(col) for col in R.cofactor_columns(letter, r)))
        equal = all(sp.cancel(e) == 0 for e in engine - cof)                           # as matrices over Q(r)
        same = adjugate and equal
        integer = [R.cofactor(letter, r0) for r0 in rates]
        scaled = multiples(integer, cof, rates)     # k with N_ = k·cof at r = v
        checks.append(Check(f"{letter.upper()} fixes {{x_{j + 1} = 0}} pointwise, so the plane after a collision "
                            f"{letter} is {letter.upper()}·P, with normal cof({letter.upper()}) n; the projective map "
                            f"moves normals by this cof({letter.upper()}): the engine's cof({letter.upper()}) equals "
                            "it as a matrix over Q(r), and the integer matrix it steps with at each r of the runs is a "
                            "positive multiple of it there", fixed and same and all(k is not None for k in scaled),
                            [f"cof({letter.upper()}) = det·{letter.upper()}^(-T) = `{show(cof.applyfunc(sp.factor).tolist())}`",
                             f"engine − printed over Q(r): {'0' if same else show((engine - cof).applyfunc(sp.factor).tolist())}; "
                             f"integer multiples at {len(rates)} values of r: "
                             f"{sum(k is not None for k in scaled)} positive"]))
    checks += plane_identities({L: matrix(text) for L, text in zip(LETTERS, (A, B, C))})
    cones = printed_cones(reduction_cones, A, B, C)
    checks.append(Check("the next collision depends on the contact and the plane only: on each of the six cones of "
                        "states, whatever the radial part of the velocity, the particles collide next at the map's "
                        "contact j or never, and then span the plane with normal cof(K_j) n (the step and particle "
                        "lemmas with the printed A, B, C); by induction, two trajectories on one plane have the same "
                        "collision types while both last", RC.dynamics_is_proven(cones),
                        [f"{'✓' if c.motion.holds else '✗'} {c.label}: next {c.following}"
                         for c in cones.values()], witnesses=cone_witnesses(cones.values(), motion=True), ref="S6.7"))
    compared = same = 0
    for d in section4_data:
        k = d.realised
        for P1, P2, P in zip(d.planes[0][1:k + 1], d.planes[1][1:k + 1], d.orbit[1:k + 1]):
            compared += 1
            same += P1 == P2 == P
    reached = sum(d.realised >= N_COLLISIONS for d in section4_data)
    evidence = [supporting(f"on {len(section4_data)} random rational data (two per plane, exact runs of up to "
                           f"{N_COLLISIONS} collisions) the two runs have the same collision type and the same plane "
                           f"as the projective map at {same} of {compared} collisions compared; {reached} data kept "
                           f"colliding for {N_COLLISIONS} collisions on both runs, the others separated earlier.")]
    return conclude(checks, evidence=evidence + growth(section4_data))


# ================================================================ Remark 4.2 (l. 869-875): infinitely many collisions; the scan shared with Section 4.3
# ---------------------------------------------------------------- the scan (S9.2, S10, S11)
@dataclass
class ScanOrbit:
    r: flint.fmpq
    start: R.Plane
    word: str            # c_1 c_2 ... (SCAN_LENGTH letters unless a corner was met)
    bits: int            # of the final normal


@quantity("reduction_scan")
def reduction_scan() -> list[ScanOrbit]:
    """SCAN_ORBITS exact orbits of the projective map, SCAN_LENGTH collisions each,
    from random planes (integer normals in [-50, 50]^3 meeting the open face of a
    random contact) at random r = k/100 (fixed seed)."""
    rng = random.Random(SEED + 1)
    out = []
    while len(out) < SCAN_ORBITS:
        r, L = Q(rng.randint(1, 99), 100), rng.choice(LETTERS)
        try:
            P = R.canonical(L, [rng.randint(-50, 50) for _ in range(3)])
            R.next_letter(P)
        except (R.Corner, ValueError):
            continue
        w, end = R.word_of(P, r, SCAN_LENGTH)
        out.append(ScanOrbit(r, P, w, end.bits))
    return out


def occurrences(words, pattern: str) -> int:
    """Occurrences of ``pattern`` as consecutive collisions (overlaps counted): the positions k
    of a word w with w.startswith(pattern, k), found by a lookahead (which matches the empty
    text at every k, the end of w included: not counted for an empty pattern)."""
    if not pattern:
        return sum(map(len, words))
    ahead = re.compile(f"(?={re.escape(pattern)})")
    return sum(len(ahead.findall(w)) for w in words)


# ---------------------------------------------------------------- S11
STEP_REFS = {(L, s): f"S11.{2 * k + (1 if s > 0 else 2)}" for k, L in enumerate(LETTERS) for s in (1, -1)}


PRINTED_S11 = dict(reduction="infinitely many collisions", realised="a prefix", A=A_PRINTED, B=B_PRINTED, C=C_PRINTED)


@certificate("S11", needs=["reduction_cones", "reduction_scan", "section4_data"], printed=PRINTED_S11,
             expect=PASS,
             mutants=[overridden({"realised": "the whole"}, "the particles realise the whole orbit"),
                      overridden({"reduction": "finitely many collisions"}, "finitely many collisions"),
                      replaced("C", "[0, 0, -r]", "[0, 0, r]", "the pair c would not separate"),
                      replaced("B", "[[1, (1+r)/2, 0]", "[[2, (1+r)/2, 0]", "B p' ≠ p': another plane"),
                      replaced("A", "[(1+r)/2, 1, 0]", "[(1+r)/2, 2, 0]", "A moves {x = 0}"),
                      reworded("reduction", "infinitely", "finitely"),
                      reworded("realised", "a prefix", "the whole"),
                      unread("reduction", "infinitely many orbits", "not a count of collisions"),
                      unread("reduction", "many collisions", "no quantifier"),
                      unread("realised", "a part", "not an extent")])
def reduction_never_stops(reduction_cones, reduction_scan, section4_data, reduction, realised, A, B, C):
    """Proof, for every orbit (certify.dynamics.cones): a state off the corners lies in
    one of six cones (contact i, sign of n_i = |n| cos φ); on each, with the printed A, B,
    C, exactly one other gap j closes (w_j = −n_i n_j < 0 < w_k), at a time t > 0, at a
    point p' of the open face j, the pair j separates (−r w_j > 0), and the next normal
    p' ∧ K_j w = ρ cof(K_j) n (ρ > 0) lies in a cone of j unless n'_j = 0, a corner.  So
    the map is defined again at every step: infinitely many collisions.  The particles,
    whatever the radial part of their velocity, collide next at j or never, and then span
    the reduction's next plane: their collisions are a prefix.  The scan and the exact
    runs are supporting evidence."""
    claim, extent = statements.count(reduction), statements.extent(realised)     # read whole; unread text fails
    cones = printed_cones(reduction_cones, A, B, C)
    checks = [lemma_check(c) for c in cones.values()]
    for c, key in zip(checks, cones):
        c.ref = STEP_REFS[key]
    closed = RC.map_is_proven(cones)
    checks.append(Check(f"every orbit of the reduction off the corners has {reduction}: the six cones hold every "
                        "state off the corners, and each step maps a cone into a cone of the next contact, or onto a "
                        "corner (n'_j = 0)", closed and claim.infinite, witnesses=cone_witnesses(cones.values()),
                        ref="S11.7"))
    checks += [check_of(c.motion) for c in cones.values()]
    for c in checks[-6:]:
        c.ref = "S11.8"
    prefix = RC.dynamics_is_proven(cones)
    runs = [(run, d) for d in section4_data for run in d.runs]
    separated = sum(run.stop == "free" for run, d in runs)
    checks.append(Check(f"the realised collisions are {realised} of the reduction's sequence (for every datum, by "
                        "induction on the collisions)", prefix and (extent == "prefix" or separated == 0),
                        [f"{separated} exact runs end because the particles separate while the reduction goes on"],
                        witnesses=cone_witnesses(cones.values(), motion=True), ref="S11.8"))
    lengths = [len(o.word) for o in reduction_scan]
    realise = sum(R.word(d.orbit).startswith(run.word) for run, d in runs)
    evidence = [supporting(f"{len(lengths)} exact orbits from random planes meet no corner in {sum(lengths)} "
                           f"collisions (shortest {min(lengths)} of {SCAN_LENGTH}); {realise} of {len(runs)} exact "
                           f"particle runs realise a prefix of the reduction's word ({N_REDUCTION} collisions), "
                           f"{separated} of them end because the particles separate.")]
    return conclude(checks, evidence=evidence)
