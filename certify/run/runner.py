"""Certificates, shared quantities and the run that ties them together.

A *certificate* checks one claim of the paper as printed.  It is declared with
:func:`certificate`, names the shared quantities it ``needs`` (the matrix M, the
characteristic polynomial, the branches, ...) and the *printed* inputs it checks
(polynomials, constants, digits, inequality directions transcribed from the paper).
The runner computes each needed quantity once per run, only if a selected
certificate needs it, and passes both to the certificate.  A test can replace a
printed input (``overrides``) and must then see the verdict turn to FAIL.
"""
from __future__ import annotations

import importlib
import inspect
import pkgutil
import time
import traceback
from dataclasses import dataclass, field
from typing import Callable

from certify import caches
from certify.errors import UsageError

PASS, ERRATUM, FAIL, OBSERVED = "PASS", "ERRATUM", "FAIL", "OBSERVED"
STATUSES = (PASS, ERRATUM, FAIL, OBSERVED)


@dataclass
class Check:
    """One statement with its verdict and the evidence a referee can re-check."""

    statement: str
    holds: bool
    evidence: list[str] = field(default_factory=list)


@dataclass
class Outcome:
    """The verdict of one certificate."""

    status: str
    printed: list[Check]
    corrected: list[Check] = field(default_factory=list)
    evidence: list[str] = field(default_factory=list)
    figures: list[str] = field(default_factory=list)
    note: str = ""


def conclude(printed: list[Check], corrected: list[Check] | None = None,
             evidence: list[str] | None = None, figures: list[str] | None = None,
             note: str = "") -> Outcome:
    """PASS when every printed check holds; ERRATUM when one fails but every
    corrected check holds (and there is one); FAIL otherwise."""
    corrected = corrected or []
    if all(c.holds for c in printed):
        status = PASS
    elif corrected and all(c.holds for c in corrected):
        status = ERRATUM
    else:
        status = FAIL
    return Outcome(status, printed, corrected, evidence or [], figures or [], note)


@dataclass
class Certificate:
    id: str
    line: str
    statement: str
    func: Callable
    needs: tuple[str, ...]
    printed: dict
    module: str

    @property
    def title(self) -> str:
        return (inspect.getdoc(self.func) or "").split("\n")[0]


@dataclass
class Quantity:
    name: str
    func: Callable
    needs: tuple[str, ...]
    doc: str


CERTIFICATES: dict[str, Certificate] = {}
QUANTITIES: dict[str, Quantity] = {}


def certificate(id: str, line: str, statement: str, needs=(), printed=None):
    """Declare a certificate for claim ``id`` printed at ``line`` of the paper.

    ``printed`` maps names to the inputs as printed in the paper; the function
    receives them as keyword arguments next to the shared quantities it needs."""
    def wrap(func):
        if id in CERTIFICATES:
            raise ValueError(f"certificate {id} declared twice")
        CERTIFICATES[id] = Certificate(id, line, statement, func, tuple(needs),
                                       dict(printed or {}), func.__module__)
        return func
    return wrap


def quantity(name: str, needs=()):
    """Declare a shared quantity, computed at most once per run."""
    def wrap(func):
        QUANTITIES[name] = Quantity(name, func, tuple(needs), inspect.getdoc(func) or "")
        return func
    return wrap


PROOFS = "proofs"  # the package of certificates, above every layer: loaded by name, as a plug-in


def load_all() -> dict[str, Certificate]:
    """Import every module of the ``proofs`` package so that their certificates register.

    ``proofs`` sits on top of the layers (it imports the engine's faces), so the runner
    names it rather than importing it: the layering contract stays one-way."""
    package = importlib.import_module(PROOFS)
    for mod in pkgutil.iter_modules(package.__path__):
        importlib.import_module(f"{PROOFS}.{mod.name}")
    return CERTIFICATES


