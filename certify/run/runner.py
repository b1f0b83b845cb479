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

import gc
import importlib
import inspect
import multiprocessing
import pkgutil
import time
import traceback
from collections.abc import Callable
from concurrent.futures.process import BrokenProcessPool
from dataclasses import dataclass, field

from certify import caches
from certify.errors import StatementError, UsageError
from certify.witnesses import in_order, quiet, recording, witnesses_of
from certify_kernel.statements import read as read_statements

from . import executors
from .executors import default_jobs  # noqa: F401  (runner.default_jobs, used by the CLI and benchmarks)
from .files import CHECKOUT

PASS, ERRATUM, FAIL, OBSERVED = "PASS", "ERRATUM", "FAIL", "OBSERVED"
STATUSES = (PASS, ERRATUM, FAIL, OBSERVED)


@dataclass
class Check:
    """One statement with its verdict and the evidence a referee can re-check.

    ``corrects``: on a corrected check, the printed check (or its statement) that it
    replaces; the Errata show the two side by side.  ``counts``: False for a
    consistency check, one that holds by construction of the engine (the word it
    applied is the word it was given, cp(0) = -det M for every matrix): it must hold,
    or the certificate FAILs, but it is not evidence for the printed claim.
    ``ref``: the id of the formal statement (statements/*.txt, docs/statements.md) this check
    decides: the report prints that statement's text, and certificates.json gives the kernel the
    check's verdict on it with its witnesses.  ``witnesses``: the ids of the witnesses its verdict
    rests on (:mod:`certify.witnesses`), those its deciding result carries unless given."""

    statement: str
    holds: bool
    evidence: list[str] = field(default_factory=list)
    corrects: Check | str | None = None
    counts: bool = True
    witnesses: list[str] | None = None
    ref: str = ""

    def __post_init__(self):
        if self.witnesses is None:       # those its deciding result carries (a trig Result)
            self.witnesses = witnesses_of(self.holds)
        self.witnesses = in_order(self.witnesses)


def named(ref: str, check: Check) -> Check:
    """``check`` deciding the formal statement ``ref`` (a check made by a helper such as
    :func:`certify.run.checks.count_check`)."""
    check.ref = ref
    return check


# The kinds of erratum, the first column a referee reads in the Errata.
MISPRINT = "misprint"                  # one symbol or word typed for another; the argument stands
FALSE_STATEMENT = "false statement"    # the sentence is false as a statement, not by a slip of the pen
REFUTED_REMARK = "refuted remark"      # a hedged remark ("does not seem"), refuted by counterexamples
ERRATUM_KINDS = (MISPRINT, FALSE_STATEMENT, REFUTED_REMARK)


@dataclass
class Outcome:
    """The verdict of one certificate.

    On an ERRATUM, ``kind`` is one of :data:`ERRATUM_KINDS` and ``misprint`` names the
    one slip in the paper that the certificate's false checks come from (several
    certificates may share it: the report counts distinct misprints).  On an
    observation, ``agrees`` says whether what was seen agrees with the paper and
    ``reason`` says why not, in one line."""

    status: str
    printed: list[Check]
    corrected: list[Check] = field(default_factory=list)
    evidence: list[str] = field(default_factory=list)
    figures: list[str] = field(default_factory=list)
    note: str = ""
    kind: str = ""
    misprint: str | tuple = ""         # one slip, or a tuple of them (one certificate, several slips)
    agrees: bool | None = None
    reason: str = ""
    witnesses: list[dict] = field(default_factory=list)   # the certificate's witnesses (certify.witnesses)


def holds(check: Check) -> bool:
    """The verdict of a check as a plain bool; anything undecidable is False."""
    try:
        return bool(check.holds)
    except Exception:  # e.g. a SymPy relation that cannot be decided
        return False


def corrected_statement(check: Check) -> str:
    """The statement of the printed check that ``check`` corrects ("" for none)."""
    target = check.corrects
    return "" if target is None else str(target.statement if isinstance(target, Check) else target)


