"""Section 4 on the dynamics (l. 839-1051): the spherical reduction against the
particle system, Proposition 4.4, Corollary 4.5 and Remark 4.2.

The particle system is :mod:`certify.dynamics.simulate` in exact rationals (fmpq); the
reduction map is :mod:`certify.dynamics.reduction` in its three representations: projective
(exact normals in Z^3), vectorial (the printed trilinear formula, exact) and
trigonometric (the printed six cases, certified balls).  The identities of the
printed proofs are certified in ``proofs/reduction_identities.py``.

Every claim here is about every trajectory, and every verdict rests on a proof for
every state: the step lemma of the map and the particle lemma on the six cones of
states (``proofs/reduction_cones.py``), identities and signs in symbolic n, r (and θ,
φ for the six printed cases).  The exact runs and the scan of 10^5 collisions are
reported as supporting evidence, never as a check.

Random data are drawn from a fixed seed, so the report is reproducible.  A datum is
a state right after a collision: the contact letter i, p with p_i = 0 and the other
gaps positive, q with q_i > 0 (the pair separates), and a second datum
(α p, β q + γ p) spanning the same plane (α, β > 0, γ of any sign).
"""
from __future__ import annotations

import random
from dataclasses import dataclass

import flint
import sympy as sp

from certify.algebra import trig as T
from certify.algebra import Q, precision, r, show, statements
from certify.dynamics import reduction as R
from certify.dynamics import simulate as sim
from certify.dynamics import INDEX, LETTERS
from certify.run import (ERRATUM, FALSE_STATEMENT, MISPRINT, PASS, Check, certificate, conclude, overridden,
                        quantity, replaced, reworded, unread)
from proofs import reduction_cones as RC
from proofs import reduction_identities as I
from proofs.model import A_PRINTED, B_PRINTED, C_PRINTED, matrix

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
    runs: tuple          # (run from (p, q), run from (αp, βq + γp))
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
    runs = (sim.follow(p, q, r, N_COLLISIONS), sim.follow(p2, q2, r, N_COLLISIONS))
    contacts = [letter] + runs[0].events
    normals = [R.normal(s.p, s.q) for s in runs[0].states]
    planes = ([R.canonical(L, n) for L, n in zip(contacts, normals)],
              [R.plane(letter, p2, q2)] + [R.plane(e, s.p, s.q) for e, s in zip(runs[1].events, runs[1].states[1:])])
    return Datum(r, letter, runs, normals, planes, R.orbit(planes[0][0], r, N_REDUCTION))


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
    rows = ["| collisions | bits of p, q (physical, exact) | bits of t | bits of the normal n (projective) |",
            "|---:|---:|---:|---:|"]
    for k in (1, 10, 50, 100, 200):
        s = d.runs[0].states[k]
        rows.append(f"| {k} | {max(bits(z) for z in s.p + s.q)} | {bits(s.t)} | {d.orbit[k].bits} |")
    return [f"Growth of the exact numbers along one run (r = {d.r}):", "\n".join(rows)]


# ---------------------------------------------------------------- the proofs on cones (S6-S11)
SECTION2 = {L: I.SECTION2[L.upper()] for L in LETTERS}


@quantity("reduction_cones")
def reduction_cones() -> dict:
    """The step lemma of the reduction on the six cones of states (contact, sign of cos φ),
    with the collision matrices of Section 2 (proofs/reduction_cones.py)."""
    return RC.steps(SECTION2)


def printed_cones(cones: dict, A: str, B: str, C: str) -> dict:
    """The step lemmas with the printed matrices A, B, C: the shared ones when these are
    the matrices of Section 2, else computed afresh (a mutated print)."""
    K = {L: matrix(text) for L, text in zip(LETTERS, (A, B, C))}
    return cones if all(K[L] == SECTION2[L] for L in LETTERS) else RC.steps(K)


def lemma_check(s: RC.Step) -> Check:
    """The step lemma on one cone as one check; its parts as evidence (✓/✗)."""
    nxt = (f"the next collision is {s.following}; the next state lies in a cone of {s.following}, with "
           f"cos φ' {RC.SIGN[s.cos_next]}") if s.following else "no next collision proven"
    ev = [f"{'✓' if c.holds else '✗'} {c.statement}" for c in s.checks]
    ev += [e for c in s.checks if not c.holds for e in c.evidence]
    return Check(f"step lemma on the cone {s.label} (every state there, exact): {nxt}", s.holds, ev)


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


