"""The witnesses the engine gives the independent kernel (the ground floor).

A witness is data that makes a decision possible for the kernel, of a kind it reads
(docs/verify.md; ``certify.run.report.WITNESS_KINDS``): ``signed``, the factorisation that
shows a strict sign by inspection (:mod:`certify.algebra.trig`), and ``factors``, the factors
met by the sign tables of a collision word (``certify.run.witness``).  While a certificate runs
(:func:`recording`), a deciding function decorated with :func:`witnessing` records, at its
outermost call, the witness built from its arguments and its answer; a proof records others
with :func:`record`.  A witness is numbered once per certificate (the same data, the same id),
a result object carries the ids of those it was decided by (``.witnesses``), and a check names
those its verdict rests on (``certify.run.Check``): the kernel reads them in certificates.json
beside the check's statement.  Nested calls and the shared quantities (:func:`quiet`) record
nothing; without an active recording the decorator costs one attribute test.
"""
from __future__ import annotations

import functools
import json
from collections.abc import Callable
from contextlib import contextmanager


class Recording:
    """The witnesses of one certificate, once each, numbered in the order they were first recorded."""

    def __init__(self, prefix: str) -> None:
        self.prefix, self.items, self.by_key = prefix, [], {}
        self.depth = 0                    # > 0 inside a deciding function or a quiet() block

    def add(self, ob: dict) -> str:
        """The id of ``ob`` (a new one if it was not recorded before)."""
        key = json.dumps(ob, sort_keys=True, ensure_ascii=False)
        if key not in self.by_key:
            self.by_key[key] = f"{self.prefix}:{len(self.items) + 1}"
            self.items.append({"id": self.by_key[key], **ob})
        return self.by_key[key]


_ACTIVE: list[Recording] = []
_CAPTURES: list[list] = []


@contextmanager
def recording(prefix: str):
    """Record the witnesses of the certificate ``prefix`` while the block runs."""
    rec = Recording(prefix)
    _ACTIVE.append(rec)
    try:
        yield rec
    finally:
        _ACTIVE.remove(rec)


@contextmanager
def quiet():
    """Record nothing while the block runs (a shared quantity: computed once per run)."""
    rec = _ACTIVE[-1] if _ACTIVE else None
    if rec is not None:
        rec.depth += 1
    try:
        yield
    finally:
        if rec is not None:
            rec.depth -= 1


def record(ob: dict) -> str | None:
    """Record the witness ``ob`` (and keep it for every :func:`captured` block under way); its id
    (None outside a recording, or inside a deciding function or a quiet() block)."""
    if not _ACTIVE or _ACTIVE[-1].depth:
        return None
    for got in _CAPTURES:
        got.append(ob)
    return _ACTIVE[-1].add(ob)


def witnessing(build: Callable) -> Callable:
    """Decorate a deciding function: its outermost call records ``build(answer, *args, **kw)``
    (a dict, a list of dicts, or None), and the answer carries their ids (``.witnesses``) when it
    can; an exception in ``build`` (no witness: a sign left undecided) records nothing."""
    def wrap(func):
        @functools.wraps(func)
        def inner(*args, **kwargs):
            if not _ACTIVE or _ACTIVE[-1].depth:
                return func(*args, **kwargs)
            rec = _ACTIVE[-1]
            rec.depth += 1
            try:
                answer = func(*args, **kwargs)
                try:
                    obs = build(answer, *args, **kwargs)
                except Exception:         # nothing to show the kernel
                    obs = None
            finally:
                rec.depth -= 1
            listed = [] if obs is None else obs if isinstance(obs, list) else [obs]
            ids = [record(ob) for ob in listed]
            try:                          # a result object carries its witnesses
                answer.witnesses = [i for i in ids if i]
            except AttributeError:
                pass
            return answer
        return inner
    return wrap


@contextmanager
def captured():
    """The witnesses (as data) recorded while the block runs, in order, repeats included: those
    of a computation, kept with its result (a lemma of a shared quantity, a sign read as a tuple)
    so that each check that reads the result records them again (``certify.run.kept_witnesses``)."""
    got: list = []
    _CAPTURES.append(got)
    try:
        yield got
    finally:
        _CAPTURES.remove(got)


def witnesses_of(*results) -> list[str]:
    """The witnesses carried by deciding results (a trig Result, ...), in order, once each."""
    out: list[str] = []
    for res in results:
        for i in getattr(res, "witnesses", None) or []:
            if i not in out:
                out.append(i)
    return out


def in_order(ids: list[str]) -> list[str]:
    """The ids of a check once each, in the order they were first recorded (outside a recording: as given)."""
    if not _ACTIVE:
        return ids
    return sorted(set(ids), key=lambda i: int(i.rsplit(":", 1)[1]))
