"""Running a census on an executor, streaming its records to disk; CENSUS.md and its figure.

:func:`run_census` submits the words of :func:`certify.patterns.census.words` to any
:class:`concurrent.futures.Executor` (:mod:`.executors`), a bounded number at a time,
and appends each record to a JSON-lines *state* file as soon as it arrives.  With
``resume`` the words already in the state file are not analysed again (a record does
not depend on the bound L, so the state of a shorter census serves a longer one); a
last line cut by an interruption is dropped.  The records come back in census order,
so the output does not depend on the executor or on the order of completion.
"""
from __future__ import annotations

import copy
import json
import math
import re
from fractions import Fraction
from functools import lru_cache
from pathlib import Path

from certify.patterns import census, compact, island_theorem

from .executors import wait_first
from .files import REPORTS, read_first_member, read_text_or_none, write_atomic

WINDOW = 64                  # jobs in flight at once (an interruption loses at most these)


def dumps(record: dict) -> str:
    """One record as one line of JSON (sorted keys: the same bytes everywhere)."""
    return json.dumps(record, sort_keys=True, ensure_ascii=False, separators=(",", ":"))


def load_state(path) -> dict[str, dict]:
    """The records of a state file, by word, with their seconds; a line that does not
    parse (cut by an interruption) is dropped, and the file is rewritten without it.
    When a word has several lines (a record completed by a later run), the last wins."""
    text = read_text_or_none(path)
    if text is None:
        return {}
    records, kept, cut = {}, [], False
    for line in text.splitlines():
        try:
            rec = json.loads(line)
            records[rec["word"]] = rec          # a later line of a word (completed) wins
            kept.append(line)
        except (ValueError, KeyError, TypeError):
            cut = True
    if cut or (text and not text.endswith("\n")):
        write_atomic(path, "".join(line + "\n" for line in kept))
    return records


def _timeless(record: dict) -> dict:
    """The record without its seconds (:data:`certify.patterns.census.TIMES`)."""
    return {k: v for k, v in record.items() if k not in census.TIMES}


def run_census(max_length: int, executor, state=None, resume: bool = False, progress=None,
        job=census.analyse_word, window: int = WINDOW, complete=census.add_reduction,
        words=census.iter_words, current=None) -> list[dict]:
    """The census records of every word up to ``max_length``, in census order.

    ``state``: a JSON-lines file the records are appended to as they finish (created,
    or emptied unless ``resume``).  ``resume``: reuse the records found in ``state``.
    ``progress(k, n, word)`` after each word.  ``job(word)`` is what runs on the
    executor (a module-level function: it may cross processes or machines).  A state
    record without its :data:`~certify.patterns.census.REDUCTION` part (from an older
    census) is reused as it is and completed by ``complete(record)``, which computes
    only that part; the completed record is appended to the state (the last line of a
    word wins); ``complete=None``: no record is partial.  ``words(max_length)``: the words
    in census order (the five-particle census passes its own).  ``current(record)``: whether a
    state record is reused (None: every one); a record it refuses is analysed again."""
    n = sum(1 for _ in words(max_length))     # the words stream: never all in memory at once
    done = {}
    if state is not None:
        state = Path(state)
        if resume:
            done = {w: rec for w, rec in load_state(state).items()
                    if rec["length"] <= max_length and (current is None or current(rec))}
        else:
            write_atomic(state, "")
    partial = {} if complete is None else {w: done.pop(w) for w in list(done) if census.REDUCTION not in done[w]}
    done = {w: _timeless(rec) for w, rec in done.items()}
    # shortest first (a cut census is complete up to a length), streamed: submitted as the window frees
    todo = (w for w in words(max_length) if w not in done)
    if progress:
        progress(len(done), n, "")
    sink = state.open("a", encoding="utf-8") if state is not None else None

    def collect(future, word) -> None:
        record = future.result()
        if sink is not None:
            sink.write(dumps(record) + "\n")
            sink.flush()
        done[word] = _timeless(record)
        if progress:
            progress(len(done), n, word)

    try:
        pending, words_of, queue = set(), {}, todo
        while True:
            while len(pending) < window:
                word = next(queue, None)
                if word is None:
                    break
                future = executor.submit(complete, partial[word]) if word in partial else executor.submit(job, word)
                if future.done():                 # a serial executor: written before the next job
                    collect(future, word)
                else:
                    words_of[future] = word
                    pending.add(future)
            if not pending:
                if word is None:
                    break
                continue
            # a timeout, so that Ctrl-C and SIGTERM are handled while the jobs run
            finished, pending = wait_first(pending, 0.5)
            for future in sorted(finished, key=lambda f: words_of[f]):
                collect(future, words_of.pop(future))
    finally:
        if sink is not None:
            sink.close()
    return [done[w] for w in words(max_length)]          # census order


