"""certify.caches: the memos of a run, and the hook that forgets them."""
from __future__ import annotations

from certify import caches


def test_a_memo_for_a_run_is_forgotten_by_reset():
    calls = []

    @caches.for_a_run
    def double(x):
        calls.append(x)
        return x + x

    assert double(3) == double(3) == 6 and calls == [3]
    caches.reset()
    assert double(3) == 6 and calls == [3, 3]
    assert double([2]) == double([2]) == [2, 2] and calls == [3, 3, [2], [2]]    # unhashable: computed each time


def test_an_exception_is_not_kept():
    tries = []

    @caches.for_a_run
    def flaky(x):
        tries.append(x)
        if len(tries) == 1:
            raise ArithmeticError("first time")
        return x

    try:
        flaky(1)
    except ArithmeticError:
        pass
    assert flaky(1) == 1 and tries == [1, 1]


def test_a_type_error_inside_is_not_taken_for_an_unhashable_argument():
    @caches.for_a_run
    def bad(x):
        return x + "a"

    try:
        bad(1)
    except TypeError:
        return
    raise AssertionError("the TypeError of the function was swallowed")


def test_a_memo_by_identity_tells_equal_objects_apart_and_is_forgotten_by_reset():
    calls = []

    @caches.by_identity
    def total(terms):
        calls.append(terms)
        return sum(terms)

    a, b = [1, 2], [1, 2]
    assert total(a) == total(a) == 3 and calls == [a]
    assert total(b) == 3 and len(calls) == 2 and calls[1] is b        # equal, not the same object
    a.append(4)
    assert total(a) == 3          # the first value of the object: a list given is never modified
    caches.reset()
    assert total(a) == 7 and len(calls) == 3
