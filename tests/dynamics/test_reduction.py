"""Section 4 on the dynamics: the reduction map (certify.dynamics.reduction) and the
certificates S6, S7.2, S8.2, S9.2, S10, S11 (proofs/section4_*.py); their mutants and
statuses as printed are in tests/proofs/test_mutants.py."""
import itertools
import random

import flint
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from certify.algebra.balls import precision
from certify.algebra.poly import r
from certify.dynamics import cones as RC
from certify.dynamics import reduction as R
from certify.dynamics import simulate as sim
from certify.dynamics.model import INDEX, LETTERS, collide, collide_integral, collision_matrix
from certify.run.runner import CERTIFICATES, FAIL, PASS, Context, altered, run_certificate
from proofs import section4_1_reduction_theorem as S41
from proofs import section4_2_final_expressions as S42
from proofs import section4_3_impossible_sequences as S43
from tests.shared import CONTEXT as CTX
from tests.shared import outcome

Q = flint.fmpq


def declared(id, overrides) -> dict:
    """``overrides``, checked to be one of the mutants declared for ``id``."""
    assert overrides in [m.overrides(id) for m in CERTIFICATES[id].mutants]
    return overrides


# A with (1+3r)/3 for (1+r)/2: both are 2/3 at r = 1/3 (where S6 compared them before), and A
# still fixes {x = 0}: only the comparison over Q(r) sees it
AGREES_AT_ONE_THIRD = declared("S6", altered("S6", "A", "[(1+r)/2, 1, 0]", "[(1+3*r)/3, 1, 0]"))
def test_s11_reads_its_phrases_whole():
    """'the beginning' says what 'a prefix' says (the paper's words, l. 873)."""
    assert outcome("S11", realised="the beginning").status == PASS


def test_s8_erratum_is_the_c_formula():
    out = outcome("S8.2")
    failing = [c.statement for c in out.printed if not c.holds]
    assert len(failing) == 1 and "C*" in failing[0] and "ey" in failing[0]
    assert all(c.holds for c in out.corrected) and any("ez" in c.statement for c in out.corrected)


def test_enough_long_runs():
    """The issue asks for hundreds of data and runs of 200 collisions while they last."""
    data = CTX.get("section4_data")
    assert len(data) >= 200
    assert sum(d.realised >= S41.N_COLLISIONS for d in data) >= 150
    assert sum(len(o.word) for o in CTX.get("reduction_scan")) >= 10 ** 5


# ---- the engine ------------------------------------------------------------

def random_state(rng, letter):
    i = INDEX[letter]
    p = tuple(Q(0) if k == i else Q(rng.randint(1, 30), rng.randint(1, 30)) for k in range(3))
    q = tuple(Q(rng.randint(1, 30) if k == i else rng.randint(-30, 30), rng.randint(1, 30)) for k in range(3))
    return p, q


@settings(max_examples=60, deadline=None)
@given(st.integers(0, 10 ** 6), st.sampled_from(LETTERS), st.integers(2, 99))
def test_one_step_of_the_map_is_the_next_collision(seed, letter, m):
    """From any state right after a collision, if the particles collide again, the
    projective step gives that collision's contact and plane, for every radial part.
    Every path asserts: at a corner (cos φ = 0) the map refuses to step; when no pair
    approaches the map still steps (Remark 4.2: the reduction goes on); a simultaneous
    pair of collisions happens only at a corner (Remark 4.2's proof, S11)."""
    rng, r = random.Random(seed), Q(1, m)
    p, q = random_state(rng, letter)
    for lam in (Q(0), Q(-1), Q(-7, 2)):
        qq = tuple(z + lam * x for z, x in zip(q, p))
        P0 = R.plane(letter, p, qq)
        if R.sign(P0.n[INDEX[letter]]) == 0:
            assert_corner(P0, p, qq, r)
            continue
        nxt = sim.step(p, qq, r)
        if nxt is None:
            assert all(z >= 0 for z in qq) and R.step(P0, r).letter != letter
            continue
        assert len(nxt[0]) == 1, "a simultaneous collision off a corner"
        L, _t, p1, q1 = nxt
        assert R.step(P0, r) == R.plane(L, p1, q1)


