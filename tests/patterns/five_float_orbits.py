"""The periodic orbits of the five-particle reduction in floats (numpy): an independent route for
tests/patterns/test_five_orbits.py (observed, not certified)."""
import itertools
import numpy as np
import flint
from certify.dynamics.systems import system_matrix_flint, of_particles

PAIRS = list(itertools.combinations(range(4), 2))
LET = "abcd"

def matrix(word, r):
    M = system_matrix_flint(of_particles(5), word)
    return np.array([[float(e(r)) for e in row] for row in M])

def compound(M):
    return np.array([[M[i, k] * M[j, l] - M[i, l] * M[j, k] for k, l in PAIRS] for i, j in PAIRS])

def ent(w, k, m):
    return w[PAIRS.index((k, m))] if k < m else -w[PAIRS.index((m, k))]

def orbits(word, r, tol=1e-9):
    """[(κ, feasible, kind)] for the real κ > 0 of Λ²M with a real eigenvector in the face of the last letter:
    feasible when the plane's run follows the word; kind 'real'/'complex' when attracting, else None."""
    rq = flint.fmpq(*r) if isinstance(r, tuple) else r
    M = matrix(word, rq)
    W = compound(M)
    Ks = [compound(matrix(c, rq)) for c in LET]
    vals, vecs = np.linalg.eig(W)
    ev = np.linalg.eigvals(M)
    out = []
    Y = LET.index(word[-1])
    for k in range(6):
        kap = vals[k]
        if abs(kap.imag) > tol * max(1, abs(kap)) or kap.real <= 0:
            continue
        if sum(abs(vals - kap) < 1e-7 * abs(kap)) > 1:
            continue                                           # a multiple root: not analysed
        w = np.real(vecs[:, k]); w = w / np.max(np.abs(w))
        face = [-ent(w, Y, j) for j in range(4) if j != Y]
        if not (all(f > tol for f in face) or all(f < -tol for f in face)):
            continue
        if face[0] < 0:
            w = -w
        i, ok = Y, True
        for c in word:
            j = LET.index(c)
            if not all(ent(w, j, m) > tol * np.max(np.abs(w)) for m in range(4) if m not in (i, j)):
                ok = False
                break
            w = Ks[j] @ w
            i = j
        kind = None
        if ok:
            # the plane's pair: two eigenvalues with product κ
            best = min(((a, b) for a, b in itertools.combinations(range(4), 2)),
                       key=lambda ab: abs(ev[ab[0]] * ev[ab[1]] - kap.real))
            others = [ev[m] for m in range(4) if m not in best]
            m = min(abs(ev[best[0]]), abs(ev[best[1]]))
            if all(abs(n) < m * (1 - 1e-9) for n in others):
                kind = "complex" if abs(ev[best[0]].imag) > 1e-12 * abs(ev[best[0]]) else "real"
        out.append((kap.real, ok, kind))
    return out
