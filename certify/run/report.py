"""The report: outcomes in, ``REPORT.md``, ``report.json`` and ``timings.json`` out.

``REPORT.md`` and ``report.json`` depend only on the outcomes: the same code
gives the same bytes (no dates, timings or machine names), so a committed
report can be compared with a regenerated one (``python -m certify all
--check``).  Timings go to ``timings.json`` only.

``results`` is what :func:`certify.run.runner.run_selected` returns first: a list of
``(Certificate, Outcome)`` pairs, in the order they are to be shown.

Evidence strings and statements are Markdown fragments written by the
certificates; they are kept as given, except that ``|`` is escaped inside table
cells and an unclosed code fence is closed so that it cannot swallow the rest
of the report.
"""
from __future__ import annotations

import difflib
import json
import re
from pathlib import Path
from urllib.parse import quote

import certify_kernel
from certify.run import verification
from certify.run.files import CHECKOUT, write_atomic
from certify.run.runner import (
    ERRATUM,
    ERRATUM_KINDS,
    EXPLANATION,
    FAIL,
    OBSERVATION,
    OBSERVED,
    PASS,
    STATUSES,
    corrected_statement,
    holds,
)
from certify_kernel.statements import read as read_statements

PAPER = ("T. Dolmaire and E. Hübner-Rosenau, *One-dimensional inelastic collapse of four "
         "particles: asymmetric collision sequences and spherical billiard reduction*, "
         "arXiv:2411.10324")
VERSION = "arXiv:2411.10324v1"
SOURCE = (f"Line numbers (\"l. 428-434\") are lines of the paper's LaTeX source, version {VERSION}, "
          "file `inelastic-collapse-four-particles.tex`: download the source from "
          "<https://arxiv.org/e-print/2411.10324v1> (a gzipped archive) and open that file in any "
          "editor that shows line numbers.")

# The parts of the paper, by the first letter of a claim id (the order of ../shared/CLAIMS.md).
PARTS = {
    "L": "Facts from the literature",
    "M": "Section 2: the model",
    "T": "Section 3: Theorem 3.1, the pattern ababcb",
    "S": "Section 4: the spherical billiard reduction",
    "N": "Section 5: the numerical simulations",
    "B": "Beyond the paper",
}
END = "*End of the report.*"

MEANING = {
    PASS: "the statement as printed is certified in exact arithmetic "
          "(rationals, integer polynomials, isolated algebraic numbers, rigorous ball arithmetic).",
    ERRATUM: "the statement as printed is false; a corrected statement is certified "
             "and shown next to it.",
    FAIL: "neither the printed nor a corrected statement could be certified, "
          "or a check could not be completed rigorously.",
    OBSERVED: "a numerical observation (Section 5), reported with its parameters and "
              "figures; it is not a theorem and is never counted as one.",
}

MARK = {True: "✓", False: "✗"}

READING = (
    "How to read the evidence.  Eliminants are shown factored over Q; an algebraic number as "
    "\"the root of p in ]a, b[\" with p irreducible and ]a, b[ an isolating interval with rational "
    "ends, followed by certified digits.  Eliminations are done twice (a lex Gröbner basis in SymPy, "
    "a resultant in python-flint), real-root counts twice (our Sturm sequences, python-flint's root "
    "isolation).  A sign table lists, for each open cell of r between consecutive critical values, "
    "an exact rational sample, the number of real eigenvalues of M there and the sign of the "
    "condition on each branch (upper = largest real eigenvalue); the rows \"(critical)\" give the "
    "signs at the critical values themselves.  `+`, `−`: sign proven by ball arithmetic at the "
    "isolated eigenvalue; `0`: the condition vanishes there, proven exactly by a gcd in Q(r)[λ]; "
    "`·`: the fixed point x is not real there (Δ < 0); `?`: not decided at that point (a pole, or "
    "two branches colliding); an empty cell: that branch does not exist there.")


# --------------------------------------------------------------------------
# Small Markdown helpers

def _one_line(text) -> str:
    """``text`` with every run of whitespace (newlines included) made one space."""
    return " ".join(str(text).split())


def _first_line(text, width: int = 80) -> str:
    """The first line of ``text``, cut at ``width`` characters."""
    line = str(text).strip().split("\n")[0]
    return line if len(line) <= width else line[: width - 1] + "…"