def assert_corner(P0, p, q, r):
    """At a corner (cos φ = n_i = 0) the map refuses to step, and the particles never have
    a single binary collision next: the two other gaps close together or not at all."""
    with pytest.raises(R.Corner):
        R.step(P0, r)
    try:
        nxt = sim.step(p, q, r)
    except sim.MultipleCollision:
        return
    assert nxt is None or len(nxt[0]) > 1


def test_corners():
    """Contact a, p = (0, 1, 1): q = (1, ∓1, ∓1) spans a plane with n_1 = 0."""
    p = (Q(0), Q(1), Q(1))
    for s in (1, -1):
        q = (Q(1), Q(s), Q(s))
        P0 = R.plane("a", p, q)
        assert P0.n[0] == 0
        assert_corner(P0, p, q, Q(1, 3))
    with pytest.raises(sim.MultipleCollision):             # b and c close together: particles 2, 3, 4 meet
        sim.step(p, (Q(1), Q(-1), Q(-1)), Q(1, 3))


def test_s6_mutation_is_invisible_at_one_third():
    """The mutated A equals the printed one at r = 1/3 and fixes {x = 0} like it."""
    from proofs.section2_model import A_PRINTED, matrix
    K, K2 = matrix(A_PRINTED), matrix(AGREES_AT_ONE_THIRD["A"])
    third = sp.Rational(1, 3)
    assert K.subs(r, third) == K2.subs(r, third) and K != K2
    assert K2[:, 1:] == K[:, 1:] == sp.Matrix([[0, 0], [1, 0], [0, 1]])
    assert outcome("S6", **AGREES_AT_ONE_THIRD).printed[0].holds is False


def test_cofactor_over_q_of_r():
    """The engine's cof(K), built in SymPy at a symbolic r, is det(K) K^(-T) over Q(r); the
    integer matrix the map steps with at a rational r is a positive multiple of it."""
    for L in LETTERS:
        K = collision_matrix(L)
        engine = sp.Matrix.hstack(*(sp.Matrix(c) for c in R.cofactor_columns(L, r)))
        assert all(sp.cancel(e) == 0 for e in engine - K.det() * K.inv().T)
        for r0 in (Q(1, 3), Q(2, 7), Q(97, 100)):
            k = S41.multiple(R.cofactor(L, r0), engine.subs(r, sp.Rational(int(r0.p), int(r0.q))))
            assert k is not None and k > 0
    assert S41.multiple(((1, 2, 3),) * 3, sp.Matrix([[-1, -2, -3]] * 3)) is None      # negative multiple


def test_cofactor_moves_the_normal():
    """cof(K)(a ∧ b) = Ka ∧ Kb up to the positive integer clearing denominators."""
    rng = random.Random(3)
    for L in LETTERS:
        r = Q(2, 7)
        K = collision_matrix(L, sp.Rational(2, 7))
        a, b = ([Q(rng.randint(-9, 9)) for _ in range(3)] for _ in range(2))
        Ka, Kb = ([Q(int(sp.numer(z)) * 1, 1) / int(sp.denom(z)) for z in K * sp.Matrix([int(x.p) for x in v])]
                  for v in (a, b))
        lhs = R.cofactor_apply(L, r, R.cross(a, b))
        rhs = R.cross(Ka, Kb)
        assert R.cross(lhs, rhs) == (0, 0, 0) and R.dot(lhs, rhs) > 0


def test_primitive_and_orientation():
    assert R.primitive((Q(1, 2), Q(-3, 4), Q(0))) == (2, -3, 0)
    assert R.canonical("a", [4, -6, 2]).n == (-2, 3, -1)            # e_y · n > 0 for contact a
    with pytest.raises(R.Corner):
        R.canonical("b", [1, 1, 0])


