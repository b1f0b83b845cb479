"""identify.orbits_at (orbit_at once per word and r in a recording, its facts replayed) against
orbit_at itself: the same orbits, and a recording that calls it (Section 5's decide, then
verify's decided) records the same facts, with the same ids, as one calling orbit_at."""
import flint

from certify import obligations
from certify.patterns.reduction_orbits import orbit_at
from certify.run import identify as ident

WORD, R = "abacbcabcababcbcabacbacbcb", flint.fmpq(1, 5)    # N2's attracting word at r = 1/5


def _recorded(f):
    with obligations.recording("T") as rec:
        first = f(WORD, R)
        taken = obligations.take()
        again = f(WORD, R)
        taken_again = obligations.take()
    kinds = [(x.kind, x.feasible, x.branch_name) for x in first] + [(x.kind, x.feasible) for x in again]
    return kinds, rec.items, taken, taken_again


def test_orbits_at_records_what_orbit_at_records():
    ident.orbits_at.cache_clear()
    want = _recorded(orbit_at)
    assert want[1] and want[2]                 # orbit_at records facts: the comparison says something
    assert _recorded(ident.orbits_at) == want
    assert _recorded(ident.orbits_at) == want  # served from the memo: the facts replayed


def test_decided_is_the_feasible_orbit_of_orbit_at():
    ident.decided.cache_clear()
    o = ident.decided(WORD, R)
    assert o.kind == "attracting" and o.feasible
    assert (o.kind, o.branch_name, o.pair) == next((x.kind, x.branch_name, x.pair) for x in orbit_at(WORD, R)
                                                   if x.feasible)
