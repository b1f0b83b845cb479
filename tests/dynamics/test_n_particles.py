"""N particles (issue 39): the law K_i = I + w_i e_iᵀ on the gaps against the exact N-particle
simulation, collision by collision (N = 5, 6), period matrices, and N = 4 the paper's law."""
from fractions import Fraction

import flint
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from certify import cli
from certify.algebra.poly import lam
from certify.dynamics import particles
from certify.dynamics import simulate as sim
from certify.dynamics.model import (
    alphabet,
    charpoly_coefficients,
    charpoly_flint,
    check_word,
    collide,
    collide_gaps,
    collide_particles,
    particles_of,
    word_matrix_flint,
)
from certify.dynamics.particles import evolve
from certify.dynamics.systems import FOUR, THREE, of_particles, system_matrix, system_matrix_flint
from certify.errors import UsageError

Q = flint.fmpq
R = sp.Symbol("r")


def fmpq_of(f: Fraction) -> flint.fmpq:
    return Q(f.numerator, f.denominator)


def issue_matrix(i: int, gaps: int) -> sp.Matrix:
    """K_i = I + w_i e_iᵀ, w_i = h e_{i-1} - (1 + r) e_i + h e_{i+1}, as written in issue 39
    (0-based i, entries outside the gaps dropped): built here from the formula, not from the engine."""
    h = (1 + R) / 2
    w = sp.zeros(gaps, 1)
    w[i] = -(1 + R)
    if i > 0:
        w[i - 1] = h
    if i + 1 < gaps:
        w[i + 1] = h
    e = sp.zeros(gaps, 1)
    e[i] = 1
    return sp.eye(gaps) + w * e.T


def engine_matrix(letter: str, gaps: int) -> sp.Matrix:
    """The matrix of :func:`collide_gaps` read column by column."""
    cols = [collide_gaps(letter, tuple(sp.Integer(int(k == j)) for k in range(gaps)), R) for j in range(gaps)]
    return sp.Matrix(gaps, gaps, lambda i, j: sp.sympify(cols[j][i]))


# --------------------------------------------------------------------------
# The law, symbolically

@pytest.mark.parametrize("n", [3, 4, 5, 6, 7])
def test_the_law_is_the_issue_formula(n):
    for i, letter in enumerate(alphabet(n)):
        assert (engine_matrix(letter, n - 1) - issue_matrix(i, n - 1)).applyfunc(sp.expand) == sp.zeros(n - 1)


@pytest.mark.parametrize("letter", "abc")
def test_four_particles_are_the_paper(letter):
    """For N = 4 the N-particle law is the printed A, B, C (model.collide), as an identity in r, q."""
    q = sp.symbols("q1:4")
    assert all(sp.expand(x - y) == 0 for x, y in zip(collide_gaps(letter, q, R), collide(letter, q, R)))
    assert of_particles(4) is FOUR and of_particles(3) is THREE


@pytest.mark.parametrize("n", [5, 6])
def test_differences_of_the_particle_law_are_the_gap_law(n):
    """diff(v') = K_i diff(v) for every pair of N particles, identically in r, v1..vN."""
    v = sp.symbols(f"v1:{n + 1}")
    for letter in alphabet(n):
        w = collide_particles(letter, v, R)
        assert all(sp.expand(a - b) == 0 for a, b in
                   zip(particles.differences(w), collide_gaps(letter, particles.differences(v), R)))


@pytest.mark.parametrize("n", [5, 6])
def test_letters_beyond_the_alphabet_are_refused(n):
    beyond = "abcdefg"[n - 1]
    with pytest.raises(ValueError):
        collide_gaps(beyond, (1,) * (n - 1), Q(1, 2))
    with pytest.raises(ValueError):
        collide_particles(beyond, (1,) * n, Q(1, 2))
    with pytest.raises(ValueError):
        of_particles(n).collide(beyond, (1,) * (n - 1))


# --------------------------------------------------------------------------
# Period matrices and their characteristic polynomials