def _cell(text) -> str:
    """``text`` fit for a table cell: one line, ``|`` escaped."""
    return _one_line(text).replace("|", "\\|")


def _fragment(text) -> str:
    """An evidence fragment as given, without surrounding blank lines and with
    an unclosed code fence closed."""
    body = str(text).strip("\n")
    fences = sum(1 for line in body.splitlines() if line.lstrip().startswith(("```", "~~~")))
    if fences % 2:
        body += "\n```"
    return body


def _bullet(text, indent: int = 0) -> str:
    """``text`` as a list item at ``indent`` spaces; later lines are indented to
    the item's content column so that code blocks and tables stay inside it."""
    pad = " " * (indent + 2)
    first, *rest = _fragment(text).split("\n")
    lines = [" " * indent + "- " + first]
    lines += [pad + line if line.strip() else "" for line in rest]
    return "\n".join(lines)


def part_of(cid: str) -> str:
    """The part of the paper a claim id belongs to (its first letter)."""
    return PARTS.get(cid[:1], "Other claims")


def part_anchor(part: str) -> str:
    """The anchor of a part's heading (``Section 2: the model`` -> ``part-section-2-the-model``)."""
    return "part-" + re.sub(r"[^a-z0-9]+", "-", part.lower()).strip("-")


def anchor(cid: str) -> str:
    """The HTML anchor of certificate ``cid`` in REPORT.md (``T10.1`` -> ``cert-t10-1``)."""
    return "cert-" + re.sub(r"[^a-z0-9]+", "-", cid.lower()).strip("-")


def _link(cid: str) -> str:
    return f"[{cid}](#{anchor(cid)})"


def _source(cert) -> str:
    """Where the certificate is written: ``proofs/section3_theorem.py``, function name."""
    path = cert.module.replace(".", "/") + ".py"
    name = getattr(cert.func, "__name__", "")
    return f"`{path}` (`{name}`)" if name else f"`{path}`"


def _figure(cid: str, name: str) -> str:
    """An inline image for figure file ``name`` of certificate ``cid``."""
    caption = f"{cid}: " + re.sub(r"[-_]+", " ", Path(name).stem)
    caption = caption.replace("[", "\\[").replace("]", "\\]")
    return f"![{caption}](figures/{quote(name)})"


def counts(results) -> dict[str, int]:
    """How many certificates have each status (every status listed, in order)."""
    n = {s: 0 for s in STATUSES}
    for _, outcome in results:
        n[outcome.status] = n.get(outcome.status, 0) + 1
    return n


def summary_line(results) -> str:
    """``N certificates: a PASS, b ERRATUM, c FAIL, d OBSERVED (e of them disagree with the paper)``."""
    n = counts(results)
    parts = ", ".join(f"{n[s]} {s}" for s in STATUSES)
    against = len(disagreements(results))
    tail = f" ({against} of them disagree{'s' if against == 1 else ''} with the paper)" if against else ""
    return f"{len(results)} certificate{'s' if len(results) != 1 else ''}: {parts}{tail}"


DISAGREES = "disagrees"


def disagreements(results) -> list:
    """The observations that do not agree with the paper, as ``(cert, outcome)``."""
    return [(cert, o) for cert, o in results if o.status == OBSERVED and o.agrees is False]


def status_label(outcome) -> str:
    """The status as a reader should first see it: ``OBSERVED, disagrees`` for an
    observation that does not agree with the paper, else the bare status."""
    disagrees = outcome.status == OBSERVED and outcome.agrees is False
    return f"{outcome.status}, {DISAGREES}" if disagrees else outcome.status


def slips(outcome) -> list[str]:
    """The slips of the paper an ERRATUM's false checks come from (``misprint``: one text, or a
    tuple of them when one certificate meets several)."""
    m = outcome.misprint
    return [str(x) for x in m] if isinstance(m, (list, tuple)) else [str(m)] if m else []


def misprint_text(outcome) -> str:
    return "; ".join(slips(outcome))


