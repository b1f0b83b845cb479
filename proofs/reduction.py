"""Section 4 on the dynamics (l. 839-1051): the spherical reduction against the
particle system, Proposition 4.2, Corollary 4.3 and Remark 4.2.

The particle system is :mod:`certify.simulate` in exact rationals (fmpq); the
reduction map is :mod:`certify.reduction` in its three representations: projective
(exact normals in Z^3), vectorial (the printed trilinear formula, exact) and
trigonometric (the printed six cases, certified balls).  The identities of the
printed proofs are certified in ``proofs/reduction_identities.py``.

Random data are drawn from a fixed seed, so the report is reproducible.  A datum is
a state right after a collision: the contact letter i, p with p_i = 0 and the other
gaps positive, q with q_i > 0 (the pair separates), and a second datum
(α p, β q + γ p) spanning the same plane (α, β > 0, γ of any sign).
"""
from __future__ import annotations

import itertools
import random
from dataclasses import dataclass

import flint
import sympy as sp

from certify.algebra import trig as T
from certify.algebra import precision, r, show, statements
from certify.dynamics import reduction as R
from certify.dynamics import simulate as sim
from certify.dynamics import INDEX, LETTERS
from certify.run import Check, certificate, conclude, quantity
from proofs import reduction_identities as I
from proofs.model import A_PRINTED, B_PRINTED, C_PRINTED, matrix

Q = flint.fmpq
SEED = 4_1_2024
N_DATA = 300                 # random initial data (each with a second datum on its plane)
N_COLLISIONS = 200           # collisions asked of the particle system
N_REDUCTION = 250            # collisions of the reduction map per datum
SCAN_ORBITS, SCAN_LENGTH = 100, 1000      # the scan of Proposition 4.2: 10^5 collisions


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
    runs = (sim.run(p, q, r, N_COLLISIONS), sim.run(p2, q2, r, N_COLLISIONS))
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


# ---------------------------------------------------------------- S6
@certificate("S6", "l. 839-868",
             "Theorem 4.1: two trajectories with the same contact and Span(p(0),q(0)) = Span(p'(0),q'(0)) have "
             "the same plane Span(p(k),q(k)) at every collision k (and so the same collision types).",
             needs=["section4_data"], printed=dict(A=A_PRINTED, B=B_PRINTED, C=C_PRINTED))
def spherical_reduction_theorem(section4_data, A, B, C):
    """Proof: K_j fixes the plane {x_j = 0} pointwise, so with p' = p + t q,
    Span(p', K_j q) = K_j Span(p', q) = K_j Span(p, q): the new plane is K_j P whatever
    the radial part of q, and its normal is cof(K_j) n (cof(K) (a ∧ b) = Ka ∧ Kb).
    Then on the dynamics: exact runs of two data per plane, compared collision by
    collision with each other and with the projective map."""
    checks, r0 = [], sp.Rational(1, 3)
    for letter, text in zip(LETTERS, (A, B, C)):
        K, j = matrix(text), INDEX[letter]
        fixed = all((K * sp.eye(3).col(m) - sp.eye(3).col(m)).applyfunc(sp.expand) == sp.zeros(3, 1)
                    for m in range(3) if m != j)
        cof = K.adjugate().T                     # cof(K)(a ∧ b) = Ka ∧ Kb for every K
        engine = sp.Matrix([[int(z) for z in row] for row in R.cofactor(letter, Q(1, 3))])
        at_r0 = cof.subs(r, r0)
        ratio = {e / c for e, c in zip(engine, at_r0) if c != 0}
        moves = len(ratio) == 1 and ratio.pop() > 0 and all(e == 0 for e, c in zip(engine, at_r0) if c == 0)
        checks.append(Check(f"{letter.upper()} fixes {{x_{j + 1} = 0}} pointwise, so the plane after a collision "
                            f"{letter} is {letter.upper()}·P, with normal cof({letter.upper()}) n; the projective map "
                            f"moves normals by this cof({letter.upper()}) (a positive multiple, at r = 1/3)",
                            fixed and moves,
                            [f"cof({letter.upper()}) = det·{letter.upper()}^(-T) = `{show(cof.applyfunc(sp.factor).tolist())}`"]))
    compared = same = 0
    for d in section4_data:
        (run1, run2), k = d.runs, d.realised
        for P1, P2, P in zip(d.planes[0][1:k + 1], d.planes[1][1:k + 1], d.orbit[1:k + 1]):
            compared += 1
            same += P1 == P2 == P
    reached = sum(d.realised >= N_COLLISIONS for d in section4_data)
    checks.append(Check(f"on {len(section4_data)} random rational data (two per plane, exact runs of up to "
                        f"{N_COLLISIONS} collisions): same collision type and same plane at every collision, "
                        "equal to the projective map's", compared > 0 and same == compared,
                        [f"{compared} collisions compared, {same} agree; {reached} data kept colliding for "
                         f"{N_COLLISIONS} collisions on both runs, the others separated earlier"]))
    return conclude(checks, evidence=growth(section4_data))