def completed(records: dict[str, dict]) -> int:
    """How many records of a state have their reduction part."""
    return sum(census.REDUCTION in r for r in records.values())


RESULT_KEPT = ("system", "feasible", "stable", "undecided")       # of ``result`` in census.json
REDUCTION_KEPT = ("attracting", "attracting_points", "saddle", "repelling", "complex_pair", "undecided")


def brief(record: dict) -> dict:
    """The record as census.json keeps it: the self-similar part's feasible and stable
    r-sets and undecided points (exact ends), its verdict; the reduction part's attracting
    windows and points, its saddle, repelling and complex-pair sets (text), its undecided
    points and verdict.  Dropped, and recomputed for one word by ``certify pattern WORD
    --json`` and ``certify orbit WORD --json``: the existence sets of both, the reduction's
    feasible sets (exact ends), the characteristic polynomial, the diagnosis.  The times
    (:data:`~certify.patterns.census.TIMES`) are dropped too.  ``brief(brief(r)) == brief(r)``: a census written from
    the records of census.json is the census written from the analyses."""
    out = {k: v for k, v in record.items() if k not in census.TIMES}
    if out.get("result") is not None:
        out["result"] = {k: v for k, v in out["result"].items() if k in RESULT_KEPT}
    part = out.get(census.REDUCTION)
    if part is not None and part.get("result") is not None:
        out[census.REDUCTION] = dict(part, result={k: v for k, v in part["result"].items() if k in REDUCTION_KEPT})
    return out


def undecided_r(text: str) -> Fraction:
    """The r of an undecided point as the census prints it ("upper x₊ at ≈0.2679491924: ..."),
    its certified digits as a fraction."""
    found = re.search(r"at ≈?([0-9.]+)", text)
    if found is None:
        raise ValueError(f"no r in the undecided point {text!r}")
    return Fraction(found.group(1))


def feasible_ends(record: dict) -> list[dict]:
    """The upper ends of a record's feasible self-similar sets (each interval's hi, each
    point), in the end-point form of ``pattern --json``."""
    return [p["hi"] if p["kind"] == "interval" else p["at"]
            for s in (record.get("result") or {}).get("feasible", []) for p in s["pieces"]]


def highest_feasible(records) -> tuple[object, list[str]]:
    """(the largest end of every feasible self-similar set, as an exact algebraic number;
    the words that reach it), or (None, []) when no word is feasible.  Ends compared
    exactly (:func:`certify.patterns.census.end_number`)."""
    tops = [(census.end_number(e), r["word"]) for r in records for e in feasible_ends(r)]
    highest = max((e for e, _ in tops), default=None)
    return highest, sorted({w for e, w in tops if e == highest})


def document(records, max_length: int) -> dict:
    """The census as one JSON document: the summary, then every record in brief
    (:func:`brief`: what the report, the certificates T28.3-T28.4 and
    the table need; the rest is recomputed for a word by ``certify pattern WORD --json``)."""
    return {"census": census.summary(records, max_length),
            "words": [brief(r) for r in census.order(records)]}


def to_json(doc: dict) -> str:
    """The document as JSON: its summary "census" first and indented, then each record of
    "words" compact on a line of its own (a census to 20 is 5618 records: indented, census.json
    would pass 100 MB; a line a word keeps its diffs readable)."""
    dump = lambda x, **kw: json.dumps(x, sort_keys=True, ensure_ascii=False, **kw)    # noqa: E731
    assert sorted(doc) == ["census", "words"]
    words = ",\n".join(dump(rec, separators=(",", ":")) for rec in doc["words"])
    return '{"census": ' + dump(doc["census"], indent=1) + ',\n"words": [\n' + words + "\n]}\n"


# --------------------------------------------------------------------------
# The table: one row per word (CSV, gzip), for pandas and spreadsheets