def test_corner_when_cos_phi_vanishes():
    """n_i = 0: the tangent points at the vertex e_i, no gap closes."""
    P = R.canonical("a", [0, 1, -1])
    with pytest.raises(R.Corner):
        R.next_letter(P)


def test_word_of_matches_the_orbit():
    P = R.canonical("c", [5, -3, 2])
    for rr in (Q(1, 10), Q(3, 4)):
        w, end = R.word_of(P, rr, 300, reduce_every=7)
        orbit = R.orbit(P, rr, 300)
        assert w == R.word(orbit) and end == orbit[-1]


def test_printed_trilinear_formula_is_the_relabelled_one_for_contact_a():
    """For the contact a the relabelled formula is the printed one of l. 976 when the next
    collision is b, and the printed one of l. 980 with u(0) ∧ e_z (S8's erratum) when it is
    c; u_1 = cos φ = 0 is a corner.  Every path asserts, and both collisions occur."""
    rng = random.Random(5)
    seen = {"b": 0, "c": 0, "corner": 0}
    for _ in range(40):
        u = tuple(Q(rng.randint(-9, 9)) for _ in range(3))
        if u[0] == 0:
            with pytest.raises(R.Corner):
                R.vectorial_step("a", u, Q(1, 3))
            seen["corner"] += 1
            continue
        j, ut = R.vectorial_step("a", u, Q(1, 3))
        printed = {"b": S42.TRILINEAR_B, "c": S42.TRILINEAR_C_CORRECTED}[j]
        assert R.formula(printed)(u, Q(1, 3)) == ut
        seen[j] += 1
    assert seen["b"] > 0 and seen["c"] > 0 and seen["corner"] > 0


def test_trigonometric_step_on_an_exact_state():
    """p = (0, 3/5, 4/5), q = (1, -2, -1): a collision b follows (cos φ > 0)."""
    P = R.plane("a", (Q(0), Q(3), Q(4)), (Q(1), Q(-2), Q(-1)))
    with precision(128):
        T = R.angles(P)
        assert T.ct.overlaps(flint.arb(Q(3, 5))) and T.st.overlaps(flint.arb(Q(4, 5)))
        T1, X = R.trig_step(T, Q(1, 10)), R.angles(R.step(P, Q(1, 10)))
    assert T1.letter == X.letter == "b"
    assert all(a.overlaps(b) for a, b in ((T1.ct, X.ct), (T1.cp, X.cp)))


def _trig_agreement_step_by_step(planes, r, prec, closed=False):
    """What S7.2 compared before trig_agreement: trig_step from angles(P) against angles(P1), pair
    by pair (with ``closed``, the angles of closed_angles)."""
    def angles(P):
        return R.Angles(*R.closed_angles(P.letter, P.n)) if closed else R.angles(P)
    agree = undecided = 0
    for P, P1 in zip(planes, planes[1:]):
        try:
            with precision(prec):
                T, X = R.trig_step(angles(P), r), angles(P1)
            agree += T.letter == P1.letter and all(a.overlaps(b) for a, b in
                                                   ((T.ct, X.ct), (T.st, X.st), (T.cp, X.cp), (T.sp, X.sp)))
        except sim.Undecided:
            undecided += 1
    return agree, undecided


@pytest.mark.parametrize("prec", [128, 2])
def test_trig_agreement_is_the_step_by_step_comparison(prec):
    """trig_agreement counts what trig_step gives pair by pair from the closed-form angles (at any
    precision: the same ball operations; at 2 bits signs go undecided), and at 128 bits what it gives
    from angles(): on exact orbits (all agree), and on orbits with planes swapped (some steps then
    disagree)."""
    rng, seen = random.Random(7), set()
    for r0 in (Q(1, 10), Q(1, 37), Q(50, 99)):
        orbits = []
        for letter in LETTERS:
            n = [rng.randint(-30, 30) for _ in range(3)]
            try:
                P = R.canonical(letter, n)
                R.next_letter(P)
            except (R.Corner, ValueError):
                continue
            planes = R.orbit(P, r0, 120)
            orbits += [planes, planes[:40:2] + planes[40:]]
        for planes in orbits:
            got = R.trig_agreement(planes, r0, prec)
            assert got == _trig_agreement_step_by_step(planes, r0, prec, closed=True)
            if prec >= 64:
                assert got == _trig_agreement_step_by_step(planes, r0, prec)
            seen.add((got[0] + got[1] == len(planes) - 1, got[1] > 0))
    assert (False, False) in seen or (False, True) in seen     # some disagreement was counted
    assert (True, prec < 64) in seen


