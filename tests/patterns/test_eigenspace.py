"""The points of a multiple eigenvalue (certify.patterns.eigenspace), undecided before, decided now;
each decision checked by a second route in SymPy (exact in Q(√2), Q(√3)): the eigenspace of
M(r₀) from SymPy's eigenvects, the word's velocities and positions from the paper's matrices."""
import flint
import pytest
import sympy as sp

from certify.algebra import Algebraic
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
    (silver,) = Algebraic.roots(flint.fmpz_poly([1, -6, 1]), 0, 1)      # 3 - 2√2, L5.1's printed upper end
    assert [e["set"] for e in res.stable] == [f"]≈0.1275440976, ≈{silver.digits(10)}["]


def _velocity_forms(word, q0, r0):
    """The linear forms that must be > 0 for ``word`` to run from q(0) = q0 (SymPy, affine in the
    parameters of q0): u = q_2(0) and -q_{i_k}(t_{k-1}) for every collision k (the paper's A, B, C)."""
    q, forms = sp.Matrix(q0), [sp.expand(q0[1])]
    for letter in word:
        forms.append(sp.expand(-q[INDEX[letter]]))
        q = (collision_matrix(letter).subs(R, r0) * q).applyfunc(sp.expand)
    return forms


def _farkas(forms, params):
    """A Farkas certificate that the forms cannot all be > 0: weights y ≥ 0, not all 0, on at most
    len(params) + 1 of them, with Σ y·form a constant ≤ 0 (SymPy, exact); None if none is found."""
    from itertools import combinations
    rows = [[sp.radsimp(sp.Poly(f, *params).coeff_monomial(p)) for p in params] for f in forms]
    consts = [sp.radsimp(f.subs({p: 0 for p in params})) for f in forms]
    for k in range(1, len(params) + 2):
        for S in combinations(range(len(forms)), k):
            null = sp.Matrix([rows[i] for i in S]).T.nullspace(simplify=True)
            if len(null) != 1:
                continue
            y = [sp.radsimp(e) for e in null[0]]
            if all(e <= 0 for e in y):
                y = [-e for e in y]
            if all(e >= 0 for e in y) and sp.radsimp(sum(e * consts[i] for e, i in zip(y, S))) <= 0:
                return S, y
    return None


def test_a_plane_of_data_where_no_datum_runs_the_word():
    """acbacbacbacbacbcab at r₀ = 2 - √3 (M(r₀) = λ₀I: a plane of data, 6 points undecided in the
    census at the existence requirement x).  Now: no datum of the plane meets the velocities'
    requirements of the whole word, so the points are in no feasible set (undecided for existence
    only: the stage's own copy keeps them).  Second route: a Farkas certificate in SymPy, exact in
    Q(√3), for q(0) = (-1, u, v) free."""
    word = "acbacbacbacbacbcab"
    res = analyse(word, formulas=False)
    assert res.undecided == [] and res.feasible == []
    kept = [(R.branch, rc) for R in res.regions["exists"] for rc, _why in R.undecided]
    assert len(kept) == 6 and all(abs(float(rc.lo) - 0.2679491924) < 1e-9 for _b, rc in kept)
    r0 = 2 - sp.sqrt(3)
    normal = res.normal
    M0 = candidate(normal).M.subs(R, r0).applyfunc(sp.expand)
    assert (M0 - M0[0, 0] * sp.eye(3)).applyfunc(sp.radsimp) == sp.zeros(3)
    u, v = sp.symbols("u v")
    assert _farkas(_velocity_forms(normal, [-1, u, v], r0), [u, v]) is not None


