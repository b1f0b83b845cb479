"""The points of a multiple eigenvalue (certify.patterns.eigenspace), undecided before, decided now;
each decision checked by a second route in SymPy (exact in Q(√2), Q(√3)): the eigenspace of
M(r₀) from SymPy's eigenvects, the word's velocities and positions from the paper's matrices."""
import sympy as sp

from certify.dynamics.model import INDEX, collision_matrix
from certify.dynamics.words import candidate
from certify.patterns.pattern import analyse

R = sp.Symbol("r")


def _regions_at(res, stage, digits):
    """The (branch, fixed point) whose set at ``stage`` holds the isolated point ≈digits."""
    out = set()
    for e in getattr(res, stage):
        for piece in e["pieces"]:
            if piece["kind"] == "point" and piece["at"]["digits"].startswith(digits):
                out.add((e["branch"], e["fixed_point"]))
    return out


def _run(word, q0, r0):
    """Velocities q(t_k) and positions p(t_k) = P0 + x P1 of ``word`` from p(0) = (1, 0, x),
    in SymPy (the paper's A, B, C at r = r0)."""
    x = sp.Symbol("x")
    q, p = sp.Matrix(q0), sp.Matrix([1, 0, x])
    out = [(p, q)]
    for letter in word:
        i = INDEX[letter]
        t = -p[i] / q[i]
        p = (p + t * q).applyfunc(sp.expand)
        p[i] = 0
        q = (collision_matrix(letter).subs(R, r0) * q).applyfunc(sp.radsimp)
        out.append((p, q))
    return out, x


def _feasible_datum(word, q0, r0):
    """Whether q0 realises ``word`` with one of the fixed points x of p_3(t_n)/p_1(t_n) (u > 0,
    x > 0, each pair approaching, each other gap open at each collision), exactly in SymPy."""
    steps, x = _run(word, q0, r0)
    p_end = steps[-1][0]
    for xv in sp.solve(sp.expand(p_end[2] - x * p_end[0]), x):
        xv = sp.radsimp(xv)
        if not xv.is_real or not xv > 0:
            continue
        ok = sp.radsimp(q0[1]) > 0
        letters = [INDEX[word[-1]]] + [INDEX[c] for c in word]
        for k in range(1, len(word) + 1):
            i = letters[k]
            p, q = steps[k - 1]
            ok = ok and sp.radsimp(q[i]) < 0
            ok = ok and all(sp.radsimp(p[j].subs(x, xv)) > 0 for j in range(3) if j != i and j != letters[k - 1])
        if ok:
            return True
    return False


def test_abcb_at_3_minus_2_sqrt2_is_feasible_on_its_eigenspace():
    """abcb at r₀ = 3 - 2√2: λ₀ = r₀ is a double eigenvalue with a plane of eigenvectors, so the
    generic u = q_2(0) is 0/0 (the census left 4 points undecided).  Decided now: feasible (upper and
    middle x₋).  Second route: a datum of the plane, found in SymPy, realises abcb."""
    res = analyse("abcb", formulas=False)
    assert res.undecided == []
    assert _regions_at(res, "feasible", "0.1715728") == {("upper", "x₋"), ("middle", "x₋")}
    r0 = 3 - 2 * sp.sqrt(2)
    M0 = candidate("abcb").M.subs(R, r0).applyfunc(sp.radsimp)
    [(lam0, mult, basis)] = [e for e in M0.eigenvects() if sp.radsimp(e[0] - r0) == 0]
    assert mult == 2 and len(basis) == 2
    found = []
    for t in (sp.Rational(k, 8) for k in range(-16, 17)):
        q = basis[0] + t * basis[1]
        if sp.radsimp(q[0]) == 0:
            continue
        q = (q / -q[0]).applyfunc(sp.radsimp)
        if _feasible_datum("abcb", list(q), r0):
            found.append(t)
            break
    assert found


def test_acbacbcab_at_2_minus_sqrt3_fails_on_its_eigenspace():
    """acbacbcab at r₀ = 2 - √3: M(r₀) = λ₀I (every vector an eigenvector), the branches could not
    be isolated (6 points undecided).  Decided now: no datum.  Second route, in SymPy: with
    q(0) = (-1, u, v) free, u > 0 and the last approach contradict each other (the
    latter, q_2(t_8) < 0, says that a negative multiple of u is positive)."""
    res = analyse("acbacbcab", formulas=False)
    assert res.undecided == [] and res.feasible == []
    r0 = 2 - sp.sqrt(3)
    M0 = candidate("acbacbcab").M.subs(R, r0).applyfunc(sp.expand)
    assert (M0 - M0[0, 0] * sp.eye(3)).applyfunc(sp.expand) == sp.zeros(3)
    u, v = sp.symbols("u v")
    q = sp.Matrix([-1, u, v])
    for letter in "acbacbca":                                        # the velocities only: q(t_8)
        q = (collision_matrix(letter).subs(R, r0) * q).applyfunc(sp.expand)
    lin = sp.Poly(sp.expand(-q[1]), u, v)                            # q_2(t_8) < 0 needed before the last b
    assert lin.coeff_monomial(v) == 0 and lin.coeff_monomial(1) == 0
    assert sp.radsimp(lin.coeff_monomial(u)) < 0                    # -q_1 = c·u, c < 0: u < 0


def test_ababcbcb_window_end_on_a_line_of_data():
    """(ab)²(cb)² at its window's lower end ≈0.1275440976 (a double eigenvalue, a line of data):
    4 points undecided before; decided now, never stable there (λ₀ double is not dominant), the
    stable window unchanged."""
    res = analyse("ababcbcb", formulas=False)
    assert res.undecided == []
    assert [e["set"] for e in res.stable] == ["]≈0.1275440976, ≈0.1715728753["]
