"""Section 4 (l. 518-1035): the trigonometric identities of the spherical reduction.

Every printed vector, time and chain of equalities is transcribed below as text, as it
stands in the paper, and checked by :mod:`certify.algebra.trig` (each identity by a Gröbner
normal form modulo cos²+sin²−1 and by the Weierstrass substitution; signs by
inspection of the factors under θ ∈ ]0, π/2[, sin φ > 0, 0 < r < 1 and the sign of
cos φ).  Chains are written one member per line, each further line starting with
``=``; every ``=`` is a separate check.  In the texts, ``V(a, b, c)`` is a column
vector, ``M([[...]])`` a printed matrix, ``A``, ``B``, ``C`` the matrices of Section 2
(l. 209-232), ``er`` = e_r = p(0), ``q0`` = q_λ(0) at λ = 0, ``p1`` = p_λ(1) at λ = 0.
Line numbers in the checks are those of the paper's file.
"""
import sympy as sp

from certify.algebra import trig as T
from certify.algebra import lam, statements
from certify.dynamics import INDEX, LETTERS, collision_matrix
from certify.run import (ERRATUM, FALSE_STATEMENT, MISPRINT, PASS, Check, certificate, conclude, overridden,
                        replaced, reworded, unread)

from proofs.model import A_PRINTED, B_PRINTED, C_PRINTED, matrix

# One misprint, false in S8.1 (the formula) and S8.2 (the reduction it gives): counted once.
E_Y_FOR_E_Z = "l. 980: e_y printed for e_z in the trilinear formula for ũ(1) after a contact a and a collision c"

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

# ---------------------------------------------------------------- as printed: the trigonometric version (l. 888-926)
CONTACT_P0 = {"a": "(0, cos(θ), sin(θ))", "b": "(sin(θ), 0, cos(θ))", "c": "(cos(θ), sin(θ), 0)"}
CONTACT_Q0 = {"a": "(sin(φ), -sin(θ)*cos(φ), cos(θ)*cos(φ))", "b": "(cos(θ)*cos(φ), sin(φ), -sin(θ)*cos(φ))",
              "c": "(-sin(θ)*cos(φ), cos(θ)*cos(φ), sin(φ))"}
# contact, sign of cos φ: "next pair | matrix | p(t1) before normalisation | radicand"
SIX_CASES = {
    "a, φ ∈ ]0,π/2[": "2-3 | B | (cos(θ)*sin(φ), 0, cos(φ)) | cos(θ)^2*sin(φ)^2 + cos(φ)^2",      # l. 891-893
    "a, φ ∈ ]π/2,π[": "3-4 | C | (sin(θ)*sin(φ), -cos(φ), 0) | sin(θ)^2*sin(φ)^2 + cos(φ)^2",     # l. 896-898
    "b, φ ∈ ]0,π/2[": "3-4 | C | (cos(φ), cos(θ)*sin(φ), 0) | cos(φ)^2 + cos(θ)^2*sin(φ)^2",      # l. 905-907
    "b, φ ∈ ]π/2,π[": "1-2 | A | (0, sin(θ)*sin(φ), -cos(φ)) | sin(θ)^2*sin(φ)^2 + cos(φ)^2",     # l. 910-912
    "c, φ ∈ ]0,π/2[": "1-2 | A | (0, cos(φ), cos(θ)*sin(φ)) | cos(φ)^2 + cos(θ)^2*sin(φ)^2",      # l. 919-921
    "c, φ ∈ ]π/2,π[": "2-3 | B | (-cos(φ), 0, sin(θ)*sin(φ)) | cos(φ)^2 + sin(θ)^2*sin(φ)^2",     # l. 924-926
}
Q_T1 = "K*q0 - dot(K*q0, p)*p"      # l. 893, 898, ...: the numerator of q(t1), p = p(t1) normalised

# ---------------------------------------------------------------- as printed: the vectorial version (l. 937-982)
U0 = "(cos(φ), sin(θ)*sin(φ), -cos(θ)*sin(φ))"                                  # l. 947
EY_DOT_U0 = "sin(θ)*sin(φ)"                                                     # l. 949
ORIENTATION = "a: y, b: z, c: x"           # l. 949: t = y, z, x for contacts k = 1, 2, 3
U0_WEDGE = {"ey": "(cos(θ)*sin(φ), 0, cos(φ))",                                 # l. 958
            "ez": "(sin(θ)*sin(φ), -cos(φ), 0)",                                # l. 962
            "ex": "(0, -cos(θ)*sin(φ), -sin(θ)*sin(φ))",                        # l. 967
            "p0": "(sin(φ), -sin(θ)*cos(φ), cos(θ)*cos(φ))"}                    # l. 971
TRILINEAR_B = "cross(cross(u0, ey), B*cross(u0, cross(ex, u0)))"                # l. 976
TRILINEAR_C = "cross(cross(u0, ey), C*cross(u0, cross(ex, u0)))"                # l. 980
TRILINEAR_C_CORRECTION = ("(u0, ey)", "(u0, ez)")     # stated: for a collision c, p(1) ∝ u(0) ∧ e_z (l. 962)
TRILINEAR_C_CORRECTED = statements.corrected(TRILINEAR_C, *TRILINEAR_C_CORRECTION)

# ---------------------------------------------------------------- as printed: Proposition 4.4 (l. 1005-1034)
P_NEXT_AC = "(sin(θ)*sin(φ), -cos(φ), 0)"                                       # l. 1012
Q_NEXT_AC = "Cq - dot(Cq, pk)*pk"                                               # l. 1016
C_TIMES_QK = """
M([[1, 0, 0], [0, 1, (1+r)/2], [0, 0, -r]])*V(sin(φ), -sin(θ)*cos(φ), cos(θ)*cos(φ))
= V(sin(φ), -sin(θ)*cos(φ) + (1+r)/2*cos(θ)*cos(φ), -r*cos(θ)*cos(φ))"""        # l. 1020
PROJECTION_CHAIN = """
V(sin(φ), -sin(θ)*cos(φ) + (1+r)/2*cos(θ)*cos(φ), -r*cos(θ)*cos(φ))
  - (-cos(θ)*sin(θ)*cos(φ) + (1+r)/2*cos(θ)^2*cos(φ) - r*cos(θ)*sin(θ)*cos(φ))*V(0, cos(θ), sin(θ))
= V(sin(φ),
    -sin(θ)*cos(φ) + (1+r)/2*cos(θ)*cos(φ) + (1+r)*cos(θ)^2*sin(θ)*cos(φ) - (1+r)/2*cos(θ)^3*cos(φ),
    -r*cos(θ)*cos(φ) + (1+r)*cos(θ)*sin(θ)^2*cos(φ) - (1+r)/2*cos(θ)^2*sin(θ)*cos(φ))"""  # l. 1024-1031
