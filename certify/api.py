"""The Python face of certify, for a notebook (docs/api.md): six functions over the engine's own.

- :func:`analyse`: the exact analysis of a periodic word (``certify pattern``), a
  :class:`~certify.patterns.PatternResult`.
- :func:`windows`: its certified windows of r, each a :class:`~certify.patterns.pattern.Window`
  with exact algebraic ends (:class:`~certify.algebra.Algebraic`).
- :func:`family_window`: the stable window of (ab)^n(cb)^n for any n ≥ 2 (``certify pattern``'s
  route for the family: the engine up to n = 7, the theorem of family_limit beyond).
- :func:`island`: the island theorem at a rational r (``certify island``), every step proved.
- :func:`identify`: the class of the simulated orbits at r (``certify identify``).
- :func:`certificate`: one certificate of the paper run (``certify run ID``).

The numbers are read as the command line reads them, from their text (3/10, 0.3, 1e-1 or 10^-1,
read exactly: 0.3 is 3/10, a float by its shortest decimal; a Fraction or an int as itself); a bad
argument is a ValueError in one line that names what is allowed.  Algebraic numbers, windows,
analyses, island theorems and certificates show themselves in LaTeX or Markdown in a notebook
(``_repr_latex_``, ``_repr_markdown_``).  Nothing here computes on its own: each function checks
its arguments and calls the engine's function named beside it.
"""
from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from fractions import Fraction
from typing import NamedTuple

from certify.algebra import Algebraic
from certify.cli.options import r_range, r_value
from certify.cli.section5 import float64_r
from certify.errors import UsageError
from certify.patterns import family_windows, island_theorem, pattern
from certify.patterns.family import family_n, family_word
from certify.patterns.island_theorem import Theorem
from certify.patterns.pattern import STAGES, PatternResult, Window
from certify.run import identify as identification
from certify.run import report, runner

Rational = Fraction | int | float | str   # Fraction(3, 10), 0, "3/10", "0.3", 0.3: read exactly from the text

__all__ = ["Rational", "analyse", "windows", "family_window", "island", "identify", "certificate", "Certified",
           "STAGES"]


@contextmanager
def _plain_errors() -> Iterator[None]:
    """The command line's UsageError (a bad word, a bad r) as a ValueError with the same line."""
    try:
        yield
    except UsageError as exc:
        raise ValueError(str(exc)) from None


def _r(r: Rational) -> Fraction:
    """r as ``--r`` reads it: an exact rational in [2^-60, 1 - 2^-60] (ValueError otherwise)."""
    with _plain_errors():
        return r_value(str(r), "r")


def analyse(word: str, lo: Rational = 0, hi: Rational = 1) -> PatternResult:
    """The exact analysis of the periodic ``word`` over ]lo, hi[ (:func:`certify.patterns.analyse`,
    ``certify pattern WORD --r-range LO HI``): where in r self-similar data exist, are feasible,
    are stable, each set certified with exact algebraic ends; a notebook shows it as Markdown."""
    with _plain_errors():
        lo_q, hi_q = r_range(str(lo), str(hi))
        normal, system, _why = pattern.read(word)
    n = family_n(normal) if system == "four" else None
    if n is not None and n > family_windows.EXACT_N0 and (lo_q, hi_q) == (0, 1):
        raise ValueError(f"{word}: the engine's analysis over ]0, 1[ takes hours for n = {n} > "
                         f"{family_windows.EXACT_N0}: family_window({n}) gives its stable window by the "
                         "theorem; analyse(word, lo, hi) runs the engine on ]lo, hi[")
    return pattern.analyse(word, lo_q, hi_q)


def windows(word: str, stage: str = "stable", branch: int | None = None,
            lo: Rational = 0, hi: Rational = 1) -> list[Window]:
    """The maximal open intervals of r in the ``stage`` set of ``word`` (exists, feasible or
    stable), on every branch or on ``branch`` (0 upper, 1 middle, 2 lower), increasing by branch:
    :meth:`PatternResult.intervals`.  Isolated points of the set are in
    ``analyse(word).points(stage)``."""
    pattern.check_stage(stage)                      # before the work
    return analyse(word, lo, hi).intervals(stage, branch)


def family_window(n: int) -> tuple[Algebraic, Algebraic]:
    """The stable set of (ab)^n(cb)^n in ]0, 1[, one open window ]lo, hi[ with exact ends, for any
    n ≥ 2: for n ≤ 7 the engine's exact analysis (:func:`analyse`, its stable set), for n ≥ 8 the theorem of
    certify/patterns/family_limit.py (:func:`certify.patterns.family_windows.proved_window`: lo the one
    zero of F_n in ]r_(n+1), r_n[, hi = r_n where nθ = π), valid once the proof's facts are re-verified
    in this process (about 8 s the first time; a ValueError if they fail)."""
    if isinstance(n, bool) or not isinstance(n, int) or n < 2:
        raise ValueError(f"n must be an integer ≥ 2, not {n!r}")
    if n <= family_windows.PROVED_N0:      # stable sets only: the eigenspace route does not change them (L4-L6)
        [w] = pattern.analyse(family_word(n), eigenspace=False).intervals("stable")
        return w.lo, w.hi
    failures = family_windows.theorem()["failures"]
    if failures:
        raise ValueError(f"the family's theorem does not hold here: {failures[0]}")
    return family_windows.proved_window(n)


def island(r: Rational) -> Theorem:
    """The island theorem at the rational r (:func:`certify.patterns.island_theorem.theorem`,
    ``certify island --r R``): its steps, each proved exactly; ``.elliptic``, ``.holds``,
    ``.c_max`` (the island is {Q < c_max}) and ``.quasi_periodic``."""
    return island_theorem.theorem(_r(r))


def identify(r: Rational, orbits: int = 8,
             collisions: int = identification.COLLISIONS) -> list[identification.Identified]:
    """The class of each of the first ``orbits`` simulated orbits of the tool's grid of initial
    data at r (:func:`certify.run.identify.identify`, ``certify identify --r R``): island
    (proved), attracting periodic (its word certified for ever) or unresolved (observed only)."""
    if isinstance(orbits, bool) or not isinstance(orbits, int) or orbits < 1:
        raise ValueError(f"orbits must be a positive integer (the first of the tool's grid), not {orbits!r}")
    if isinstance(collisions, bool) or not isinstance(collisions, int) or collisions < 1:
        raise ValueError(f"collisions must be a positive integer, not {collisions!r}")
    with _plain_errors():
        rs = float64_r([_r(r)])
    return identification.identify(rs, orbits=orbits, collisions=collisions)


class Certified(NamedTuple):
    """One certificate and its outcome; a notebook shows it as its section of REPORT.md."""

    certificate: runner.Certificate
    outcome: runner.Outcome

    @property
    def status(self) -> str:
        return self.outcome.status

    def _repr_markdown_(self) -> str:
        return report._section(self.certificate, self.outcome)


def certificate(id: str) -> Certified:
    """Run the certificate ``id`` of the paper (``certify run ID``: :func:`certify.run.runner.run_certificate`
    in a fresh context): PASS, ERRATUM, FAIL or OBSERVED, with its checks and evidence."""
    with _plain_errors():
        chosen = runner.select([id])
    exact = [c for c in chosen if c.id == id.strip().upper()]
    if not exact:
        raise ValueError(f"{id!r} names several certificates: one of {', '.join(c.id for c in chosen)}")
    return Certified(exact[0], runner.run_certificate(exact[0]))