def misprints(results) -> list[tuple[str, str, list]]:
    """The distinct errors of the paper behind the errata, in the order met:
    ``(misprint, kind, [(cert, outcome), ...])``; certificates sharing one misprint
    are grouped under it, a certificate with several slips is under each."""
    groups: dict[str, tuple[str, list]] = {}
    for cert, outcome in results:
        if outcome.status == ERRATUM:
            for key in slips(outcome) or [f"(not stated: {cert.id})"]:
                groups.setdefault(key, (outcome.kind or "(kind not stated)", []))[1].append((cert, outcome))
    return [(key, kind, members) for key, (kind, members) in groups.items()]


def errata_line(results) -> str:
    """``D distinct errors of the paper, in E certificates: m misprints (in k certificates), ...``;
    ``""`` when there are none."""
    groups = misprints(results)
    if not groups:
        return ""
    parts = []
    for kind in ERRATUM_KINDS + ("(kind not stated)",):
        mine = [g for g in groups if g[1] == kind]
        if mine:
            certs = len({cert.id for g in mine for cert, _ in g[2]})
            parts.append(f"{len(mine)} {kind}{'s' if len(mine) != 1 else ''} (in {certs} certificate"
                         f"{'s' if certs != 1 else ''})")
    n = len({cert.id for g in groups for cert, _ in g[2]})
    return (f"{len(groups)} distinct error{'s' if len(groups) != 1 else ''} of the paper, in {n} certificate"
            f"{'s' if n != 1 else ''}: " + ", ".join(parts))


# --------------------------------------------------------------------------
# REPORT.md, part by part

def _head(results=()) -> str:
    meanings = "\n".join(f"- **{s}**: {MEANING[s]}" for s in STATUSES)
    main = main_results_line(results)
    return ("# certify: the claims of arXiv:2411.10324, checked\n\n" + (f"{main}\n\n" if main else "")
            + f"Every claim of {PAPER} is checked as printed, with the paper's line "
            f"numbers.  {SOURCE}  Each certificate ends in one of four statuses:\n\n{meanings}\n\n{READING}")


MAIN_RESULT = re.compile(r"^(Theorem|Proposition|Corollary) (\d+\.\d+)\b")


def main_results(results) -> list[tuple[str, bool, list]]:
    """The paper's main results (theorems, propositions, corollaries) in the order the
    certificates state them: (name, holds, members), members = the (certificate, outcome)
    whose statement opens with the name.  It holds when none FAILs and each member is a
    PASS, or an ERRATUM whose misprint says that the name holds (a false step of its proof,
    or a remark stated beside it: "the proposition holds", "Corollary 4.5 holds")."""
    found: dict[str, list] = {}
    for cert, outcome in results:
        m = MAIN_RESULT.match(cert.statement)
        if m:
            found.setdefault(m.group(0), []).append((cert, outcome))

    def stands(name, outcome):
        kind = name.split()[0].lower()
        return outcome.status == PASS or (outcome.status == ERRATUM and bool(
            re.search(rf"({re.escape(name)}|the {kind}) holds", misprint_text(outcome))))
    return [(name, all(stands(name, o) for _, o in members), members) for name, members in found.items()]


def main_results_line(results) -> str:
    """One line for the first screen: which main results hold, with their certificates."""
    found = main_results(results)
    if not found:
        return ""

    def named(name, members):
        return f"{name} ({', '.join(_link(c.id) for c, _ in members)})"
    held = [named(n, m) for n, ok, m in found if ok]
    not_held = [named(n, m) for n, ok, m in found if not ok]
    text = ("**The main results**: " + (", ".join(held) + (" hold" if len(held) > 1 else " holds") if held else "")
            + ("; " if held and not_held else "") + (", ".join(not_held) + " not certified" if not_held else ""))
    island = [(c, o) for c, o in results if c.id == ISLAND_CLAIM]
    if island and island[0][1].status == PASS:
        text += (".  The suggestion of the abstract, that the orbits might be quasi-periodic, is proved for an island "
                 f"of the reduction ({_link(ISLAND_CLAIM)}) at every rational r in ]3−2√2, 1[, wherever its rotation "
                 "number is irrational; at the resonances, where it is rational (r = 2−√3: 1/3), the island's orbits "
                 "are periodic")
    settled = [f"{what} ({_link(cid)})" for cid, what in OPEN_PROBLEMS
               if any(c.id == cid and o.status == PASS for c, o in results)]
    if settled:
        text += ".  Questions the paper leaves open, settled here: " + "; ".join(settled)
    return text + ".  Where the paper errs, and what is certified instead: [Errata](#errata)."


