"""The engine's memoised results, and one hook that forgets them all (the ground floor).

A module that memoises across runs (the candidate of a word, the cofactor matrices,
the conditions on eigenvalue branches, SymPy's own cache) registers the function that
empties its cache with :func:`register`; :func:`reset` calls them all, so that the
next run is cold (the benchmark does this before each repetition).  The runner thus
needs to know no module above it.
"""
from __future__ import annotations

from collections.abc import Callable

_CLEARS: list[Callable[[], None]] = []


def register(clear: Callable[[], None]) -> Callable[[], None]:
    """Remember ``clear`` (a function of no argument that empties one cache); return it."""
    if clear not in _CLEARS:
        _CLEARS.append(clear)
    return clear


def reset() -> None:
    """Empty every registered cache."""
    for clear in _CLEARS:
        clear()