TABLE = "census-words.csv.gz"        # next to census.json: one row per word
COLUMNS = {
    "word": "the normal form (the class's key; census.json's `word`)",
    "compact": "the word with powers, as CENSUS.md prints it",
    "length": "collisions in a period",
    "blocks": "its blocks, separated by spaces",
    "contains_abcab": "abcab or its mirror cbacb occurs cyclically (T28)",
    "outcome": "`analysed` or `error` (the self-similar analysis)",
    "feasible": "feasible self-similar data somewhere in ]0, 1[ (empty: error)",
    "stable": "stable self-similar (collapsing) data somewhere (empty: error)",
    "undecided": "the self-similar analysis left points undecided (empty: error)",
    "attracting": "an attracting periodic orbit of the reduction somewhere",
    "feasible_set": "the feasible r-sets per branch and fixed point, as text (≈ and 10 digits)",
    "stable_set": "the stable r-sets, as text",
    "attracting_set": "the attracting windows of the reduction per branch, with the in-plane pair, as text",
    "feasible_exact": "JSON: the feasible r-sets with exact ends (census.json's `result.feasible`)",
    "stable_exact": "JSON: the stable r-sets with exact ends (`result.stable`)",
    "attracting_exact": "JSON: the attracting windows with exact ends (`reduction.result.attracting`)",
    "feasible_lo": "float: the least end of the feasible r-sets (empty: none)",
    "feasible_hi": "float: the largest end of the feasible r-sets",
    "stable_lo": "float: the least end of the stable r-sets",
    "stable_hi": "float: the largest end of the stable r-sets",
    "attracting_lo": "float: the least end of the attracting windows",
    "attracting_hi": "float: the largest end of the attracting windows",
    "undecided_points": "the undecided self-similar points, separated by ` | `",
    "verdict": "the self-similar verdict (`certify pattern`)",
    "reduction_outcome": "`analysed`, `three particles` or `error` (the reduction)",
    "reduction_verdict": "the reduction's verdict (`certify orbit`)",
    "error": "the error of either analysis, one line",
}


def _float_ends(pieces) -> tuple[float, float] | tuple[str, str]:
    """(least, largest) end of the pieces as floats of their certified digits; ("", "") without."""
    ends = [float(p[k]["digits"]) for p in pieces for k in (("lo", "hi") if p["kind"] == "interval" else ("at",))]
    return (min(ends), max(ends)) if ends else ("", "")


def _json_cell(value) -> str:
    return json.dumps(value, sort_keys=True, ensure_ascii=False, separators=(",", ":"))


def table_row(record: dict) -> dict:
    """A record of census.json as a row of :data:`TABLE` (the keys of :data:`COLUMNS`)."""
    result = record.get("result") or {}
    part = record.get(census.REDUCTION) or {}
    attracting = (part.get("result") or {}).get("attracting", [])
    analysed = record["outcome"] == "analysed"
    row = {"word": record["word"], "compact": record["compact"], "length": record["length"],
           "blocks": " ".join(record["blocks"]), "contains_abcab": record["contains_abcab"],
           "outcome": record["outcome"], "feasible": record["feasible"], "stable": record["stable"],
           "undecided": record["undecided"], "attracting": bool(part.get("attracting")),
           "feasible_set": _sets(record, "feasible") if analysed else "",
           "stable_set": _sets(record, "stable") if analysed else "",
           "attracting_set": _attracting(record),
           "feasible_exact": _json_cell(result.get("feasible", [])),
           "stable_exact": _json_cell(result.get("stable", [])),
           "attracting_exact": _json_cell(attracting),
           "undecided_points": " | ".join(result.get("undecided", [])),
           "verdict": record["verdict"], "reduction_outcome": part.get("outcome", ""),
           "reduction_verdict": part.get("verdict", ""),
           "error": "; ".join(e for e in (record["error"], part.get("error")) if e)}
    for stage in ("feasible", "stable"):
        row[f"{stage}_lo"], row[f"{stage}_hi"] = _float_ends([p for s in result.get(stage, []) for p in s["pieces"]])
    row["attracting_lo"], row["attracting_hi"] = _float_ends([dict(a, kind="interval") for a in attracting])
    return {k: ("" if row[k] is None else row[k]) for k in COLUMNS}


def table(doc: dict) -> bytes:
    """:data:`TABLE`: a header, then one CSV row per word of the census, in census order,
    compressed with gzip (no time stamp: the same bytes for the same census)."""
    import csv
    import gzip
    import io
    text = io.StringIO()
    writer = csv.DictWriter(text, fieldnames=list(COLUMNS), lineterminator="\n")
    writer.writeheader()
    for record in doc["words"]:
        writer.writerow(table_row(record))
    return gzip.compress(text.getvalue().encode("utf-8"), compresslevel=9, mtime=0)


