"""Beyond the paper (issue 39): the spherical reduction for N particles, answering l. 1234 ("it
would be interesting to study if there exists a similar spherical reduction for systems with five
or more particles").  Not a claim of the paper: the statements (statements/6_beyond.txt) are ours.

B1  for five particles, symbolically in r and the coordinates, and for N = 3, ..., 8 from the
    engine's law: K_i = I + w_i e_iᵀ fixes the face {p_i = 0} pointwise; free flight keeps p ∧ q;
    a collision maps p ∧ q by Λ²K_i; on a face, the next pair depends on the plane only.
"""
from __future__ import annotations

import random
from itertools import combinations

import flint
import sympy as sp

from certify.algebra import r
from certify.dynamics import LETTERS_N, collide_gaps, collide_particles
from certify.dynamics import simulate as sim
from certify.run import PASS, Check, certificate, conclude, identity, replaced
from proofs.section2_model import matrix

H = "(1+r)/2"
K_PRINTED = {"K_a": f"[[-r, 0, 0, 0], [{H}, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]",
             "K_b": f"[[1, {H}, 0, 0], [0, -r, 0, 0], [0, {H}, 1, 0], [0, 0, 0, 1]]",
             "K_c": f"[[1, 0, 0, 0], [0, 1, {H}, 0], [0, 0, -r, 0], [0, 0, {H}, 1]]",
             "K_d": f"[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, {H}], [0, 0, 0, -r]]"}
GENERAL_N = range(3, 9)          # the N for which the uniform argument is checked from the engine's law
RUNS, COLLISIONS, SEED = 12, 40, 39


def proved(c: Check) -> Check:
    """The identity check ``c`` with its evidence in one line: how many coordinate identities, and
    that each difference's numerator expanded to 0 (the routes of :func:`certify.algebra.trig.equal`)."""
    zeros = c.evidence[0].count("`0`") if c.evidence else 0
    c.evidence = [f"{zeros} coordinate identities in r and the coordinates: the numerator of each difference "
                  "expands to 0 (and the two other routes of the identity agree)" if c.holds else c.evidence[0]]
    return c


def wedge(u, v) -> sp.Matrix:
    """The bivector u ∧ v of R^n: its coordinates u_j v_k − u_k v_j, j < k in lexicographic order."""
    return sp.Matrix([u[j] * v[k] - u[k] * v[j] for j, k in combinations(range(len(u)), 2)])


def compound(K: sp.Matrix) -> sp.Matrix:
    """Λ²K, the matrix of u ∧ v ↦ Ku ∧ Kv on the coordinates of :func:`wedge` (its 2×2 minors)."""
    P = list(combinations(range(K.shape[0]), 2))
    return sp.Matrix([[K[j, c] * K[k, d] - K[j, d] * K[k, c] for c, d in P] for j, k in P])


def law_matrix(i: int, n: int) -> sp.Matrix:
    """K_i of N = n particles derived from the collision law on the velocities
    (:func:`certify.dynamics.collide_particles`): column k is q' for the velocities
    (0, ..., 0, 1, ..., 1) whose gaps' velocities are e_k."""
    cols = []
    for k in range(n - 1):
        v = collide_particles(LETTERS_N[i], [sp.Integer(0 if m <= k else 1) for m in range(n)], r)
        cols.append([sp.expand(v[m + 1] - v[m]) for m in range(n - 1)])
    return sp.Matrix(cols).T


def engine_matrix(i: int, n: int) -> sp.Matrix:
    """K_i of N = n particles as the engine applies it (:func:`certify.dynamics.model.collide_gaps`)."""
    return sp.Matrix.hstack(*(sp.Matrix(collide_gaps(LETTERS_N[i], tuple(sp.eye(n - 1).col(k)), r))
                              for k in range(n - 1)))


def coordinates(n: int) -> tuple[sp.Matrix, sp.Matrix]:
    """The gaps p and their velocities q of N = n particles, as symbols."""
    return sp.Matrix(sp.symbols(f"p_1:{n}")), sp.Matrix(sp.symbols(f"q_1:{n}"))


def on_face(p: sp.Matrix, i: int) -> sp.Matrix:
    """p with p_i = 0: a point of the face {p_i = 0}."""
    return sp.Matrix([0 if k == i else x for k, x in enumerate(p)])


def collided(p: sp.Matrix, q: sp.Matrix, i: int) -> sp.Matrix:
    """The gaps at the collision i: p + t q at t = −p_i/q_i."""
    return p - p[i] / q[i] * q


