"""tools/five_particle_search.py (observed, floats): its datum against certify pattern's exact sets for
four particles, and the five-particle word it finds."""
import importlib.util
from fractions import Fraction
from pathlib import Path

import pytest

from certify.patterns.pattern import analyse

ROOT = Path(__file__).resolve().parents[1]
spec = importlib.util.spec_from_file_location("five_particle_search", ROOT / "tools" / "five_particle_search.py")
search = importlib.util.module_from_spec(spec)
spec.loader.exec_module(search)


def inside(intervals, r: float, margin: float = 1e-3) -> bool | None:
    """True/False away from the ends (None within ``margin`` of one)."""
    for lo, hi in intervals:
        a, b = float(lo.digits(15)), float(hi.digits(15))
        if min(abs(r - a), abs(r - b)) < margin:
            return None
        if a < r < b:
            return True
    return False


@pytest.mark.parametrize("word", ["ababcbcb", "abcb", "ababcb"])
def test_the_datum_of_two_eigenvalues_is_the_pattern_for_four_particles(word):
    """Stable and feasible at r exactly where certify pattern's exact analysis says so (grid of 0.01)."""
    res = analyse(word)
    stable = [(lo, hi) for *_, lo, hi in res.intervals("stable")]
    feasible = [(lo, hi) for *_, lo, hi in res.intervals("feasible")]
    for k in range(1, 100):
        r = k / 100
        found = search.data(word, r, 4)
        for expected, seen in ((inside(stable, r), any(s for *_, s in found)), (inside(feasible, r), bool(found))):
            assert expected is None or expected == seen, (word, r)


def test_the_five_particle_word():
    """abadcbcabc: stable at 0.26, feasible but not stable at 0.2, neither at 0.27."""
    assert any(s for *_, s in search.data("abadcbcabc", 0.26, 5))
    assert search.data("abadcbcabc", 0.2, 5) and not any(s for *_, s in search.data("abadcbcabc", 0.2, 5))
    assert not search.data("abadcbcabc", 0.27, 5)
    assert search.canonical("abcbdcbdcd", "abcd") == "abadcbcabc"     # its mirror (a↔d, b↔c), rotated


def test_words_are_classes():
    ws = list(search.words(6, 5))
    assert len(ws) == len(set(ws)) and all(set(w) == set("abcd") for w in ws)
    assert all(search.canonical(w, "abcd") == w for w in ws)


@pytest.mark.parametrize("word, r, particles", [("abadcbcabc", 0.26, 5), ("ababcbcb", 0.15, 4)])
def test_the_plane_is_the_dominant_eigenvector_of_the_second_compound(word, r, particles):
    """Where the datum is stable, κ = λμ is the strictly dominant eigenvalue of Λ²M_w and its eigenvector
    is the plane Span(p(0), q(0)): contracted with the last face's coordinate it gives p(0) (one algebraic
    function κ of r carries the datum: the route of a five-particle certify pattern, docs/particles.md)."""
    import itertools

    import numpy as np
    gaps = particles - 1
    (lam, mu, stable), = [d for d in search.data(word, r, particles) if d[2]]
    M = search.period_matrix(word, gaps, r)
    pairs = list(itertools.combinations(range(gaps), 2))
    W = np.array([[M[i, k] * M[j, m] - M[i, m] * M[j, k] for (k, m) in pairs] for (i, j) in pairs])
    ev, V = np.linalg.eig(W)
    order = np.argsort(-abs(ev))
    assert abs(ev[order[0]] - lam * mu) < 1e-12 and abs(ev[order[1]]) < abs(ev[order[0]]) * (1 - 1e-3)
    B = np.zeros((gaps, gaps))
    for (i, j), b in zip(pairs, V[:, order[0]].real):
        B[i, j], B[j, i] = b, -b
    Y = "abcd".index(word[-1])
    ew, U = np.linalg.eig(M)
    q0, e = U[:, np.argmin(abs(ew - lam))].real, U[:, np.argmin(abs(ew - mu))].real
    p0 = e[Y] * q0 - q0[Y] * e
    assert np.allclose(B[:, Y] / B[0, Y], p0 / p0[0], rtol=1e-9)


COMMITTED = ROOT / "reports" / "five-patterns"


def certified(word: str) -> tuple[list[float], list[float]]:
    """The committed file's r range (a grid of 31 points on it) and certified stable window [lo, hi]."""
    import json

    import numpy as np
    doc = json.loads((COMMITTED / f"{word}.json").read_text(encoding="utf-8"))
    pieces = [p for s in doc["stable"] for p in s["pieces"] if p["kind"] == "interval"]
    lo, hi = (float(Fraction(x)) for x in doc["r_range"])
    return (list(np.linspace(lo, hi, 31)),
            [min(float(p["lo"]["digits"]) for p in pieces), max(float(p["hi"]["digits"]) for p in pieces)])


@pytest.mark.parametrize("word", ["abacbacbdcbcdcdbcdbcabcb", "ababcbcabacbacbdcbdcdcbcbdcdbcdbcabc"])
def test_the_half_map_gives_the_datum_of_the_word(word):
    """For the committed 24- and 36-letter words X·m(X): M_W = N², and the datum from N = J·M_X is
    stable at the same grid points as the ordinary datum, its ends the same to 1e-8."""
    import numpy as np
    assert search.symmetric(word, 5) == word
    N = search.half_map(word, 4, 0.2)
    assert np.allclose(N @ N, search.period_matrix(word, 4, 0.2), rtol=0, atol=1e-12)
    grid, _ = certified(word)
    (ends, hits), (half_ends, half_hits) = (search.window(word, grid, 5, True, h) for h in (False, True))
    assert hits and half_hits == hits and len(half_ends) == len(ends) == 2
    assert np.allclose(half_ends, ends, rtol=0, atol=1e-8)