FORM_C = "(-sin(θ)*cos(φ), cos(θ)*cos(φ), sin(φ))"                             # l. 1033 (θ', φ')
COS_NEXT, SIN_NEXT = sp.symbols("cos_φ' sin_φ'")                              # what the conclusion is about
READ_COMPONENT = 1                                                              # l. 1033: the first component
CONCLUSION = "cos(φ') < 0"                                                      # l. 1033


# ================================================================ helpers
def vec(text: str, **names) -> sp.Matrix:
    """A printed vector."""
    return T.vector(text, **names)


def identity(statement: str, lhs, rhs) -> Check:
    """The check lhs ≡ rhs, with the evidence of both routes."""
    res = T.equal(lhs, rhs)
    return Check(statement, res.holds, res.evidence)


def links(name: str, members: list, lines: str) -> list[Check]:
    """One check per printed '=' of a chain."""
    return [identity(f"l. {lines}, {name}: member {k + 1} = member {k + 2}", members[k], members[k + 1])
            for k in range(len(members) - 1)]


def concluded(printed: list[Check], corrected: list[Check] | None = None, note: str = "", kind: str = "",
              misprint: str = ""):
    """:func:`conclude`, where the corrected computation is the printed one with the stated
    corrections applied, check for check: each failing printed check is corrected by the
    check in the same place (unless a correction already names it)."""
    corrected = corrected or []
    named = {id(c.corrects) for c in corrected if c.corrects is not None}
    if len(corrected) == len(printed):
        for wrong, fix in zip(printed, corrected):
            if not wrong.holds and id(wrong) not in named and fix.corrects is None and fix is not wrong:
                fix.corrects = wrong
    return conclude(printed, corrected, note=note, kind=kind, misprint=misprint)


def result_check(statement: str, res: T.Result) -> Check:
    return Check(statement, res.holds, res.evidence)


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

        def record(u, v):
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
    parts = [T.equal(vs[0], v) for v in vs[1:]]
    return Check(statement, all(parts), [e for p_ in parts for e in p_.evidence])


def hit_point(p0, q0, k: int):
    """p(0) + t q(0) at the time t = −p_k/q_k where the gap k closes."""
    return p0 - p0[k] / q0[k] * q0


# ================================================================ S1
@certificate("S1", "l. 528-531, 744-752",
             "The printed tangent-plane bases at p(0) for contacts a and b are orthonormal and orthogonal to p(0); "
             "{e_x, p(0), e_θ} is direct, also in the limit cases θ = 0, π/2; q(0) = cos φ e_θ + sin φ e_x + λ e_r "
             "is the printed coordinate vector (and its b analogue).",
             printed=dict(p0_a=P0_A, e_x=E_X, e_theta_a=E_THETA_A, limit_0=LIMIT_0, limit_pi2=LIMIT_PI2,
                          q_a_sum=Q_A_SUM, q_a=Q_A, p0_b=P0_B, e_theta_b=E_THETA_B, e_y=E_Y, q_b_sum=Q_B_SUM, q_b=Q_B),
             expect=PASS,
             mutants=[replaced("e_theta_a", "-sin(θ)", "sin(θ)", "a sign of e_θ")])
def tangent_bases(p0_a, e_x, e_theta_a, limit_0, limit_pi2, q_a_sum, q_a, p0_b, e_theta_b, e_y, q_b_sum, q_b):
    """Gram matrices and determinants as identities in θ; the limit bases by substitution."""
    pa, ex, eta = vec(p0_a), vec(e_x), vec(e_theta_a)
    pb, etb, ey = vec(p0_b), vec(e_theta_b), vec(e_y)
    frame = sp.Matrix.hstack(ex, pa, eta).T                 # rows e_x, p(0), e_θ
    checks = [identity("l. 545: (e_x, p(0), e_θ) is orthonormal: its Gram matrix is I", frame * frame.T, sp.eye(3)),
              identity("l. 545: det(e_x, p(0), e_θ) = +1 for every θ (direct)", frame.det(), 1)]
    for angle, text in (("0", limit_0), ("π/2", limit_pi2)):
        L = T.parse(text)
        same = (frame.xreplace(T.ANGLE[angle]) - L).is_zero_matrix
        checks.append(Check(f"l. 545: at θ = {angle} the basis is the printed {T.show(L.tolist())}, det = +1",
                            same and L.det() == 1, [f"(e_x, p(0), e_θ) at θ = {angle}: "
                                                    f"`{T.show(frame.xreplace(T.ANGLE[angle]).tolist())}`, det {L.det()}"]))
    checks.append(identity("l. 614: cos φ e_θ + sin φ e_x + λ e_r is the printed vector q(0) (e_r = p(0))",
                           T.parse(q_a_sum, eθ=eta, ex=ex, er=pa), vec(q_a)))
    frame_b = sp.Matrix.hstack(etb, ey, pb).T
    checks += [identity("l. 775: the printed basis of contact b and p(0) are orthonormal: Gram matrix I",
                        frame_b * frame_b.T, sp.eye(3)),
               identity("l. 779: cos φ e_θ + sin φ e_y + λ e_r is the printed q_λ(0) of contact b (e_r = p(0))",
                        T.parse(q_b_sum, eθ=etb, ey=ey, er=pb), vec(q_b))]
    return conclude(checks, note="e_r is p(0) (l. 617: 'e_r and p(0) are colinear'); the paper states no "
                    "orientation for the basis of contact b, and none is checked.")


