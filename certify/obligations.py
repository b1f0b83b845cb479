"""The facts the engine proves, recorded as data for the independent kernel (the ground floor).

While a certificate runs (:func:`recording`), the engine's public deciding functions (a Sturm
count, a comparison of algebraic numbers, printed digits, a sign table read on a branch, a
trigonometric identity, ...) are wrapped with :func:`fact`: each outermost call records an
*obligation*, a JSON-ready dict in the language of docs/verify.md, built from its arguments
and its answer.  A check takes the obligations recorded since the previous check
(:func:`take`): the facts its verdict was computed from.  Nested calls (a Sturm count inside
an isolation) and shared quantities (:func:`quiet`) record nothing.  Without an active
recording the wrappers cost one attribute test.
"""
from __future__ import annotations

import functools
import json
from collections.abc import Callable
from contextlib import contextmanager


class Recording:
    """The obligations of one certificate (deduplicated, numbered in order) and those not yet
    taken by a check."""

    def __init__(self, prefix: str) -> None:
        self.prefix, self.items, self.by_key, self.pending = prefix, [], {}, []
        self.depth = 0
        self.taken: set[str] = set()      # ids a check has taken from the pending ones
        self.by_id: dict[str, dict] = {}

    def add(self, ob: dict) -> str:
        """The id of ``ob`` (a new one if it was not recorded before)."""
        key = _key(ob)
        if key not in self.by_key:
            self.by_key[key] = f"{self.prefix}:{len(self.items) + 1}"
            self.items.append({"id": self.by_key[key], **ob})
            self.by_id[self.by_key[key]] = self.items[-1]
        return self.by_key[key]


def _key(ob: dict) -> str:
    """A text equal for two obligations iff their contents are: their JSON, where the
    polynomials of a sign table ("cp", "parts": the same list objects in every query of a
    table) are written once per object (:func:`_text`)."""
    if "cp" not in ob and "parts" not in ob:
        return json.dumps(ob, sort_keys=True, ensure_ascii=False)
    rest = {k: v for k, v in ob.items() if k not in ("cp", "parts")}
    parts = ob.get("parts")
    return json.dumps([json.dumps(rest, sort_keys=True, ensure_ascii=False), _text(ob.get("cp")),
                       sorted((k, _text(v)) for k, v in parts.items()) if isinstance(parts, dict) else _text(parts)])


_TEXTS: dict = {}                # id of a list -> (it, its JSON)


def _text(value) -> str:
    """json.dumps of a list, memoised by identity (a list in a record is never modified)."""
    if not isinstance(value, list):
        return json.dumps(value, sort_keys=True, ensure_ascii=False)
    entry = _TEXTS.get(id(value))
    if entry is None or entry[0] is not value:
        if len(_TEXTS) > 20000:
            _TEXTS.clear()
        entry = _TEXTS[id(value)] = (value, json.dumps(value, sort_keys=True, ensure_ascii=False))
    return entry[1]


_ACTIVE: list[Recording] = []


@contextmanager
def recording(prefix: str):
    """Record the obligations of the certificate ``prefix`` while the block runs."""
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
    """Record ``ob`` for the next check; its id."""
    if not _ACTIVE or _ACTIVE[-1].depth:
        return None
    rec = _ACTIVE[-1]
    oid = rec.add(ob)
    if oid not in rec.pending and oid not in rec.taken:   # a fact goes to the first check that takes it
        rec.pending.append(oid)
    return oid


_CAPTURES: list[list] = []


def emit(ob: dict) -> str | None:
    """Record ``ob`` (a query of a table: the table first), and keep it for every
    :func:`replaying` computation under way; its id."""
    if not _ACTIVE or _ACTIVE[-1].depth:
        return None
    for got in _CAPTURES:
        got.append(ob)
    return record({**ob, "table": _ACTIVE[-1].add(ob["table"])} if isinstance(ob.get("table"), dict) else ob)


def replaying(func: Callable) -> Callable:
    """functools.cache for a computation whose facts a certificate relies on: the facts
    recorded while it first ran are recorded again at every later call, so that what a
    certificate records does not depend on what ran before it in the same process.  Outside
    a recording it computes afresh (it could capture nothing to replay later)."""
    memo: dict = {}

    @functools.wraps(func)
    def inner(*args):
        if not _ACTIVE or _ACTIVE[-1].depth:
            return func(*args)
        if args not in memo:
            got: list = []
            _CAPTURES.append(got)
            try:
                memo[args] = (func(*args), got)
            finally:
                _CAPTURES.remove(got)
        else:
            for ob in memo[args][1]:
                emit(ob)
        return memo[args][0]
    inner.cache_clear = memo.clear   # type: ignore[attr-defined]
    _MEMOS.append(memo)
    return inner