def face_and_bivector(Ks: list, n: int) -> tuple[Check, Check, Check]:
    """(i) K_i p = p on the face {p_i = 0}; Λ²K_i (p ∧ q) = K_i p ∧ K_i q; (iii) at the collision i,
    p'_i = 0 and p' ∧ K_i q = Λ²K_i (p ∧ q): each for every i, as identities in r, p, q."""
    p, q = coordinates(n)
    both = lambda f: sp.Matrix.vstack(*(f(i, K) for i, K in enumerate(Ks)))      # noqa: E731
    fixed = identity(f"(i) K_i fixes the face {{p_i = 0}} pointwise ({n} particles, every pair)",
                     both(lambda i, K: K * on_face(p, i)), both(lambda i, K: on_face(p, i)))
    binet = identity(f"Λ²K_i (p ∧ q) = K_i p ∧ K_i q ({n} particles, every pair)",
                     both(lambda i, K: compound(K) * wedge(p, q)), both(lambda i, K: wedge(K * p, K * q)))
    moved = identity(f"(iii) at the collision i, p' = p − (p_i/q_i) q has p'_i = 0 and p' ∧ K_i q = Λ²K_i (p ∧ q) "
                     f"({n} particles, every pair)",
                     both(lambda i, K: sp.Matrix([collided(p, q, i)[i], *wedge(collided(p, q, i), K * q)])),
                     both(lambda i, K: sp.Matrix([0, *(compound(K) * wedge(p, q))])))
    return fixed, binet, moved


def next_pair_identities() -> list[Check]:
    """(iv), five particles: a point αp + βq of the plane lies on the face i (p_i = 0) only for
    β = 0; the states (αp, βq + γp) have the bivector αβ p ∧ q; their ratios ρ_k = −q_k/p_k are
    (βρ_k − γ)/α, and the pair k closes at t_k = 1/ρ_k."""
    p, q = coordinates(5)
    a, b, g, t = sp.symbols("α β γ t")
    rho = sp.Matrix([-q[k] / p[k] for k in range(4)])
    return [identity("(iv) (αp + βq)_i = β q_i on the face p_i = 0, every face",
                     sp.Matrix([(a * on_face(p, i) + b * q)[i] for i in range(4)]), sp.Matrix([b * q[i] for i in range(4)])),
            identity("(iv) (αp) ∧ (βq + γp) = αβ (p ∧ q)", wedge(a * p, b * q + g * p), a * b * wedge(p, q)),
            identity("(iv) the ratios of (αp, βq + γp) are (βρ_k − γ)/α, and p_k + t q_k = 0 at t = 1/ρ_k",
                     sp.Matrix([*(-(b * q[k] + g * p[k]) / (a * p[k]) for k in range(4)), p[0] + q[0] / rho[0]]),
                     sp.Matrix([*((b * rho[k] - g) / a for k in range(4)), 0]))]


def uniform(n: int) -> Check:
    """For N = n: the law on the velocities gives the engine's K_i, which is I + w_i e_iᵀ (rank one
    off I, zero outside column i), and (i), (iii) hold for it symbolically."""
    Ks = [engine_matrix(i, n) for i in range(n - 1)]
    same = all((law_matrix(i, n) - K).is_zero_matrix for i, K in enumerate(Ks))
    rank_one = all(all((K - sp.eye(n - 1))[:, k].is_zero_matrix for k in range(n - 1) if k != i)
                   for i, K in enumerate(Ks))
    fixed, _, moved = face_and_bivector(Ks, n)
    said = {True: "yes", False: "no"}
    return Check(f"N = {n}: the law gives K_i = I + w_i e_iᵀ (columns k ≠ i of K_i − I zero), so K_i fixes "
                 "{p_i = 0}, and a collision maps p ∧ q by Λ²K_i", same and rank_one and fixed.holds and moved.holds,
                 [f"the law on the velocities gives the engine's K_i: {said[same]}; K_i − I zero off column i: "
                  f"{said[rank_one]}; (i) as {(n - 1) ** 2} coordinate identities and (iii) as "
                  f"{(n - 1) * (1 + (n - 1) * (n - 2) // 2)} in r, p, q: {said[fixed.holds]}, {said[moved.holds]}"])


def rational(x: flint.fmpq) -> sp.Rational:
    return sp.Rational(int(x.p), int(x.q))


