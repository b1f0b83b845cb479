"""certify_kernel: checks the paper's statements, written as data, with the standard library alone.

The statements (statements/*.txt, :mod:`certify_kernel.statements`) are the paper's claims in a
small language, each with its line and the verdict the tool gives it (holds, refuted by its
correction, corrects a refuted one); the kernel builds every object they name from its own
definitions (:mod:`certify_kernel.evaluate`) and decides each statement exactly.  From
reports/certificates.json, written by the engine, it reads only the engine's verdicts (which
must be the statement file's) and *witnesses*: data that make a decision cheaper or possible
(a factorisation whose signs are read by inspection), each checked against the kernel's own
objects.  A statement is *verified* when the kernel's decision is its verdict; a certificate's
status (PASS, ERRATUM, OBSERVED) is computed from its statements' verdicts and must be the
engine's.  docs/verify.md says how to read the files.
"""
from __future__ import annotations

import json
import multiprocessing
import os
import signal

from . import family, particles, pattern, reduction, signs, substitution  # noqa: F401  (they register their functions, predicates, quantifiers)
from .evaluate import Context, NotVerified, truth
from .language import Syntax, parse
from .statements import Paper, read
from .values import Undefined, declare, declare_angle

FORMAT = "certify-certificates/2"


def load(path: str) -> dict:
    """The certificates file, read as JSON (no code is evaluated)."""
    with open(path, encoding="utf-8") as f:
        try:
            data = json.load(f)
        except ValueError as exc:
            raise ValueError(f"{path}: not JSON ({exc})") from None
    if not isinstance(data, dict) or data.get("format") != FORMAT or not isinstance(data.get("certificates"), list):
        raise ValueError(f"{path}: not a certificates file of format {FORMAT}")
    for c in data["certificates"]:
        if not isinstance(c, dict) or not isinstance(c.get("id"), str) or not isinstance(c.get("statements"), dict):
            raise ValueError(f"{path}: a certificate without an id or statements")
    return data


def prepare(paper: Paper) -> None:
    """Declare the variables and angles of the statement files (before anything is evaluated)."""
    for name in paper.vars:
        declare(name)
    for name in paper.angles:
        declare_angle(name)


def status_of(statements: list) -> str:
    """PASS when every printed statement holds, ERRATUM when some is refuted and has its
    correction, OBSERVED for numerical observations (the verdicts of the statement file)."""
    if statements and all(s.verdict == "observed" for s in statements):
        return "OBSERVED"
    return "ERRATUM" if any(s.verdict == "refuted" for s in statements) else "PASS"


def check_statement(s, lets: dict, witnesses=None) -> tuple[bool, str]:
    """(verified, why not).  Raises ValueError when the kernel's decision contradicts the verdict
    or the statement is not a formula of the language."""
    if s.verdict == "observed":
        return False, "an observation"
    if s.unformalised:
        return False, f"not formalised: {s.unformalised}"
    ctx = Context(lets, witnesses)
    try:
        got = truth(parse(s.formula), ctx)
    except NotVerified as exc:
        return False, str(exc)
    except (Syntax, Undefined, ZeroDivisionError) as exc:
        raise ValueError(f"{s.id} ({s.where}): {exc}") from None
    except (TypeError, AttributeError, IndexError, KeyError, RecursionError) as exc:     # a line, not a traceback
        raise ValueError(f"{s.id} ({s.where}): the kernel cannot evaluate it ({type(exc).__name__}: {exc})") from None
    want = s.verdict != "refuted"
    if got != want:
        at = f" (at r = {ctx.counterexample})" if not got and getattr(ctx, "counterexample", None) else ""
        raise ValueError(f"{s.id}: the statement file says it {'holds' if want else 'is refuted'}; "
                         f"the kernel finds it {'true' if got else 'false'}{at}")
    return True, ""


def verify_certificate(cert, engine: dict | None, lets: dict) -> dict:
    """Check one certificate of the statement files against its entry of certificates.json."""
    out = {"id": cert.id, "status": status_of(cert.statements), "ok": True, "failure": "",
           "statements": [], "counted": 0, "verified": 0}
    if engine is None:
        return {**out, "ok": False, "failure": "certificates.json has no entry for it"}
    unread = _unread(engine)
    if unread:
        return {**out, "ok": False, "failure": f"{unread}: the kernel reads verdicts and witnesses only"}
    if engine.get("status") != out["status"]:
        return {**out, "ok": False, "failure": f"the run says {engine.get('status')}, its statements' verdicts "
                f"make it {out['status']}"}
    mine = {s.id for s in cert.statements}
    theirs = set(engine["statements"])
    if mine != theirs:
        extra = sorted(theirs - mine) or sorted(mine - theirs)
        return {**out, "ok": False, "failure": f"statement {extra[0]}: not in both certificates.json and the "
                "statement file"}
    for s in cert.statements:
        rec = engine["statements"][s.id]
        verdict = {"holds": "holds", "corrects": "holds", "refuted": "refuted", "observed": "observed"}[s.verdict]
        if not isinstance(rec, dict) or rec.get("verdict") != verdict:
            return {**out, "ok": False, "failure": f"statement {s.id}: the run's verdict "
                    f"{rec.get('verdict') if isinstance(rec, dict) else rec!r} is not the statement file's {verdict}"}
        try:
            ok, why = check_statement(s, lets, rec.get("witness"))
        except ValueError as exc:
            return {**out, "ok": False, "failure": str(exc)}
        out["statements"].append((s.id, ok, why))
        if s.verdict != "observed":
            out["counted"] += 1
            out["verified"] += ok
    return out