def claim_key(id: str):
    """Sort ids as the claims are listed: M1 < M2 < T1 < T2 < T10 < T10.1."""
    order = "LMTSN"
    head, num = id[0], id[1:]
    parts = tuple(int(p) for p in num.split("."))
    return (order.index(head) if head in order else len(order), parts)


def select(ids=None) -> list[Certificate]:
    """The certificates named by ``ids`` (all when None); an id without suffix
    selects its sub-certificates too.  Unknown ids raise UsageError."""
    certs = load_all()
    if not ids:
        return sorted(certs.values(), key=lambda c: claim_key(c.id))
    chosen = {}
    for i in ids:
        i = i.strip().upper()
        hits = [c for c in certs.values() if c.id == i or c.id.startswith(i + ".")]
        if not hits:
            raise UsageError(f"unknown claim id {i!r} (see 'python -m certify list')")
        for c in hits:
            chosen[c.id] = c
    return sorted(chosen.values(), key=lambda c: claim_key(c.id))


class Context:
    """The shared quantities of one run, each computed once, on demand."""

    def __init__(self):
        self.values: dict[str, object] = {}
        self.seconds: dict[str, float] = {}

    def get(self, name: str):
        if name not in self.values:
            if name not in QUANTITIES:
                raise KeyError(f"no shared quantity named {name!r}")
            q = QUANTITIES[name]
            args = {n: self.get(n) for n in q.needs}
            t = time.perf_counter()
            self.values[name] = q.func(**args)
            self.seconds[name] = time.perf_counter() - t
        return self.values[name]


def altered(id: str, name: str, old: str, new: str) -> dict:
    """Overrides for :func:`run_certificate` replacing the first ``old`` by ``new`` in
    the printed text ``name`` of certificate ``id``: a mutated print, which must turn
    the certificate FAIL.  ValueError when ``old`` is not in that text."""
    text = CERTIFICATES[id].printed[name]
    if old not in text:
        raise ValueError(f"{old!r} not in the printed {name} of {id}")
    return {name: text.replace(old, new, 1)}


def run_certificate(cert: Certificate, ctx: Context | None = None,
                    overrides: dict | None = None) -> Outcome:
    """Run one certificate; any exception is a FAIL with its message as evidence.

    ``overrides`` replaces printed inputs (used by the mutation tests)."""
    ctx = ctx or Context()
    printed = dict(cert.printed)
    if overrides:
        unknown = set(overrides) - set(printed)
        if unknown:
            raise KeyError(f"{cert.id} has no printed input {sorted(unknown)}")
        printed.update(overrides)
    try:
        args = {n: ctx.get(n) for n in cert.needs}
        outcome = cert.func(**args, **printed)
    except Exception as exc:  # a check that could not be completed is a FAIL
        tb = traceback.format_exception_only(type(exc), exc)[-1].strip()
        outcome = Outcome(FAIL, [Check("the certificate ran to completion", False, [f"`{tb}`"])])
    return outcome


def reset_caches() -> None:
    """Forget what the engine memoises across runs (every cache registered with
    :func:`certify.caches.register`): the next run is cold."""
    caches.reset()


def run(ids=None, progress=None) -> tuple[list[tuple[Certificate, Outcome]], dict]:
    """Run the selected certificates; return the outcomes and the timings."""
    certs = select(ids)
    ctx = Context()
    results, timings = [], {}
    for k, cert in enumerate(certs):
        if progress:
            progress(k, len(certs), cert.id)
        before = dict(ctx.seconds)
        t = time.perf_counter()
        outcome = run_certificate(cert, ctx)
        total = time.perf_counter() - t
        shared = sum(v for n, v in ctx.seconds.items() if n not in before)
        timings[cert.id] = {"seconds": round(total, 4), "of_which_shared": round(shared, 4)}
        results.append((cert, outcome))
    if progress:
        progress(len(certs), len(certs), "")
    return results, {"certificates": timings,
                     "shared": {n: round(v, 4) for n, v in ctx.seconds.items()}}
