"""An independent reference for (ab)^n(cb)^n: its stable set, straight from the matrices,
in mpmath at high precision (no engine code: the collision law is written again here from
the paper's A, B, C, l. 209-232).  Observed, not certified: floating point with many digits."""
import mpmath as mp

IDX = {"a": 0, "b": 1, "c": 2}


def collide(letter, q, r):
    """K q for K = A, B, C, h = (1 + r)/2."""
    q1, q2, q3 = q
    h = (1 + r) / 2
    if letter == "a":
        return [-r * q1, q2 + h * q1, q3]
    if letter == "b":
        return [q1 + h * q2, -r * q2, q3 + h * q2]
    return [q1, q2 + h * q3, -r * q3]


def matrix(word, r):
    """M_w = K_{c_m} ... K_{c_1}."""
    M = mp.eye(3)
    for letter in word:
        cols = [collide(letter, [M[0, j], M[1, j], M[2, j]], r) for j in range(3)]
        M = mp.matrix([[cols[j][i] for j in range(3)] for i in range(3)])
    return M


def analyse(n, r):
    """(stable, why): whether (ab)^n(cb)^n has stable self-similar data at r, and the
    first condition that fails ('dominance', 'u', 'x complex', or per fixed point)."""
    word = "ab" * n + "cb" * n
    M = matrix("cb", r) ** n * matrix("ab", r) ** n
    ev, _ = mp.eig(M)
    ev = sorted(ev, key=abs, reverse=True)
    lam = ev[0]
    tol = mp.mpf(10) ** (-mp.mp.dps // 3)
    if abs(mp.im(lam)) > tol * abs(lam) or mp.re(lam) <= 0 or abs(ev[1]) >= abs(lam) * (1 - tol):
        return False, "dominance"
    lam = mp.re(lam)
    A = M - lam * mp.eye(3)
    det = A[0, 1] * A[1, 2] - A[0, 2] * A[1, 1]
    u = (A[0, 0] * A[1, 2] - A[0, 2] * A[1, 0]) / det
    v = (A[0, 1] * A[1, 0] - A[0, 0] * A[1, 1]) / det
    if u <= 0:
        return False, "u"
    q, P, hist = [mp.mpf(-1), u, v], [(mp.mpf(1), mp.mpf(0)), (mp.mpf(0), mp.mpf(0)), (mp.mpf(0), mp.mpf(1))], []
    for letter in word:                         # p = P0 + x P1, times defined by p_i = 0
        k = IDX[letter]
        t = (-P[k][0] / q[k], -P[k][1] / q[k])
        hist.append((list(P), list(q)))
        P = [(P[j][0] + t[0] * q[j], P[j][1] + t[1] * q[j]) for j in range(3)]
        P[k] = (mp.mpf(0), mp.mpf(0))
        q = collide(letter, q, r)
    (d, c), (b, a) = P[0], P[2]
    disc = (a - d) ** 2 + 4 * b * c
    if disc < 0:
        return False, "x complex"
    why = []
    for sign, name in ((1, "x+"), (-1, "x-")):
        x = (a - d + sign * mp.sqrt(disc)) / (2 * c)
        fail = _fails(word, hist, P, x, (a, b, c, d))
        if fail is None:
            return True, name
        why.append(f"{name}: {fail}")
    return False, "; ".join(why)


def _fails(word, hist, P, x, abcd):
    """The first prefix condition, or the attraction, that fails at the fixed point x."""
    if x <= 0:
        return "x"
    letters = [IDX[word[-1]]] + [IDX[c] for c in word]
    m = len(word)
    for k in range(1, m + 1):
        i = letters[k]
        Pk, qk = hist[k - 1]
        if not qk[i] < 0:
            return f"q_{i + 1}(t_{k - 1})"
        if not (k == 1 or letters[k - 2] == i) and not Pk[i][0] + x * Pk[i][1] > 0:
            return f"p_{i + 1}(t_{k - 1})"
    if not P[0][0] + x * P[0][1] > 0:
        return "p_1(t_m)"
    a, b, c, d = abcd
    if not abs((a * d - b * c) / (c * x + d) ** 2) < 1:
        return "f'"
    return None


def window(n, steps=80):
    """(lo, hi): the stable set's ends near 7 - 4√3 + 0.2/n², by bisection from a stable
    point found by scanning s = n²(r - r*) in [0.19, 0.23]."""
    rs = 7 - 4 * mp.sqrt(3)
    for k in range(400):
        mid = rs + (mp.mpf("0.19") + k * mp.mpf("0.0001")) / n ** 2
        if analyse(n, mid)[0]:
            break
    else:
        raise AssertionError(f"no stable point found for n = {n}")

    def end(a, b):              # a stable, b not
        for _ in range(steps):
            c = (a + b) / 2
            a, b = (c, b) if analyse(n, c)[0] else (a, c)
        return a, b
    return end(mid, rs)[0], end(mid, rs + 1 / mp.mpf(n) ** 2)[0]