@settings(max_examples=300, deadline=None)
@given(st.sampled_from(LETTERS), st.tuples(*[st.integers(-10 ** 40, 10 ** 40) | st.integers(-3, 3)] * 3))
def test_closed_angles_are_the_angles(letter, n):
    """closed_angles are balls of the numbers angles() encloses (overlapping at 128 bits, within
    2^-400 at 512 bits), or the same Corner."""
    n = tuple(map(flint.fmpz, n))
    P = R.Plane(letter, n)
    try:
        A = R.angles(P, 512)
    except R.Corner:
        with pytest.raises(R.Corner):
            R.closed_angles(letter, n)
        return
    for prec in (128, 512):
        with precision(prec):
            A, C = R.angles(P), R.closed_angles(letter, n)
        assert C[0] == letter
        for a, c in zip((A.ct, A.st, A.cp, A.sp), C[1:]):
            assert a.overlaps(c)
            if prec == 512:
                assert abs(a.mid() - c.mid()) < flint.arb(2) ** -400


def test_admissible_words_and_blocks():
    """The windows the proofs allow are the words with no letter twice in a row and no aca, cac."""
    allowed = RC.transitions(CTX.get("reduction_cones"))
    assert allowed == {("a", "b"): {"a", "c"}, ("a", "c"): {"b"}, ("b", "a"): {"b", "c"}, ("b", "c"): {"a", "b"},
                       ("c", "a"): {"b"}, ("c", "b"): {"a", "c"}}
    for n in range(1, 7):
        by_hand = ["".join(w) for w in itertools.product(LETTERS, repeat=n)
                   if all(x != y for x, y in zip(w, w[1:])) and "aca" not in "".join(w) and "cac" not in "".join(w)]
        assert sorted(RC.admissible(n, allowed)) == sorted(by_hand)
    assert len(RC.admissible(3, allowed)) == 10
    assert S43.parses("abcbacbca", ["ab", "cb", "acb", "cab"])       # ab cb acb + "ca" cut short
    assert not S43.parses("babcb", ["ab", "cb", "acb", "cab"])
    assert S43.offsets(S43.PRINTED_S10["window"]) == {2, 3}
    assert S43.implication(S43.PRINTED_S9["cac"]) == ("ca", "c")


def test_conversions_round_trip():
    """trigonometric → vectorial → projective → trigonometric: on rational points of
    the circles (cos θ, sin θ) = (3/5, 4/5), (cos φ, sin φ) = (∓5/13, 12/13), u = p(0) ∧ q(0)
    is exact, its Plane has the contact's orientation, and angles() gives θ, φ back."""
    for L in LETTERS:
        for cp in (Q(5, 13), Q(-5, 13)):
            A = R.Angles(L, Q(3, 5), Q(4, 5), cp, Q(12, 13))
            P = R.canonical(L, A.u())
            assert R.primitive(A.u()) == P.n                  # the printed orientation e_t · u > 0
            with precision(128):
                B = R.angles(P)
            assert all(flint.arb(x).overlaps(y) for x, y in ((A.ct, B.ct), (A.st, B.st), (A.cp, B.cp), (A.sp, B.sp)))
            assert R.next_letter(P) == R.CASES[(L, 1 if cp > 0 else -1)][0]


def test_altered_refuses_a_text_that_is_not_printed():
    with pytest.raises(ValueError):
        altered("S10", "blocks", "bca", "abc")


