"""The exceptions that cross layers (the ground floor: every layer may import it).

:class:`UsageError` is a user mistake (an unknown claim id, r outside ]0,1[, a bad
option, an unwritable output): the command line turns it into one line on stderr
and exit code 2, before any work is done.  :class:`StatementError` is a printed text
that the grammar of :mod:`certify.algebra.statements` does not read: the runner turns
it into a FAIL of the certificate that quotes the text.
"""
from __future__ import annotations


class UsageError(Exception):
    """A user mistake (unknown id, bad option, unwritable output): exit code 2."""


class StatementError(ValueError):
    """A printed text that the grammar does not read, or a relation that cannot be
    evaluated on the certified facts given: the certificate FAILs with this reason."""