# --------------------------------------------------------------------------
# CENSUS.md

def _cell(text: str) -> str:
    return str(text).replace("|", "\\|").replace("\n", " ")


def _sets(record: dict, key: str) -> str:
    sets = census.r_sets(record, key)
    return "; ".join(f"{name}: {text}" for name, text in sets) or "∅"


def _attracting(record: dict) -> str:
    """The attracting windows of a record's periodic orbit of the reduction, as text."""
    part = record.get(census.REDUCTION)
    if part is None:
        return "not computed"
    if part["outcome"] != "analysed":
        return part["error"] or part["outcome"]
    wins = [f"{a['branch']}: ]{census.show_end(a['lo'])}, {census.show_end(a['hi'])}[ ({a['pair']} pair)"
            for a in part["result"]["attracting"]]
    wins += [f"{p['branch']}: {{{census.show_end(p['at'])}}}" for p in part["result"]["attracting_points"]]
    return "; ".join(wins) or "∅"


NOT_COLLAPSE = ("an orbit with a complex in-plane pair is not a collapse: no velocity eigenvector lies in the plane, "
                "the velocity turns in it by the argument of the pair each period, and the particles leave the word "
                "within a period or two (the prefix of Remark 4.2, S11)")


def reduction_lines(s: dict, recs: list, L: int) -> list[str]:
    """The findings on the attracting periodic orbits of the reduction."""
    f = s["reduction"]
    by = {r["word"]: r for r in recs}
    lines = ["### Attracting periodic orbits of the reduction", "",
             "The periodic orbits (b, n*) of the reduction map of Section 4 with each word (`certify orbit WORD`, "
             "docs/orbit.md): n* a real left eigenvector of M_w, attracting where its eigenvalue is strictly the "
             "smallest of M_w in modulus. They are what the simulator settles on (Section 5). Where the in-plane "
             "pair is real they carry self-similar data; " + NOT_COLLAPSE + ".", "",
             f"- words with a feasible periodic orbit of the reduction: {len(f['feasible'])}; with an attracting "
             f"one: {len(f['attracting'])}; with undecided points: {len(f['undecided'])}; errors: {len(f['errors'])}"
             + (f"; not computed: {len(f['missing'])}" if f["missing"] else ""),
             "- attracting periodic orbits of the reduction:" + ("".join(
                 f"\n  - `{by[w]['compact']}` on {_attracting(by[w])}" for w in f["attracting"]) or " none"),
             "- with a complex in-plane pair where attracting (not collapse): "
             + (", ".join(f"`{by[w]['compact']}`" for w in f["complex_pair_attracting"]) or "none"),
             "- families (the words x_0 v^n x_1 … with one or two repeated factors v, attracting for at least three "
             "consecutive n): " + ("; ".join(
                 f"{', '.join(f'`{c}`' for c in fam['compact'])} (repeated: {', '.join(fam['repeated'])})"
                 for fam in f["families"]) or f"none up to length {L}"),
             "", "The r in ]0, 1[ with an attracting periodic orbit of the reduction of length at most L (the union "
             "of the windows, exact ends compared as algebraic numbers; a row where the union grows):", "",
             "| L | union of the attracting windows | gaps in ]0, 1[ |", "|---:|---|---|"]
    if not f["union_by_length"]:
        lines.append(f"| {L} | ∅ | ]0, 1[ |")
    for u in f["union_by_length"]:
        lines.append(f"| {u['max_length']} | {u['set']} | {census.show_gaps(u)} |")
    if f["union_by_length"] and f["union_by_length"][-1]["max_length"] < L:
        lines.append(f"| {L} | the same (no new window after L = {f['union_by_length'][-1]['max_length']}) | |")
    return lines + [""] + resonance_lines(f.get("attracting_windows", {}), by)


def committed_windows(path=None) -> tuple[dict, dict] | None:
    """The attracting windows of the committed census ({word: [{"lo", "hi", ...}]}, as
    census.json holds them) and the compact form of each of their words (:func:`compact`,
    as the census records it), or None without a census file.  Only the file's summary is
    decoded (:func:`.files.read_first_member`: the megabytes of word records are not even read), once per
    version of the file (its size and time of change)."""
    path = Path(path or REPORTS / "census.json")
    try:
        stat = path.stat()
    except OSError:
        return None
    found = _windows_of(str(path.resolve()), stat.st_size, stat.st_mtime_ns)
    return None if found is None else copy.deepcopy(found)