def test_verdicts_rest_on_the_proofs_not_on_the_samples():
    """S9.2, S10 and S11 keep their verdicts when the scan is replaced by a word that
    contradicts them (aca, a corner after 6 collisions) and the particle runs by none:
    the scan and the runs are supporting evidence; the proofs on the cones decide."""
    ctx = Context()
    ctx.values["reduction_scan"] = [S41.ScanOrbit(Q(1, 2), R.canonical("a", [1, 1, -1]), "acacab", 1)]
    ctx.values["section4_data"] = []
    for id in ("S9.2", "S10", "S11"):
        out = run_certificate(CERTIFICATES[id], ctx)
        assert out.status == CERTIFICATES[id].expect, (id, [c.statement for c in out.printed if not c.holds])
        assert any(e.startswith("Supporting evidence, not proof") for e in out.evidence)


def test_s10_erratum_is_the_leading_b():
    """The block decomposition fails because every state of a cone whose next contact is b
    starts its word with b (an exact witness by the engine), and holds without that b."""
    out = outcome("S10")
    failing = [c for c in out.printed if not c.holds]
    assert len(failing) == 1 and "concatenation" in failing[0].statement
    assert sum("has c_1 = b" in e for e in failing[0].evidence) == 2
    assert all(c.holds for c in out.corrected) and "first letter when that is b" in out.corrected[-1].statement


def test_a_wrong_proof_fails_whatever_the_samples():
    """With the step lemmas replaced by ones computed from a wrong C, S9.2 and S10 FAIL."""
    ctx = Context()
    wrong = {L: collision_matrix(L) for L in LETTERS}
    wrong["c"] = wrong["c"].subs(-r, r)
    ctx.values["reduction_cones"] = RC.steps(wrong)
    ctx.values["section4_data"] = []
    ctx.values["reduction_scan"] = CTX.get("reduction_scan")
    for id in ("S6", "S7.2", "S8.2", "S9.2", "S10", "S11"):
        out = run_certificate(CERTIFICATES[id], ctx)
        assert out.status == FAIL, id
        if id in ("S6", "S7.2"):                  # the lemmas are the only failing checks
            assert [c.statement for c in out.printed if not c.holds] == [
                c.statement for c in out.printed if "six cones" in c.statement]


def test_s7_case_check_fails_on_an_altered_case():
    """The printed case a, cos φ > 0 with the pair 3-4: its proof (S7.1's step, and the
    projective map's step) fails, and the other five cases still hold."""
    out = outcome("S7.2", **declared("S7.2", altered("S7.2", "a_pos", "2-3", "3-4")))
    cases = [c for c in out.printed if "the printed step (S7.1) is the projective map's step" in c.statement
             or c.statement.endswith("the printed step (as in S7.1)")]
    assert len(cases) == 6 and [c.holds for c in cases] == [False, True, True, True, True, True]


def test_s8_corrected_c_formula_is_proven_and_the_printed_one_refuted():
    out = outcome("S8.2")
    fixed = [c for c in out.corrected if "u(0) ∧ e_z" in c.statement]
    assert len(fixed) == 1 and fixed[0].holds and any("their cross product" in e for e in fixed[0].evidence)
    assert any(e.startswith("Supporting evidence, not proof") and "0 of 261 collisions a→c" in e for e in out.evidence)


def test_ball_run_follows_the_exact_orbit_and_encloses_its_oriented_normal():
    """ball_run (identify's second route) on a rational state: the same letters as the exact
    reduction, and its last ball contains a positive multiple of the exact oriented normal
    (the ratios n_k / n_t enclose the exact ones, n_t > 0)."""
    r = flint.fmpq(3, 10)
    P = R.canonical("b", (-3, 1, 4))
    exact, last = R.word_of(P, r, 60)
    letters, L, n = R.ball_run("b", P.n, r, 60, 512)
    assert letters == exact and L == last.letter
    t = R.ORIENTATION[L]
    assert n[t] > 0 and last.n[t] > 0
    for k in range(3):
        assert (n[k] / n[t]).contains(flint.fmpq(last.n[k], last.n[t]))
    assert len(R.ball_run("b", P.n, r, 60, 16)[0]) < 60          # too few bits: stops at an undecided sign