def test_the_half_map_resolves_the_56_letter_word():
    """The 56-letter word: the --half window's ends are the certified ends (committed file) to 1e-6
    (the ordinary datum loses μ in rounding: on this machine its upper end is off by about 5e-7, a
    figure that depends on the BLAS, so it is not asserted)."""
    word = "abacbacbcabacbcbabacbcdcdbcbdcdbcdbcbdcdbcbcdcdbcbabacbc"
    grid, (lo, hi) = certified(word)
    half_ends, _ = search.window(word, grid, 5, True, True)
    assert len(half_ends) == 2 and abs(half_ends[0] - lo) < 1e-6 and abs(half_ends[1] - hi) < 1e-6


def test_the_digits_resolve_the_128_letter_word():
    """F₂(4)·A, 128 letters (committed, certified): at 50 digits (--digits, data_mp) the half datum's
    stable window, bisected, has the certified ends to 1e-9, where float64 is at its rounding limit; at 40
    digits data_mp agrees with the float datum on the 56-letter word."""
    import functools

    import numpy as np

    from certify.patterns import five
    word = five.family_word("abacbacbc", 4)
    _, (lo, hi) = certified(word)
    grid = list(np.linspace(lo - 1e-7, hi + 1e-7, 21))
    ends, hits = search.window(word, grid, 5, True, True, functools.partial(search.data_mp, digits=50))
    assert len(ends) == 2 and abs(ends[0] - lo) < 1e-9 and abs(ends[1] - hi) < 1e-9
    W = five.family_word("abacbacbc", 1)
    for r in (0.17865, 0.1787, 0.17875):
        floats, digits = search.data(W, r, 5, True), search.data_mp(W, repr(r), 5, True, 40)
        assert sorted((round(a, 9), s) for a, _, s in floats) == sorted((round(a, 9), s) for a, _, s in digits)


def test_the_law_of_the_family_predicts_the_next_member():
    """docs/particles.md's observed law for F₂(k)·A: s_k = 1/√(ℓ_k - (3 - 2√2)) nearly linear in k.  From
    the certified lower ends ℓ_3, ℓ_4 (committed files) it predicts ℓ_5 = L + 1/(2s_4 - s_3)²; at 50
    digits the 152-letter member is stable within 10⁻⁶ of that prediction (a scan of step 10⁻⁸)."""
    import math

    import numpy as np

    from certify.patterns import five
    L = 3 - 2 * math.sqrt(2)
    s3, s4 = (1 / math.sqrt(certified(five.family_word("abacbacbc", k))[1][0] - L) for k in (3, 4))
    predicted = L + 1 / (2 * s4 - s3) ** 2
    word = five.family_word("abacbacbc", 5)
    hits = [r for r in np.linspace(predicted - 1e-6, predicted + 1e-6, 201)
            if any(s for *_, s in search.data_mp(word, r, 5, True, 50))]
    assert hits and len(word) == 152


def test_the_resonance_rule_predicts_member_six():
    """docs/particles.md's rule (certify/patterns/five_rule.py): F₂(k)·A is stable just below the island's
    resonance ρ = p/q, q = 4k + 5, at ε = 1/(1 - 2ρ) - q with q²ε falling (observed).  From the certified
    member k = 4 (its lower end's q²ε, committed file) it puts k = 6 (176 letters, q = 29) at
    0 < ε < c₄/29² (c₄ ≈ 16.65); a 60-digit scan of that piece of r (120 points) finds the member stable there."""
    import mpmath

    from certify.patterns import five

    def epsilon(r, q):
        rho = mpmath.acos(-(1 - r) ** 2 / (4 * r)) / (2 * mpmath.pi)
        return 1 / (1 - 2 * rho) - q

    def r_at(q, eps):
        c = mpmath.cos(mpmath.pi * (1 - 1 / (q + eps)))
        return (1 - 2 * c) - mpmath.sqrt((1 - 2 * c) ** 2 - 1)

    from certify.patterns.five_rule import resonance
    (_, q4), (_, q6) = resonance("abacbacbc", 4), resonance("abacbacbc", 6)
    assert (q4, q6) == (21, 29)
    _, (lo4, _hi) = certified(five.family_word("abacbacbc", 4))
    with mpmath.workdps(30):                       # not the global precision: other tests share the process
        c4 = q4 ** 2 * epsilon(mpmath.mpf(lo4), q4)
        assert 16.5 < c4 < 16.8
        a, b = float(r_at(q6, c4 / q6 ** 2)), float(r_at(q6, 0))
    word = five.family_word("abacbacbc", 6)
    hits = [a + (b - a) * i / 119 for i in range(120)
            if any(s for *_, s in search.data_mp(word, a + (b - a) * i / 119, 5, True, 60))]
    assert hits and len(word) == 176


def test_half_needs_a_symmetric_word(capsys):
    """abadcbcabc is no rotation of any X·m(X): one line on stderr, exit status 2."""
    assert search.main(["--word", "abadcbcabc", "--half", "--r", "0.2", "0.3", "3"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "not X·m(X)" in err