@lru_cache(maxsize=4)
def _windows_of(path: str, size: int, mtime_ns: int) -> tuple[dict, dict] | None:
    summary = read_first_member(path, "census")
    if summary is None:
        return None
    windows = summary["reduction"].get("attracting_windows", {})
    return windows, {word: compact(word) for word in windows}


RESONANCE_Q = island_theorem.RESONANCE_Q


def resonance_lines(windows: dict, by: dict) -> list[str]:
    """The window ends that are resonances of the island's rotation number (the same algebraic
    number, :func:`certify.patterns.island_theorem.window_resonances`; ``certify island``)."""
    found = island_theorem.window_resonances(windows, RESONANCE_Q)
    if not windows:
        return []
    rows = [f"- `{by[w]['compact'] if w in by else w}`: {island_theorem.resonance_phrase(side, d, p, q)}"
            for w, side, d, (p, q) in found]
    return ["The ends of the attracting windows that are resonances of the island around [ac]b (`certify island "
            f"--resonances {RESONANCE_Q}`: the rotation number of the b-to-b map there is p/q, q ≤ {RESONANCE_Q}; "
            "the same algebraic number, compared exactly; ρ = 1/2 at 3−2√2 and ρ → 1/4 at r = 1 are the ends of "
            "the island's interval):", ""] + (rows or ["- none"]) + [""]


FIRST = 5                  # the words a summary line names before "…"
WIDTH = 100                # the appendix's lines (a list of words wrapped)
CELL = 400                 # the longest cell of the table of notable words (the rest: the data table)


def _names(words: list[str], by: dict, first: int | None = FIRST) -> str:
    """Compact names of ``words`` (normal forms), the first ``first`` of them, then "…"."""
    shown = [f"`{by[w]['compact'] if w in by else w}`" for w in words[:first]]
    return ", ".join(shown) + (", …" if first is not None and len(words) > first else "") or "none"


def _wrapped(words: list[str], by: dict) -> list[str]:
    """Every word of ``words``, compact, in lines of at most :data:`WIDTH` characters."""
    import textwrap
    return textwrap.wrap(_names(words, by, None), WIDTH, break_long_words=False, break_on_hyphens=False)


def _short(text: str, limit: int = CELL) -> str:
    """A cell of at most ``limit`` characters; longer, cut and sent to the data table."""
    return text if len(text) <= limit else text[:limit].rsplit(";", 1)[0] + "; … (all: " + TABLE + ")"


def summary_lines(s: dict, by: dict, recs: list) -> list[str]:
    """The summary a reader wants first (a screen): each count with its first words, the
    largest r with feasible self-similar data, the highest undecided point."""
    f, red, L = s["stable_findings"], s["reduction"], s["max_length"]
    points = sum(len((by[w].get("result") or {}).get("undecided", [])) for w in s["undecided"])
    row = lambda what, words, count=None: f"| {what} | {count or len(words)} | {_names(words, by)} |"  # noqa: E731
    return [
        "## Summary", "",
        f"{s['words']} words (classes of primitive periods of the blocks ab, cb, acb, cab of at most {L} "
        f"collisions), each analysed exactly two ways (below). All lists: the appendix; every word: {TABLE}.", "",
        "| words with | count | the first |", "|---|---:|---|",
        row("stable self-similar (collapsing) data", s["stable"]),
        row("an attracting periodic orbit of the reduction", red["attracting"]),
        row("… of which with a complex in-plane pair (not a collapse)", red["complex_pair_attracting"]),
        row("feasible self-similar data", s["feasible"]),
        row("abcab or cbacb (cyclically) and feasible self-similar data (T28)", s["abcab"]["feasible"],
            f"{len(s['abcab']['feasible'])} of {s['abcab']['words']}"),
        row("undecided self-similar points", s["undecided"], f"{len(s['undecided'])} ({points} points)"),
        row("a feasible periodic orbit of the reduction", red["feasible"]),
        row("undecided points of the reduction", red["undecided"]),
        row("an analysis error (either way)", sorted(set(s["errors"]) | set(red["errors"]))), "",
        _threshold_line(recs, by), _undecided_line(s, by),
        "- stable self-similar data other than (ab)^n(cb)^n (and the three-particle ab): "
        + (_names(f["other_than_ab_n_cb_n"], by) if f["other_than_ab_n_cb_n"] else f"none up to length {L}"),
        "",
    ]