ISLAND_CLAIM = "N7.1"       # the paper's suggestion (l. 95), proved for the island around [ac]b
# the paper's open questions (l. 1084-1086, 1214-1217) that a certificate settles, as the first screen names them
OPEN_PROBLEMS = (
    ("L5", "the stability windows of (ab)^n(cb)^n are disjoint and accumulate on 7−4√3 from above, for every n ≥ 2"),
    ("L6", "their upper ends are where q₂(0) = 0 on the dominant branch (CDKK's conjecture), for every n ≥ 2"),
    ("T28.3", "the largest r with self-similar collapse along a periodic pattern of at most 20 collisions is "
              "abcb's r_exist ≈ 0.19166"),
    ("T28.4", "up to 20 collisions no asymmetric periodic pattern is stable"),
    ("N2.7", "the apparent chaos is proved at sampled r by horseshoes of the b-to-b map (on sets of measure zero)"),
)


def _contents(results) -> str:
    """The table of contents: the overview, then each part of the paper with its certificates."""
    lines = ["## Contents", "", "- [Summary](#summary)", "- [Where the tool disagrees with the paper](#disagreements)",
             "- [Errata](#errata)",
             "- [All certificates](#all-certificates)"]
    for part, members in _by_part(results):
        ids = ", ".join(f"{_link(cert.id)} {status_label(outcome)}" for cert, outcome in members)
        lines.append(f"- [{part}](#{part_anchor(part)}): {ids}")
    return "\n".join(lines)


def _by_part(results) -> list[tuple[str, list]]:
    """The results grouped by part of the paper, in the order they come."""
    groups: dict[str, list] = {}
    for cert, outcome in results:
        groups.setdefault(part_of(cert.id), []).append((cert, outcome))
    return list(groups.items())


def _summary(results, kernel=None) -> str:
    n = counts(results)
    against = disagreements(results)
    rows = [f"| {s} | {n[s]} |" for s in n]
    if against:
        rows.insert(STATUSES.index(OBSERVED) + 1, f"| of which disagree with the paper | {len(against)} |")
    lines = ["## Summary", "", "| Status | Certificates |", "|---|---:|", *rows,
             f"| **Total** | **{len(results)}** |"]
    failing = [cert.id for cert, outcome in results if outcome.status == FAIL]
    if failing:
        lines += ["", "Failing: " + ", ".join(_link(c) for c in failing) + "."]
    if errata_line(results):
        lines += ["", errata_line(results) + "; see [Errata](#errata)."]
    lines += ["", kernel_line(kernel)]
    return "\n".join(lines)


def _disagreements(results) -> str:
    """Every place the tool disagrees with the paper, one line each with its reason:
    the errata by distinct error, then the observations that do not agree."""
    lines = ['## <a id="disagreements"></a>Where the tool disagrees with the paper', ""]
    for key, kind, members in misprints(results):
        ids = ", ".join(_link(cert.id) for cert, _ in members)
        lines.append(f"- ERRATUM, {kind}: {_one_line(key)} ({ids})")
    for cert, outcome in disagreements(results):
        lines.append(f"- OBSERVED, {DISAGREES}: {_link(cert.id)} ({_cell(cert.line)}): {_one_line(outcome.reason)}")
    if len(lines) == 2:
        lines.append("Nowhere: every certificate is PASS, or OBSERVED and agreeing with the paper.")
    return "\n".join(lines)


def _tokens(text: str) -> list[re.Match]:
    """Words, numbers and single signs of ``text`` (a code span is read inside)."""
    return list(re.finditer(r"\w+|[^\w\s`]", text))


MAX_CHANGES = 3   # more changes than this: the correction is a restatement, not an edit