_MEMOS: list[dict] = []


def forget() -> None:
    """Empty every :func:`replaying` memo (with the engine's caches: a cold run)."""
    for memo in _MEMOS:
        memo.clear()


def take(own: list[str] | None = None) -> list[str]:
    """The facts of the check being made: ``own`` when the deciding result carried its facts
    (they leave the pending ones), else the ids recorded since the last check."""
    if not _ACTIVE:
        return list(own or [])
    rec = _ACTIVE[-1]
    if own is not None:
        rec.pending = [i for i in rec.pending if i not in own]
        return list(own)
    out, rec.pending = rec.pending, []
    rec.taken.update(out)
    return out


def facts_of(*results) -> list[str]:
    """The facts carried by deciding results (a trig Result, ...), in order, once each."""
    out: list[str] = []
    for res in results:
        for i in getattr(res, "facts", None) or []:
            if i not in out:
                out.append(i)
    return out


def fact(build: Callable) -> Callable:
    """Decorate a deciding function: its outermost call records ``build(answer, *args, **kw)``
    (a dict, a list of dicts, or None for nothing); an exception in ``build`` records an
    obligation of kind ``unsupported`` with the reason, so that nothing is silently left out."""
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
                except Exception as exc:  # the fact has no form in the obligation language
                    obs = {"kind": "unsupported", "reason": f"{func.__qualname__}: {type(exc).__name__}: {exc}"[:300]}
            finally:
                rec.depth -= 1
            listed = [] if obs is None else obs if isinstance(obs, list) else [obs]
            ids = [emit(ob) for ob in listed]
            try:                        # a result object carries its own facts (see take)
                answer.facts = [i for i in ids if i]
            except AttributeError:
                pass
            return answer
        return inner
    return wrap


def recording_now() -> bool:
    """Whether a deciding function called here would record its fact (a certificate is
    being made and no :func:`quiet` block is open)."""
    return bool(_ACTIVE) and not _ACTIVE[-1].depth


def silent(func: Callable) -> Callable:
    """Decorate an engine routine whose inner facts are the engine's business (an isolation,
    a table's construction): nothing it calls records."""
    @functools.wraps(func)
    def inner(*args, **kwargs):
        if not _ACTIVE:
            return func(*args, **kwargs)
        with quiet():
            return func(*args, **kwargs)
    return inner


@contextmanager
def gathered(again: bool = False):
    """The ids recorded while the block runs (a list filled in place), for a check made
    later: ``Check(..., obligations=take(ids))``; they leave the pending ones (a check that
    does not name its facts does not get them); with ``again``, also those of the facts the
    block records again that an earlier check took (a second reading of one table)."""
    ids: list[str] = []
    rec = _ACTIVE[-1] if _ACTIVE else None
    before = list(rec.pending) if rec is not None else []
    got: list = []
    if again:
        _CAPTURES.append(got)
    try:
        yield ids
    finally:
        if again:
            _CAPTURES.remove(got)
        if rec is not None:
            ids.extend(i for i in rec.pending if i not in before)
            for ob in got:
                if isinstance(ob.get("table"), dict):
                    ob = {**ob, "table": rec.add(ob["table"])}
                if rec.add(ob) not in ids:
                    ids.append(rec.add(ob))
            rec.pending = [i for i in rec.pending if i in before]


@contextmanager
def captured():
    """The obligations (as data) emitted while the block runs, in order, repeats included:
    the facts of a computation, kept with its result (a lemma of a shared quantity, a sign
    read as a tuple) so that each check that reads the result records them again
    (``certify.run.kept_facts``)."""
    got: list = []
    _CAPTURES.append(got)
    try:
        yield got
    finally:
        _CAPTURES.remove(got)


def in_order(ids: list[str]) -> list[str]:
    """The ids of a check once each, in the order they were first recorded (as the file lists them)."""
    if not _ACTIVE:
        return ids
    return sorted(set(ids), key=lambda i: int(i.rsplit(":", 1)[1]))
