"""The exceptions that cross layers, and the one way of saying "undecided" (the ground
floor: every layer may import it).

:class:`UsageError` is a user mistake (an unknown claim id, r outside ]0,1[, a bad
option, an unwritable output): the command line turns it into one line on stderr
and exit code 2, before any work is done.  :class:`StatementError` is a printed text
that the grammar of :mod:`certify.algebra.statements` does not read: the runner turns
it into a FAIL of the certificate that quotes the text.

Undecided: three-valued answers, in the manner of Arb's predicates
------------------------------------------------------------------

Every question the engine asks about an exact quantity through enclosures (the sign of
a polynomial at an algebraic number, the order of two balls, a zero test, the next
collision) has three answers:

* a proven answer -- a sign in {-1, 0, +1}, True or False, an order, a collision: it
  holds for the exact quantity, whatever precision produced it;
* :data:`UNDECIDED` -- the enclosures at the precision allowed did not decide.  It says
  *nothing* about the exact value (it is neither "false" nor "zero"): more precision, or
  an exact test, may decide it; a condition that meets it is reported as undecided,
  never as holding or failing.  It is never a truth value: compare it with ``==``,
  never read it with ``if``;
* (where the question has none) a proven "there is nothing": no real branch of that
  index at this r (``NO_BRANCH`` of :mod:`certify.algebra.branches`), x not real
  (Δ < 0: ``None``).  These are answers, not undecided.

A function that returns an answer returns :data:`UNDECIDED` when it cannot decide; a
function that must deliver a proven answer (a certified sign, a run of the dynamics)
raises :class:`Undecided` instead.  Where not even the shape of the answer is known
(the real branches at an r that could not be isolated, so no list of signs to put
:data:`UNDECIDED` in; balls whose order overlaps), the answer is ``None``.  Nothing
else means undecided: not a bare ``ArithmeticError`` (which stays a contradiction:
routes that disagree, a relation that does not hold), not ``ValueError``.  Where python-flint signals that its
root finder did not converge (``ValueError``), the caller turns it into one of the two.
:data:`UNDECIDED` is the string ``"?"``, so that sign tables and reports print it as
they always have.
"""
from __future__ import annotations

UNDECIDED = "?"       # a sign or truth value the enclosures did not decide (printed as is)


class UsageError(Exception):
    """A user mistake (unknown id, bad option, unwritable output): exit code 2."""


class StatementError(ValueError):
    """A printed text that the grammar does not read, or a relation that cannot be
    evaluated on the certified facts given: the certificate FAILs with this reason."""


class Undecided(ArithmeticError):
    """A sign, comparison or zero test that the enclosures cannot decide at the
    precision allowed (see the module's docstring): says nothing about the exact value."""
