"""The figure of ``certify chaos --figure PATH``: the boxes of a proved horseshoe on the b-section
and, one panel per covering relation N_i ⇒ N_j, the image of N_i in N_j's coordinates (N_j the
square [−1, 1]²).  Floats, a drawing only: the proof is :func:`certify.numerics.horseshoe.prove`'s."""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from certify.numerics import horseshoe

from . import saving


def _f(z) -> float:
    return float(horseshoe.Fraction(int(z.p), int(z.q))) if hasattr(z, "p") else float(z)


def horseshoe_figure(path, H: horseshoe.Horseshoe, cloud: int = 4000) -> Path:
    """Draw the proved horseshoe ``H`` into ``path`` (PNG, written atomically)."""
    plt = saving.pyplot()
    P = H.proof
    assert P is not None and P.holds, "a figure only of a proved horseshoe"
    edges = list(P.covers)
    cols = 4
    rows = 1 + math.ceil(len(edges) / cols)
    fig = plt.figure(figsize=(3.2 * cols, 3.0 * rows))
    ax = fig.add_subplot(rows, 1, 1)
    fm = horseshoe.FloatMap(H.r)
    z, pts = np.array([0.3, -1.0]), []
    for k in range(cloud + 100):
        z, _w = fm.step(z)
        if z is None:
            break
        if k >= 100:
            pts.append(z)
    if pts:
        a = np.array(pts)
        ax.plot(a[:, 0], a[:, 1], ",", color="0.6", label="a float64 orbit (observed)")
    for b in P.boxes:
        V = np.array([[_f(x) for x in v] for v in b.vertices()] + [[_f(x) for x in b.vertices()[0]]])
        ax.plot(V[:, 0], V[:, 1], "-", lw=1.5)
        ax.annotate(b.name, (V[0, 0], V[0, 1]), fontsize=7)
    cs = np.array([[_f(x) for x in b.c] for b in P.boxes])
    pad = 0.15 * max(np.ptp(cs[:, 0]), np.ptp(cs[:, 1]), 1e-3)
    ax.set_xlim(cs[:, 0].min() - pad, cs[:, 0].max() + pad)
    ax.set_ylim(cs[:, 1].min() - pad, cs[:, 1].max() + pad)
    ax.set_xlabel("u")
    ax.set_ylabel("v")
    ax.set_title(f"r = {H.r}: the boxes of the horseshoe (saddle {H.saddle}) on the b-section (u, v)", fontsize=9)
    for n, (i, j) in enumerate(edges):
        a_, b_ = P.boxes[i], P.boxes[j]
        axn = fig.add_subplot(rows, cols, cols + n + 1)
        axn.fill([-1, 1, 1, -1], [-1, -1, 1, 1], color="0.85")
        img = [b_.coordinates(horseshoe.image(a_.word, v, H.r)) for v in a_.vertices()]
        Q = np.array([[_f(x) for x in p] for p in img + img[:1]])
        axn.plot(Q[:, 0], Q[:, 1], "-", color="C3")
        axn.set_xlim(-4, 4)
        axn.set_ylim(-1.6, 1.6)
        axn.set_title(f"{a_.name} ⇒ {b_.name} (in {b_.name}'s x, y)", fontsize=8)
        axn.tick_params(labelsize=6)
    fig.tight_layout()
    return saving.write_figure(fig, path)