def _threshold_line(recs: list, by: dict) -> str:
    """The largest end of every feasible self-similar set (exact) and the words reaching it."""
    highest, reached = highest_feasible(recs)
    if highest is None:
        return "- the largest r with feasible self-similar data: none (no word has feasible self-similar data)"
    end = next(e for e in feasible_ends(by[reached[0]]) if census.end_number(e) == highest)
    return (f"- the largest r with feasible self-similar data: {census.show_end(end)}, "
            f"reached by {_names(reached, by)} "
            "(the largest end of every feasible set, compared exactly; certificate T28.3 checks it on the committed "
            "census)")


def _undecided_line(s: dict, by: dict) -> str:
    """The highest undecided self-similar point (its r as printed, 10 certified digits), the
    first word with it, and how many more points share that r."""
    points = [(w, p) for w in s["undecided"] for p in (by[w].get("result") or {}).get("undecided", [])]
    if not points:
        return "- the highest undecided self-similar point: none"
    top = max(undecided_r(p) for _w, p in points)
    at_top = [(w, p) for w, p in points if undecided_r(p) == top]
    more = (f" (and {len(at_top) - 1} more points at that r, in {len({w for w, _p in at_top})} words in all)"
            if len(at_top) > 1 else "")
    return f"- the highest undecided self-similar point: {_names([at_top[0][0]], by)}, {at_top[0][1]}{more}"


def notable_lines(recs: list) -> list[str]:
    """The table of the words a reader looks at: stable, attracting, undecided, in error."""
    attracting = lambda r: bool((r.get(census.REDUCTION) or {}).get("attracting"))     # noqa: E731
    rank = lambda r: (0 if r["stable"] else 1 if attracting(r) else 2 if r["undecided"] else 3,  # noqa: E731
                      r["length"], r["word"])
    notable = sorted((r for r in recs if r["stable"] or attracting(r) or r["undecided"] or r["outcome"] == "error"
                      or (r.get(census.REDUCTION) or {}).get("outcome") == "error"), key=rank)
    lines = ["## Notable words", "",
             "The words with stable self-similar data, then with an attracting periodic orbit of the reduction, with "
             f"undecided self-similar points, in error. Every word, with its sets and exact ends: {TABLE} "
             "(docs/census.md); one word in full: `certify pattern WORD`, `certify orbit WORD`.", "",
             "| word | length | blocks | feasible r-sets | stable r-sets | attracting periodic orbit of the reduction "
             "| note |", "|---|---:|---|---|---|---|---|"]
    for r in notable:
        analysed = r["outcome"] == "analysed"
        undecided = (r.get("result") or {}).get("undecided", [])
        note = r["error"] if not analysed else (f"{len(undecided)} undecided points" if undecided else "")
        lines.append(f"| `{r['compact']}` | {r['length']} | {' '.join(r['blocks'])} | "
                     f"{_cell(_short(_sets(r, 'feasible'))) if analysed else '—'} | "
                     f"{_cell(_short(_sets(r, 'stable'))) if analysed else '—'} | "
                     f"{_cell(_short(_attracting(r)))} | {_cell(_short(note))} |")
    return lines + ([] if notable else ["| none | | | | | | |"]) + [""]


def appendix_lines(s: dict, by: dict) -> list[str]:
    """The long lists, wrapped: the words of each count of the summary."""
    red = s["reduction"]
    lists = [("with stable self-similar data", s["stable"]),
             ("with an attracting periodic orbit of the reduction", red["attracting"]),
             ("with feasible self-similar data", s["feasible"]),
             ("containing abcab or cbacb (cyclically) with feasible self-similar data (T28)", s["abcab"]["feasible"]),
             ("containing abcab or cbacb, undecided or in error", s["abcab"]["undecided_or_error"]),
             ("with undecided self-similar points", s["undecided"]),
             ("with a feasible periodic orbit of the reduction", red["feasible"]),
             ("with undecided points of the reduction", red["undecided"]),
             ("with an error of the self-similar analysis", s["errors"]),
             ("with an error of the reduction's analysis", red["errors"])]
    lines = ["## Appendix: the lists", "",
             "Each list in census order (length, then the word), compact (a power written out in census.json's "
             "`word`)."]
    for what, words in lists:
        lines += ["", f"### Words {what} ({len(words)})", ""] + (_wrapped(words, by) or ["none"])
    return lines + [""]


