"""The engine's memoised results, and one hook that forgets them all (the ground floor).

A module that memoises across runs (the candidate of a word, the cofactor matrices,
the conditions on eigenvalue branches, SymPy's own cache) registers the function that
empties its cache with :func:`register`; :func:`reset` calls them all, so that the
next run is cold (the benchmark does this before each repetition).  The runner thus
needs to know no module above it.
"""
from __future__ import annotations

import functools
from collections.abc import Callable

_CLEARS: list[Callable[[], None]] = []
_OF_A_WORD: list[Callable[[], None]] = []


def register(clear: Callable[[], None], of_a_word: bool = False) -> Callable[[], None]:
    """Remember ``clear`` (a function of no argument that empties one cache); return it.
    ``of_a_word``: the cache is keyed by a collision word (a word's candidate, its
    Spectrum), and :func:`reset_words` empties it too."""
    if clear not in _CLEARS:
        _CLEARS.append(clear)
    if of_a_word and clear not in _OF_A_WORD:
        _OF_A_WORD.append(clear)
    return clear


def reset_words() -> None:
    """Empty the caches keyed by a word: what a run over many words (the census) forgets
    after each one, keeping the memos that serve every word."""
    for clear in _OF_A_WORD:
        clear()


def reset() -> None:
    """Empty every registered cache."""
    for clear in _CLEARS:
        clear()


def by_identity(func: Callable, limit: int = 20000) -> Callable:
    """``func(obj)`` memoised by the identity of ``obj`` until :func:`reset` (its memo registered
    here), for objects that are the same in many queries of a run and whose hash is costly or
    missing (a polynomial, a list of terms).  ``obj`` is kept alive beside its value, so its id
    is not reused while the entry lasts; past ``limit`` entries the memo starts again."""
    memo: dict = {}
    register(memo.clear)

    @functools.wraps(func)
    def inner(obj):
        entry = memo.get(id(obj))
        if entry is None or entry[0] is not obj:
            if len(memo) > limit:
                memo.clear()
            entry = memo[id(obj)] = (obj, func(obj))
        return entry[1]
    return inner


def for_a_run(func: Callable) -> Callable:
    """``func`` memoised until :func:`reset` (its memo registered here): for pure steps that
    several callers of one run take on the same arguments.  An unhashable argument is
    computed every time; an exception is not kept."""
    cached = functools.cache(func)
    register(cached.cache_clear)

    @functools.wraps(func)
    def inner(*args):
        try:
            return cached(*args)
        except TypeError:
            try:
                hash(args)
            except TypeError:          # an unhashable argument: no memo
                return func(*args)
            raise                      # the function's own TypeError
    return inner