def _decided(f, *args):
    try:
        return f(*args)
    except (R.Corner, sim.Undecided):
        return "refused"


def test_the_ball_next_letter_decides_as_next_letter():
    """ball_run's _next_index_ball against next_letter on a Plane of the same balls: the same
    letter, or both refusing (a corner, or a sign the balls do not decide), on balls that
    straddle 0, exact zeros and decided entries of every sign, at every contact."""
    rng = random.Random(3)
    choices = [flint.arb(0), flint.arb(0, 1), flint.arb(1, Q(1, 2)), flint.arb(-2, Q(1, 3)), flint.arb(3),
               flint.arb(-1)]
    with precision(64):
        for _ in range(400):
            letter = rng.choice(LETTERS)
            n = tuple(rng.choice(choices) * rng.choice((1, 2)) for _ in range(3))
            plane = _decided(lambda: R.next_letter(R.Plane(letter, n)))       # noqa: B023
            k = R._next_index_ball(R.INDEX[letter], n)
            assert (LETTERS[k] if k >= 0 else "refused") == plane, (letter, n)


@settings(max_examples=100, deadline=None)
@given(st.sampled_from(LETTERS), st.tuples(*[st.integers(-60, 60)] * 3), st.integers(1, 99), st.integers(1, 3))
def test_orbit_is_step_after_step(letter, n, k, c):
    """orbit() (the content of each new normal read off det M) is step() applied again and again
    from canonical(P), a corner included; a start normal that is not primitive (c > 1) too."""
    r0 = flint.fmpq(k, 100)
    try:
        P = R.canonical(letter, n)
    except (R.Corner, ValueError):
        return
    start = R.Plane(letter, tuple(c * z for z in P.n))
    want, rows = [start], R.cofactors(r0)
    for _ in range(40):
        try:
            want.append(R.step(want[-1], r0, rows))
        except R.Corner:
            break
    assert R.orbit(start, r0, 40) == want


@settings(max_examples=100, deadline=None)
@given(st.sampled_from(LETTERS), st.tuples(*[st.integers(-30, 30)] * 3), st.integers(1, 99),
       st.sampled_from([1, 2, 5, 64]))
def test_word_of_on_integers_is_the_plane_path(letter, n, k, every):
    """word_of on an integer normal (no Plane per step) gives the letters and the end of the
    Plane path (taken for a rational normal), a corner included."""
    r0 = flint.fmpq(k, 100)
    exact = R.Plane(letter, tuple(flint.fmpz(z) for z in n))
    plane = R.Plane(letter, tuple(flint.fmpq(z) for z in n))
    try:
        want = R.word_of(plane, r0, 60, every)
    except (R.Corner, ValueError) as exc:
        with pytest.raises(type(exc)):
            R.word_of(exact, r0, 60, every)
        return
    assert R.word_of(exact, r0, 60, every) == want


@settings(max_examples=200, deadline=None)
@given(st.sampled_from(LETTERS), st.tuples(*[st.integers(-10 ** 30, 10 ** 30) | st.integers(-3, 3)] * 3),
       st.integers(1, 99), st.integers(1, 99))