def test_a_line_of_data_where_a_pair_never_approaches():
    """abacbacbacbacbacb at r₀ = 2 - √3 (a line of data): 4 points undecided in the census at
    u = q_2(0) (no witness runs the word).  Now decided: some pair has q_{i_k}(t_{k-1}) = 0 on the
    whole line, the word never runs.  Second route: SymPy's eigenvectors of M(r₀) and the forms."""
    word = "abacbacbacbacbacb"
    res = analyse(word, formulas=False)
    assert res.undecided == [] and res.feasible == []
    r0 = 2 - sp.sqrt(3)
    M0 = candidate(word).M.subs(R, r0).applyfunc(sp.radsimp)
    lines = [e for e in M0.eigenvects(simplify=True) if len(e[2]) == 2]
    assert len(lines) == 1
    b0, b1 = lines[0][2]
    s = sp.Symbol("s")
    q0 = b0 + s * b1 if sp.radsimp(b0[0]) != 0 else b1 + s * b0
    q0 = (q0 / -q0[0]).applyfunc(sp.radsimp)
    forms = _velocity_forms(word, list(q0), r0)
    assert any(sp.radsimp(f) == 0 for f in forms[1:])


def test_a_simple_eigenvalue_where_the_first_gap_is_0_over_0():
    """ababacbacbacbacbcbcb at r₀ ≈ 0.3903691107 (a simple eigenvalue of the upper branch, where q(0)
    from rows 1-2 of the eigen-equation is 0/0): p_3(t_1) = x₊ + q_3(0) was undecided.  Now from the
    other rows: < 0, the point fails.  Second route: python-flint balls at r₀ — M(r₀), its largest
    real eigenvalue, the eigenvector from rows 1 and 3 (or 2 and 3) of M - λI, the word run from
    p(0) = (1, 0, x) (affine in x) and the positive fixed point of p_3(t_n)/p_1(t_n) (the other one
    is negative; the engine's label x₊ depends on the scale of its a, b, c, d)."""
    import flint

    from certify.algebra.algebraic import Algebraic
    from certify.algebra.balls import precision
    word = "ababacbacbacbacbcbcb"
    res = analyse(word, formulas=False)
    assert res.undecided == []
    [r0] = [a for a in Algebraic.roots(flint.fmpq_poly([1, -12, 27, -16, 27, -12, 1]))
            if a.arb(64) > flint.arb("0.39") and a.arb(64) < flint.arb("0.391")]
    with precision(400):
        Rb = r0.arb(400)
        Mq = candidate(word).Mq
        M = [[sum((flint.arb(c) * Rb ** k for k, c in enumerate(e.coeffs())), flint.arb(0)) for e in row]
             for row in Mq]
        lams = [z.real for z in flint.acb_mat(M).eig() if not (z.imag > 0 or z.imag < 0)]
        lam0 = max(lams, key=lambda z: z.mid())
        A = [[M[i][j] - (lam0 if i == j else 0) for j in range(3)] for i in range(3)]

        def cross(u, w):
            return [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]]
        q = next(c for c in (cross(A[0], A[2]), cross(A[1], A[2])) if c[0] > 0 or c[0] < 0)
        q = [e / -q[0] for e in q]
        p = [(flint.arb(1), flint.arb(0)), (flint.arb(0), flint.arb(0)), (flint.arb(0), flint.arb(1))]
        first = None
        for letter in word:
            i = INDEX[letter]
            t = (-p[i][0] / q[i], -p[i][1] / q[i])
            p = [(P0 + t[0] * qj, P1 + t[1] * qj) for (P0, P1), qj in zip(p, q)]
            p[i] = (flint.arb(0), flint.arb(0))
            first = first or p[2]
            q = [sum((Mi * qj for Mi, qj in zip(row, q)), flint.arb(0)) for row in _ball_matrix(letter, Rb)]
        (d, c), _p2, (b, a) = p
        xs = [(a - d + sigma * ((a - d) ** 2 + 4 * b * c).sqrt()) / (2 * c) for sigma in (1, -1)]
        positive = [x for x in xs if x > 0]
        assert len(positive) == 1 and all(x < 0 for x in xs if x not in positive)
        assert first[0] + positive[0] * first[1] < 0                # p_3(t_1) < 0: the gap c closed


