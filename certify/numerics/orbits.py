"""Sweeps of orbits over r: :func:`iterate` and its result :class:`Orbits`.

The initial data (θ0, φ0) are taken right after a b-collision (the contact b, the
pair 2-3 in contact, as the paper represents b-collisions only, l. 1058):
p(0) = (sin θ0, 0, cos θ0), q(0) = (cos θ0 cos φ0, sin φ0, −sin θ0 cos φ0) (l. 894),
so that the normal is u = p(0) ∧ q(0) = (−cos θ0 sin φ0, cos φ0, sin θ0 sin φ0).

The paper does not print its grid of 8 initial configurations ("a regular grid, with
2 values of θ0 and 4 values of φ0", captions of Figures 5.1-5.4): the eight are the
tool's choice, the tool's grid of 8 initial data.  :func:`paper_grid` (named for the
paper's description, not its data) is the interior regular grid θ0 ∈ {π/6, π/3} (θ ∈ ]0, π/2[ cut in 3), φ0 ∈ {π/5,
2π/5, 3π/5, 4π/5} (φ ∈ ]0, π[ cut in 5), θ0 outer, φ0 inner; none of them is a
corner (cos φ0 ≠ 0, sin θ0 cos θ0 ≠ 0).
"""
from __future__ import annotations

import math
from collections.abc import Callable
from concurrent.futures import Executor
from dataclasses import dataclass

import numpy as np

from . import engines, rules

KEYS = ("r", "theta0", "phi0", "phi", "breaks", "collisions", "certified")


def paper_grid() -> tuple[np.ndarray, np.ndarray]:
    """(θ0, φ0), 8 each: 2 values of θ0 times 4 of φ0 (module docstring)."""
    thetas = [math.pi * k / 6 for k in (1, 2)]
    phis = [math.pi * k / 5 for k in (1, 2, 3, 4)]
    theta0 = np.array([t for t in thetas for _ in phis])
    phi0 = np.array([p for _ in thetas for p in phis])
    return theta0, phi0


def load_float64() -> None:
    """Import the float64 engine in this process (numba and the kernel's definitions: about
    0.3 s, once per process; its compiled sweep loads from numba's cache at the first call).
    Nothing runs: a parallel region launched here would be inherited, half alive, by the
    processes the runner forks later."""
    from . import kernel  # noqa: F401


def grid(count: int) -> tuple[np.ndarray, np.ndarray]:
    """``count`` initial data, the tool's grid: the first ``count`` of :func:`paper_grid`
    when at most 8; beyond, the eight and then, level by level, the same two θ0 times the
    midpoints of the previous level's φ cells, φ0 = π(2k−1)/(5·2^j), j = 1, 2, …
    (φ0 = π/2, a corner, excluded at j = 1: it is never on the grid), θ0 outer within a
    level.  So the grid of N > 8 is a superset of the eight."""
    theta0, phi0 = paper_grid()
    if count <= 8:
        return theta0[:count], phi0[:count]
    thetas, phis = list(theta0), list(phi0)
    level = 1
    while len(thetas) < count:
        den = 5 * 2 ** level
        cells = [math.pi * k / den for k in range(1, den, 2) if 2 * k != den]
        for t in (math.pi / 6, math.pi / 3):
            for p in cells:
                thetas.append(t)
                phis.append(p)
        level += 1
    return np.array(thetas[:count]), np.array(phis[:count])


