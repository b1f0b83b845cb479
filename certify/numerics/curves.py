"""Observed rotation numbers of the curves that unresolved orbits trace on the b-section.

An orbit that repeats a word w without converging (its periodic orbit at r is not attracting)
returns to the b-section along a curve: every k-th state at b (k = the b's in w, G = f^k the
return map of w) lies on one loop.  Its rotation number is estimated as the island's is
defined (:data:`certify.patterns.island_theorem.CONVENTION`): the mean angle by which G turns
the state counterclockwise in the (u, v) chart of :mod:`certify.numerics.horseshoe`, measured
in coordinates where the loop is round (the points whitened by their covariance, about their
mean), divided by 2π.  Floats, the float64 run of ``certify identify``: observed, never a
proof.  The radius drift (the whitened radius at the end of the run over that at its middle)
says whether the loop stays put (≈ 1: an invariant curve) or spirals (a slow transient).
"""
from __future__ import annotations

import math

import flint
import numpy as np

from . import engines
from .horseshoe import chart_of


def b_states(r: flint.fmpq, theta0: float, phi0: float, collisions: int) -> np.ndarray:
    """The chart points (u, v) of the float64 run's states right after each b-collision."""
    res = engines.float64_orbit(r, theta0, phi0, collisions, word=True, checkpoints=range(1, collisions + 1))
    pts = [chart_of(n) for _c, (j, n) in sorted(res.checkpoints.items()) if j == 1]
    return np.array(pts, dtype=float).reshape(-1, 2)


def rotation_estimate(points: np.ndarray, k: int = 1) -> dict | None:
    """The rotation number of G = f^k on the loop of ``points`` (states at b, in order; the
    last half used, every k-th point), the radius drift and the points used; None with fewer
    than 20 points or a flat loop."""
    half = points[len(points) // 2:]
    z = half[::k]
    if len(z) < 20:
        return None
    centre = z.mean(axis=0)
    cov = np.cov((z - centre).T)
    w, V = np.linalg.eigh(cov)
    if not w.min() > 1e-14 * max(w.max(), 1e-300):
        return None
    white = (z - centre) @ V @ np.diag(w ** -0.5) @ V.T
    angles = np.arctan2(white[:, 1], white[:, 0])
    turn = np.mod(np.diff(angles), 2 * math.pi)
    radius = np.hypot(white[:, 0], white[:, 1])
    tenth = max(len(radius) // 10, 1)
    return {"returns": k, "rotation": f"{float(turn.mean() / (2 * math.pi)):.6f}",
            "radius_drift": f"{float(np.median(radius[-tenth:]) / np.median(radius[:tenth])):.3g}",
            "points": int(len(z))}
