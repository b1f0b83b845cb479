"""identify.orbits_at (orbit_at once per word and r in a run) against orbit_at itself: the same
orbits, computed once until the caches' reset."""
import flint

from certify import caches
from certify.patterns.reduction_orbits import orbit_at
from certify.run import identify as ident

WORD, R = "abacbcabcababcbcabacbacbcb", flint.fmpq(1, 5)    # N2's attracting word at r = 1/5


def _kinds(orbits):
    return [(x.kind, x.feasible, x.branch_name) for x in orbits]


def test_orbits_at_is_orbit_at_once_per_run():
    caches.reset()
    first = ident.orbits_at(WORD, R)
    assert _kinds(first) == _kinds(orbit_at(WORD, R))
    assert ident.orbits_at(WORD, R) is first           # served from the memo
    caches.reset()
    again = ident.orbits_at(WORD, R)
    assert again is not first and _kinds(again) == _kinds(first)


def test_decided_is_the_feasible_orbit_of_orbit_at():
    ident.decided.cache_clear()
    o = ident.decided(WORD, R)
    assert o.kind == "attracting" and o.feasible
    assert (o.kind, o.branch_name, o.pair) == next((x.kind, x.branch_name, x.pair) for x in orbit_at(WORD, R)
                                                   if x.feasible)
