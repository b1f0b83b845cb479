"""The exceptions that cross layers (the ground floor: every layer may import it).

:class:`UsageError` is a user mistake (an unknown claim id, r outside ]0,1[, a bad
option, an unwritable output): the command line turns it into one line on stderr
and exit code 2, before any work is done.
"""
from __future__ import annotations


class UsageError(Exception):
    """A user mistake (unknown id, bad option, unwritable output): exit code 2."""