# ================================================================ S2
t = sp.Symbol("t")
TAN = sθ / cθ


def solves(name: str, members: list, p0, q, k: int, lines: str) -> Check:
    """Every printed form of a time solves p_k(0) + t q_k(0) = 0."""
    parts = [T.is_zero((p0 + m * q)[k]) for m in members]
    return Check(f"l. {lines}: both printed forms of {name} solve p_{k + 1}(0) + t q_{k + 1}(0) = 0",
                 all(parts), [e for p_ in parts for e in p_.evidence])


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


def witness_point(ti, tj, cos_phi: int) -> tuple[bool, str]:
    """A rational point with cos φ of the given sign where both times are positive."""
    pt = T.point("1/2", "1/2" if cos_phi > 0 else "2", λ=-2)
    vals = [T.at(ti, pt), T.at(tj, pt)]
    ok = all(v > 0 for v in vals) and (pt[cφ] > 0) == (cos_phi > 0)
    return ok, f"at cos θ = {pt[cθ]}, sin θ = {pt[sθ]}, cos φ = {pt[cφ]}, sin φ = {pt[sφ]}, λ = -2 the times are {vals[0]}, {vals[1]}"


def combined(statement: str, parts: list[T.Result]) -> Check:
    return Check(statement, all(parts), [e for p_ in parts for e in p_.evidence])


