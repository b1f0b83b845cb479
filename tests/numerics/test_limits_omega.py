"""limits.omega without the list of clusters, against the omega it replaced (read from clusters())."""
import numpy as np
import pytest

from certify.numerics import limits
from certify.numerics.limits import Omega, clusters, coverage


def _reference_omega(values, gap=limits.GAP, point=limits.POINT, max_pieces=limits.MAX_PIECES):
    cl = clusters(values, gap)
    if not cl:
        return Omega("none", 0, 0.0, 0.0)
    width = max(hi - lo for lo, hi, _ in cl)
    kind = "points" if width < point else "pieces" if len(cl) <= max_pieces else "spread"
    return Omega(kind, len(cl), float(width), coverage(values))


def _samples():
    rng = np.random.default_rng(26)
    yield np.array([])
    yield np.array([np.nan, np.inf])
    yield np.array([1.0])
    yield np.array([[1.0, 1.0 + 1e-9], [2.0, np.nan]])
    for n in (3, 60, 2000):
        yield rng.uniform(0, np.pi, n)                                   # spread
        yield np.repeat(rng.uniform(0, np.pi, 7), n) + rng.normal(0, 1e-9, 7 * n)   # points
        pieces = rng.uniform(0, np.pi, 5)
        yield (pieces[:, None] + rng.uniform(0, 0.02, (5, n))).ravel()   # pieces


@pytest.mark.parametrize("k", range(13))
@pytest.mark.parametrize("gap", [limits.GAP, limits.PIECE_GAP])
def test_omega_is_the_omega_of_the_clusters(k, gap):
    values = list(_samples())[k]
    assert limits.omega(values, gap) == _reference_omega(values, gap)


def test_the_samples_have_every_kind():
    assert {limits.omega(v).kind for v in _samples()} == {"none", "points", "pieces", "spread"}
