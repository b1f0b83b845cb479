"""The candidate of a word on python-flint (certify.algebra.poly.Frac) equals, field by
field, the candidate computed in SymPy's rational function field K (the reference
below is the former implementation, kept verbatim in substance)."""
import pytest
import sympy as sp

from certify.algebra.poly import FIELD, RING, Lf, Rf, from_flint, lam, r, to_field, to_ring
from certify.dynamics.model import characteristic_polynomial, word_matrix
from certify.dynamics.systems import BY_NAME, candidate_in, eigenvector2, run_in, system_matrix, system_matrix_flint
from certify.dynamics.words import check_position_map, eigenvector, position_map, run_word

K = FIELD


def ref_word_matrix(system, word):
    """M_w with SymPy's factor (the former word_matrix/system_matrix): the product is the
    engine's, what is compared is factor_flint against sp.factor."""
    n = system.gaps
    M = system_matrix_flint(system, word)
    return sp.Matrix(n, n, lambda i, j: sp.factor(from_flint(M[i][j], r)))


def ref_eigenvector(M, rows=(0, 1)):
    A = [[M[i][j] - (Lf if i == j else K.zero) for j in range(3)] for i in range(3)]
    (a11, a12), (a21, a22) = [(A[i][1], A[i][2]) for i in rows]
    b1, b2 = (A[i][0] for i in rows)
    det = a11 * a22 - a12 * a21
    return (-K.one, (b1 * a22 - a12 * b2) / det, (a11 * b2 - b1 * a21) / det)


def ref_run(system, word, q0):
    n = system.gaps
    p = [(K.one, K.zero), (K.zero, K.zero)] + ([(K.zero, K.one)] if n == 3 else [])
    q = tuple(q0)
    out = []
    for letter in word:
        i = system.index[letter]
        t = (-p[i][0] / q[i], -p[i][1] / q[i])
        p = [(P0 + t[0] * qj, P1 + t[1] * qj) for (P0, P1), qj in zip(p, q)]
        p[i] = (K.zero, K.zero)
        q = system.collide(letter, q, Rf)
        out.append((letter, p, q))
    return out


def ref_position_map(last_p, cp):
    (d0, c0), (b0, a0) = last_p[0], last_p[2]
    den = RING.one
    for e in (a0, b0, c0, d0):
        den = den.lcm(e.denom)
    C = to_ring(cp)
    return tuple((e.numer * den.quo(e.denom)).rem(C).as_expr() for e in (a0, b0, c0, d0))


def ref_candidate(system_name, word):
    system = BY_NAME[system_name]
    if system_name == "four":
        M = ref_word_matrix(system, word)
        cp = sp.expand(M.charpoly(lam).as_expr())
        Mk = [[to_field(e) for e in row] for row in M.tolist()]
        q0 = ref_eigenvector(Mk)
        run = ref_run(system, word, q0)
        abcd = ref_position_map(run[-1][1], cp)
        others = [ref_eigenvector(Mk, rows) for rows in ((0, 2), (1, 2))]
        return M, cp, q0, others, abcd, run
    M = ref_word_matrix(system, word)
    cp = sp.expand(M.charpoly(lam).as_expr())
    (m11, m12), (m21, m22) = [[to_field(e) for e in row] for row in M.tolist()]
    first = (-K.one, (m11 - Lf) / m12 if m12 != K.zero else None)
    second = (-K.one, m21 / (m22 - Lf))
    q0 = first if first[1] is not None else second
    others = [second] if first[1] is not None else []
    return M, cp, q0, others, None, ref_run(system, word, q0)


def same(e, f):
    """Equal elements of K, with the very same (canonical) numerator and denominator."""
    return e == f and e.numer == f.numer and e.denom == f.denom and type(e) is type(f)


WORDS = [("four", w) for w in ("ababcb", "abcab", "ababacbcb", "abacbcb", "abcbab", "abacbab", "ababcbcb",
                               "abacbcabcb", "abcbacbab", "ababababcbcbcbcb", "abacbcabacbcbcab", "abcabcbab",
                               "abababcbcb", "abcacbcb")] + \
        [("three", w) for w in ("ab", "aab", "abb", "aabab", "abaabb")] + \
        [("symmetric", w) for w in ("sb", "ssb", "sbsbb")]