def changes(before: str, after: str) -> str:
    """What differs from ``before`` to ``after``, word by word: ``smaller → larger``,
    ``ey → ez``; ``""`` when the two read the same; "restated" when more than
    :data:`MAX_CHANGES` places differ."""
    a, b = _tokens(before), _tokens(after)
    ops = difflib.SequenceMatcher(None, [m.group() for m in a], [m.group() for m in b], autojunk=False)
    out = []
    for tag, i1, i2, j1, j2 in ops.get_opcodes():
        if tag == "equal":
            continue
        old = before[a[i1].start():a[i2 - 1].end()] if i2 > i1 else ""
        new = after[b[j1].start():b[j2 - 1].end()] if j2 > j1 else ""
        out.append(f"`{old}` → `{new}`" if old and new else f"+ `{new}`" if new else f"− `{old}`")
    return "; ".join(out) if len(out) <= MAX_CHANGES else "restated (compare the two columns)"


def erratum_pairs(outcome) -> list[tuple]:
    """Each failing printed check with the corrected checks that replace it."""
    wrong = [c for c in outcome.printed if c.counts and not holds(c)]
    return [(c, [k for k in outcome.corrected if corrected_statement(k) == str(c.statement)])
            for c in wrong]


def _erratum(cert, outcome) -> str:
    """Each false printed statement next to its certified correction, and what changed;
    further checks made false by the same change are named below the table, not repeated."""
    lines = [f"**{_link(cert.id)}** (paper: {_cell(cert.line)}): {_one_line(cert.statement)}", "",
             "| As printed (false) | Corrected (certified) | What changed |", "|---|---|---|"]
    seen, again = set(), []
    for printed, fixes in erratum_pairs(outcome):
        left = f"{MARK[False]} {_cell(printed.statement)}"
        if not fixes:
            lines.append(f"| {left} | (see [{cert.id}](#{anchor(cert.id)})) | |")
        for k, fix in enumerate(fixes):
            change = changes(_one_line(printed.statement), _one_line(fix.statement))
            core = re.sub(r"`(as printed|corrected)` → `(as printed|corrected)`(; )?", "", change)
            if core and core in seen and holds(fix):
                again.append(_one_line(printed.statement))
                continue
            seen.add(core)
            lines.append(f"| {left if k == 0 else ''} | {MARK[holds(fix)]} {_cell(fix.statement)} | "
                         f"{_cell(change) or 'the same words: see the evidence'} |")
    if again:
        lines += ["", f"The same change also corrects {len(again)} more check{'s' if len(again) != 1 else ''} "
                      f"of {cert.id}: " + "; ".join(again) + "."]
    return "\n".join(lines)


def _errata(results) -> str:
    """The errata grouped by the one error of the paper each comes from."""
    groups = misprints(results)
    if not groups:
        return "## Errata\n\nNone: no certificate has status ERRATUM."
    parts = ["## Errata", errata_line(results) + ".  Kinds: a *misprint* is one symbol or word typed for "
             "another, the argument standing; a *false statement* is false as a statement; a *refuted remark* is "
             "a hedged remark (\"does not seem\") refuted by counterexamples."]
    for k, (key, kind, members) in enumerate(groups, 1):
        ids = ", ".join(_link(cert.id) for cert, _ in members)
        parts.append(f"#### {k}. {_one_line(key)}\n\n*{kind.capitalize()}*, in {ids}.")
        parts += [_erratum(cert, outcome) for cert, outcome in members]
    return "\n\n".join(parts)


def _natural(cid: str) -> tuple:
    """A certificate id's sort key: its letter, then its numbers as numbers (L3 < L10, N2.7 < N7.1)."""
    return tuple(int(t) if t.isdigit() else t for t in re.split(r"(\d+)", cid))


def kernel_line(kernel) -> str:
    """The summary's line on the independent kernel (reports/kernel.json), with the statements it
    does not verify and why, in a few words each."""
    if not kernel:
        return "Independent kernel: not run (`python -m certify verify`, docs/verify.md)."
    failed = sorted(i for i, r in kernel["certificates"].items() if not r["ok"])
    k, n = kernel["verified"], kernel["statements"]
    by_id = sorted(kernel["certificates"].items(), key=lambda kv: _natural(kv[0]))   # the same order, read back or not
    missing = [f"{sid} ({_short(why)})" for _id, r in by_id if r["ok"] and r["counted"]
               for sid, why in r["statements"].items() if why]
    return (f"Independent kernel (`python -m certify verify`, docs/verify.md): **{k}/{n} statements verified**: "
            f"of the {n} formal statements of the PASS and ERRATUM certificates (statements/*.txt, the paper's "
            f"claims written as data), the kernel decides {k} exactly with its own definitions and the Python "
            "standard library alone, each as the verdict the report gives it; each statement's line below says "
            "whether it is verified and, if not, why." + (f"  Not verified: {', '.join(missing)}." if missing else "")
            + (f"  **The kernel rejects {', '.join(failed)}.**" if failed else ""))