def _ball_matrix(letter, Rb):
    """The collision matrix of ``letter`` (the paper's A, B, C) at a ball of r."""
    import flint
    C = collision_matrix(letter)
    out = [[flint.arb(0)] * 3 for _ in range(3)]
    for i in range(3):
        for j in range(3):
            for (k,), cf in sp.Poly(sp.expand(C[i, j]), R).terms():
                cf = sp.Rational(cf)
                out[i][j] += flint.arb(int(cf.p)) / int(cf.q) * Rb ** k
    return out


def _spy_cancel(monkeypatch):
    """Record (family, (a, b, c, d) before, after) of every :meth:`Family.cancel`."""
    from certify.patterns.eigenspace import Family
    seen, orig = [], Family.cancel

    def spy(self, abcd):
        out = orig(self, abcd)
        seen.append((self, abcd, out))
        return out
    monkeypatch.setattr(Family, "cancel", spy)
    return seen


def _same_map(fam, before, after) -> bool:
    """(a, b, c, d) and (a', b', c', d') proportional in K[s] (every 2x2 minor of the pair is 0,
    exact in Q(r₀)[s]): the same Möbius map wherever both are defined."""
    return all(fam.red(before[i] * after[j] - before[j] * after[i]).is_zero()
               for i in range(4) for j in range(i + 1, 4))


def test_the_position_map_cancelled_on_a_line_of_data(monkeypatch):
    """(ab)³(cb)³ at ≈0.0945194072 (a double eigenvalue, a line of data q_a + s·d): its position map's
    a, b, c, d (degree 11 in s) share the factors q_{i_k}(t_{k-1}) of the run's common denominator,
    which made Δ a constant times a square and the norms of degree 176 (beyond NORM_DEGREE: 2 points
    undecided in the census).  Cancelled now: the lower and middle x₋ points decided (not feasible),
    x₊ feasible on both (a datum of the eigenspace), the stable window unchanged.  Second route for the
    cancellation: the 2x2 minors of the map before and after are 0 exactly; a mutant (one entry
    times s + 1) is caught."""
    seen = _spy_cancel(monkeypatch)
    res = analyse("abababcbcbcb", formulas=False)
    assert res.undecided == []
    assert _regions_at(res, "feasible", "0.0945194") == {("middle", "x₊"), ("lower", "x₊")}
    assert [e["set"] for e in res.stable] == ["]≈0.09451940725, ≈0.1010205144["]
    assert seen
    for fam, before, after in seen:
        assert max(e.degrees()[1] for e in after) < max(e.degrees()[1] for e in before)
        assert _same_map(fam, before, after)
    fam, before, after = seen[0]
    _r, s = fam.m.context().gens()
    mutant = (after[0], after[1], fam.red(after[2] * (s + 1)), after[3])
    assert not _same_map(fam, before, mutant)


def test_a_line_of_data_decided_where_the_census_stopped():
    """aba(cb)²(abc)²b at ≈0.1516570691 (a line of data; 4 points undecided in the census, at q_2(t_1)
    and x: norms beyond NORM_DEGREE): decided now with the position map cancelled, no datum of the
    line realises the word (no feasible point, no feasible set)."""
    res = analyse("abacbcbabcabcb", formulas=False)
    assert res.undecided == [] and res.feasible == []


@pytest.mark.slow
def test_the_census_points_of_twenty_collisions_decided():
    """(ab)⁵(cb)⁵ at ≈0.0796489098 (its map's entries at the isolated s where c = 0 cancel to ~1e-64:
    decided at 2048 bits, undecided at 512) and a(bac)²bab(cba)²(cb)² at ≈0.1602898915 (norms of degree
    532 before the cancellation): no point left undecided; the first keeps its stable window."""
    res = analyse("abababababcbcbcbcbcb", formulas=False)
    assert res.undecided == []
    assert [e["set"] for e in res.stable] == ["]≈0.07964890975, ≈0.08070090315["]
    res = analyse("abacbacbabcbacbacbcb", formulas=False)
    assert res.undecided == [] and res.feasible == []