def test_vectorial_ray_is_the_vectorial_step_up_to_a_positive_factor(letter, u, m, d):
    """collide_integral is 2d·collide; vectorial_ray gives the contact of vectorial_step and a
    positive multiple of its ũ(1) (or the same Corner); same_ray is v ∧ w = 0 and v · w > 0."""
    r0 = flint.fmpq(m, d)
    u = tuple(flint.fmpz(z) for z in u)
    assert collide_integral(letter, u, r0) == tuple(2 * r0.q * z for z in collide(letter, u, r0))
    try:
        j, ut = R.vectorial_step(letter, u, r0)
    except R.Corner:
        with pytest.raises(R.Corner):
            R.vectorial_ray(letter, u, r0)
        return
    j2, ray = R.vectorial_ray(letter, u, r0)
    assert j2 == j and ray == tuple(2 * r0.q * z for z in ut)
    for v, w in ((ray, ut), (ut, u), (u, tuple(-z for z in u)), (u, (0, 0, 0)), ((0, 0, 0), u), (u, u)):
        assert R.same_ray(v, w) == (R.cross(v, w) == (0, 0, 0) and R.dot(v, w) > 0)


@settings(max_examples=200, deadline=None)
@given(st.tuples(*[st.integers(-10 ** 12, 10 ** 12)] * 2), st.tuples(*[st.integers(-10 ** 12, 10 ** 12)] * 2),
       st.integers(1, 10 ** 6), st.tuples(*[st.integers(-4, 4)] * 3))
def test_normal_with_a_candidate_is_the_normal(p, q, q1, other):
    """normal(p, q, candidate) and plane(..., candidate) are normal(p, q) and plane(...) whatever
    the primitive candidate: the answer, its opposite, another vector, one with zeros."""
    p, q = (flint.fmpz(0),) + tuple(map(flint.fmpz, p)), (flint.fmpz(q1),) + tuple(map(flint.fmpz, q))
    if not any(R.cross(p, q)):
        return
    want = R.normal(p, q)
    candidates = [want, tuple(-z for z in want), (flint.fmpz(0), flint.fmpz(0), flint.fmpz(1))]
    if any(other):
        candidates.append(R.primitive(tuple(map(flint.fmpz, other))))
    for c in candidates:
        assert R.normal(p, q, c) == want
        try:
            P = R.plane("a", p, q)
        except R.Corner:
            with pytest.raises(R.Corner):
                R.plane("a", p, q, c)
            continue
        assert R.plane("a", p, q, c) == P


@settings(max_examples=100, deadline=None)
@given(st.tuples(*[st.integers(-10 ** 20, 10 ** 20)] * 3), st.integers(1, 99), st.integers(1, 99),
       st.sampled_from([S42.TRILINEAR_B, S42.TRILINEAR_C, S42.TRILINEAR_C_CORRECTED,
                        "cross(B*u0, C*cross(u0, ey))", "A*(B*(C*u0))", "cross(ex, u0)"]))
def test_integral_formula_is_a_positive_multiple(u, m, d, text):
    """formula(text, integral=True) is (2d)^k times formula(text), k the number of matrices
    applied: the same ray, in integers (what tally_runs compares)."""
    r0, u = Q(m, d), tuple(flint.fmpz(z) for z in u)
    exact, scaled = R.formula(text)(u, r0), R.formula(text, integral=True)(u, r0)
    k = sum(text.count(f"{L}*") for L in "ABC")
    assert all(type(z) is flint.fmpz for z in scaled)
    assert scaled == tuple((2 * r0.q) ** k * z for z in exact)       # r0 = m/d in lowest terms


def _occurrences(words, pattern):
    return sum(sum(w.startswith(pattern, k) for k in range(len(w))) for w in words)


def _parses(word, blocks):
    k = 0
    while k < len(word):
        nxt = [B for B in blocks if word.startswith(B, k)]
        if not nxt:
            return any(B.startswith(word[k:]) for B in blocks)
        k += len(nxt[0])
    return True


def _window_holds(words, ks):
    seen = good = 0
    for w in words:
        for k, L in enumerate(w):
            if L == "b" and k + max(ks) < len(w):
                seen += 1
                good += any(w[k + m] == "b" for m in ks)
    return seen, good


@settings(max_examples=300, deadline=None)
@given(st.lists(st.text("abc", max_size=40), max_size=4), st.text("abc", max_size=3),
       st.lists(st.sampled_from(["ab", "cb", "acb", "cab", "a", "b", "ba", "abc", "c"]), max_size=5, unique=True),
       st.sets(st.integers(1, 4), min_size=1))