WITNESSES = ("signed", "factors", "datum")   # the kinds of witness the kernel reads (signs, pattern, particles)


def _unread(engine: dict) -> str:
    """What a certificate's entry holds beyond its status, its statements' verdicts and witnesses of
    a kind the kernel reads ("" when nothing): objects, obligations, covers, moduli or counts are
    never taken from a run, so a run that writes them is rejected, the field named."""
    extra = sorted(set(engine) - {"id", "status", "statements"})
    if extra:
        return f"the field {extra[0]!r}"
    for sid, rec in sorted(engine["statements"].items()):
        extra = sorted(set(rec) - {"verdict", "witness"}) if isinstance(rec, dict) else ["(not an object)"]
        if extra:
            return f"statement {sid}: the field {extra[0]!r}"
        w = rec.get("witness", [])
        if not isinstance(w, list) or any(not isinstance(x, dict) or x.get("kind") not in WITNESSES for x in w):
            return f"statement {sid}: a witness of no kind the kernel reads"
    return ""


_WORK: dict = {}


def _one(k: int) -> dict:
    cert = _WORK["certs"][k]
    return verify_certificate(cert, _WORK["engine"].get(cert.id), _WORK["lets"])


def _worker_start() -> None:
    """In a forked worker: SIGTERM (the pool's terminate, when it exits) ends it at once and Ctrl-C
    is the parent's.  A Python handler inherited from the parent could take SIGTERM without dying,
    and the pool's exit, which holds the task queue's lock and joins its workers, would wait for
    ever (seen under pytest-xdist, whose worker had a handler left by an earlier test).  The worker
    is forked with SIGTERM blocked (:func:`_pool`), so a SIGTERM that comes before this line is held,
    not swallowed by the inherited handler, and ends the worker when it is unblocked here."""
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGTERM})


def _pool(jobs: int):
    """A pool of ``jobs`` forked workers (:func:`_worker_start`), forked while this thread blocks
    SIGTERM (restored at once: a SIGTERM to this process meanwhile is delivered then)."""
    old = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGTERM})
    try:
        return multiprocessing.get_context("fork").Pool(jobs, initializer=_worker_start)
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, old)


def verify_all(data: dict, paper: Paper, jobs: int = 1, ids=None, tick=None) -> list[dict]:
    """The results of :func:`verify_certificate` for the certificates of the statement files (those
    named by ``ids``), in their order; on ``jobs`` processes (fork), the heaviest first; ``tick(k,
    n, id)`` after each and ``tick(0, n, "")`` before the first (a progress bar, drawn at once)."""
    prepare(paper)
    certs = [c for c in paper.certificates if ids is None or c.id in ids]
    if tick:
        tick(0, len(certs), "")
    engine = {c["id"]: c for c in data["certificates"]}
    _WORK.update(certs=certs, engine=engine, lets=paper.lets)
    order = sorted(range(len(certs)), key=lambda k: -len(json.dumps(engine.get(certs[k].id, ""))))
    done: dict = {}
    if jobs > 1 and len(certs) > 1 and hasattr(os, "fork"):
        with _pool(jobs) as pool:
            for r in pool.imap_unordered(_one, order, chunksize=1):
                done[next(k for k in order if certs[k].id == r["id"])] = r
                if tick:
                    tick(len(done), len(certs), r["id"])
    else:
        for k in order:
            done[k] = _one(k)
            if tick:
                tick(len(done), len(certs), certs[k].id)
    return [done[k] for k in range(len(certs))]


def counts(results: list[dict]) -> tuple[int, int]:
    """(K, N): of the N statements of the PASS and ERRATUM certificates, the K verified."""
    proved = [r for r in results if r["ok"] and r["status"] in ("PASS", "ERRATUM")]
    return sum(r["verified"] for r in proved), sum(r["counted"] for r in proved)


def line(result: dict) -> str:
    """One line per certificate: its status and how many of its statements the kernel verified."""
    if not result["ok"]:
        return f"{result['id']}: FAILED: {result['failure']}"
    n, k = result["counted"], result["verified"]
    if not n:
        return f"{result['id']}: {result['status']} (an observation: nothing to verify)"
    missing = [f"{i} ({why})" for i, ok, why in result["statements"] if not ok]
    return f"{result['id']}: {result['status']}, {k}/{n} statements verified" + \
        (f"; not verified: {', '.join(missing)}" if missing else "")


__all__ = ["FORMAT", "load", "read", "prepare", "status_of", "check_statement", "verify_certificate", "verify_all",
           "counts", "line"]