@pytest.mark.parametrize("word", ["abcd", "abcdcb", "adbc", "abacbdcb", "dcbabcbd"])
def test_period_matrix_and_charpoly_of_five_particle_words(word):
    """M_w = K_{c_n} ... K_{c_1} (the issue's K_i multiplied by SymPy) and its quartic det(λI - M_w)
    (python-flint, Faddeev-LeVerrier) against SymPy's charpoly; det M_w = (-r)^n."""
    S = of_particles(5)
    M = sp.eye(4)
    for letter in word:
        M = issue_matrix(alphabet(5).index(letter), 4) * M
    assert (system_matrix(S, word) - M).applyfunc(sp.expand) == sp.zeros(4)
    cp = charpoly_flint(system_matrix_flint(S, word))
    assert sp.expand(cp - M.charpoly(lam).as_expr()) == 0
    assert sp.Poly(cp, lam).degree() == 4
    assert sp.expand(cp.subs(lam, 0) - (-R) ** len(word)) == 0


def test_charpoly_of_three_by_three_unchanged():
    """The cubic of a four-particle word by Faddeev-LeVerrier equals the cofactor route."""
    from certify.dynamics.model import faddeev_leverrier
    M = word_matrix_flint("ababcb")
    assert faddeev_leverrier(M) == charpoly_coefficients(M)


# --------------------------------------------------------------------------
# The exact N-particle simulation, collision by collision

rationals = st.fractions(min_value=-5, max_value=5, max_denominator=20).map(fmpq_of)
small_r = st.fractions(min_value=0, max_value=1, max_denominator=40).filter(lambda f: 0 < f < 1).map(fmpq_of)


def data(n: int):
    """Ordered positions and velocities of n particles, some of them mirror-symmetric."""
    generic = st.tuples(st.lists(rationals, min_size=n, max_size=n).map(sorted),
                        st.lists(rationals, min_size=n, max_size=n))
    k, mid = n // 2, [Q(0)] * (n % 2)

    def mirrored(z):
        a, w = sorted(abs(e) for e in z[:k]), z[k:]
        return ([-e for e in reversed(a)] + mid + a, list(reversed(w)) + mid + [-e for e in w])
    mirror = st.lists(rationals, min_size=2 * k, max_size=2 * k).map(mirrored)
    return st.one_of(generic, mirror)


def check_against_the_gap_law(x, v, r, n: int, collisions: int) -> particles.History:
    """The particle run (absolute law) and the gap run (K_i) agree collision by collision: the
    same letters, times, p = diff(x), q = diff(v); and q after k collisions is M_{w_k}(r) q(0),
    M the period matrix of the prefix (python-flint polynomials in r evaluated at r)."""
    h = evolve(x, v, r, collisions, particles=n)
    diff = particles.differences
    run = sim.follow_gaps(diff(h.x), diff(h.v), h.r, collisions)
    assert run.events == [c.letters for c in h.collisions]
    assert {"n": "n", "free": "separate", "multiple": "triple"}[run.stop] == h.stop
    q0 = diff(h.v)
    flat = ""
    S = of_particles(n)
    for s, c in zip(run.states[1:], h.collisions):
        assert (s.t, s.p, s.q) == (c.t, diff(c.x), diff(c.v))
        assert all(c.x[i] == c.x[i + 1] for i in (alphabet(n).index(L) for L in c.letters))
        flat += c.letters
        M = system_matrix_flint(S, flat)
        assert tuple(sum((M[i][j](h.r) * q0[j] for j in range(n - 1)), Q(0)) for i in range(n - 1)) == diff(c.v)
    return h


@pytest.mark.parametrize("n", [5, 6])
@settings(max_examples=40, deadline=None)
@given(st.data())
def test_gap_law_against_the_particle_simulation(n, draw):
    x, v = draw.draw(data(n))
    r = draw.draw(small_r)
    check_against_the_gap_law(x, v, r, n, 25)


SEVERAL = {   # (x, v, r): data with 60 collisions over every letter (found by a small random search)
    5: [([2, 5, 7, 8, 10], [1, 1, "1/2", "1/3", "1/3"], "1/5"),
        ([0, 2, 6, 8, 9], ["-1/3", "-1/3", 1, "-1/2", -2], "1/7"),
        ([0, 1, 8, 10, 11], [2, "1/2", "1/3", "1/3", 0], "1/10"),
        ([3, 5, 7, 8, 9], [1, "1/3", 2, -2, "-1/2"], "1/20")],
    6: [([1, 3, 4, 5, 6, 11], [1, 2, -1, -1, 1, "-1/2"], "1/4"),
        ([0, 3, 5, 7, 10, 11], [2, 1, "-1/2", 0, 0, -2], "1/10"),
        ([3, 4, 5, 7, 8, 9], ["1/3", 1, "-1/2", "1/3", "1/2", "-1/3"], "1/5")],
}


