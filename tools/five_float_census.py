"""The attracting periodic orbits of the five-particle reduction in floats, word by word, beyond the exact
census's length (issue 39: the shortest complex-pair attractor).  Observed, not certified.

    python tools/five_float_census.py --length 13 --points 1000 --jobs 2 --json scan13.json

For every class of words of ``--length`` collisions (:func:`certify.patterns.five.word_classes`) and every
r of a grid of ``--points`` values in ]0, 1[, M_w(r) is the float product of the letters' matrices (each
evaluated exactly at r, then rounded).  A periodic orbit of the reduction attracts only where κ = λμ, the
product of the two eigenvalues of largest modulus, strictly dominates: λ, μ of moduli above the two others
(a complex pair or two real ones of one sign).  Where numpy's eigenvalues show that and the plane of
their eigenvectors lies in the face of the last letter and follows the word (a filter over the whole grid
at once, tested to drop no point the check below keeps), the orbit is checked
by tests/patterns/five_float_orbits.py (κ simple, its plane in the face of the last letter, the plane's
run following the word, the same route as the exact census's float check).  Printed: each word with an
attracting orbit, its kind (real pair: stable self-similar collapse; complex pair: not a collapse) and
the grid points where it was seen, as runs [first, last] of consecutive points.  A window narrower than
the grid's step can be missed.
"""
from __future__ import annotations

import argparse
import json
import multiprocessing
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

import flint  # noqa: E402

from certify.patterns.five import word_classes  # noqa: E402
from certify.run.files import write_atomic  # noqa: E402
from certify.run.progress import Bar  # noqa: E402
from tests.patterns import five_float_orbits as floats  # noqa: E402

LETTERS = floats.LETTERS


def grid(points: int) -> list[flint.fmpq]:
    """``points`` rationals i/(points + 1) in ]0, 1[."""
    return [flint.fmpq(i, points + 1) for i in range(1, points + 1)]


def letter_matrices(rs: list[flint.fmpq]) -> dict[str, np.ndarray]:
    """For each letter, its matrix at every r of the grid, shape (len(rs), 4, 4): exact at r, then floats."""
    return {c: np.array([floats.matrix(c, r) for r in rs]) for c in LETTERS}