def runs_evidence() -> str:
    """Supporting evidence, not proof: exact five-particle runs (fmpq) from random states right after
    a collision, and from a second state of the same plane (αp, βq + γp): the bivector after each
    collision is Λ²K_(c_k) ··· Λ²K_(c_1) (p ∧ q) exactly (αβ times it for the second), and the two
    runs have the same collisions while both last."""
    rng = random.Random(SEED)
    Ks = {L: compound(engine_matrix(i, 5)) for i, L in enumerate("abcd")}
    compared = agreed = exact = steps = 0
    for _ in range(RUNS):
        r0 = flint.fmpq(rng.randint(1, 30), 100)
        i = rng.randrange(4)
        p = [flint.fmpq(0) if k == i else flint.fmpq(rng.randint(1, 50), 10) for k in range(4)]
        q = [flint.fmpq(rng.randint(1, 50), 10) if k == i else flint.fmpq(rng.randint(-50, 50), 10) for k in range(4)]
        al, be = (flint.fmpq(rng.randint(1, 20), 7) for _ in range(2))
        ga = flint.fmpq(rng.randint(-20, 20), 7)
        one = sim.follow_gaps(p, q, r0, COLLISIONS)
        two = sim.follow_gaps([al * x for x in p], [be * y + ga * x for x, y in zip(p, q)], r0, COLLISIONS)
        bivector, scale = wedge(sp.Matrix(p), sp.Matrix(q)), rational(al * be)
        for k, (s1, s2, letters) in enumerate(zip(one.states[1:], two.states[1:], one.events)):
            steps += 1
            for L in letters:
                bivector = Ks[L].subs(r, rational(r0)) * bivector
            w1, w2 = (wedge(sp.Matrix([rational(x) for x in s.p]), sp.Matrix([rational(x) for x in s.q]))
                      for s in (s1, s2))
            exact += w1 == bivector and (one.events[:k + 1] != two.events[:k + 1] or w2 == scale * bivector)
        n = min(len(one.events), len(two.events))
        compared += n
        agreed += sum(x == y for x, y in zip(one.events[:n], two.events[:n]))
    return (f"Supporting evidence, not proof: {RUNS} exact five-particle runs (up to {COLLISIONS} collisions, "
            f"random rational states on a face, r in ]0, 0.3]): the bivector p ∧ q after the collision equals the "
            f"product of the Λ²K_i applied to the initial one (αβ times it on the second run, while both agree) at "
            f"{exact} of {steps} collisions; a second state of the same plane (αp, βq + γp) collides as the first at "
            f"{agreed} of {compared} collisions compared.")


@certificate("B1", printed=K_PRINTED, expect=PASS,
             mutants=[replaced("K_b", "[0, -r, 0, 0]", "[0, r, 0, 0]", "not the law: the pair b would not separate"),
                      replaced("K_a", "[(1+r)/2, 1, 0, 0]", "[(1+r)/2, 2, 0, 0]", "K_a moves the face {p_1 = 0}"),
                      replaced("K_c", "[0, 0, (1+r)/2, 1]", "[0, 1, (1+r)/2, 1]", "K_c moves the face {p_3 = 0}"),
                      replaced("K_d", "[0, 0, 1, (1+r)/2]", "[0, 0, 1, (1+r)/3]", "not the law of the pair d")])
def n_particle_reduction(K_a, K_b, K_c, K_d):
    """Proof, for N particles: K_i = I + w_i e_iᵀ (the law, B1.1) differs from I in column i only,
    so K_i p = p when p_i = 0 (i).  Free flight p ↦ p + t q keeps p ∧ q (ii).  At the collision i
    the gaps p' lie on the face, so p' ∧ K_i q = K_i p' ∧ K_i q = Λ²K_i (p' ∧ q) = Λ²K_i (p ∧ q)
    (iii): the plane P = Span(p, q) follows P(k+1) = K_(c_(k+1)) P(k), whatever the velocity's
    component along p.  On the face i (p_i = 0 < p_k, q_i > 0 after the collision i), the states of
    P are (αp, βq + γp) with α, β > 0 (B1.6, B1.7); the pair k closes at t_k = 1/ρ_k, ρ_k = −q_k/p_k,
    the first at the largest ρ_k if it is > 0; the state's ratios are (βρ_k − γ)/α (B1.8), one
    increasing map for every k, so each state of the plane on the face collides next at the same
    pairs (those of largest ρ_k), or never: the next pair depends on P and i only.  Checked as
    identities in r and the coordinates for five particles as printed (B1.1-B1.8), for six (B1.9),
    and for N = 3, ..., 8 from the engine's law (the argument is the same for every N).  Exact runs
    of the particles are supporting evidence."""
    Ks = [matrix(K) for K in (K_a, K_b, K_c, K_d)]
    law = all((law_matrix(i, 5) - K).applyfunc(sp.expand).is_zero_matrix and
              (engine_matrix(i, 5) - K).applyfunc(sp.expand).is_zero_matrix for i, K in enumerate(Ks))
    checks = [Check("the law on the velocities (momentum kept, relative velocity times −r) gives the printed K_a, "
                    "K_b, K_c, K_d on the four gaps, and the engine applies them", law, ref="B1.1")]
    p, q = coordinates(5)
    fixed, binet, moved = face_and_bivector(Ks, 5)
    flight = identity("(ii) (p + t q) ∧ q = p ∧ q", wedge(p + sp.Symbol("t") * q, q), wedge(p, q))
    for c, ref in zip((fixed, flight, binet, moved, *next_pair_identities()), ("B1.2", "B1.3", "B1.4", "B1.5",
                                                                               "B1.6", "B1.7", "B1.8")):
        c.ref = ref
        checks.append(proved(c))
    six = [engine_matrix(i, 6) for i in range(5)]
    fixed6, _, moved6 = face_and_bivector(six, 6)
    checks.append(Check("six particles: K_i fixes {p_i = 0} pointwise, and a collision maps p ∧ q by Λ²K_i",
                        fixed6.holds and moved6.holds, [f"{c.statement}: {'✓' if c.holds else '✗'}"
                                                        for c in (fixed6, moved6)], ref="B1.9"))
    checks += [uniform(n) for n in GENERAL_N]
    return conclude(checks, evidence=[runs_evidence()])