def markdown(doc: dict, figure: str | None = None) -> str:
    """CENSUS.md: a summary that fits a screen (the counts with their first words, the largest
    r with feasible self-similar data, the undecided points), the findings (stable self-similar
    data, then the attracting periodic orbits of the reduction), the notable words, and the
    long lists in an appendix; every word is in the table :data:`TABLE`."""
    s, recs = doc["census"], doc["words"]
    L = s["max_length"]
    by = {r["word"]: r for r in recs}
    lines = [
        f"# Census of periodic patterns up to length {L}",
        "",
        "Written by `python -m certify census --max-length "
        f"{L}` (certify/patterns/census.py, certify/run/census_report.py), or from its census.json by `python "
        f"tools/census_render.py` (the same bytes); do not edit by hand. Data: census.json, {TABLE} (docs/census.md).",
        "",
    ] + summary_lines(s, by, recs) + [
        "## What was analysed",
        "",
        "Every primitive period made of the blocks ab, cb, acb, cab (Corollary 4.5, l. 1037-1051, with the "
        "correction certified in S10), of at most "
        f"{L} collisions, one per class of rotations and the mirror a<->c (the pattern module's normal form), "
        "analysed two ways:",
        "",
        "1. **stable self-similar (collapsing) data** (`certify pattern WORD`): the r-sets in ]0, 1[ where its "
        "self-similar candidate (the velocity an eigenvector of M_w, λ > 0) realises it (feasible, per eigenvalue "
        "branch and fixed point x±) and where it is moreover stable;",
        "2. **attracting periodic orbits of the reduction** (`certify orbit WORD`): the r-intervals where the "
        "reduction map of Section 4 has an attracting periodic orbit with this word, per real eigenvalue branch, "
        "with its in-plane pair (real: it carries self-similar data; complex: not a collapse).",
        "",
        "## Findings",
        "",
        "### Stable self-similar (collapsing) data",
        "",
    ]
    f = s["stable_findings"]
    stable = [r for r in census.order(recs) if r["stable"]]
    lines += ["- stable self-similar data:"] + [f"  - `{r['compact']}` on {_sets(r, 'stable')}" for r in stable] + [
        "- stable self-similar windows reaching above 3-2√2 ≈ 0.171573 (compared on certified isolating intervals "
        "and minimal polynomials): " + (_names(f["above_3-2√2"], by) if f["above_3-2√2"] else f"none up to length {L}")
        + (f"; not decided: {_names(f['undecided_against_3-2√2'], by)}" if f["undecided_against_3-2√2"] else ""),
        "- T28 (l. 515, Remark 3.3: a pattern containing abcab 'does not seem to have feasible initial data'): "
        + (f"refuted: {len(s['abcab']['feasible'])} words contain abcab (cyclically, or its mirror cbacb) and have "
           f"feasible self-similar data, the shortest {_names(s['abcab']['feasible'], by)} (all in the appendix; "
           "certificate T28 re-checks the shortest and runs the exact dynamics from their data)"
           if s["abcab"]["feasible"] else f"no counterexample up to length {L}"),
        "",
    ]
    lines += reduction_lines(s, recs, L)
    if figure:
        lines += [f"![stable self-similar windows and attracting windows of the reduction]({figure})", ""]
    lines += notable_lines(recs) + appendix_lines(s, by)
    return "\n".join(lines).rstrip("\n") + "\n"


# --------------------------------------------------------------------------
# The figure: every stable window on one r-axis

def _floats(pairs) -> list[tuple[float, float]]:
    return [(float(lo["digits"]), float(hi["digits"])) for lo, hi in pairs]


