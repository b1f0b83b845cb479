"""The kernel's reduction map (certify_kernel/reduction.py): the step lemma on the six cones, the
predicates on the collision words of every orbit, and the statements of statements/4_dynamics.txt."""
from __future__ import annotations

from fractions import Fraction

import pytest

from certify_kernel import check_statement, prepare, read
from certify_kernel import reduction as R
from certify_kernel.evaluate import NotVerified
from certify_kernel.language import parse
from certify_kernel.statements import DEFAULT
from certify_kernel.values import declare

for _name in ("n1", "n2", "n3"):
    declare(_name)


def decide(formula: str) -> bool:
    t = parse(formula)
    return R.PREDICATES[t[1]](None, *t[2])


def test_the_step_lemma_gives_the_printed_next_collisions():
    # l. 888-928: after a, cos φ > 0 gives b and cos φ < 0 gives c; after b: c, a; after c: a, b
    g = R.graph()
    assert {(R.LETTERS[i], s): R.LETTERS[j] for (i, s), (j, _) in g.items()} == \
        {("a", 1): "b", ("a", -1): "c", ("b", 1): "c", ("b", -1): "a", ("c", 1): "a", ("c", -1): "b"}
    assert g[(0, -1)][1] == (-1,) and g[(2, 1)][1] == (1,)       # after ac, cos φ' < 0; after ca, cos φ' > 0
    assert all(len(signs) == 2 for key, (_, signs) in g.items() if key not in ((0, -1), (2, 1)))


def test_windows_of_length_three_are_the_ten_without_aca_and_cac():
    assert R.words(3) == {"aba", "abc", "acb", "bab", "bac", "bca", "bcb", "cab", "cba", "cbc"}


@pytest.mark.parametrize("formula, holds", [
    ("windows(ac_ implies not aca)", True),
    ("windows(ca_ implies not cac)", True),
    ("windows(b___ implies b_b_ or b__b)", True),
    ("windows(___ implies b__ or _b_ or __b)", True),
    ("windows(b___ implies b_b_)", False),            # bacb: an exact orbit has it
    ("windows(ab_ implies aba)", False),
    ("concatenation(ab, cb, acb, cab)", False),       # c_1 = b after a state of the cone (a, u_1 > 0)
    ("concatenation(b, ab, cb, acb, cab)", True),
    ("concatenation(ab, cb, acb)", False),
    ("endless()", True),
])
def test_predicates(formula, holds):
    assert decide(formula) is holds


def test_a_false_window_is_shown_on_an_exact_orbit():
    assert R.orbit(0, (1, 1, -1), Fraction(1, 2), 8) == "abcbabcb"
    assert R.exhibited("bacb", 1) and not R.exhibited("aca", 0)


def test_a_pattern_needs_one_length():
    with pytest.raises(ValueError):
        decide("windows(ab_ implies abcb)")


def test_an_allowed_window_without_an_orbit_is_not_verified(monkeypatch):
    monkeypatch.setattr(R, "exhibited", lambda w, skip: False)
    with pytest.raises(NotVerified):
        decide("windows(b___ implies b_b_)")


def test_the_statements_of_the_dynamics_are_verified_without_witnesses():
    paper = read(DEFAULT)
    prepare(paper)
    mine = [c for c in paper.certificates if c.id in ("S6", "S9.1", "S9.2", "S10", "S11")]
    assert [c.id for c in mine] == ["S6", "S11", "S9.1", "S9.2", "S10"]
    for c in mine:
        for s in c.statements:
            assert check_statement(s, paper.lets) == (True, ""), s.id