def _short(why: str) -> str:
    """A reason in a few words: up to its first colon or parenthesis."""
    head = why.split(" (")[0].split(":")[0].strip()
    return head if len(head) <= 60 else head[:59] + "…"


def _table(results, kernel=None) -> str:
    rows = [f"| {_link(cert.id)} | {_cell(cert.line)} | {_cell(cert.statement)} | {status_label(outcome)} | "
            f"{verification.cell(kernel, cert.id)} |" for cert, outcome in results]
    return "\n".join(["## All certificates", "", "| Id | Paper | Statement | Status | Kernel |",
                      "|---|---|---|---|---|", *rows])


SAME = "(as above)"
def _role(check) -> str:
    if check.counts:
        return ""
    if str(check.statement).startswith(EXPLANATION):
        return " *(certified explanation, beside the observation: not the paper's claim)*"
    if str(check.statement).startswith(OBSERVATION):
        return " *(observed, not certified: not the paper's claim)*"
    return " *(consistency check of the engine, not evidence)*"


def _verified(kernel, cert_id: str, check) -> str:
    """What the kernel says of a check's formal statement, for its line in the report (nothing for
    an observation: the kernel has nothing to verify there)."""
    if not getattr(check, "ref", "") or kernel is None:
        return ""
    why = verification.why_not(kernel, cert_id, check.ref)
    if why is None or why == "an observation":
        return ""
    return " · *kernel: verified*" if why == "" else f" · *kernel: not verified ({_one_line(why)})*"


def _checks(title: str, checks, shown: set | None = None, kernel=None, cert_id: str = "") -> str:
    """The checks with their evidence; an evidence fragment already in ``shown`` (the
    same sign table under "As printed" and "Corrected") is not repeated."""
    shown = set() if shown is None else shown
    items = []
    for check in checks:
        role = _role(check)
        evidence = [str(e) for e in check.evidence]
        repeated = bool(evidence) and all(e in shown for e in evidence)
        said = _verified(kernel, cert_id, check)
        items.append(_bullet(f"{MARK[holds(check)]} {_one_line(text_of(check))}{role}{said}"
                             + (f" {SAME}" if repeated else "")))
        if not repeated:
            items += [_bullet(e if e not in shown else f"{_first_line(e)} {SAME}", indent=2) for e in evidence]
        shown.update(evidence)
    return f"**{title}**\n\n" + "\n".join(items)


def _section(cert, outcome, kernel=None) -> str:
    """Everything about one certificate: verdicts, note, evidence, figures."""
    printed = "as printed: " if outcome.status != PASS else ""
    label = status_label(outcome)
    parts = [f'### <a id="{anchor(cert.id)}"></a>{cert.id} — {label} — {printed}{_one_line(cert.statement)}',
             f"Paper: {_one_line(cert.line)} of the source · Status: **{label}** · "
             f"Proof: {_source(cert)}"]
    if outcome.status == OBSERVED and outcome.agrees is False:
        parts.append(f"**Does not agree with the paper:** {_one_line(outcome.reason)}")
    if outcome.status == ERRATUM:
        parts.append(f"**Erratum ({outcome.kind}):** {_one_line(misprint_text(outcome))}")
    shown: set = set()
    if outcome.printed:
        parts.append(_checks("As printed", outcome.printed, shown, kernel, cert.id))
    if outcome.corrected:
        parts.append(_checks("Corrected (certified)", outcome.corrected, shown, kernel, cert.id))
    if str(outcome.note).strip():
        parts.append("**Note.** " + _fragment(outcome.note))
    if outcome.evidence:
        parts += ["**Evidence**", *(_fragment(e) for e in outcome.evidence)]
    parts += [_figure(cert.id, name) for name in outcome.figures]
    return "\n\n".join(parts)