def window_figure(doc: dict, path, marks: dict | None = None) -> Path | None:
    """The census figure (floats of certified ends: a drawing only), written through
    :mod:`.saving` (reproducible bytes) to ``path``.  Top: one row per word with stable
    self-similar data or an attracting periodic orbit of the reduction, its stable
    self-similar windows (blue) above its attracting windows of the reduction (orange:
    real in-plane pair; red: complex, not a collapse).  Bottom: on the r-axis of Figure
    5.1 (0.072-0.999), the union of the attracting windows of the words of at most L
    collisions, one row per L where it grows.  None when nothing is to be drawn."""
    from certify.numerics.figures import SPECS

    from . import saving
    plt = saving.pyplot()
    red = doc["census"].get("reduction") or {}
    rows = []
    for r in doc["words"]:
        stable = census.windows(r) if r["stable"] else []
        att = [(float(lo["digits"]), float(hi["digits"]), pair) for lo, hi, pair in census.attracting_windows(r)]
        if stable or att:
            rows.append((r["compact"], stable, att))
    if not rows:
        return None
    rows.sort(key=lambda row: (-max(hi for _lo, hi, *_ in row[1] + row[2]), row[0]))
    unions = red.get("union_by_length", [])
    fig, (ax, bx) = plt.subplots(2, 1, figsize=(7.2, 2.4 + 0.3 * len(rows) + 0.25 * len(unions)),
                                 gridspec_kw={"height_ratios": [max(len(rows), 2), max(len(unions), 2)]})
    colour = {"real": "tab:orange", "complex": "tab:red", "real and complex": "tab:red"}
    for k, (_name, stable, att) in enumerate(rows):
        for lo, hi in stable:
            ax.barh(k - 0.18, hi - lo, left=lo, height=0.34, color="tab:blue")
        for lo, hi, pair in att:
            ax.barh(k + 0.18, hi - lo, left=lo, height=0.34, color=colour[pair])
    ax.set_yticks(range(len(rows)), [name for name, _s, _a in rows], fontsize=7)
    ax.invert_yaxis()
    for label, value in (marks or {}).items():
        ax.axvline(value, color="grey", lw=0.6, ls="--")
        ax.annotate(label, (value, 1.0), xycoords=("data", "axes fraction"), fontsize=7, rotation=90,
                    va="top", ha="right")
    top = max(hi for _n, s, a in rows for _lo, hi, *_ in s + a)
    ax.set_xlim(0, min(1.0, math.ceil(top * 20 + 1) / 20))
    ax.set_xlabel("r")
    from matplotlib.patches import Patch
    ax.legend(handles=[Patch(color="tab:blue", label="stable self-similar (collapsing) data"),
                       Patch(color="tab:orange", label="attracting periodic orbit of the reduction, real pair"),
                       Patch(color="tab:red", label="attracting periodic orbit of the reduction, complex pair")],
              fontsize=6, loc="best")
    L = doc["census"]["max_length"]
    ax.set_title(f"census up to length {L}: stable self-similar windows and attracting windows of the reduction",
                 fontsize=9)
    spec = SPECS["5.1"]
    for k, u in enumerate(unions):
        for lo, hi in _floats((i["lo"], i["hi"]) for i in u["intervals"]):
            bx.barh(k, hi - lo, left=lo, height=0.6, color="tab:orange")
        for p in u["points"]:
            bx.plot([float(p["digits"])], [k], "|", color="tab:orange")
    bx.set_yticks(range(len(unions)), [f"L ≤ {u['max_length']}" for u in unions], fontsize=7)
    bx.invert_yaxis()
    bx.set_xlim(spec.lo, spec.hi)
    bx.set_xlabel(f"r (the axis of Figure {spec.id}, {spec.lo}-{spec.hi})")
    bx.set_title("r with an attracting periodic orbit of the reduction of length at most L", fontsize=9)
    fig.tight_layout()
    path = Path(path)
    with saving.output_dir(path.parent):
        saving.save_figure(fig, path.name)
    return path


# --------------------------------------------------------------------------
# The command: certify census --max-length L

FIGURE = "census-windows.png"        # next to CENSUS.md, not in figures/ (which `certify all` prunes)


def marks() -> dict:
    """The thresholds drawn on the figure: 7-4√3 (L1), 5-2√6 (T26), 3-2√2 (L2)."""
    return {"7-4√3": 7 - 4 * 3 ** 0.5, "5-2√6": 5 - 2 * 6 ** 0.5, "3-2√2": 3 - 2 * 2 ** 0.5}


def written_length(out) -> int | None:
    """The longest period of the census already in OUT/census.json, or None."""
    import json
    try:
        return int(json.loads((Path(out) / "census.json").read_text(encoding="utf-8"))["census"]["max_length"])
    except (OSError, ValueError, KeyError, TypeError):
        return None


def write_outputs(records, max_length: int, out) -> dict:
    """OUT/CENSUS.md, OUT/census.json, OUT/census-words.csv.gz (:data:`TABLE`) and
    OUT/census-windows.png from the census records (analysed, or read back from a
    census.json: the same bytes, :func:`brief`); returns the document."""
    out = Path(out)
    doc = document(records, max_length)
    drawn = window_figure(doc, out / FIGURE, marks())
    if drawn is None and (out / FIGURE).exists():
        (out / FIGURE).unlink()
    write_atomic(out / "CENSUS.md", markdown(doc, FIGURE if drawn else None))
    write_atomic(out / "census.json", to_json(doc))
    write_atomic(out / TABLE, table(doc))
    return doc