def test_word_counts_are_the_letter_by_letter_ones(words, pattern, blocks, ks):
    """occurrences (S9.2), parses and window_holds (S10), by regular expressions and str.find, count
    what the letter-by-letter definitions count (overlaps, the first block that fits, short words)."""
    assert S41.occurrences(words, pattern) == _occurrences(words, pattern)
    assert [S43.parses(w, blocks) for w in words] == [_parses(w, blocks) for w in words]
    assert S43.window_holds(words, ks) == _window_holds(words, ks)


@given(st.sampled_from(LETTERS), st.tuples(*[st.integers(-50, 50)] * 3))
def test_oriented_reads_the_sign_of_an_integer_entry(letter, n):
    """oriented on fmpz entries is oriented on fmpq entries: the orientation e_t · n > 0 (a corner alike)."""
    t = R.ORIENTATION[letter]
    zs, qs = tuple(map(flint.fmpz, n)), tuple(map(Q, n))
    if n[t] == 0:
        for v in (zs, qs):
            with pytest.raises(R.Corner):
                R.oriented(letter, v)
        return
    P, P2 = R.oriented(letter, zs), R.oriented(letter, qs)
    assert P.letter == P2.letter == letter and P.n[t] > 0 and tuple(map(Q, P.n)) == P2.n


@pytest.mark.parametrize("A, B, C", [(S41.A_PRINTED, S41.B_PRINTED, S41.C_PRINTED),
                                     (S41.A_PRINTED.replace("[(1+r)/2, 1, 0]", "[(1+3*r)/3, 1, 0]"),
                                      S41.B_PRINTED.replace("[[1, (1+r)/2, 0]", "[[2, (1+r)/2, 0]"),
                                      S41.C_PRINTED.replace("[0, 0, -r]", "[0, 1/(1+r), -r]"))])
def test_multiples_at_the_rates_are_multiple(A, B, C):
    """S6's multiples (cof evaluated in fmpq at every rate) are multiple() of cof.xreplace, rate by
    rate: k > 0 where the engine's integer matrix is k·cof, None elsewhere (a mutated print; an
    entry that is not a polynomial in r goes to multiple itself)."""
    rates = sorted({Q(1, 3), Q(1, 10), Q(2, 7), Q(50, 99)})
    for letter, text in zip(LETTERS, (A, B, C)):
        cof = S41.matrix(text).adjugate().T
        for K in (letter, "abc"[(INDEX[letter] + 1) % 3]):        # the matching integer matrices, and others
            integer = [R.cofactor(K, r0) for r0 in rates]
            want = [S41.multiple(N_, cof.xreplace({r: sp.Rational(int(v.p), int(v.q))}))
                    for N_, v in zip(integer, rates)]
            got = S41.multiples(integer, cof, rates)
            assert got == want and [type(k) for k in got] == [type(k) for k in want]
            if A == S41.A_PRINTED and K == letter:
                assert all(k is not None and k > 0 for k in got)


@settings(max_examples=300, deadline=None)
@given(st.sampled_from(LETTERS), st.tuples(*[st.integers(-3, 3) | st.integers(-10 ** 30, 10 ** 30)] * 3))
def test_next_letter_of_an_integer_normal_is_the_generic_one(letter, n):
    """next_letter on fmpz entries (the signs read once, _next_letter_exact) gives the letter, or
    the Corner with the same message, that the generic path gives on the same normal in fmpq."""
    zs, qs = tuple(map(flint.fmpz, n)), tuple(map(Q, n))
    try:
        want = R.next_letter(R.Plane(letter, qs))
    except R.Corner as exc:
        with pytest.raises(R.Corner) as got:
            R.next_letter(R.Plane(letter, zs))
        assert ("interior" in str(got.value)) == ("interior" in str(exc))      # the same kind of corner
        return
    assert R.next_letter(R.Plane(letter, zs)) == want