def render_markdown(results, kernel=None) -> str:
    """The text of REPORT.md: head, contents, summary, errata, table, then the
    certificates part by part, and a last line that closes the report; ``kernel``: the
    independent kernel's results (reports/kernel.json, :mod:`certify.run.verification`)."""
    parts = [_head(results), _contents(results), _summary(results, kernel), _disagreements(results),
             _errata(results), _table(results, kernel)]
    for part, members in _by_part(results):
        parts.append(f'## <a id="{part_anchor(part)}"></a>{part}')
        parts += [_section(cert, outcome, kernel) for cert, outcome in members]
    return "\n\n".join(parts + [END]) + "\n"


# --------------------------------------------------------------------------
# report.json and timings.json

def _check_data(check) -> dict:
    data = {"statement": str(check.statement), "holds": holds(check),
            "evidence": [str(e) for e in check.evidence]}
    if corrected_statement(check):
        data["corrects"] = corrected_statement(check)
    if not check.counts:
        data["consistency"] = True
    return data


def certificate_data(cert, outcome) -> dict:
    """One certificate and its outcome as plain JSON data."""
    return {
        "id": cert.id,
        "line": cert.line,
        "statement": cert.statement,
        "proof": {"module": cert.module, "function": getattr(cert.func, "__name__", "")},
        "part": part_of(cert.id),
        "status": outcome.status,
        **({"erratum": {"kind": outcome.kind, "misprint": misprint_text(outcome)}}
           if outcome.status == ERRATUM else {}),
        **({"agrees": outcome.agrees, "reason": outcome.reason} if outcome.status == OBSERVED else {}),
        "printed": [_check_data(c) for c in outcome.printed],
        "corrected": [_check_data(c) for c in outcome.corrected],
        "note": str(outcome.note),
        "evidence": [str(e) for e in outcome.evidence],
        "figures": [f"figures/{name}" for name in outcome.figures],
    }


def render_json(results) -> str:
    """The text of report.json (deterministic, like REPORT.md)."""
    data = {"paper": PAPER, "statuses": MEANING, "summary": counts(results),
            "disagree": [cert.id for cert, _ in disagreements(results)],
            "errors_of_the_paper": [{"misprint": key, "kind": kind, "certificates": [c.id for c, _ in members]}
                                    for key, kind, members in misprints(results)],
            "certificates": [certificate_data(c, o) for c, o in results]}
    return json.dumps(data, indent=2, ensure_ascii=False) + "\n"


CERTIFICATES_FORMAT = "certify-certificates/2"   # certify_kernel.FORMAT: docs/verify.md
WITNESS_KINDS = certify_kernel.WITNESSES         # the facts the kernel reads as witnesses (.signs, .pattern)
_STATEMENTS: dict = {}


def paper_statements(directory=None) -> dict:
    """The statement files (statements/*.txt, docs/statements.md) read once: id -> statement."""
    key = str(directory or CHECKOUT / "statements")
    if key not in _STATEMENTS:
        paper = read_statements(key)
        _STATEMENTS[key] = {s.id: s for c in paper.certificates for s in c.statements}
    return _STATEMENTS[key]


def text_of(check) -> str:
    """What the report prints for a check: the text of its formal statement (with its id) when it
    decides one, else its own statement."""
    ref = getattr(check, "ref", "")
    if ref:
        s = paper_statements().get(ref)
        if s is None:
            raise KeyError(f"the check names the statement {ref}, which statements/ does not have")
        return f"{ref}: {s.text}"
    return str(check.statement)


def _statements_of(outcome) -> dict:
    """ref -> {"verdict", "witness"}: the run's verdict on each formal statement its checks decide
    (holds when every check naming it holds), with their witnesses of the kinds the kernel reads."""
    facts = {ob["id"]: ob for ob in getattr(outcome, "witnesses", [])}
    out: dict = {}
    for check in list(outcome.printed) + list(outcome.corrected):
        if not getattr(check, "ref", ""):
            continue
        entry = out.setdefault(check.ref, {"verdict": "holds", "witness": []})
        if not holds(check):
            entry["verdict"] = "refuted"
        for i in check.witnesses or []:
            ob = facts.get(i)
            data = {k: v for k, v in ob.items() if k != "id"} if ob is not None else None
            if data is not None and ob.get("kind") in WITNESS_KINDS and data not in entry["witness"]:
                entry["witness"].append(data)
    if outcome.status == OBSERVED:
        for entry in out.values():
            entry["verdict"] = "observed"
    for entry in out.values():
        if not entry["witness"]:
            del entry["witness"]
    return out


