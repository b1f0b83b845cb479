"""The step lemma of the reduction on the six cones of states (certify/dynamics/cones.py):
the symbolic proof against the exact engine (certify.dynamics.reduction, certify.dynamics.simulate) at
random rational points of each cone, and what breaks when a matrix is wrong."""
import random

import flint
import pytest
import sympy as sp

from certify.algebra.poly import r
from certify.dynamics import cones as RC
from certify.dynamics import reduction as R
from certify.dynamics import simulate as sim
from certify.dynamics.model import INDEX, LETTERS, collision_matrix

Q = flint.fmpq
SECTION2 = {L: collision_matrix(L) for L in LETTERS}
STEPS = RC.steps(SECTION2)


def test_the_six_step_lemmas_hold():
    assert set(STEPS) == {(c, s) for c in LETTERS for s in (1, -1)}
    for (c, s), st in STEPS.items():
        assert st.holds, [x.statement for x in st.checks if not x.holds]
        # cos φ > 0 sends a contact to its cyclic successor (l. 881-929)
        assert st.following == LETTERS[(INDEX[c] + (1 if s > 0 else 2)) % 3]
    # Proposition 4.2: after a then c, cos φ' < 0; after c then a, cos φ' > 0; elsewhere free
    assert {k: st.cos_next for k, st in STEPS.items()} == {("a", 1): None, ("a", -1): -1, ("b", 1): None,
                                                          ("b", -1): None, ("c", 1): 1, ("c", -1): None}


def test_cones():
    for c in LETTERS:
        C = RC.cone(c)
        assert C.check.holds and C.sigma == -1 and C.eps == -1


def random_normal(st, rng):
    """An integer normal of the cone of ``st``: the signs of its hypotheses, random sizes."""
    return tuple(sg * rng.randint(1, 40) for sg in RC.representative(st))


@pytest.mark.parametrize("key", sorted(STEPS))
def test_the_engine_agrees_with_the_lemma(key):
    """At random points of the cone and random r: the engine's next contact is the lemma's,
    its next normal is a positive multiple of the lemma's n' = p' ∧ K_j w there, and a proven
    sign of n'_j is the engine's."""
    st, rng = STEPS[key], random.Random(sorted(STEPS).index(key))
    for _ in range(25):
        n, r0 = random_normal(st, rng), Q(rng.randint(1, 99), 100)
        P = R.canonical(st.contact, n)
        assert P.n == R.primitive(n)                  # the orientation of the cone is the engine's
        assert R.next_letter(P) == st.following
        nxt = R.step(P, r0)
        at = {**dict(zip(RC.N, n)), r: sp.Rational(int(r0.p), int(r0.q))}
        lemma = [st.normal[k].xreplace(at) for k in range(3)]
        ratio = {sp.Rational(int(a)) / b for a, b in zip(nxt.n, lemma)}
        assert len(ratio) == 1 and ratio.pop() > 0
        if st.cos_next is not None:
            assert R.sign(nxt.n[INDEX[st.following]]) == st.cos_next


@pytest.mark.parametrize("key", sorted(STEPS))
def test_the_particles_agree_with_the_lemma(key):
    """From a state of the cone, q = α w + λ p with α > 0 and λ of any sign: the particles
    collide next at the lemma's contact, or never, and then span the reduction's plane."""
    st, rng = STEPS[key], random.Random(7 + sorted(STEPS).index(key))
    i = INDEX[st.contact]
    outcomes = set()
    for _ in range(25):
        n, r0 = random_normal(st, rng), Q(rng.randint(1, 99), 100)
        P = R.canonical(st.contact, n)
        p, w = R.position(P), R.tangent(P)
        alpha, lam = Q(rng.randint(1, 20), rng.randint(1, 20)), Q(rng.randint(-40, 40), rng.randint(1, 10))
        q = tuple(alpha * wk + lam * pk for wk, pk in zip(w, p))
        assert p[i] == 0 and q[i] > 0
        nxt = sim.step(tuple(Q(z) for z in p), q, r0)
        if nxt is None:
            outcomes.add("never")
            assert all(z >= 0 for z in q)
            continue
        L, _t, p1, q1 = nxt
        outcomes.add(L)
        assert L == st.following and R.plane(L, p1, q1) == R.step(P, r0)
    assert st.following in outcomes


def test_a_wrong_matrix_breaks_the_lemma_where_it_is_used():
    """C with +r instead of −r: the pair c no longer separates after a collision c, so the
    lemma fails on the two cones whose next contact is c, and only there."""
    wrong = dict(SECTION2, c=SECTION2["c"].subs(-r, r))
    assert wrong["c"][2, 2] == r
    steps = RC.steps(wrong)
    broken = {k for k, st in steps.items() if not st.holds}
    assert broken == {k for k, st in STEPS.items() if st.following == "c"}
    for k in broken:
        failing = [c.statement for c in steps[k].checks if not c.holds]
        assert len(failing) == 1 and "separates" in failing[0]


def test_the_transitions_exclude_exactly_aca_and_cac():
    allowed = RC.transitions(STEPS)
    assert allowed[("a", "c")] == {"b"} and allowed[("c", "a")] == {"b"}
    assert all(len(z) == 2 for k, z in allowed.items() if k not in (("a", "c"), ("c", "a")))
    assert STEPS[("a", -1)].excludes("a").holds and not STEPS[("a", -1)].excludes("b").holds
    assert not STEPS[("a", 1)].excludes("a").holds and not STEPS[("a", 1)].excludes("c").holds