@dataclass
class Orbits:
    """The result of :func:`iterate`: r (n_r,), theta0 and phi0 (n_orbits,), phi
    (n_r, n_orbits, keep) the φ of the last b-collisions in order, NaN-padded at the
    front, breaks (n_r, n_orbits) the break codes (:data:`rules.BREAKS`, 0 completed),
    collisions (n_r, n_orbits) the collisions done, certified (n_r, n_orbits) the
    collisions proven (the certified horizon: the accumulated error bound of float64
    and mp, every collision of ball); word (n_r, n_orbits) the collision words, when
    asked (else None)."""

    r: np.ndarray
    theta0: np.ndarray
    phi0: np.ndarray
    phi: np.ndarray
    breaks: np.ndarray
    collisions: np.ndarray
    certified: np.ndarray
    word: np.ndarray | None = None
    engine: str = "float64"

    def save(self, path) -> None:
        """Write the arrays to an .npz file (``numpy.savez``; the path as given):
        :data:`KEYS`, and ``word`` (strings) when the words were asked."""
        arrays = {k: getattr(self, k) for k in KEYS}
        if self.word is not None:
            arrays["word"] = self.word
        np.savez(path, **arrays)

    @classmethod
    def load(cls, path) -> Orbits:
        with np.load(path) as data:
            return cls(*(data[k] for k in KEYS), word=data["word"] if "word" in data.files else None)

    def certified_fraction(self) -> float:
        """The fraction of the collisions done that are certified (1 when none done)."""
        done = int(self.collisions.sum())
        return float(self.certified.sum()) / done if done else 1.0

    def summary(self) -> str:
        """A few lines: sizes, breaks by name, the certified collisions, the range of φ."""
        n_r, n_o = self.breaks.shape
        lines = [f"{self.engine}: {n_r} value(s) of r × {n_o} orbit(s), "
                 f"{int(self.collisions.max(initial=0))} collisions at most, {self.phi.shape[-1]} kept"]
        for code, name in rules.BREAKS.items():
            count = int((self.breaks == code).sum())
            if count:
                lines.append(f"  {count:>7} {name} (break {code})")
        lines.append(f"  certified: {int(self.certified.sum())} of {int(self.collisions.sum())} collisions "
                     f"({self.certified_fraction():.2%}); certified horizon per orbit from "
                     f"{int(self.certified.min()) if self.certified.size else 0} "
                     f"to {int(self.certified.max(initial=0))}")
        finite = self.phi[np.isfinite(self.phi)]
        if finite.size:
            lines.append(f"  φ in [{finite.min():.6f}, {finite.max():.6f}], {finite.size} kept angles")
        return "\n".join(lines)


def _check(r, theta0, phi0, collisions, keep, engine):
    r = np.atleast_1d(np.asarray(r, dtype=float))
    theta0 = np.atleast_1d(np.asarray(theta0, dtype=float))
    phi0 = np.atleast_1d(np.asarray(phi0, dtype=float))
    if r.ndim != 1 or theta0.shape != phi0.shape or theta0.ndim != 1:
        raise ValueError("r, theta0, phi0 must be 1-d arrays, theta0 and phi0 of one length")
    if not np.all((r > 0) & (r < 1)):
        raise ValueError("r must lie in ]0, 1[")
    if collisions < 0 or keep < 0:
        raise ValueError("collisions and keep must be non-negative")
    if engine not in engines.ENGINES:
        raise ValueError(f"unknown engine {engine!r}: use one of {', '.join(engines.ENGINES)}")
    return r, theta0, phi0