def render_certificates(results) -> str:
    """The text of certificates.json: for each certificate its status and, for each formal
    statement its checks decide, the run's verdict and the witnesses the kernel may read (never
    the objects: the kernel builds those from statements/); one certificate per line,
    deterministic like report.json."""
    head = {"format": CERTIFICATES_FORMAT, "paper": VERSION, "schema": "docs/verify.md"}
    lines = []
    for cert, outcome in results:
        lines.append(json.dumps({"id": cert.id, "status": outcome.status, "statements": _statements_of(outcome)},
                                ensure_ascii=False, separators=(",", ":"), sort_keys=True))
    text = json.dumps(head, ensure_ascii=False)[:-1] + ', "certificates": [\n' + ",\n".join(lines) + "\n]}\n"
    return text


def render_timings(timings: dict) -> str:
    """The text of timings.json: the runner's timings and their total, in seconds."""
    per_cert = timings.get("certificates", {})
    total = round(sum(t["seconds"] for t in per_cert.values()), 4)
    return json.dumps({"total_seconds": total, **timings}, indent=2) + "\n"


# --------------------------------------------------------------------------
# Writing, and comparing with a committed report

def write_report(results, timings: dict, out_dir, kernel: bool = True, jobs: int = 2) -> str:
    """Write REPORT.md, report.json, certificates.json, kernel.json and timings.json into ``out_dir``.

    All texts are rendered before anything is written (the kernel's results read back from
    kernel.json, or decided now: :func:`certify.run.verification.results_for`), and each file is
    replaced atomically; REPORT.md comes last.  Returns the text of REPORT.md.
    """
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    certificates = render_certificates(results)
    verdicts = verification.results_for(certificates, out, jobs) if kernel else None
    markdown, data, times = render_markdown(results, verdicts), render_json(results), render_timings(timings)
    write_atomic(out / "report.json", data)
    write_atomic(out / "certificates.json", certificates)
    write_atomic(out / "timings.json", times)
    write_atomic(out / "REPORT.md", markdown)
    return markdown


_SECTION = re.compile(r'^### <a id="[^"]*"></a>(\S+) — ')


def _owners(lines: list[str]) -> list[str]:
    """For each line of a report, the part it belongs to: ``summary`` (everything
    before the first certificate), a certificate id, or ``outside`` (the closing line
    and anything after it)."""
    owner, out = "summary", []
    for line in lines:
        match = _SECTION.match(line)
        if match:
            owner = match.group(1)
        if line == END:
            owner = "outside"
        out.append(owner)
    return out


def changed_parts(old: str | None, new: str) -> list[str]:
    """What differs between a committed REPORT.md and a regenerated one.

    Returns ``[]`` when they are identical, ``["missing"]`` when there was no
    committed report, else the changed parts in order: ``summary`` (head, contents,
    summary, errata, table), certificate ids (marked ``(new)`` or ``(removed)``), and
    ``outside any certificate`` for lines that belong to none (after the closing line,
    or a part heading).  Lines are compared with difflib, so a line added or removed
    anywhere is charged to the part that holds it, not to the last certificate."""
    if old is None:
        return ["missing"]
    if old == new:
        return []
    a, b = old.split("\n"), new.split("\n")
    own_a, own_b = _owners(a), _owners(b)
    ids_a = {m.group(1) for line in a if (m := _SECTION.match(line))}
    ids_b = {m.group(1) for line in b if (m := _SECTION.match(line))}
    changed: list[str] = []

    def note(part: str) -> None:
        if part == "outside":
            part = "outside any certificate"
        elif part in ids_b and part not in ids_a:
            part = f"{part} (new)"
        elif part in ids_a and part not in ids_b:
            part = f"{part} (removed)"
        if part not in changed:
            changed.append(part)

    for tag, i1, i2, j1, j2 in difflib.SequenceMatcher(None, a, b, autojunk=False).get_opcodes():
        if tag != "equal":
            for i in range(i1, i2):
                note(own_a[i])
            for j in range(j1, j2):
                note(own_b[j])
    return changed or ["whitespace"]