@pytest.mark.parametrize("n", [5, 6])
def test_several_words(n):
    """Hand-picked data: long words using every pair; each checked collision by collision."""
    letters = set()
    for x, v, r in SEVERAL[n]:
        h = check_against_the_gap_law(x, v, r, n, 60)
        letters |= {L for c in h.collisions for L in c.letters}
        assert len(h.collisions) == 60, h.word
        assert len({L for c in h.collisions for L in c.letters}) >= 3
    assert letters == set(alphabet(n))


@settings(max_examples=60, deadline=None)
@given(data(4), small_r)
def test_four_particles_gap_simulator_is_the_paper_simulator(xv, r):
    """follow_gaps (the N-particle route) = follow (the four-particle one) for N = 4: same run,
    ties and multiple collisions included."""
    x, v = xv
    diff = particles.differences
    p, q = diff(x), diff(v)
    a, b = sim.follow(p, q, r, 30), sim.follow_gaps(p, q, r, 30)
    assert (a.events, a.stop, a.reason) == (b.events, b.stop, b.reason)
    assert [(s.t, s.p, s.q) for s in a.states] == [(s.t, s.p, s.q) for s in b.states]
    assert evolve(x, v, r, 30).word == a.word


def test_multiple_collision_of_five():
    """x = (0, 1, 2, 3, 4), v = (1, 1, 0, -1, -1): particles 2, 3, 4 meet at t = 1 (b and c tie);
    six particles 1 apart, v = (1, 0, 1, 0, 1, 0): a, c, e close together at t = 1, one event [ace]."""
    h = evolve([0, 1, 2, 3, 4], [1, 1, 0, -1, -1], "1/2", 5, particles=5)
    assert h.stop == "triple" and h.triple.particles == (2, 3, 4) and h.triple.t == 1
    h = evolve([0, 1, 2, 3, 4, 5], [1, 0, 1, 0, 1, 0], "1/2", 5, particles=6)
    assert h.collisions[0].letters == "ace" and h.word.startswith("[ace]")


# --------------------------------------------------------------------------
# Words and bad input

def test_words_of_n_particles():
    assert check_word("abcdcb", 5) == "abcdcb" and particles_of("abcdcb") == 5 and particles_of("abcb") == 4
    assert particles_of("ab") == 4 and particles_of("abcdeb") == 6


@pytest.mark.parametrize("word, n", [("abce", 5), ("abcd", 4), ("abcdefgb", 6)])
def test_a_letter_beyond_the_alphabet(word, n):
    with pytest.raises(UsageError) as exc:
        check_word(word, n)
    message = str(exc.value)
    assert "\n" not in message and f"use the letters {', '.join(alphabet(n))}" in message


def test_four_particle_message_unchanged():
    with pytest.raises(UsageError, match=r"^invalid pattern word 'abd': use the letters a, b, c$"):
        check_word("abd")


@pytest.mark.parametrize("x, v, n, message", [
    ([0, 1, 2, 3], [0, 0, 0, 0, 0], 5, "expected five values x1 x2 x3 x4 x5, got 4"),
    ([0, 1, 2, 3, 4], [0, 0, 0, 0, 0], 6, "expected six values x1 x2 x3 x4 x5 x6, got 5"),
    ([0, 1, 3, 2, 4], [0, 0, 0, 0, 0], 5, "x3 = 3 > x4 = 2"),
    ([0, 1], [0, 0], 2, "the number of particles must be an integer from 3 to 27, got 2"),
])
def test_invalid_n_particle_data(x, v, n, message):
    with pytest.raises(UsageError, match=message):
        evolve(x, v, "1/2", 3, particles=n)


def test_pattern_with_a_bad_five_particle_word_is_one_line_exit_2(capsys):
    """`certify pattern` takes five-particle words (tests/patterns/test_five.py); a bad one (a pair unused) is
    bad input: one line, exit 2."""
    assert cli.main(["pattern", "abdb"]) == 2
    out, err = capsys.readouterr()
    assert out == "" and err.count("\n") == 1 and err.startswith("certify: error: ")