@certificate("S2", "l. 617-630, 686-690",
             "After a contact a, the next collision is b iff cos φ > 0 and c iff cos φ < 0: the printed t_b, t_c, "
             "t_c - t_b, the sign of t_c - t_b, and the case analysis in λ; the analogue t_c, t_a after a contact b.",
             printed=dict(p0_a=P0_A, q_a=Q_A, t_b=T_B_AB, t_c=T_C_AB, difference=T_C_MINUS_T_B, order=ORDER,
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
    b_first = [R["i<0 ⇒ λ"], R["λ ⇒ λ2"], R["⇒ j<0"], R["order+"]]
    c_first = [R["j<0 ⇒ λ2"], R["λ2 ⇒ λ"], R["⇒ i<0"], R["order−"]]
    common = [
        solves("t_b", TB, pa, qa, 1, "620"), solves("t_c", TC, pa, qa, 2, "620"),
        identity("l. 625: the printed t_c - t_b is the difference of the printed times", T.parse(difference), TC[0] - TB[0]),
        combined("l. 626: if t_b, t_c > 0 then sign(t_c - t_b) = sign(cos φ), as t_c - t_b = cos φ (tanθ + 1/tanθ) t_b t_c",
                 [R["order+"], R["order−"]]),
        combined("l. 628: cos φ > 0 and t_b < 0 give 0 < tanθ cos φ < λ", [R["tan>0"], R["i<0 ⇒ λ"]]),
        combined("l. 628: then -cos φ/tanθ < λ", [R["λ ⇒ λ2"]]),
        combined("l. 628: and so t_c < 0", [R["⇒ j<0"]]),
    ]
    conclusion = [combined("l. 628: when cos φ > 0 the first collision after a, if any, is b "
                           "(t_b < 0 ⇒ t_c < 0; t_b > 0 ⇒ t_c < 0 or t_c > t_b)", b_first),
                  combined("l. 629: when cos φ < 0 it is c (t_c < 0 ⇒ t_b < 0; both positive ⇒ t_c < t_b)", c_first)]
    RB = race(TCB[0], TAB[0], "c", "a")
    ok2, ev2 = witness_point(TCB[0], TAB[0], -1)
    tie = T.is_zero((TCB[0] - TAB[0]).subs(cφ, 0))                  # cos φ = 0: t_c = t_a
    first = {1: True, -1: False, 0: False}                           # t_c strictly the smallest, by the sign of cos φ
    proofs = [RB[k] for k in ("i<0 ⇒ λ", "λ ⇒ λ2", "⇒ j<0", "order+", "order−")] + [T.Result(ok2, [ev2]), tie]
    condition = statements.relation(smallest_bc, {"cos(φ)": cφ, "sin(φ)": sφ})
    read = {s: condition.holds({cφ: s, sφ: 1}) for s in first}
    bc = [solves("t_c", TCB, pb, qb, 2, "787"), solves("t_a", TAB, pb, qb, 0, "787"),
          combined(f"l. 789: t_c is the smallest positive collision time iff {smallest_bc} (cos φ > 0: t_c < 0 ⇒ t_a < 0, "
                   "both positive ⇒ t_c < t_a; cos φ < 0: both positive ⇒ t_a < t_c, which happens; cos φ = 0: "
                   "t_c = t_a)", proofs + [T.Result(read == first, ["the printed condition for cos φ > 0, < 0, = 0: "
                                                                     + ", ".join("yes" if read[s] else "no" for s in first)])])]
    known = {T_C - T_B: 1} if R["order+"].holds else {}              # certified: t_c - t_b > 0

    def order_check(label, text):
        if text is None:
            return Check(f"l. 628 corrected: the stated correction {' → '.join(ORDER_CORRECTION)} applies to the "
                         f"printed `{order}`", False)
        holds = bool(known) and statements.relation(text, {"t_c": T_C, "t_b": T_B}).holds(known)
        return Check(f"{label}: cos φ > 0, t_b > 0, t_c > 0 ⇒ {text}", holds and ok_pt, R["order+"].evidence + (
            [] if holds else [f"false whenever its hypotheses hold, and they do hold: {pt_ev}"]))
    as_printed = order_check("l. 628", order)
    corrected_order = order_check("l. 628 corrected", statements.corrected(order, *ORDER_CORRECTION))
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


def reduction_case(chains: dict, p0_text: str, q_text: str, letter: str, lines: dict) -> list[Check]:
    """The printed computation of one case of Theorem 4.1 (contact, next collision ``letter``):
    the collision time, the chain for p_λ(1), the cross product, K e_r and the dot product,
    every '=' separately; then the conclusion, computed directly."""
    k, K = INDEX[letter], SECTION2[letter.upper()]
    p0, q = vec(p0_text), vec(q_text)
    q0, tl = q.subs(lam, 0), T.parse(chains["t_lambda"])
    p1 = (p0 + tl * q).subs(lam, 0)
    M, seen = recording_matrices()
    names = dict(M=M, er=p0, q0=q0, p1=p1, **SECTION2)
    P, X, KE, D = (T.chain(chains[n], **names) for n in ("p_chain", "cross_chain", "K_er_chain", "dot_chain"))
    checks = []
    if "condition" in chains:
        checks.append(identity(f"l. {lines['t']}: the printed condition is p_{k + 1}(0) + t q_{k + 1}(0) = 0",
                               T.parse(chains["condition"]), (p0 + t * q)[k]))
    checks.append(identity(f"l. {lines['t']}: the printed t_λ solves it", (p0 + tl * q)[k], 0))
    checks.append(identity(f"l. {lines['p']}: p(0) + t_λ q_λ(0) is member 1 of the chain for p_λ(1)", p0 + tl * q, P[0]))
    checks += links("p_λ(1) for every λ", P, lines["p"])
    checks.append(result_check(f"l. {lines['x']}: p(1) ∧ q(1) = p(1) ∧ {letter.upper()}q(0) is colinear to member 1, "
                               f"`{T.members(chains['cross_chain'])[0]}`", T.parallel(p1.cross(K * q0), X[0])))
    checks += links("cross product", X, lines["x"])
    fx = call_factors(chains["cross_chain"], "cross", names)
    checks += [same_factors(f"l. {lines['x']}: the first factor of the cross product is the same in members 1-3",
                            fx, [0, 1, 2], 0),
               same_factors(f"l. {lines['x']}: the second factor {letter.upper()}q(0) = printed matrix × printed q(0) = "
                            "printed vector (members 1-3)", fx, [0, 1, 2], 1)]
    checks.append(identity(f"l. {lines['e']}: {letter.upper()} e_r is member 1 of its chain (e_r = p(0))", K * p0, KE[0]))
    checks += links(f"{letter.upper()} e_r", KE, lines["e"])
    checks += links(f"({letter.upper()} e_r)·[p(1) ∧ q(1)]", D, lines["d"])
    fd = call_factors(chains["dot_chain"], "dot", names)
    checks += [same_factors(f"l. {lines['d']}: member 2 of the dot product has the factors of member 1: "
                            f"{letter.upper()} e_r", fd, [0, 1], 0),
               same_factors(f"l. {lines['d']}: and the scaled p(1) ∧ q(1)", fd, [0, 1], 1)]
    checks.append(matrices_are(letter, seen, f"{lines['x']}, {lines['e']}"))
    return checks


def reduction_conclusion(chains: dict, p0_text: str, q_text: str, letter: str) -> list[Check]:
    """(K e_r)·[p(1) ∧ q(1)] = 0, and directly: p_λ(1) ∧ K q_λ(0) ∥ p(1) ∧ K q(0) for every λ."""
    K = SECTION2[letter.upper()]
    p0, q = vec(p0_text), vec(q_text)
    n, d = T.fraction(T.parse(chains["t_lambda"]))
    pl = d * p0 + n * q                                  # d · p_λ(1): d ≢ 0 does not change the direction
    p1, q0 = pl.subs(lam, 0), q.subs(lam, 0)
    return [identity(f"conclusion: ({letter.upper()} e_r)·[p(1) ∧ q(1)] = 0", (K * p0).dot(p1.cross(K * q0)), 0),
            result_check("hence P_λ(1) = Span(p_λ(1), q_λ(1)) does not depend on λ: p_λ(1) ∧ q_λ(1) ∥ p(1) ∧ q(1) "
                         "(p_λ(1) times the denominator of t_λ)", T.parallel(pl.cross(K * q), p1.cross(K * q0)))]


def certify_case(chains, p0, q, letter, lines, corrections=None, note="", misprint=""):
    """Printed checks; corrected checks = the same with the stated corrections (old text →
    new text in one member of a chain) applied.  A check that reads the same words in
    both names the member it was computed with, so that the errata show the change; a
    stated correction whose old text is not in the printed member fails."""
    printed = reduction_case(chains, p0, q, letter, lines) + reduction_conclusion(chains, p0, q, letter)
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
    corrected = reduction_case(fixed, p0, q, letter, lines) + reduction_conclusion(fixed, p0, q, letter)
    for wrong, fix in zip(printed, corrected):
        if not wrong.holds and wrong.statement == fix.statement:
            for index, member, new_member in changed:
                wrong.statement += f", with member {index + 1} as printed, `{member}`"
                fix.statement += f", with member {index + 1} corrected, `{new_member}`"
    return concluded(printed, corrected, note=note, kind=MISPRINT, misprint=misprint)


@certificate("S3", "l. 630-703", "Case ab: the printed t_λ; p_λ(1) = (1/(cosφ sinθ - λ cosθ))(sinφ cosθ, 0, cosφ) "
             "for every λ; the printed B q(0), cross product, B e_r and (B e_r)·[p(1) ∧ q(1)] = 0, every '=' checked.",
             printed=dict(p0=P0_A, q=Q_A, **AB),
             expect=PASS,
             mutants=[replaced("cross_chain", "V(-r*cos(φ)^2*sin(θ)", "V(r*cos(φ)^2*sin(θ)", "a sign of the cross product"),
                      replaced("t_lambda", "- λ*cos(θ)", "+ λ*cos(θ)", "a sign of t_λ")])
def case_ab(p0, q, **chains):
    """Identities in θ, φ, r, λ modulo the circle relations."""
    return certify_case(chains, p0, q, "b", dict(t="641-645", p="649-656", x="676-682", e="686", d="690-701"))


@certificate("S4", "l. 705-763", "Case ac: the printed t_λ; p_λ(1) = (1/(cosφ cosθ + λ sinθ))(-sinφ sinθ, cosφ, 0) "
             "for every λ; the printed C q(0), cross product, C e_r and (C e_r)·[p(1) ∧ q(1)] = 0, every '=' checked.",
             printed=dict(p0=P0_A, q=Q_A, **AC),
             expect=ERRATUM,
             mutants=[replaced("K_er_chain", "-r*sin(θ))", "-r*cos(θ))", "C e_r with cos θ for sin θ")])
def case_ac(p0, q, **chains):
    """Identities in θ, φ, r, λ modulo the circle relations; l. 734 (left) corrected."""
    return certify_case(chains, p0, q, "c", dict(t="708-712", p="716-726", x="734-744", e="748", d="752-761"),
                        AC_CORRECTION, misprint="l. 734: cos θ printed for cos φ in p(1)",
                        note="l. 734 prints (-sinφ sinθ, cosθ, 0) ∧ (C q(0)) where p(1) ∝ "
                        "(-sinφ sinθ, cosφ, 0) (l. 722-726, and l. 735): a misprint; the rest of the "
                        "computation uses cos φ and the conclusion (C e_r)·[p(1) ∧ q(1)] = 0 holds.")


@certificate("S5", "l. 765-845", "Case bc: the printed t_λ; p_λ(1) = (1/(cosφ sinθ - λ cosθ))(cosφ, sinφ cosθ, 0) "
             "for every λ; the printed C q(0), cross product, C e_r and (C e_r)·[p(1) ∧ q(1)] = 0, every '=' checked.",
             printed=dict(p0=P0_B, q=Q_B, **BC),
             expect=PASS,
             mutants=[replaced("dot_chain", "(sin(θ)^2 + cos(θ)^2) - r", "(sin(θ)^2 + cos(θ)^2) + r", "a sign of the dot product")])
def case_bc(p0, q, **chains):
    """Identities in θ, φ, r, λ modulo the circle relations."""
    return certify_case(chains, p0, q, "c", dict(t="790-792", p="796-808", x="816-826", e="830", d="834-843"))


# ================================================================ S7.1
CASE_KEYS = {"a_pos": ("a", 1), "a_neg": ("a", -1), "b_pos": ("b", 1), "b_neg": ("b", -1),
             "c_pos": ("c", 1), "c_neg": ("c", -1)}
RANGE = {1: "φ ∈ ]0,π/2[", -1: "φ ∈ ]π/2,π[", None: "φ ∈ ]0,π["}


def contact_frame(contact: str, p0, q0) -> Check:
    """p(0), q(0) unit and orthogonal, q_i(0) = sin φ > 0 for the gap i in contact."""
    i = INDEX[contact]
    res = T.equal(sp.Matrix([p0.dot(p0), q0.dot(q0), p0.dot(q0), q0[i], p0[i]]), sp.Matrix([1, 1, 0, sφ, 0]))
    return Check(f"contact {contact}: |p(0)| = |q(0)| = 1, p(0)·q(0) = 0, p_{i + 1}(0) = 0, q_{i + 1}(0) = sin φ > 0",
                 res.holds, res.evidence)


def next_gap(contact: str, p0, q0, H: T.Signs) -> tuple[int | None, list[str]]:
    """The one other gap k that closes on the ray p(0) + t q(0) (p_k(0) > 0, q_k(0) < 0)
    while the third one opens (q_l(0) > 0), all signs read from the factors under H."""
    others = [j for j in range(3) if j != INDEX[contact]]
    sp_ = {j: T.sign(p0[j], H)[0] for j in others}
    sq = {j: T.sign(q0[j], H)[0] for j in others}
    ev = [f"gap {j + 1}: p = `{T.show(p0[j])}` {'> 0' if sp_[j] == 1 else '?'}, "
          f"q = `{T.show(q0[j])}` {'> 0' if sq[j] == 1 else '< 0' if sq[j] == -1 else '?'}" for j in others]
    closing = [j for j in others if sq[j] == -1 and sp_[j] == 1]
    ok = len(closing) == 1 and all(sq[j] == 1 for j in others if j not in closing)
    return (closing[0] if ok else None), ev


def six_case(key: str, spec: str, p0, q0, q_t1: str) -> list[Check]:
    """One printed case of l. 886-929: the next collision, p(t1), its norm, q(t1)."""
    contact, cos_phi = CASE_KEYS[key]
    H, label = T.hypotheses(cos_phi), f"contact {contact}, {RANGE[cos_phi]}"
    pair, letter, V_text, R_text = (x.strip() for x in spec.split("|"))
    k, ev = next_gap(contact, p0, q0, H)
    first = Check(f"{label}: the next collision is the printed {pair} with matrix {letter}: the only gap the ray "
                  "p(0) + t q(0) closes", k is not None and PAIR.get(pair) == LETTERS[k] and letter == LETTERS[k].upper(), ev)
    if k is None:
        return [first]
    V, R = vec(V_text), T.parse(R_text)
    hit = hit_point(p0, q0, k)
    inside = [T.has_sign(V[j], 1, H) for j in range(3) if j != k]
    w = T.parse(q_t1, K=SECTION2[letter], q0=q0, p=V / sp.sqrt(R)).applyfunc(sp.expand)
    if w.has(sp.sqrt):
        raise ValueError("the normalisation of p(t1) did not cancel")
    return [first,
            result_check(f"{label}: the printed p(t1) ∝ `{V_text}` is a positive multiple of the point p(0) + t q(0) "
                         f"where gap {k + 1} closes", T.positively_proportional(hit, V, H)),
            combined(f"{label}: p(t1) lies on p_{k + 1} = 0 with its two other components > 0 (θ' ∈ ]0,π/2[)",
                     [T.is_zero(V[k])] + inside),
            combined(f"{label}: the printed radicand `{R_text}` is |p(t1)|², and it is > 0",
                     [T.equal(R, V.dot(V)), T.has_sign(R, 1, H)]),
            combined(f"{label}: q(t1) = {letter}q(0) - ({letter}q(0)·p(t1))p(t1), normalised, is orthogonal to p(t1) "
                     f"and its component {k + 1} is > 0 (φ' ∈ ]0,π[)", [T.is_zero(w.dot(V)), T.has_sign(w[k], 1, H)])]


@certificate("S7.1", "l. 877-929",
             "The six printed cases of the trigonometric version: for each contact and each range of φ, the printed next "
             "collision is the one the ray p(0) + t q(0) reaches, the printed p(t1) is the hit point normalised by the "
             "printed radicand, and the printed q(t1) is orthogonal to p(t1) with positive component along the new gap.",
             printed=dict(p0_a=CONTACT_P0["a"], q0_a=CONTACT_Q0["a"], p0_b=CONTACT_P0["b"], q0_b=CONTACT_Q0["b"],
                          p0_c=CONTACT_P0["c"], q0_c=CONTACT_Q0["c"], q_t1=Q_T1,
                          **{key: SIX_CASES[f"{c}, {RANGE[s]}"] for key, (c, s) in CASE_KEYS.items()}),
             expect=PASS,
             mutants=[replaced("c_neg", "(-cos(φ), 0", "(cos(φ), 0", "a sign of p(t1)"),
                      replaced("a_pos", "2-3 | B", "3-4 | C", "another pair and matrix for a, cos φ > 0"),
                      replaced("b_neg", "sin(θ)^2*sin(φ)^2", "sin(θ)^2*sin(φ)", "an exponent of the radicand")])
def trigonometric_version(p0_a, q0_a, p0_b, q0_b, p0_c, q0_c, q_t1, **cases):
    """Signs from the factors under θ ∈ ]0,π/2[, sin φ > 0, 0 < r < 1 and the sign of cos φ."""
    frames = {"a": (vec(p0_a), vec(q0_a)), "b": (vec(p0_b), vec(q0_b)), "c": (vec(p0_c), vec(q0_c))}
    checks = [contact_frame(c, *frames[c]) for c in LETTERS]
    for key, spec in cases.items():
        checks += six_case(key, spec, *frames[CASE_KEYS[key][0]], q_t1)
    return conclude(checks, note="The normalisation of q(t1) divides by a positive norm and changes no sign; it is "
                    "not expanded.  p(t1) is checked up to its normalisation, which is the printed square root.")


# ================================================================ S8.1
def orientation_axes(text: str) -> dict:
    """'a: y, b: z, c: x' as {contact: e_t}."""
    pairs = dict(item.split(":") for item in text.replace(" ", "").split(","))
    return {c: UNIT[f"e{pairs[c]}"] for c in pairs}


def not_normal(u, p, H: T.Signs, tφ: str) -> list[str]:
    """Evidence that u is not normal to p: u·p ≢ 0, with its value at a rational point of H."""
    d = u.dot(p)
    pt = T.point("1/2", tφ, r="1/3")
    return T.is_zero(d).evidence + [f"at cos θ = {pt[cθ]}, cos φ = {pt[cφ]}, r = 1/3: ũ(1)·p(1) = {T.at(d, pt)}"
                                    f" (hypotheses hold there: {'yes' if T.satisfied(H, pt) else 'no'})"]


def trilinear(text: str, letter: str, u0, p1, q0, H: T.Signs, axis, tφ: str) -> Check:
    """The printed ũ(1) is a positive multiple of p(1) ∧ K q(0) (the normal of P(1) oriented
    as p ∧ q), and that normal has e_t·u > 0 for the new contact."""
    K = SECTION2[letter]
    u1 = T.parse(text, u0=u0, **UNIT, **SECTION2)
    normal = p1.cross(K * q0)
    prop = T.positively_proportional(u1, normal, H)
    orient = T.has_sign(axis.dot(normal), 1, H)
    ev = prop.evidence + orient.evidence + ([] if prop.holds else not_normal(u1, p1, H, tφ))
    return Check(f"l. 976-980: ũ(1) = `{text}` is a positive multiple of p(1) ∧ {letter}q(0), "
                 f"the normal of P(1) with e_t·u(1) > 0 ({RANGE[H.sign(cφ)]})", prop.holds and orient.holds, ev)


@certificate("S8.1", "l. 931-987",
             "The vectorial version: u(0) = p(0) ∧ q(0) as printed; the printed u(0) ∧ e_y, u(0) ∧ e_z, u(0) ∧ e_x, "
             "u(0) ∧ p(0) = q(0); e_x ∧ u(0) ∝ p(0); the two trilinear formulas for ũ(1) with the convention e_t·u ≥ 0.",
             printed=dict(p0=CONTACT_P0["a"], q0=CONTACT_Q0["a"], u0=U0, ey_dot_u0=EY_DOT_U0, orientation=ORIENTATION,
                          u0_wedge_ey=U0_WEDGE["ey"], u0_wedge_ez=U0_WEDGE["ez"], u0_wedge_ex=U0_WEDGE["ex"],
                          u0_wedge_p0=U0_WEDGE["p0"], trilinear_b=TRILINEAR_B, trilinear_c=TRILINEAR_C),
             expect=ERRATUM,
             mutants=[replaced("u0", "-cos(θ)*sin(φ)", "cos(θ)*sin(φ)", "a sign of u(0)"),
                      overridden({"orientation": "a: y, b: x, c: z"}, "another orientation convention")])
def vectorial_version(p0, q0, u0, ey_dot_u0, orientation, u0_wedge_ey, u0_wedge_ez, u0_wedge_ex, u0_wedge_p0,
                      trilinear_b, trilinear_c):
    """Cross products as identities; orientations as positive ratios; a wrong plane by a rational witness."""
    p0, q0, u0 = vec(p0), vec(q0), vec(u0)
    pos, neg, H = T.hypotheses(1), T.hypotheses(-1), T.hypotheses()
    p1b, p1c = hit_point(p0, q0, 1), hit_point(p0, q0, 2)
    Wy, Wz, Wx, Wp = (vec(x) for x in (u0_wedge_ey, u0_wedge_ez, u0_wedge_ex, u0_wedge_p0))
    axes = orientation_axes(orientation)
    ey_u = T.parse(ey_dot_u0)
    checks = [
        identity("l. 943-947: p(0) ∧ q(0) is the printed u(0)", p0.cross(q0), u0),
        combined(f"l. 949: e_y·u(0) = `{ey_dot_u0}` ≥ 0, and e_t·u(0) ≥ 0 with the printed convention t = ({orientation})",
                 [T.equal(T.E_Y.dot(u0), ey_u), T.has_sign(ey_u, 1, H), T.has_sign(axes["a"].dot(u0), 1, H)]),
        combined("l. 958-960: u(0) ∧ e_y is the printed vector, a positive multiple of p(1) when the next collision is b",
                 [T.equal(u0.cross(T.E_Y), Wy), T.positively_proportional(Wy, p1b, pos)]),
        combined("l. 962-963: u(0) ∧ e_z is the printed vector, a positive multiple of p(1) when the next collision is c",
                 [T.equal(u0.cross(T.E_Z), Wz), T.positively_proportional(Wz, p1c, neg)]),
        combined("l. 967-969: u(0) ∧ e_x is the printed vector, of orientation opposite to p(0); e_x ∧ u(0) ∝ p(0) > 0",
                 [T.equal(u0.cross(T.E_X), Wx), T.positively_proportional(-Wx, p0, H),
                  T.positively_proportional(T.E_X.cross(u0), p0, H)]),
        combined("l. 971: u(0) ∧ p(0) is the printed vector, which is q(0)", [T.equal(u0.cross(p0), Wp), T.equal(Wp, q0)]),
        trilinear(trilinear_b, "B", u0, p1b, q0, pos, axes["b"], "1/2"),
    ]
    printed_c = trilinear(trilinear_c, "C", u0, p1c, q0, neg, axes["c"], "2")
    fixed_c = statements.corrected(trilinear_c, *TRILINEAR_C_CORRECTION)
    corrected_c = (trilinear(fixed_c, "C", u0, p1c, q0, neg, axes["c"], "2") if fixed_c else
                   Check(f"the stated correction `{TRILINEAR_C_CORRECTION[0]}` → `{TRILINEAR_C_CORRECTION[1]}` "
                         f"applies to the printed `{trilinear_c}`", False))
    return concluded(checks + [printed_c], checks + [corrected_c], kind=MISPRINT, misprint=E_Y_FOR_E_Z,
                    note="Contacts: the paper writes k = 1, 2, 3 for the contacts a, b, c in the orientation convention "
                         "(l. 949), where k also indexes the collisions.  For a collision c, p(1) ∝ u(0) ∧ e_z "
                         "(l. 962), so the factor [u(0) ∧ e_y] of l. 980 must be [u(0) ∧ e_z].")


# ================================================================ S9.1
FRAME_AXIS = {"a": T.E_X, "c": T.E_Z}          # e_θ = e_axis ∧ p for the printed frames of contacts a and c
SIGN_C = "sin(φ)*cos(φ)*(cos(θ)^2 + (1+r)/2*sin(θ)*cos(θ))"     # (p(k+1) ∧ C q(k))_z, ours
SIGN_A = "sin(φ)*cos(φ)*(sin(θ)^2 + (1+r)/2*sin(θ)*cos(θ))"     # (p(k+1) ∧ A q(k))_x, ours


def frame_lemma(contact: str, p0_text: str, q0_text: str) -> Check:
    """In the frame of ``contact``, q(0) = cos φ e_θ + sin φ e_axis with e_θ = e_axis ∧ p(0), and
    every representative q' = q(0) + μ p(0) of the velocity in the plane has q'·e_θ = cos φ."""
    mu = sp.Symbol("μ")
    p0, q0, axis = vec(p0_text), vec(q0_text), FRAME_AXIS[contact]
    e_theta = axis.cross(p0)
    res = T.equal(sp.Matrix.vstack(q0, sp.Matrix([(q0 + mu * p0).dot(e_theta)])),
                  sp.Matrix.vstack(cφ * e_theta + sφ * axis, sp.Matrix([cφ])))
    return Check(f"contact {contact}: e_θ = e_{'x' if contact == 'a' else 'z'} ∧ p(0), q(0) = cos φ e_θ + sin φ "
                 "e_axis, and (q(0) + μ p(0))·e_θ = cos φ for every μ: cos φ' is read on any representative",
                 res.holds, res.evidence)


def next_angle_sign(contact: str, letter: str, cos_phi: int, axis_index: int, formula: str) -> list[Check]:
    """After ``contact`` then ``letter`` (cos φ of sign ``cos_phi``): with P the printed-form
    hit point and K q(k) the velocity after the collision, sign(cos φ') = sign((P ∧ K q(k))_axis)
    (as K q(k)·e_θ' = (P ∧ K q(k))_axis / |P|); the factored formula and its sign."""
    H = T.hypotheses(cos_phi)
    p0, q0 = vec(CONTACT_P0[contact]), vec(CONTACT_Q0[contact])
    k, ev = next_gap(contact, p0, q0, H)
    P = hit_point(p0, q0, k)
    Kq = SECTION2[letter] * q0
    axis = FRAME_AXIS[LETTERS[k]]
    s = T.parse(formula)
    triple = T.equal(Kq.dot(axis.cross(P)), P.cross(Kq)[axis_index])
    value = T.positively_proportional(P.cross(Kq)[axis_index] * sp.ones(1, 1), s * sp.ones(1, 1), H)
    sign = T.has_sign(s, cos_phi, H)
    return [Check(f"{contact} then {LETTERS[k]} ({RANGE[cos_phi]}): the collision is {letter.lower()}", LETTERS[k] == letter.lower(), ev),
            combined(f"K q(k)·(e_axis ∧ p(k+1)) = (p(k+1) ∧ K q(k))_axis, a positive multiple of `{formula}`, which is "
                     f"{'>' if cos_phi > 0 else '<'} 0: cos φ' {'>' if cos_phi > 0 else '<'} 0", [triple, value, sign])]


@certificate("S9.1", "l. 997-1035",
             "Proposition 4.4: no aca and no cac, by the printed argument: after a then c, q(k+1) ∝ Cq(k) - "
             "(Cq(k)·p(k))p(k) as printed, whose first component sin φ > 0 gives cos φ' < 0, so the next collision is b.",
             printed=dict(p_k=CONTACT_P0["a"], q_k=CONTACT_Q0["a"], p_next=P_NEXT_AC, q_next=Q_NEXT_AC,
                          C_times_qk=C_TIMES_QK, projection=PROJECTION_CHAIN, form_c=FORM_C,
                          read_component=READ_COMPONENT, conclusion=CONCLUSION),
             expect=ERRATUM,
             mutants=[replaced("projection", "+ (1+r)*cos(θ)^2*sin(θ)", "+ (1-r)*cos(θ)^2*sin(θ)", "a sign in the projection"),
                      overridden({"conclusion": "cos(φ') > 0"}, "the conclusion reversed"),
                      reworded("conclusion", "cos(φ')", "sin(φ')", "sin φ' > 0 by definition"),
                      reworded("conclusion", "<", ">"),
                      reworded("conclusion", "<", "≥"),
                      unread("conclusion", "cos(φ'') < 0", "an unknown name")])
def no_aca_no_cac(p_k, q_k, p_next, q_next, C_times_qk, projection, form_c, read_component, conclusion):
    """The printed algebra as printed; whether its vector is q(k+1); the corrected argument.
    The printed conclusion (cos φ' < 0) is read and evaluated on the certified signs of
    cos φ' (< 0, by the sign of (p(k+1) ∧ C q(k))_z) and sin φ' (> 0, φ' ∈ ]0,π[)."""
    pk, qk, Pn = vec(p_k), vec(q_k), vec(p_next)
    neg = T.hypotheses(-1)
    C = SECTION2["C"]
    M, seen = recording_matrices()
    CQ, PR = T.chain(C_times_qk, M=M), T.chain(projection)
    w = T.parse(q_next, Cq=C * qk, pk=pk)
    n = Pn.cross(C * qk)                                   # normal of P(k+1) = Span(p(k+1), C q(k))
    j = int(read_component) - 1
    algebra = [identity("l. 1020: C q(k) (C of Section 2) is member 1", C * qk, CQ[0])] + links("C q(k)", CQ, "1020") + [
        matrices_are("c", seen, "1020"),
        identity("l. 1016, 1024: the printed Cq(k) - (Cq(k)·p(k))p(k) is member 1 of l. 1024-1031", w, PR[0]),
        *links("the projection", PR, "1024-1031"),
        result_check("l. 1012: p(k+1) ∝ the printed (sinθ sinφ, -cosφ, 0), a positive multiple of the hit point",
                     T.positively_proportional(hit_point(pk, qk, 2), Pn, neg)),
        identity(f"l. 1033: component {j + 1} of the printed vector is sin φ, and component {j + 1} of the form "
                 f"`{form_c}` of q(k+1) is -sinθ' cosφ' (frame of contact c)", sp.Matrix([w[j], vec(form_c)[j]]),
                 sp.Matrix([sφ, -sθ * cφ]))]
    in_plane = [T.is_zero(w.dot(Pn)), T.is_zero(w.dot(n))]
    pt = T.point("1/2", "2", r="1/3")
    vector_claim = Check("l. 1014-1016: q(k+1) is a positive multiple of the printed Cq(k) - (Cq(k)·p(k))p(k): it should "
                         "be orthogonal to p(k+1) and lie in P(k+1)", all(in_plane),
                         [f"·p(k+1): {'; '.join(in_plane[0].evidence)}", f"·(p(k+1) ∧ Cq(k)): {'; '.join(in_plane[1].evidence)}",
                          f"at cos θ = {pt[cθ]}, cos φ = {pt[cφ]}, r = 1/3: ·p(k+1) = {T.at(w.dot(Pn), pt)}, "
                          f"·(p(k+1) ∧ Cq(k)) = {T.at(w.dot(n), pt)}"])
    w_true = C * qk - (C * qk).dot(Pn) / Pn.dot(Pn) * Pn
    true_first = T.has_sign(w_true[0], 1, neg)
    aca = next_angle_sign("a", "C", -1, 2, SIGN_C)
    cac = next_angle_sign("c", "A", 1, 0, SIGN_A)
    then_b = [Check(f"after a contact {c} with cos φ' {'<' if s < 0 else '>'} 0 the next collision is b",
                    next_gap(c, vec(CONTACT_P0[c]), vec(CONTACT_Q0[c]), T.hypotheses(s))[0] == INDEX["b"])
              for c, s in (("c", -1), ("a", 1))]
    # certified: cos φ' < 0 (aca[1]) and sin φ' > 0 (φ' ∈ ]0,π[ by definition); the printed conclusion read on them
    read = statements.relation(conclusion, {"cos(φ')": COS_NEXT, "sin(φ')": SIN_NEXT}).holds({COS_NEXT: -1, SIN_NEXT: 1})
    concl = Check(f"l. 1033-1034: {conclusion}, so c_(k+2) = b (no aca)", aca[1].holds and read and then_b[0].holds,
                  aca[1].evidence)
    projection = combined("corrected: q(k+1) ∝ Cq(k) - (Cq(k)·p(k+1))p(k+1)/|p(k+1)|², the projection on p(k+1)^⊥: "
                          "orthogonal to p(k+1), in P(k+1)", [T.is_zero(w_true.dot(Pn)), T.is_zero(w_true.dot(n))])
    projection.corrects = vector_claim
    corrected = algebra + [
        projection,
        frame_lemma("c", CONTACT_P0["c"], CONTACT_Q0["c"]),
        *aca, then_b[0], concl,
        result_check("its first component is > 0 as well (the printed reading of the sign gives the right answer for "
                     "the right vector)", true_first),
        frame_lemma("a", CONTACT_P0["a"], CONTACT_Q0["a"]),
        *cac, then_b[1],
        Check("no cac: after c then a, cos φ' > 0 and the next collision is b", all(cac) and then_b[1].holds)]
    return concluded(algebra + [vector_claim, concl], corrected, kind=FALSE_STATEMENT,
                     misprint="l. 1014-1016: q(k+1) projected on p(k)^⊥, not p(k+1)^⊥ (a step of the proof of "
                              "Proposition 4.4; the proposition holds)",
                    note="The printed proof projects C q(k) on p(k)^⊥ instead of p(k+1)^⊥; the proposition holds, "
                         "by the sign of (p(k+1) ∧ C q(k))_z read on any representative of the velocity.  The cac case "
                         "is done directly (the paper: 'by symmetry').")