def _float64(r, theta0, phi0, collisions, keep, strict, progress):
    n_r, n_o = len(r), len(theta0)
    normals = np.array([rules.initial_normal(t, p) for t, p in zip(theta0, phi0)], dtype=float).reshape(n_o, 3)
    letters = np.full(n_o, rules.INDEX[rules.START], dtype=np.int64)
    phi = np.empty((n_r, n_o, keep))
    breaks = np.zeros((n_r, n_o), dtype=np.int8)
    counts = np.zeros((n_r, n_o), dtype=np.int64)
    certified = np.zeros((n_r, n_o), dtype=np.int64)
    from . import kernel  # numba, imported where the float64 engine first runs
    # batches, for the progress bar; each batch is one parallel call
    per = max(1, min(n_r, (1 << 22) // max(1, n_o * max(collisions, 1))))
    for lo in range(0, n_r, per):
        hi = min(n_r, lo + per)
        rows = np.array([rules.float_rows(x) for x in r[lo:hi]]).reshape(hi - lo, 27)     # the kernel's layout
        kernel.sweep(letters, normals, rows, rules.TOL64, rules.G64, rules.K64, rules.TINY64, collisions, keep,
                     strict, phi[lo:hi], breaks[lo:hi], counts[lo:hi], certified[lo:hi])
        if progress is not None:
            progress(hi, n_r, f"r = {r[hi - 1]:.6g}")
    return phi, breaks, counts, certified


def _float64_words(r, theta0, phi0, collisions, strict):
    """The collision words of the float64 orbits (one traced orbit at a time)."""
    return [[engines.float64_orbit(float(x), float(t), float(p), collisions, word=True, strict=strict).word
             for t, p in zip(theta0, phi0)] for x in r]


def _tasks(engine, r, theta0, phi0, collisions, keep, dps, strict, words, executor, progress):
    n_r, n_o = len(r), len(theta0)
    phi = np.full((n_r, n_o, keep), np.nan)
    breaks = np.zeros((n_r, n_o), dtype=np.int8)
    counts = np.zeros((n_r, n_o), dtype=np.int64)
    certified = np.zeros((n_r, n_o), dtype=np.int64)
    word = [[""] * n_o for _ in range(n_r)]
    jobs = [(a, b) for a in range(n_r) for b in range(n_o)]
    args = [(engine, float(r[a]), float(theta0[b]), float(phi0[b]), collisions, keep, dps, strict, words)
            for a, b in jobs]
    if executor is None:
        done = zip(jobs, (engines.task(*x) for x in args))
    else:
        futures = {executor.submit(engines.task, *x): job for job, x in zip(jobs, args)}
        from concurrent.futures import as_completed
        done = ((futures[f], f.result()) for f in as_completed(futures))
    for k, ((a, b), (ph, code, count, cert, w)) in enumerate(done, 1):
        phi[a, b], breaks[a, b], counts[a, b], certified[a, b], word[a][b] = ph, code, count, cert, w
        if progress is not None:
            progress(k, len(jobs), f"r = {r[a]:.6g}")
    return phi, breaks, counts, certified, word


def iterate(r, theta0, phi0, collisions: int = 10_000, keep: int = 500, engine: str = "float64",
             dps: int | None = None, executor: Executor | None = None,
             progress: Callable[[int, int, str], None] | None = None, strict: bool = False,
             words: bool = False) -> Orbits:
    """Iterate the reduction map from every (θ0, φ0) at contact b, for every r, up to
    ``collisions`` collisions or a break; keep the φ of the last ``keep`` b-collisions.

    ``engine``: "float64" (numba, parallel over orbits; ``executor`` unused), "mp"
    (mpmath at ``dps`` digits, default 30) or "ball" (certified arb, precision raised
    up to ``dps`` digits, default 5000).  ``executor``: a concurrent.futures Executor
    for the mp and ball orbits (None: in this process).  ``progress(k, n, label)``:
    called as the work advances.  ``strict``: stop every orbit at its certified
    horizon (break 5, ``rules.HORIZON``); without it the float64 and mp orbits go on
    past it (shadowing orbits) and ``certified`` says how far they are proven.
    ``words``: also return each orbit's collision word (``Orbits.word``)."""
    r, theta0, phi0 = _check(r, theta0, phi0, collisions, keep, engine)
    word = None
    if engine == "float64":
        phi, breaks, counts, certified = _float64(r, theta0, phi0, collisions, keep, strict, progress)
        if words:
            word = _float64_words(r, theta0, phi0, collisions, strict)
    else:
        phi, breaks, counts, certified, word = _tasks(engine, r, theta0, phi0, collisions, keep, dps, strict, words,
                                                      executor, progress)
    if words:
        word = np.array(word, dtype=str).reshape(len(r), len(theta0))
    else:
        word = None
    return Orbits(r, theta0, phi0, phi, breaks, counts, certified, word, engine)