def conclude(printed: list[Check], corrected: list[Check] | None = None,
             evidence: list[str] | None = None, figures: list[str] | None = None,
             note: str = "", kind: str = "", misprint: str | tuple = "") -> Outcome:
    """The verdict, resting only on the checks that could fail (``counts``):

    - PASS when every printed check holds (and one of them counts);
    - ERRATUM when a printed check that counts fails, every corrected check holds,
      and each failing printed check has its correction (a corrected check whose
      ``corrects`` names it);
    - FAIL otherwise, and whenever a consistency check fails.

    ``kind`` (an ERRATUM's kind, :data:`ERRATUM_KINDS`) and ``misprint`` (the one slip,
    in a few words with its line, shared by every certificate it makes false) are kept
    on an ERRATUM only; a certificate that can end in ERRATUM gives both (the report
    shows "(kind not stated)" otherwise, and tests/proofs/test_claims.py checks the committed
    report for it)."""
    if kind and kind not in ERRATUM_KINDS:
        raise ValueError(f"unknown kind of erratum {kind!r}")
    corrected = corrected or []
    evidence_checks = [c for c in printed if c.counts]
    consistent = all(holds(c) for c in printed + corrected if not c.counts)
    wrong = [c for c in evidence_checks if not holds(c)]
    fixed = {corrected_statement(c) for c in corrected}
    if consistent and evidence_checks and not wrong:
        status = PASS
    elif (consistent and wrong and all(holds(c) for c in corrected)
          and all(str(c.statement) in fixed for c in wrong)):
        status = ERRATUM
    else:
        status = FAIL
    erratum = status == ERRATUM
    return Outcome(status, printed, corrected, evidence or [], figures or [], note,
                   kind if erratum else "", misprint if erratum else "")


AGREES = "The observation agrees with the printed statement."
# The statement of a check that explains an observation (N2, N5, N6: a committed word
# re-certified at its r): it must hold, like a consistency check, but it is our certified
# explanation beside the observation, not the engine's consistency nor the paper's claim.
EXPLANATION = "explanation:"
OBSERVATION = "observed, not explained:"   # what a committed finding shows without a proof
DISAGREES = "The observation does not agree with the printed statement"


def observe(printed: list[Check], evidence: list[str] | None = None, figures: list[str] | None = None,
            note: str = "", reason: str = "") -> Outcome:
    """The verdict of a numerical observation (Section 5): OBSERVED, never PASS, with
    ``agrees`` saying whether what was seen agrees with the printed statement (every
    printed check that counts holds) or not.  When it does not, ``reason`` is the one
    line a reader sees first (the certificate's ``reason``, else the checks that do not
    hold), and the note names the checks.  FAIL only when a consistency check fails
    (the engine itself is in doubt) or there is nothing to compare."""
    evidence_checks = [c for c in printed if c.counts]
    consistent = all(holds(c) for c in printed if not c.counts)
    wrong = [" ".join(str(c.statement).split()) for c in evidence_checks if not holds(c)]
    head = AGREES if not wrong else DISAGREES + ": " + "; ".join(wrong) + "."
    status = OBSERVED if consistent and evidence_checks else FAIL
    why = "" if not wrong else " ".join(str(reason).split()) or "; ".join(wrong)
    return Outcome(status, printed, [], evidence or [], figures or [], (head + " " + note).strip(),
                   agrees=not wrong, reason=why)


# The kinds of mutant: a constant (a coefficient, a digit, a letter, a sign) altered; the
# wording of a printed condition altered so that it is false (the altered text must show in a
# failing printed check); a wording the grammar does not read (it must be refused, quoted).
# A fourth kind, committed: a committed finding that a certificate re-certifies (a word and its
# r in reports/section5-orbits.json) altered; the certificate FAILs, an observation too (the
# finding is ours, certified, not the paper's claim).
CONSTANT, WORDING, UNREAD, COMMITTED = "constant", "wording", "unread", "committed"
MUTANT_KINDS = (CONSTANT, WORDING, UNREAD, COMMITTED)