def candidates(word: str, K: dict[str, np.ndarray], steps: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """M_w at every r (M_w = K_last ⋯ K_first) and the indices of the r where an attracting orbit may be:
    the two eigenvalues λ, μ of largest modulus dominate the other two, κ = λμ is real and positive, and
    the plane of λ, μ (the bivector u∧v of their eigenvectors, made real; its coordinates ω_km read by
    five_float_orbits.entry on the transpose, one row per r) lies in the face of the last letter and its
    run follows the word.  A filter, in numpy over the whole grid at once; each index it
    keeps is checked again by :func:`attractors`.  ``steps``: the letters' Λ²K_c, shape (R, 4, 6, 6)."""
    M = K[word[0]]
    for c in word[1:]:
        M = K[c] @ M
    ev, V = np.linalg.eig(M)
    order = np.argsort(-np.abs(ev), axis=1)
    ev = np.take_along_axis(ev, order, axis=1)
    V = np.take_along_axis(V, order[:, None, :], axis=2)
    kappa = ev[:, 0] * ev[:, 1]
    keep = (np.abs(ev[:, 1]) > np.abs(ev[:, 2]) * (1 + 1e-9)) & (kappa.real > 0) \
        & (np.abs(kappa.imag) <= 1e-9 * np.abs(kappa))
    u, v = V[:, :, 0], V[:, :, 1]
    w = np.stack([u[:, k] * v[:, m] - u[:, m] * v[:, k] for k, m in floats.PAIRS], axis=1)
    big = w[np.arange(len(w)), np.argmax(np.abs(w), axis=1)]
    w = (w / np.where(big == 0, 1, big)[:, None]).real
    Y = LETTERS.index(word[-1])
    face = np.stack([-floats.entry(w.T, Y, j) for j in range(4) if j != Y], axis=1)
    keep &= np.all(face > 1e-12, axis=1) | np.all(face < -1e-12, axis=1)
    w = w * np.sign(face[:, :1])
    i = Y
    for c in word:
        j = LETTERS.index(c)
        scale = np.max(np.abs(w), axis=1)
        for m in range(4):
            if m not in (i, j):
                keep &= floats.entry(w.T, j, m) > 1e-12 * scale
        w = np.einsum("rij,rj->ri", steps[:, j], w)
        i = j
    return M, np.nonzero(keep)[0]


def attractors(word: str, K: dict[str, np.ndarray], steps: np.ndarray) -> dict[str, list[int]]:
    """{kind: grid indices} where ``word``'s reduction has an attracting feasible periodic orbit: the
    indices :func:`candidates` keeps, each checked by tests/patterns/five_float_orbits.py."""
    M, where = candidates(word, K, steps)
    found: dict[str, list[int]] = {}
    for i in where:
        for _kappa, _feasible, kind in floats.orbits_of(word, M[i], steps[i]):
            if kind:
                found.setdefault(kind, []).append(int(i))
    return found


def runs(indices: list[int]) -> list[tuple[int, int]]:
    """Maximal runs of consecutive indices, as (first, last)."""
    out: list[tuple[int, int]] = []
    for i in sorted(set(indices)):
        if out and i == out[-1][1] + 1:
            out[-1] = (out[-1][0], i)
        else:
            out.append((i, i))
    return out


_STATE: dict = {}
CHUNK = 200                      # words per job


def _setup(points: int) -> None:
    rs = grid(points)
    K = letter_matrices(rs)
    steps = np.array([[floats.compound(K[c][i]) for c in LETTERS] for i in range(len(rs))])
    _STATE.update(rs=rs, K=K, steps=steps)


def _job(words: list[str]) -> list[tuple[str, dict]]:
    return [(w, f) for w in words if (f := attractors(w, _STATE["K"], _STATE["steps"]))]


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--length", type=int, required=True, help="the words' number of collisions")
    ap.add_argument("--points", type=int, default=1000, help="grid points in ]0, 1[")
    ap.add_argument("--jobs", type=int, default=1)
    ap.add_argument("--json", type=Path, default=None, help="write the words found and the grid here")
    args = ap.parse_args(argv)
    if args.length < 4 or args.points < 1 or args.jobs < 1:
        print("five_float_census: --length must be at least 4, --points and --jobs at least 1", file=sys.stderr)
        return 2
    start = time.perf_counter()
    words = [w for w in word_classes(args.length) if len(w) == args.length]
    chunks = [words[i:i + CHUNK] for i in range(0, len(words), CHUNK)]
    bar, found = Bar("word"), []
    with multiprocessing.Pool(args.jobs, _setup, (args.points,)) as pool:
        for k, part in enumerate(pool.imap(_job, chunks), 1):
            found += part
            bar(min(CHUNK * k, len(words)), len(words))
    seconds = time.perf_counter() - start
    step = 1 / (args.points + 1)
    print(f"{len(words)} words of {args.length}, {args.points} r in ]0, 1[ (step {step:.2g}): "
          f"{len(found)} with an attracting orbit (observed), {seconds:.0f} s")
    for w, kinds in found:
        for kind, idx in sorted(kinds.items()):
            spans = ", ".join(f"[{(a + 1) * step:.4f}, {(b + 1) * step:.4f}]" if a < b else f"{(a + 1) * step:.4f}"
                              for a, b in runs(idx))
            print(f"  {w}: {kind} pair at {spans}")
    if args.json:
        try:
            write_atomic(args.json, json.dumps({"length": args.length, "points": args.points, "words": len(words),
                                         "seconds": seconds, "found": [
                                                {"word": w, "kinds": {k: runs(v) for k, v in kinds.items()}}
                                                for w, kinds in found]}, indent=1) + "\n")
        except OSError as exc:
            print(f"five_float_census: cannot write {args.json}: {exc.strerror}", file=sys.stderr)
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