@pytest.mark.parametrize("system,word", WORDS)
def test_candidate_equals_the_sympy_field_computation(system, word):
    try:
        ref = ref_candidate(system, word)
    except ZeroDivisionError:
        with pytest.raises(ZeroDivisionError):
            candidate_in.__wrapped__(system, word)
        return
    new = candidate_in.__wrapped__(system, word)
    M, cp, q0, others, abcd, run = ref
    assert new.M == M and new.cp == cp
    assert [sp.srepr(e) for e in new.M] == [sp.srepr(e) for e in M] and sp.srepr(new.cp) == sp.srepr(cp)
    if system == "four":
        assert word_matrix(word) == M and characteristic_polynomial(M) == cp
    else:
        assert system_matrix(BY_NAME[system], word) == M
    assert len(new.q0) == len(q0) and all(same(a, b) for a, b in zip(new.q0, q0))
    assert len(new.q0_other) == len(others)
    for qa, qb in zip(new.q0_other, others):
        assert all(same(a, b) for a, b in zip(qa, qb))
    assert new.abcd == abcd
    assert len(new.steps) == len(run)
    for step, (letter, p, q) in zip(new.steps, run):
        assert step.letter == letter
        assert all(same(a, b) for a, b in zip(step.q, q)) and len(step.q) == len(q)
        assert len(step.p) == len(p)
        assert all(same(a, b) and same(c, d) for (a, c), (b, d) in zip(step.p, p))
    if abcd is not None:
        check_position_map(new.steps, new.abcd, new.cp)
        assert position_map(new.steps, new.cp) == abcd
        Mk = [[to_field(e) for e in row] for row in M.tolist()]
        assert all(same(a, b) for a, b in zip(eigenvector(Mk), q0))
        assert all(same(a, b) for (_, pa, _), sb in zip(run, run_word(word, q0)) for a, b in
                   zip((e for pair in pa for e in pair), (e for pair in sb.p for e in pair)))
    else:
        steps = run_in(BY_NAME[system], word, q0)
        assert all(same(a, b) for (_, pa, _), sb in zip(run, steps) for a, b in
                   zip((e for pair in pa for e in pair), (e for pair in sb.p for e in pair)))
        Mk = [[to_field(e) for e in row] for row in M.tolist()]
        assert eigenvector2(Mk)[1] == (-K.one, to_field(Mk[1][0]) / (Mk[1][1] - Lf))


def test_position_map_rejects_a_wrong_map():
    c = candidate_in("four", "abcab")
    a, b, cc, d = c.abcd
    with pytest.raises(ArithmeticError):
        check_position_map(c.steps, (2 * a, b, 2 * cc, d), c.cp)


def test_factor_and_charpoly_on_flint_are_sympys():
    """factor_flint/charpoly_flint give the very expressions of sp.factor and
    sp.expand(charpoly) (constants, signs, rational contents, repeated factors)."""
    from certify.algebra.poly import to_fmpq_poly
    from certify.dynamics.model import charpoly_flint, factor_flint, word_matrix_flint
    for e in [0, sp.Rational(3, 2), -r, 1 - r, (1 - r)**2 * (3 + r) / 4, -(r**2 + 1) * (r - 2) / 6, 2 * r, r**3]:
        p = to_fmpq_poly(e)
        assert sp.srepr(factor_flint(p)) == sp.srepr(sp.factor(from_flint(p, r)))
    for w in ("ababcb", "abcbacbab", "abacbcabacbcbcab"):
        Mq = word_matrix_flint(w)
        M = sp.Matrix(3, 3, lambda i, j, Mq=Mq: sp.factor(from_flint(Mq[i][j], r)))
        assert sp.srepr(charpoly_flint(Mq)) == sp.srepr(sp.expand(M.charpoly(lam).as_expr()))