@dataclass(frozen=True)
class Mutant:
    """One alteration of a certificate's printed inputs that must turn it FAIL (an
    observation: disagree on one more check).  ``changes`` are ``(name, old, new)``:
    the first ``old`` in the printed text ``name`` replaced by ``new`` (:func:`altered`),
    or, with ``old`` None, the input ``name`` replaced whole by ``new``.  ``why``: what
    the alteration makes false, in one line."""

    kind: str
    changes: tuple
    why: str = ""

    def __post_init__(self):
        if self.kind not in MUTANT_KINDS or not self.changes:
            raise ValueError(f"a mutant of kind {self.kind!r} with changes {self.changes!r}")

    def overrides(self, id: str) -> dict:
        """The printed inputs of certificate ``id`` this mutant replaces, for :func:`run_certificate`."""
        out = {}
        for name, old, new in self.changes:
            out.update({name: new} if old is None else altered(id, name, old, new))
        return out


def replaced(name: str, old: str, new: str, why: str = "", kind: str = CONSTANT) -> Mutant:
    """The first ``old`` in the printed text ``name`` replaced by ``new``."""
    return Mutant(kind, ((name, old, new),), why)


def overridden(values: dict, why: str = "") -> Mutant:
    """Printed inputs replaced whole (a word, a tuple of digits, two ends together)."""
    return Mutant(CONSTANT, tuple((name, None, v) for name, v in values.items()), why)


def committed(name: str, new, why: str = "") -> Mutant:
    """The committed findings the input ``name`` points to, altered (``new``: what the
    certificate reads instead): FAIL, for an observation too."""
    return Mutant(COMMITTED, ((name, None, new),), why)


def reworded(name: str, old: str, new: str, why: str = "") -> Mutant:
    """A printed condition reworded so that it is false: FAIL, the altered text shown failing."""
    return replaced(name, old, new, why, WORDING)


def unread(name: str, text: str, why: str = "") -> Mutant:
    """A printed condition replaced by a text the grammar does not read (or the certificate
    cannot evaluate): FAIL, with that reason and the text quoted."""
    return Mutant(UNREAD, ((name, None, text),), why)


@dataclass
class Certificate:
    id: str
    line: str
    statement: str
    func: Callable
    needs: tuple[str, ...]
    printed: dict
    module: str
    mutants: tuple[Mutant, ...] = ()
    expect: str = ""

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


def certificate(id: str, line: str | None = None, statement: str | None = None, needs=(), printed=None, mutants=(),
                expect: str = ""):
    """Declare a certificate for claim ``id`` printed at ``line`` of the paper, stating ``statement``:
    both, when not given, as the statement files say them (statements/*.txt: the line ``certificate
    ID  l. LINES  "TITLE"``), where the paper's claims are written once.

    ``printed`` maps names to the inputs as printed in the paper; the function
    receives them as keyword arguments next to the shared quantities it needs.
    ``mutants`` (:class:`Mutant`) alter those inputs and must each turn it FAIL;
    ``expect`` is its status on the paper as printed, as the report labels it
    (PASS, ERRATUM, OBSERVED, "OBSERVED, disagrees")."""
    def wrap(func):
        if id in CERTIFICATES:
            raise ValueError(f"certificate {id} declared twice")
        written = paper_certificates().get(id)
        if (line is None or statement is None) and written is None:
            raise ValueError(f"certificate {id}: no line and statement given, and none in statements/*.txt")
        CERTIFICATES[id] = Certificate(id, line if line is not None else written.line,
                                       statement if statement is not None else written.title, func, tuple(needs),
                                       dict(printed or {}), func.__module__, tuple(mutants), expect)
        return func
    return wrap


_PAPER: dict = {}


def paper_certificates() -> dict:
    """The certificates of the statement files (id -> certify_kernel.statements.Certificate), read once."""
    if not _PAPER:
        _PAPER.update({c.id: c for c in read_statements(CHECKOUT / "statements").certificates})
    return _PAPER


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
    order = "LMTSNB"                 # B: beyond the paper, after its sections
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

    def __init__(self) -> None:
        self.values: dict[str, object] = {}
        self.seconds: dict[str, float] = {}

    def get(self, name: str):
        if name not in self.values:
            if name not in QUANTITIES:
                raise KeyError(f"no shared quantity named {name!r}")
            q = QUANTITIES[name]
            args = {n: self.get(n) for n in q.needs}
            t = time.perf_counter()
            with quiet():
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
        with recording(cert.id) as rec:
            outcome = cert.func(**args, **printed)
        outcome.witnesses = rec.items
    except StatementError as exc:  # a printed text the grammar does not read: never a guess
        outcome = Outcome(FAIL, [Check("the printed text was read", False, [f"`{exc}`"])])
    except Exception as exc:  # a check that could not be completed is a FAIL
        tb = traceback.format_exception_only(type(exc), exc)[-1].strip()
        outcome = Outcome(FAIL, [Check("the certificate ran to completion", False, [f"`{tb}`"])])
    return outcome