# ---------------------------------------------------------------- S7.2
# The six printed cases (l. 881-929), transcribed once in proofs/reduction_identities.py (S7.1).
PRINTED_S7 = {**{f"p0_{c}": I.CONTACT_P0[c] for c in LETTERS}, **{f"q0_{c}": I.CONTACT_Q0[c] for c in LETTERS},
              **{key: I.SIX_CASES[f"{c}, {I.RANGE[s]}"] for key, (c, s) in I.CASE_KEYS.items()}}


def engine_is_printed(printed: dict) -> list[Check]:
    """The engine's six cases (certify.reduction.P0, Q0, CASES) are the printed ones:
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


def trig_agrees(P: R.Plane, P1: R.Plane, r, prec: int = 128) -> bool:
    """The trigonometric step from (θ, φ) of the physical state P gives the contact of
    the next physical state P1 and balls of cos, sin of θ, φ overlapping P1's.  (θ, φ
    are functions of the contact and the plane: p ∝ n ∧ e_i, q̂ ∝ |n|² e_i − n_i n.)"""
    with precision(prec):
        T, X = R.trig_step(R.angles(P), r), R.angles(P1)
    return T.letter == P1.letter and all(a.overlaps(b) for a, b in
                                         ((T.ct, X.ct), (T.st, X.st), (T.cp, X.cp), (T.sp, X.sp)))


@certificate("S7.2", "l. 877-929",
             "The trigonometric reduction (the six printed cases) reproduces the next collision of the particle "
             "system: same contact, same θ and φ, at every collision.",
             needs=["section4_data"], printed=PRINTED_S7)
def trigonometric_map_agrees_with_dynamics(section4_data, **printed):
    """At each collision k of the exact runs: θ, φ of the exact state as certified balls
    (128 bits), one step of the six printed cases, compared with θ, φ of the exact
    state k+1.  The sign of cos φ that picks the case is proven by the balls."""
    checks = engine_is_printed(printed)
    compared = agree = undecided = 0
    if all(c.holds for c in checks):
        for d in section4_data:
            for P, P1 in zip(d.planes[0], d.planes[0][1:]):
                compared += 1
                try:
                    agree += trig_agrees(P, P1, d.r)
                except sim.Undecided:
                    undecided += 1
    checks.append(Check("at every collision of the exact runs the six cases give the next contact and (θ, φ)",
                        compared > 0 and agree == compared,
                        [f"{compared} collisions of {len(section4_data)} runs: {agree} agree, {undecided} undecided"]))
    return conclude(checks)


# ---------------------------------------------------------------- S8.2
# transcribed once in proofs/reduction_identities.py (S8.1)
PRINTED_S8 = dict(orientation=I.ORIENTATION, to_b=I.TRILINEAR_B, to_c=I.TRILINEAR_C)


@certificate("S8.2", "l. 931-987",
             "The vectorial reduction reproduces the next collision of the particle system: u(0) = p(0) ∧ q(0), "
             "the printed trilinear formulas give u(1) ∝ p(1) ∧ q(1), with e_t · u(k) ≥ 0.",
             needs=["section4_data"], printed=PRINTED_S8)
def vectorial_map_agrees_with_dynamics(section4_data, orientation, to_b, to_c):
    """At each collision k of the exact runs, u(k) = p(k) ∧ q(k) (exact); the trilinear
    formula gives ũ(k+1), which must be a positive multiple of p(k+1) ∧ q(k+1), the
    normal of the physical plane with the printed orientation.  The printed formulas
    are for the contact a; the other contacts use the relabelled formula
    (:func:`certify.reduction.vectorial_step`, "in a similar manner", l. 987)."""
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
    ok = {k: v[0] > 0 and v[0] == v[1] for k, v in tally.items()}
    evidence = [f"{k}: {v[1]} of {v[0]} collisions" for k, v in tally.items()]
    printed = [Check("u(k) = p(k) ∧ q(k) satisfies the orientation e_t · u(k) > 0 (t = y, z, x for a, b, c)",
                     oriented[0] > 0 and oriented[0] == oriented[1], [f"{oriented[1]} of {oriented[0]} states"]),
               Check(f"contact a, next b: `{to_b}` ∝ p(1) ∧ q(1), positively", ok["a→b"], evidence[:1]),
               Check(f"contact a, next c: `{to_c}` ∝ p(1) ∧ q(1), positively", ok["a→c"], evidence[1:2]),
               Check("contacts b and c: the relabelled formula [u ∧ e_j] ∧ [K_j(u ∧ [e_i ∧ u])] ∝ p(1) ∧ q(1)",
                     ok["relabelled"], evidence[2:])]
    corrected = []
    if not ok["a→c"] and "ey" in to_c:
        fixed = R.formula(to_c.replace("ey", "ez", 1))
        n = good = 0
        for d in section4_data:
            contacts = [d.letter] + d.runs[0].events
            for L, L1, u, u1 in zip(contacts, contacts[1:], d.normals, d.normals[1:]):
                if L == "a" and L1 == "c":
                    ut = fixed(u, d.r)
                    n += 1
                    good += R.cross(ut, u1) == (0, 0, 0) and R.dot(ut, u1) > 0
        corrected = [printed[0], printed[1],
                     Check("contact a, next c, with p(1) ∝ u(0) ∧ e_z (as in l. 962): "
                           f"`{to_c.replace('ey', 'ez', 1)}` ∝ p(1) ∧ q(1), positively",
                           n > 0 and good == n, [f"{good} of {n} collisions"]), printed[3]]
    return conclude(printed, corrected)


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
             "Proposition 4.2 on long orbits: no aca and no cac in 10^5 collisions of exact orbits of the reduction "
             "map, nor in the exact particle runs.",
             needs=["reduction_scan", "section4_data"], printed=PRINTED_S9)
def no_aca_cac_on_long_orbits(reduction_scan, section4_data, aca, cac):
    """Count the excluded patterns in the words of the exact orbits (each letter
    decided by an exact sign)."""
    scan = [o.word for o in reduction_scan]
    physical = [run.word for d in section4_data for run in d.runs]
    checks = []
    for text in (aca, cac):
        pair, excluded = implication(text)
        pattern = pair + excluded
        n_scan, n_phys = occurrences(scan, pattern), occurrences(physical, pattern)
        checks.append(Check(f"{text}: no {pattern}", n_scan == 0 and n_phys == 0,
                            [f"{pattern} occurs {n_scan} times in {sum(map(len, scan))} collisions of "
                             f"{len(scan)} exact reduction orbits, {n_phys} times in "
                             f"{sum(map(len, physical))} collisions of {len(physical)} exact particle runs; "
                             f"{pair} occurs {occurrences(scan, pair)} times in the orbits"]))
    return conclude(checks)


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


def admissible(n: int) -> list[str]:
    """Every word of length n with no letter twice in a row and no aca, cac: the
    words the reduction allows by Proposition 4.2 and l. 881-929."""
    words = ("".join(w) for w in itertools.product(LETTERS, repeat=n))
    return [w for w in words if all(x != y for x, y in zip(w, w[1:])) and "aca" not in w and "cac" not in w]


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
             "Corollary 4.3: b occurs infinitely often, and c_k = b implies c_{k+2} = b or c_{k+3} = b; every "
             "pattern c_1 c_2 … is a concatenation of the blocks ab, cb, acb, cab.",
             needs=["reduction_scan"], printed=PRINTED_S10)
def b_recurs(reduction_scan, window, blocks):
    """From Proposition 4.2 by exhausting the admissible words of length 4 that start
    with b; then on the scan's 10^5 exact collisions.  The block decomposition fails
    for orbits whose first collision is b (no block starts with b): the corrected
    statement drops that leading b."""
    ks, blks = offsets(window), [B.strip() for B in blocks.split(",")]
    starts_b = [w for w in admissible(4) if w[0] == "b"]
    seen, good = window_holds(starts_b, ks)
    scan = [o.word for o in reduction_scan]
    s_seen, s_good = window_holds(scan, ks)
    printed = [Check(f"{window}: every admissible word b??? (no repeated letter, no aca, cac) has b at the "
                     "stated places", seen == good > 0, [f"{good} of {seen}: {', '.join(starts_b)}"]),
               Check(f"{window} on the scan (so b occurs infinitely often)", s_seen == s_good > 0,
                     [f"{s_good} of {s_seen} collisions b"])]
    whole = [w for w in scan if parses(w, blks)]
    leading_b = [w for w in scan if w.startswith("b")]
    printed.append(Check(f"every pattern is a concatenation of {', '.join(blks)}", len(whole) == len(scan),
                         [f"{len(whole)} of {len(scan)} orbit words parse; {len(leading_b)} start with b, e.g. "
                          f"`{(leading_b or [''])[0][:24]}…`"]))
    minus_b = [w[1:] if w.startswith("b") else w for w in scan]
    short = admissible(6)
    corrected = printed[:2] + [
        Check(f"c_1 c_2 …, without its first letter when that is b, is a concatenation of {', '.join(blks)}: "
              "on every admissible word of length 6 and on the scan",
              all(parses(w[1:] if w[0] == "b" else w, blks) for w in short) and
              all(parses(w, blks) for w in minus_b), [f"{len(short)} admissible words of length 6"])]
    return conclude(printed, corrected)


# ---------------------------------------------------------------- S11
PRINTED_S11 = dict(reduction="infinitely many collisions", realised="a prefix")


def next_state_lemma() -> list[str]:
    """Exact identities behind "the reduction never stops": for a normal n and contact
    i, with p = ±(n ∧ e_i) > 0 and w = |n|² e_i − n_i n: w ⊥ n, w ⊥ p, w_i = n_j² + n_k²,
    w_m = −n_i n_m (m ≠ i).  Returns the failures (empty when all hold)."""
    n = sp.Matrix(sp.symbols("n1:4"))
    bad = []
    for L in LETTERS:
        i = INDEX[L]
        e = sp.eye(3).col(i)
        p = n.cross(e)
        w = (n.dot(n)) * e - n[i] * n
        others = [m for m in range(3) if m != i]
        for name, val in (("w·n", w.dot(n)), ("w·p", w.dot(p)),
                          ("w_i − Σ n_m²", w[i] - sum(n[m] ** 2 for m in others)),
                          *((f"w_{m + 1} + n_i n_{m + 1}", w[m] + n[i] * n[m]) for m in others)):
            if sp.expand(val) != 0:
                bad.append(f"contact {L}: {name} = {val}")
    return bad


@certificate("S11", "l. 869-875",
             "Remark 4.2: every orbit of the reduction off the corners has infinitely many collisions; the "
             "collisions realised by the particle system are a prefix of it.",
             needs=["reduction_scan", "section4_data"], printed=PRINTED_S11)
def reduction_never_stops(reduction_scan, section4_data, reduction, realised):
    """Proof: with w the tangential velocity (identities below), exactly one gap j ≠ i
    closes (w_j = −n_i n_j < 0, the other w_k > 0, since p > 0 forces n_j n_k < 0), at
    the time t = p_j/(n_i n_j) > 0; then p'_i = t w_i > 0, p'_k = p_k + t w_k > 0, and
    q'_j = −r w_j > 0 (M3): the new state lies in the open face with sin φ' > 0, so
    the map is defined again unless cos φ' = 0, a corner.  On the dynamics: every
    exact particle run's word is a prefix of the reduction's word."""
    claim, extent = statements.count(reduction), statements.extent(realised)     # read whole; unread text fails
    bad = next_state_lemma()
    checks = [Check("the tangential velocity w = |n|² e_i − n_i n: w ⊥ n, w ⊥ p, w_i = n_j² + n_k² > 0, "
                    "w_m = −n_i n_m: exactly one other gap closes and the next state lies in the open face",
                    not bad, bad or ["all identities hold for the three contacts"])]
    lengths = [len(o.word) for o in reduction_scan]
    unbroken = all(k == SCAN_LENGTH for k in lengths)
    # infinitely many: no orbit stops at a corner; finitely many: every orbit does
    reached = unbroken if claim.infinite else all(k < SCAN_LENGTH for k in lengths)
    checks.append(Check(f"{len(lengths)} exact orbits from random planes have {reduction}: "
                        f"{'no' if unbroken else 'a'} corner in {sum(lengths)} collisions", reached,
                        [f"shortest orbit: {min(lengths)} of {SCAN_LENGTH} collisions"]))
    runs = [(run, d) for d in section4_data for run in d.runs]
    prefix = sum(R.word(d.orbit).startswith(run.word) for run, d in runs)
    separated = sum(run.stop == "free" for run, d in runs)
    holds = prefix == len(runs) and (extent == "prefix" or separated == 0)
    checks.append(Check(f"the realised collisions are {realised} of the reduction's sequence", holds,
                        [f"{prefix} of {len(runs)} exact runs realise a prefix of the reduction's word "
                         f"({N_REDUCTION} collisions); {separated} of them end because the particles separate, "
                         "while the reduction goes on"]))
    return conclude(checks)