@certificate("S6", "l. 839-868",
             "Theorem 4.1: two trajectories with the same contact and Span(p(0),q(0)) = Span(p'(0),q'(0)) have "
             "the same plane Span(p(k),q(k)) at every collision k (and so the same collision types).",
             needs=["section4_data", "reduction_cones"], printed=dict(A=A_PRINTED, B=B_PRINTED, C=C_PRINTED),
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
    next depends on the plane only: on the six cones of states (proofs/reduction_cones.py)
    the particles, whatever the radial part of their velocity, collide next at the map's
    j or never.  By induction, two trajectories on one plane have the same collisions
    while both last, and the same planes.  The exact runs of two data per plane, compared
    collision by collision with each other and with the projective map, are supporting
    evidence."""
    checks, rates = [], sorted({d.r for d in section4_data} | {Q(1, 3)})
    for letter, text in zip(LETTERS, (A, B, C)):
        K, j = matrix(text), INDEX[letter]
        fixed = all((K * sp.eye(3).col(m) - sp.eye(3).col(m)).applyfunc(sp.expand) == sp.zeros(3, 1)
                    for m in range(3) if m != j)
        cof = K.adjugate().T                     # cof(K)(a ∧ b) = Ka ∧ Kb for every K
        engine = sp.Matrix.hstack(*(sp.Matrix(col) for col in R.cofactor_columns(letter, r)))
        same = all(sp.cancel(e) == 0 for e in engine - cof)                 # as matrices over Q(r)
        scaled = [multiple(R.cofactor(letter, r0), cof.subs(r, sp.Rational(int(r0.p), int(r0.q)))) for r0 in rates]
        checks.append(Check(f"{letter.upper()} fixes {{x_{j + 1} = 0}} pointwise, so the plane after a collision "
                            f"{letter} is {letter.upper()}·P, with normal cof({letter.upper()}) n; the projective map "
                            f"moves normals by this cof({letter.upper()}): the engine's cof({letter.upper()}) equals "
                            "it as a matrix over Q(r), and the integer matrix it steps with at each r of the runs is a "
                            "positive multiple of it there", fixed and same and all(k is not None for k in scaled),
                            [f"cof({letter.upper()}) = det·{letter.upper()}^(-T) = `{show(cof.applyfunc(sp.factor).tolist())}`",
                             f"engine − printed over Q(r): {'0' if same else show((engine - cof).applyfunc(sp.factor).tolist())}; "
                             f"integer multiples at {len(rates)} values of r: "
                             f"{sum(k is not None for k in scaled)} positive"]))
    cones = printed_cones(reduction_cones, A, B, C)
    checks.append(Check("the next collision depends on the contact and the plane only: on each of the six cones of "
                        "states, whatever the radial part of the velocity, the particles collide next at the map's "
                        "contact j or never, and then span the plane with normal cof(K_j) n (the step and particle "
                        "lemmas with the printed A, B, C); by induction, two trajectories on one plane have the same "
                        "collision types while both last", RC.dynamics_is_proven(cones),
                        [f"{'✓' if c.motion.holds else '✗'} {c.label}: next {c.following}"
                         for c in cones.values()]))
    compared = same = 0
    for d in section4_data:
        (run1, run2), k = d.runs, d.realised
        for P1, P2, P in zip(d.planes[0][1:k + 1], d.planes[1][1:k + 1], d.orbit[1:k + 1]):
            compared += 1
            same += P1 == P2 == P
    reached = sum(d.realised >= N_COLLISIONS for d in section4_data)
    evidence = [supporting(f"on {len(section4_data)} random rational data (two per plane, exact runs of up to "
                           f"{N_COLLISIONS} collisions) the two runs have the same collision type and the same plane "
                           f"as the projective map at {same} of {compared} collisions compared; {reached} data kept "
                           f"colliding for {N_COLLISIONS} collisions on both runs, the others separated earlier.")]
    return conclude(checks, evidence=evidence + growth(section4_data))


# ---------------------------------------------------------------- S7.2
# The six printed cases (l. 881-929), transcribed once in proofs/reduction_identities.py (S7.1).
PRINTED_S7 = {**{f"p0_{c}": I.CONTACT_P0[c] for c in LETTERS}, **{f"q0_{c}": I.CONTACT_Q0[c] for c in LETTERS},
              **{key: I.SIX_CASES[f"{c}, {I.RANGE[s]}"] for key, (c, s) in I.CASE_KEYS.items()}}


def engine_is_printed(printed: dict) -> list[Check]:
    """The engine's six cases (certify.dynamics.reduction.P0, Q0, CASES) are the printed ones:
    the same p(0), q(0), next pair and p(t1), as polynomials in cos, sin of θ, φ."""
    args = (T.cθ, T.sθ, T.cφ, T.sφ)
    checks = []
    for c in LETTERS:
        ok = (T.vector(printed[f"p0_{c}"]) == sp.Matrix(R.P0[c](*args[:2])) and
              (T.vector(printed[f"q0_{c}"]) - sp.Matrix(R.Q0[c](*args))).applyfunc(sp.expand) == sp.zeros(3, 1))
        for key, (c2, s) in I.CASE_KEYS.items():
            if c2 != c:
                continue
            pair, _K, vec, _radicand = (x.strip() for x in printed[key].split("|"))
            j, p1 = R.CASES[(c, s)]
            ok = ok and I.PAIR.get(pair) == j and \
                (T.vector(vec) - sp.Matrix(p1(*args))).applyfunc(sp.expand) == sp.zeros(3, 1)
        checks.append(Check(f"contact {c}: the map steps with the printed p(0), q(0), next pair and p(t1)", ok,
                            [f"`{printed[k]}`" for k in (f"p0_{c}", f"q0_{c}", f"{c}_pos", f"{c}_neg")]))
    return checks


def trig_agrees(P: R.Plane, P1: R.Plane, r, prec: int = 128, last: list | None = None) -> bool:
    """The trigonometric step from (θ, φ) of the physical state P gives the contact of
    the next physical state P1 and balls of cos, sin of θ, φ overlapping P1's.  (θ, φ
    are functions of the contact and the plane: p ∝ n ∧ e_i, q̂ ∝ |n|² e_i − n_i n.)
    ``last``: [state, its angles at ``prec``] from the previous call along the orbit,
    where P1 was this call's P (each state ends one step and starts the next), or
    [None, None]; updated here."""
    last = [None, None] if last is None else last

    def angles(Q: R.Plane) -> R.Angles:
        if last[0] is not Q:
            last[1], last[0] = R.angles(Q), Q
        return last[1]
    with precision(prec):
        T, X = R.trig_step(angles(P), r), angles(P1)
    return T.letter == P1.letter and all(a.overlaps(b) for a, b in
                                         ((T.ct, X.ct), (T.st, X.st), (T.cp, X.cp), (T.sp, X.sp)))


def case_is_the_map(key: str, spec: str, p0, q0) -> Check:
    """One printed case (contact i, sign of cos φ) for every θ ∈ ]0,π/2[ and φ in its range:
    the printed step of S7.1 (next pair = the gap the ray closes, p(t1) its hit point in
    the open face, q(t1) ⊥ p(t1) with q_j(t1) > 0), and it is the projective map's step:
    with u = p(0) ∧ q(0), u_i u_j > 0 (the map's rule for the next contact j) and
    p(t1) ∧ K q(0), the normal of Span(p(t1), q(t1)), is a positive multiple of cof(K) u.
    The same contact and plane give the same θ', φ' (p(t1) is the position in the open
    face, q(t1) the unit tangent with q_j > 0)."""
    contact, s = I.CASE_KEYS[key]
    label = f"contact {contact}, {I.RANGE[s]}"
    steps = I.six_case(key, spec, p0, q0, I.Q_T1)
    pair, letter, V_text, _radicand = (x.strip() for x in spec.split("|"))
    j = I.PAIR.get(pair)
    if j is None or letter not in I.SECTION2 or not all(c.holds for c in steps):
        return Check(f"{label}: the printed step (as in S7.1)", False,
                     [f"{'✓' if c.holds else '✗'} {c.statement}" for c in steps])
    H, K, i = T.hypotheses(s), I.SECTION2[letter], INDEX[contact]
    u0 = p0.cross(q0)
    rule = T.has_sign(u0[i] * u0[INDEX[j]], 1, H)
    plane = T.positively_proportional(I.vec(V_text).cross(K * q0), K.adjugate().T * u0, H)
    return Check(f"{label}: the printed step (S7.1) is the projective map's step for every θ, φ in the case: the "
                 f"next contact {j} (u_{i + 1} u_{INDEX[j] + 1} > 0, u = p(0) ∧ q(0)) and the plane, p(t1) ∧ "
                 f"{letter}q(0) being a positive multiple of cof({letter}) u", rule.holds and plane.holds,
                 [f"✓ {c.statement}" for c in steps] + [f"u = `{T.show(u0)}`"] + rule.evidence + plane.evidence)


@certificate("S7.2", "l. 877-929",
             "The trigonometric reduction (the six printed cases) reproduces the next collision of the particle "
             "system: same contact, same θ and φ, at every collision.",
             needs=["section4_data", "reduction_cones"], printed=PRINTED_S7,
             expect=PASS,
             mutants=[replaced("a_pos", "2-3", "3-4", "another pair for a, cos φ > 0"),
                      replaced("c_neg", "sin(θ)*sin(φ)", "cos(θ)*sin(φ)", "a factor of the c, cos φ < 0 case"),
                      replaced("q0_b", "-sin(θ)*cos(φ)", "sin(θ)*cos(φ)", "a sign of q(0) for contact b")])
def trigonometric_map_agrees_with_dynamics(section4_data, reduction_cones, **printed):
    """For every collision: each printed case is, for every θ, φ in its range, the step of
    the projective map (:func:`case_is_the_map`), and the particles follow the projective
    map (the step and particle lemmas on the six cones, proofs/reduction_cones.py).  The
    engine's trigonometric map is the printed one.  Supporting evidence: at each collision
    of the exact runs, one step of the six cases from θ, φ of the exact state as certified
    balls (128 bits) against θ, φ of the exact state k+1."""
    checks = engine_is_printed(printed)
    frames = {c: (T.vector(printed[f"p0_{c}"]), T.vector(printed[f"q0_{c}"])) for c in LETTERS}
    checks += [case_is_the_map(key, printed[key], *frames[c]) for key, (c, _s) in I.CASE_KEYS.items()]
    checks.append(Check("the particles follow the projective map: on each of the six cones of states they collide "
                        "next at its contact, or never, and then span its plane (step and particle lemmas, S11)",
                        RC.dynamics_is_proven(reduction_cones)))
    compared = agree = undecided = 0
    if all(c.holds for c in checks[:3]):
        for d in section4_data:
            last = [None, None]
            for P, P1 in zip(d.planes[0], d.planes[0][1:]):
                compared += 1
                try:
                    agree += trig_agrees(P, P1, d.r, last=last)
                except sim.Undecided:
                    undecided += 1
    evidence = [supporting(f"at {compared} collisions of {len(section4_data)} exact runs the six cases give the next "
                           f"contact and (θ, φ) (balls overlapping): {agree} agree, {undecided} undecided.")]
    return conclude(checks, evidence=evidence)


# ---------------------------------------------------------------- S8.2
# transcribed once in proofs/reduction_identities.py (S8.1)
PRINTED_S8 = dict(orientation=I.ORIENTATION, to_b=I.TRILINEAR_B, to_c=I.TRILINEAR_C)


def trilinear_on_cone(text: str | None, st: RC.Step) -> T.Result:
    """The formula ``text`` (the relabelled one when None) at u = n is a positive multiple
    of the next normal n' = p' ∧ K_j w of the cone's step, for every state of the cone."""
    u = tuple(RC.N)
    ut = R.formula(text)(u, r) if text else R.trilinear(st.contact, st.following, u, r)
    return T.positively_proportional(sp.Matrix(ut), st.normal, st.H)


def not_normal_at(text: str, st: RC.Step) -> tuple[bool, str]:
    """An exact state of the cone (integer normal, r = 1/3) where the formula is not
    parallel to the next normal: a counterexample."""
    n = RC.representative(st)
    at = {**dict(zip(RC.N, n)), r: sp.Rational(1, 3)}
    ut = sp.Matrix(R.formula(text)(n, sp.Rational(1, 3)))
    n1 = st.normal.xreplace(at)
    wedge = ut.cross(n1)
    return (not wedge.is_zero_matrix, f"at n = {n} (a state of the cone {st.label}), r = 1/3: ũ(1) = "
                                      f"{T.show(ut)}, the next normal {T.show(n1)}, their cross product {T.show(wedge)}")


@certificate("S8.2", "l. 931-987",
             "The vectorial reduction reproduces the next collision of the particle system: u(0) = p(0) ∧ q(0), "
             "the printed trilinear formulas give u(1) ∝ p(1) ∧ q(1), with e_t · u(k) ≥ 0.",
             needs=["section4_data", "reduction_cones"], printed=PRINTED_S8,
             expect=ERRATUM,
             mutants=[replaced("to_b", "ey", "ez", "another axis in the b formula"),
                      replaced("orientation", "a: y", "a: z", "another orientation for a"),
                      replaced("to_b", "cross(ex, u0)", "cross(u0, ex)", "the cross product reversed")])
def vectorial_map_agrees_with_dynamics(section4_data, reduction_cones, orientation, to_b, to_c):
    """For every state, on the six cones of states (proofs/reduction_cones.py): right
    after a collision, p ∧ q = α p ∧ w = αρ n (α, ρ > 0), so the orientation holds when
    n_t > 0 on every cone; the trilinear formula at u = n is a positive multiple of the
    next normal n' = p' ∧ K_j w, which is p(1) ∧ q(1) up to a positive factor whatever
    the radial part (the particle lemma).  The printed formulas are for the contact a;
    the other contacts use the relabelled formula (:func:`certify.dynamics.reduction.trilinear`,
    "in a similar manner", l. 987).  A printed formula that fails is refuted at an exact
    state of its cone.  The exact runs are supporting evidence."""
    axes = {c: [k for k in range(3) if e[k]][0] for c, e in I.orientation_axes(orientation).items()}
    cones = reduction_cones
    lemmas = RC.dynamics_is_proven(cones)
    orient = [T.has_sign(RC.N[axes[c]], 1, st.H) for (c, _s), st in cones.items()]
    a_b, a_c = cones[("a", 1)], cones[("a", -1)]
    on_b, on_c = trilinear_on_cone(to_b, a_b), trilinear_on_cone(to_c, a_c)
    relabelled = [trilinear_on_cone(None, st) for st in cones.values()]
    premise = "; with the step and particle lemmas on the six cones (S11)"
    printed = [Check(f"u(k) = p(k) ∧ q(k) = αρ n satisfies the orientation e_t · u(k) > 0 (t = {orientation}) on every "
                     "cone of states", lemmas and all(orient), [e for o in orient for e in o.evidence[:1]]),
               Check(f"contact a, next b: `{to_b}` ∝ p(1) ∧ q(1), positively, for every state{premise}",
                     lemmas and a_b.following == "b" and on_b.holds, on_b.evidence),
               Check(f"contact a, next c: `{to_c}` ∝ p(1) ∧ q(1), positively, for every state{premise}",
                     lemmas and a_c.following == "c" and on_c.holds,
                     on_c.evidence + ([] if on_c.holds else [not_normal_at(to_c, a_c)[1]])),
               Check(f"every contact: the relabelled formula [u ∧ e_j] ∧ [K_j(u ∧ [e_i ∧ u])] ∝ p(1) ∧ q(1), "
                     f"positively, for every state{premise}", lemmas and all(relabelled),
                     [e for x in relabelled for e in x.evidence[:1]])]
    corrected = []
    fixed = statements.corrected(to_c, *I.TRILINEAR_C_CORRECTION)     # the correction stated once, for S8.1 too
    if not printed[2].holds and fixed:
        on_fixed = trilinear_on_cone(fixed, a_c)
        refuted, witness = not_normal_at(to_c, a_c)
        corrected = [printed[0], printed[1],
                     Check(f"contact a, next c, with p(1) ∝ u(0) ∧ e_z (as in l. 962): `{fixed}` ∝ p(1) ∧ q(1), "
                           f"positively, for every state{premise}; the printed one is refuted at an exact state",
                           lemmas and a_c.following == "c" and on_fixed.holds and refuted,
                           on_fixed.evidence + [witness], corrects=printed[2]), printed[3]]
    evidence = [supporting(tally_runs(section4_data, orientation, to_b, to_c))]
    return conclude(printed, corrected, evidence=evidence, kind=MISPRINT, misprint=I.E_Y_FOR_E_Z)


def tally_runs(section4_data, orientation, to_b, to_c) -> str:
    """At each collision k of the exact runs: ũ(k+1) from u(k) = p(k) ∧ q(k) against
    p(k+1) ∧ q(k+1), and the orientation of u(k)."""
    t = {c: [k for k in range(3) if e[k]][0] for c, e in I.orientation_axes(orientation).items()}
    formulas = {"b": R.formula(to_b), "c": R.formula(to_c)}
    tally = {"a→b": [0, 0], "a→c": [0, 0], "relabelled": [0, 0]}
    oriented = [0, 0]
    for d in section4_data:
        contacts = [d.letter] + d.runs[0].events
        for L, L1, u, u1 in zip(contacts, contacts[1:], d.normals, d.normals[1:]):
            oriented[0] += 1
            oriented[1] += u[t[L]] > 0
            key = f"a→{L1}" if L == "a" else "relabelled"
            ut = formulas[L1](u, d.r) if L == "a" else R.vectorial_step(L, u, d.r)[1]
            tally[key][0] += 1
            tally[key][1] += R.cross(ut, u1) == (0, 0, 0) and R.dot(ut, u1) > 0
    return (f"on the exact runs, the orientation holds at {oriented[1]} of {oriented[0]} states, and the printed or "
            "relabelled formula gives a positive multiple of p(k+1) ∧ q(k+1) at " +
            ", ".join(f"{v[1]} of {v[0]} collisions {k}" for k, v in tally.items()) + ".")


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
    """Occurrences of ``pattern`` as consecutive collisions (overlaps counted)."""
    return sum(sum(w.startswith(pattern, k) for k in range(len(w))) for w in words)


# ---------------------------------------------------------------- S9.2
PRINTED_S9 = dict(aca="c_k = a, c_{k+1} = c ⇒ c_{k+2} ≠ a", cac="c_k = c, c_{k+1} = a ⇒ c_{k+2} ≠ c")


def implication(text: str) -> tuple[str, str]:
    """"c_k = a, c_{k+1} = c ⇒ c_{k+2} ≠ a" as (the pair "ac", the excluded letter "a"),
    read whole (statements.word_rule): a rule of another shape (other offsets, = for ≠,
    more premises) is not what this certificate counts, and is a StatementError."""
    rule = statements.word_rule(text)
    premises, conclusions = rule.premises, rule.conclusions
    if [(o, eq) for o, _, eq in premises] != [(0, True), (1, True)] or \
            [(o, eq) for o, _, eq in conclusions] != [(2, False)]:
        raise statements.StatementError(f"cannot evaluate {text!r}: S9.2 counts the rules c_k = x, c_{{k+1}} = y "
                                        "⇒ c_{k+2} ≠ z")
    (_, x, _), (_, y, _) = premises
    return x + y, conclusions[0][1]


@certificate("S9.2", "l. 997-1035",
             "Proposition 4.4 for every orbit of the reduction map, in its projective form: after a then c (c then a), "
             "on the whole cone of such states the next normal n' = cof(C) n (cof(A) n) has signs that exclude a (c) "
             "as the next collision.  Supported by no aca, no cac in 10^5 collisions of exact orbits and in the exact "
             "particle runs.",
             needs=["reduction_cones", "reduction_scan", "section4_data"], printed=PRINTED_S9,
             expect=PASS,
             mutants=[replaced("aca", "c_{k+1} = c", "c_{k+1} = b", "after ab both a and c may come"),
                      replaced("aca", "≠ a", "≠ b", "after ac the next is b"),
                      replaced("cac", "c_k = c", "c_k = b", "after ba both b and c may come"),
                      reworded("aca", "c_{k+2}", "c_{k+3}", "false (acba… occurs); the index was not read"),
                      reworded("cac", "≠", "="),
                      unread("aca", "c_k = a, c_{k+1} = c ⇒ c_{k+2} ≠ d", "not a letter")])
def no_aca_cac_for_every_orbit(reduction_cones, reduction_scan, section4_data, aca, cac):
    """A proof independent of S9.1's (which is in θ, φ): the states right after a
    collision x whose next collision is y form one cone (contact x, sign of n_x); on it
    the step lemma gives the next normal n' ∝ p' ∧ K_y w = ρ cof(K_y) n, and the collision
    after y is the gap m ≠ y with n'_y n'_m > 0.  So z cannot follow when n'_y n'_z < 0 is
    proven from the factors on the whole cone.  The counts on the exact orbits are
    supporting evidence."""
    scan = [o.word for o in reduction_scan]
    physical = [run.word for d in section4_data for run in d.runs]
    checks, evidence = [], []
    for text in (aca, cac):
        pair, excluded = implication(text)
        x, y = (pair + "??")[:2]
        cases = [c for c in reduction_cones.values() if c.contact == x and c.following == y]
        pattern = pair + excluded
        if len(cases) != 1:
            checks.append(Check(f"{text}: no state of contact {x} has the next collision {y}", False))
            continue
        c = cases[0]
        res = c.excludes(excluded)
        checks.append(Check(f"{text}: every state with c_k = {x}, c_(k+1) = {y} lies in the cone {c.label}; there "
                            f"the next normal n' has n'_{INDEX[y] + 1} n'_{INDEX[excluded] + 1} < 0, so the collision "
                            f"after {y} is not {excluded} (for every orbit)", c.holds and res.holds,
                            [f"n' ∝ p' ∧ {y.upper()} w = `{T.show(c.normal)}`"] + res.evidence
                            + ([] if c.holds else lemma_check(c).evidence)))
        evidence.append(supporting(
            f"{pattern} occurs {occurrences(scan, pattern)} times in {sum(map(len, scan))} collisions of {len(scan)} "
            f"exact reduction orbits and {occurrences(physical, pattern)} times in {sum(map(len, physical))} "
            f"collisions of {len(physical)} exact particle runs (which realise prefixes of the reduction's words, "
            f"S11); {pair} occurs {occurrences(scan, pair)} times in the orbits."))
    return conclude(checks, evidence=evidence)


# ---------------------------------------------------------------- S10
PRINTED_S10 = dict(window="c_k = b ⇒ c_{k+2} = b or c_{k+3} = b", blocks="ab, cb, acb, cab")


def offsets(text: str) -> set[int]:
    """"c_k = b ⇒ c_{k+2} = b or c_{k+3} = b" as {2, 3}, read whole (statements.word_rule):
    a rule of another shape (another letter, ≠, more premises) is not what this
    certificate evaluates, and is a StatementError."""
    rule = statements.word_rule(text)
    if rule.premises != ((0, "b", True),) or any(c[1:] != ("b", True) or c[0] == 0 for c in rule.conclusions):
        raise statements.StatementError(f"cannot evaluate {text!r}: S10 evaluates rules c_k = b ⇒ c_{{k+m}} = b or …")
    return {c[0] for c in rule.conclusions}


def window_holds(words, ks: set[int]) -> tuple[int, int]:
    """(b's with a full look-ahead, those followed by b at one of the offsets ks)."""
    seen = good = 0
    for w in words:
        for k, L in enumerate(w):
            if L == "b" and k + max(ks) < len(w):
                seen += 1
                good += any(w[k + m] == "b" for m in ks)
    return seen, good


def parses(word: str, blocks: list[str]) -> bool:
    """word is a concatenation of blocks, the last one possibly cut short (blocks
    end with b and contain one b, so the cut is unique)."""
    k = 0
    while k < len(word):
        nxt = [B for B in blocks if word.startswith(B, k)]
        if not nxt:
            return any(B.startswith(word[k:]) for B in blocks)
        k += len(nxt[0])
    return True


@certificate("S10", "l. 1037-1051",
             "Corollary 4.5: b occurs infinitely often, and c_k = b implies c_{k+2} = b or c_{k+3} = b; Remark 4.6: every "
             "pattern c_1 c_2 … is a concatenation of the blocks ab, cb, acb, cab.",
             needs=["reduction_cones", "reduction_scan"], printed=PRINTED_S10,
             expect=ERRATUM,
             mutants=[replaced("window", " or c_{k+3} = b", "", "the window shortened to c_{k+2}"),
                      replaced("blocks", ", cab", "", "a block dropped"),
                      reworded("window", "c_{k+3} = b", "c_{k+3} = a", "false; the letters were not read"),
                      reworded("window", "c_k = b", "c_k = a"),
                      unread("window", "c_k = b ⇒ c_{k+2} = b and c_{k+3} = b", "a conjunction in the conclusion")])
def b_recurs(reduction_cones, reduction_scan, window, blocks):
    """For every orbit: every window of an orbit's word is admissible, that is its pairs
    are proven steps (the step lemma on the six cones: the next contact is another one)
    and its triples are not excluded by the sign of the next normal (Proposition 4.4 as
    in S9.2: no aca, no cac).  The statements follow by exhausting the admissible
    windows.  The block decomposition fails for every orbit whose first collision is b
    (no block starts with b), as for every state of a cone whose next contact is b; it
    holds once that leading b is removed, by induction along the word.  The scan's 10^5
    exact collisions are supporting evidence."""
    ks, blks = offsets(window), [B.strip() for B in blocks.split(",")]
    cones = reduction_cones.values()
    lemma = all(c.holds for c in cones)
    allowed = RC.transitions(reduction_cones)
    rules = "; ".join(f"{x}{y} → {'/'.join(sorted(z))}" for (x, y), z in sorted(allowed.items()))
    starts_b = [w for w in RC.admissible(max(ks) + 1, allowed) if w[0] == "b"]
    seen, good = window_holds(starts_b, ks)
    three = RC.admissible(3, allowed)
    scan = [o.word for o in reduction_scan]
    s_seen, s_good = window_holds(scan, ks)
    printed = [Check(f"{window}: every admissible window b… of length {max(ks) + 1} has b at the stated places (for "
                     "every orbit)", lemma and seen == good > 0,
                     [f"allowed after each proven step: {rules}", f"{good} of {seen}: {', '.join(starts_b)}"]),
               Check("b occurs infinitely often: every admissible window of length 3 contains b, and every orbit off "
                     "the corners has infinitely many collisions (the step lemma on the six cones, S11)",
                     lemma and all("b" in w for w in three), [f"{len(three)} windows: {', '.join(three)}"])]
    width = max(len(B) for B in blks)
    uncovered = [w for w in RC.admissible(width, allowed) if w[0] != "b" and not any(w.startswith(B) for B in blks)]
    induction = lemma and not uncovered and all(B.endswith("b") for B in blks)
    first_b = [c for c in cones if c.holds and c.following == "b"]
    witness = []
    for c in first_b:
        P = R.canonical(c.contact, RC.representative(c))
        witness.append(f"every state of the cone {c.label} (e.g. n = {P.n}, whose first collision is "
                       f"{R.next_letter(P)} by the engine) has c_1 = b")
    induction_ev = [f"admissible windows of length {width} not starting with b and not starting with a block: "
                    f"{', '.join(uncovered) or 'none'}; every block ends with b, and no letter follows itself"]
    leading_b = [w for w in scan if w.startswith("b")]
    printed.append(Check(f"every pattern is a concatenation of {', '.join(blks)}", induction and not first_b,
                         witness + induction_ev))
    corrected = printed[:2] + [
        Check(f"c_1 c_2 …, without its first letter when that is b, is a concatenation of {', '.join(blks)}: each "
              "admissible window that does not start with b starts with a block, which ends with b, so the next "
              "letter is not b again (induction along the word)", induction, induction_ev, corrects=printed[2])]
    evidence = [supporting(f"{window} at {s_good} of {s_seen} collisions b of the scan ({len(scan)} exact orbits, "
                           f"{sum(map(len, scan))} collisions); {sum(parses(w, blks) for w in scan)} of {len(scan)} "
                           f"orbit words parse as printed, {len(leading_b)} start with b, e.g. "
                           f"`{(leading_b or [''])[0][:24]}…`; without that b, "
                           + ("all parse." if all(parses(w[1:] if w.startswith('b') else w, blks) for w in scan)
                              else "some still do not parse."))]
    return conclude(printed, corrected, evidence=evidence, kind=FALSE_STATEMENT,
                    misprint="l. 1049-1051, Remark 4.6: 'every pattern is a concatenation of ab, cb, acb, cab' is "
                             "false for a pattern that starts with b (Corollary 4.5 holds)")


# ---------------------------------------------------------------- S11
PRINTED_S11 = dict(reduction="infinitely many collisions", realised="a prefix", A=A_PRINTED, B=B_PRINTED, C=C_PRINTED)


@certificate("S11", "l. 869-875",
             "Remark 4.2: every orbit of the reduction off the corners has infinitely many collisions; the "
             "collisions realised by the particle system are a prefix of it.",
             needs=["reduction_cones", "reduction_scan", "section4_data"], printed=PRINTED_S11,
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
    """Proof, for every orbit (proofs/reduction_cones.py): a state off the corners lies in
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
    closed = RC.map_is_proven(cones)
    checks.append(Check(f"every orbit of the reduction off the corners has {reduction}: the six cones hold every "
                        "state off the corners, and each step maps a cone into a cone of the next contact, or onto a "
                        "corner (n'_j = 0)", closed and claim.infinite))
    checks += [c.motion for c in cones.values()]
    prefix = RC.dynamics_is_proven(cones)
    runs = [(run, d) for d in section4_data for run in d.runs]
    separated = sum(run.stop == "free" for run, d in runs)
    checks.append(Check(f"the realised collisions are {realised} of the reduction's sequence (for every datum, by "
                        "induction on the collisions)", prefix and (extent == "prefix" or separated == 0),
                        [f"{separated} exact runs end because the particles separate while the reduction goes on"]))
    lengths = [len(o.word) for o in reduction_scan]
    realise = sum(R.word(d.orbit).startswith(run.word) for run, d in runs)
    evidence = [supporting(f"{len(lengths)} exact orbits from random planes meet no corner in {sum(lengths)} "
                           f"collisions (shortest {min(lengths)} of {SCAN_LENGTH}); {realise} of {len(runs)} exact "
                           f"particle runs realise a prefix of the reduction's word ({N_REDUCTION} collisions), "
                           f"{separated} of them end because the particles separate.")]
    return conclude(checks, evidence=evidence)