def reset_caches() -> None:
    """Forget what the engine memoises across runs (every cache registered with
    :func:`certify.caches.register`): the next run is cold."""
    caches.reset()


def plain(outcome: Outcome) -> Outcome:
    """The outcome as the report reads it: statements and evidence as text, verdicts as
    bools.  That is all a report needs, and it crosses process boundaries (pickle)."""
    def check(c: Check) -> Check:
        return Check(str(c.statement), holds(c), [str(e) for e in c.evidence],
                     corrected_statement(c) or None, c.counts, list(c.witnesses or []), c.ref)
    return Outcome(outcome.status, [check(c) for c in outcome.printed],
                   [check(c) for c in outcome.corrected], [str(e) for e in outcome.evidence],
                   [str(f) for f in outcome.figures], str(outcome.note), str(outcome.kind),
                   tuple(outcome.misprint) if isinstance(outcome.misprint, (list, tuple)) else str(outcome.misprint),
                   outcome.agrees, str(outcome.reason), list(outcome.witnesses))


def units(certs: list[Certificate]) -> list[list[Certificate]]:
    """The certificates cut into units that share nothing: two certificates are in one
    unit when they need a common shared quantity (directly, or through the quantities
    those need).  A unit runs in one process, so each quantity is computed once per run."""
    def closure(names):
        seen, todo = set(), list(names)
        while todo:
            n = todo.pop()
            if n not in seen:
                seen.add(n)
                todo += QUANTITIES[n].needs if n in QUANTITIES else ()
        return seen
    groups: list[tuple[set, list[Certificate]]] = []
    for cert in certs:
        names = closure(cert.needs)
        joined = [g for g in groups if names and g[0] & names]
        merged = (names.union(*(g[0] for g in joined)), [c for g in joined for c in g[1]] + [cert])
        groups = [g for g in groups if all(g is not j for j in joined)] + [merged]
    return [sorted(g[1], key=lambda c: claim_key(c.id)) for g in groups]


def run_unit(certs: list[Certificate], report=None) -> tuple[list, dict]:
    """Run ``certs`` in order with one context; ``report(cert)`` after each.
    Returns ``[(cert, outcome, seconds, of_which_shared)]`` and the quantities' seconds."""
    ctx, done = Context(), []
    for cert in certs:
        before = set(ctx.seconds)
        t = time.perf_counter()
        outcome = plain(run_certificate(cert, ctx))
        total = time.perf_counter() - t
        shared = sum(v for n, v in ctx.seconds.items() if n not in before)
        done.append((cert, outcome, total, shared))
        if report:
            report(cert)
    return done, dict(ctx.seconds)


_PLAN: list[list[Certificate]] = []   # the units of a parallel run, inherited by the forked workers
_DONE = None                          # the queue on which a worker says "certificate done"


GC_THRESHOLD = (50_000, 20, 20)    # the collector's thresholds during a run (Python's default: 700, 10, 10)


def _worker_start(queue) -> None:
    """In a worker (after :func:`certify.run.executors.process_pool`'s own start: Ctrl-C
    is the parent's to handle, it terminates the workers).  The
    objects inherited from the parent (modules, SymPy's tables) are frozen out of the cyclic
    collector, and it runs less often (:data:`GC_THRESHOLD`): the exact runs build millions of
    small objects, and full collections scanned them all again and again (about 7% of a run)."""
    global _DONE
    gc.freeze()
    gc.set_threshold(*GC_THRESHOLD)
    _DONE = queue


def _worker_run(k: int):
    """In a worker: run unit ``k`` of the plan; ids instead of certificates go back."""
    queue = _DONE
    assert queue is not None  # set by _worker_start, the initializer of every worker
    try:
        reset_caches()      # each unit from cold caches: what it records does not depend on the units before
        done, seconds = run_unit(_PLAN[k], report=lambda cert: queue.put(cert.id))
    except KeyboardInterrupt:  # raised by a certificate itself
        return None
    return [(cert.id, outcome, total, shared) for cert, outcome, total, shared in done], seconds


class WorkerDied(RuntimeError):
    """A worker process ended without returning its unit (killed, or a crash in C code)."""


def _parallel(plan: list[list[Certificate]], jobs: int, progress) -> tuple[list, dict]:
    """Run the units of ``plan`` on ``jobs`` forked processes, heaviest first.  A worker
    that dies raises :class:`WorkerDied` (never a silent hang); on Ctrl-C the workers
    are stopped (:func:`certify.run.executors.process_pool`)."""
    global _PLAN
    context = multiprocessing.get_context("fork")
    queue = context.SimpleQueue()
    by_id = {c.id: c for unit in plan for c in unit}
    _PLAN = plan
    finished, seconds, count = [], {}, 0
    try:
        with executors.process_pool(min(jobs, len(plan)), _worker_start, (queue,), context) as pool:
            pending = {pool.submit(_worker_run, k) for k in range(len(plan))}
            while True:
                while not queue.empty():     # a worker's put is written before its unit's result
                    count, cid = count + 1, queue.get()
                    if progress:
                        progress(count, len(by_id), cid)
                if not pending:
                    break
                done, pending = executors.wait_first(pending, 0.05)
                for job in done:
                    try:
                        result = job.result()
                    except BrokenProcessPool:
                        raise WorkerDied("a worker process died before it returned its certificates "
                                         "(run again with --jobs 1 to see which)") from None
                    if result is None:
                        raise KeyboardInterrupt
                    finished += [(by_id[i], o, t, s) for i, o, t, s in result[0]]
                    seconds.update(result[1])
    finally:
        _PLAN = []
    return finished, seconds


def run_selected(ids=None, progress=None, jobs: int = 1,
        estimates: dict[str, float] | None = None) -> tuple[list[tuple[Certificate, Outcome]], dict]:
    """Run the selected certificates on ``jobs`` processes; return the outcomes (in claim
    order, whatever the order they finished in) and the timings.

    With ``jobs = 1`` they run unit by unit in this process, each unit from cold caches.
    With ``jobs > 1`` the units (:func:`units`) run in forked worker processes, the
    heaviest first by ``estimates`` (seconds per certificate id, e.g. the last run's
    timings; by size without them).  The outcomes are the same as with ``jobs = 1``:
    every certificate and quantity is deterministic, only the order of work changes.
    ``progress(k, n, id)`` is told when the k-th certificate is done."""
    certs = select(ids)
    plan = units(certs)
    cost = (lambda c: estimates.get(c.id, 0.0)) if estimates else (lambda c: 1.0)
    plan.sort(key=lambda unit: (-sum(cost(c) for c in unit), claim_key(unit[0].id)))
    if progress:
        progress(0, len(certs), "")
    parallel = jobs > 1 and len(plan) > 1 and "fork" in multiprocessing.get_all_start_methods()
    if parallel:
        finished, seconds = _parallel(plan, jobs, progress)
    else:
        saved = gc.get_threshold()
        gc.set_threshold(*GC_THRESHOLD)       # as in a worker (_worker_start)
        done = iter(range(1, len(certs) + 1))
        report = (lambda cert: progress(next(done), len(certs), cert.id)) if progress else None
        finished, seconds = [], {}
        try:
            for unit in plan:   # unit by unit from cold caches, as the workers do: the same records
                reset_caches()
                part, secs = run_unit(unit, report)
                finished += part
                seconds.update(secs)
        finally:
            gc.set_threshold(*saved)
    finished.sort(key=lambda item: claim_key(item[0].id))
    timings = {cert.id: {"seconds": round(total, 4), "of_which_shared": round(shared, 4)}
               for cert, _, total, shared in finished}
    return [(cert, outcome) for cert, outcome, _, _ in finished], \
        {"certificates": timings, "shared": {n: round(v, 4) for n, v in seconds.items()}}
