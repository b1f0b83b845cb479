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

import json
import math
from concurrent.futures import FIRST_COMPLETED, wait
from pathlib import Path

from certify.patterns import census
from .files import read_text_or_none, write_atomic

WINDOW = 64                  # jobs in flight at once (an interruption loses at most these)


def dumps(record: dict) -> str:
    """One record as one line of JSON (sorted keys: the same bytes everywhere)."""
    return json.dumps(record, sort_keys=True, ensure_ascii=False, separators=(",", ":"))


def load_state(path) -> dict[str, dict]:
    """The records of a state file, by word; a line that does not parse (cut by an
    interruption) is dropped, and the file is rewritten without it."""
    text = read_text_or_none(path)
    if text is None:
        return {}
    records, kept, cut = {}, [], False
    for line in text.splitlines():
        try:
            rec = json.loads(line)
            rec.pop(census.SECONDS, None)
            records[rec["word"]] = rec
            kept.append(line)
        except (ValueError, KeyError, TypeError):
            cut = True
    if cut or (text and not text.endswith("\n")):
        write_atomic(path, "".join(line + "\n" for line in kept))
    return records


def run_census(max_length: int, executor, state=None, resume: bool = False, progress=None,
        job=census.analyse_word, window: int = WINDOW) -> list[dict]:
    """The census records of every word up to ``max_length``, in census order.

    ``state``: a JSON-lines file the records are appended to as they finish (created,
    or emptied unless ``resume``).  ``resume``: reuse the records found in ``state``.
    ``progress(k, n, word)`` after each word.  ``job(word)`` is what runs on the
    executor (a module-level function: it may cross processes or machines)."""
    wanted = census.words(max_length)
    done = {}
    if state is not None:
        state = Path(state)
        if resume:
            done = {w: rec for w, rec in load_state(state).items() if w in set(wanted)}
        else:
            write_atomic(state, "")
    todo = [w for w in wanted if w not in done]       # shortest first: a cut census is complete up to a length
    n = len(wanted)
    if progress:
        progress(len(done), n, "")
    sink = state.open("a", encoding="utf-8") if state is not None else None

    def collect(future, word) -> None:
        record = future.result()
        if sink is not None:
            sink.write(dumps(record) + "\n")
            sink.flush()
        record.pop(census.SECONDS, None)
        done[word] = record
        if progress:
            progress(len(done), n, word)

    try:
        pending, words_of, queue = set(), {}, iter(todo)
        while True:
            while len(pending) < window:
                word = next(queue, None)
                if word is None:
                    break
                future = executor.submit(job, word)
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
            finished, pending = wait(pending, timeout=0.5, return_when=FIRST_COMPLETED)
            for future in sorted(finished, key=lambda f: words_of[f]):
                collect(future, words_of.pop(future))
    finally:
        if sink is not None:
            sink.close()
    return census.order(done[w] for w in wanted)


def document(records, max_length: int) -> dict:
    """The census as one JSON document: the summary, then every record."""
    return {"census": census.summary(records, max_length), "words": census.order(records)}


def to_json(doc: dict) -> str:
    return json.dumps(doc, sort_keys=True, ensure_ascii=False, indent=1) + "\n"


# --------------------------------------------------------------------------
# CENSUS.md

def _cell(text: str) -> str:
    return str(text).replace("|", "\\|").replace("\n", " ")


def _sets(record: dict, key: str) -> str:
    sets = census.r_sets(record, key)
    return "; ".join(f"{name}: {text}" for name, text in sets) or "∅"


def markdown(doc: dict, figure: str | None = None) -> str:
    """CENSUS.md: what was enumerated, the findings, then one row per word, the words
    with feasible data first, then the undecided, the errors, the rest."""
    s, recs = doc["census"], doc["words"]
    L = s["max_length"]
    rank = lambda r: (0 if r["stable"] else 1 if r["feasible"] else 2 if r["undecided"] else  # noqa: E731
                      3 if r["outcome"] == "error" else 4, r["length"], r["word"])
    lines = [
        f"# Census of periodic patterns up to length {L}",
        "",
        "Written by `python -m certify census --max-length "
        f"{L}` (certify/patterns/census.py, certify/run/census_report.py); do not edit by hand.",
        "",
        "Every primitive period made of the blocks ab, cb, acb, cab (Corollary 4.5, l. 1037-1051, with the "
        "correction certified in S10), of at most "
        f"{L} collisions, one per class of rotations and the mirror a<->c (the pattern module's normal form). "
        "For each, the r-sets in ]0, 1[ where its self-similar candidate realises it (feasible, per eigenvalue "
        "branch and fixed point x±) and where it is moreover stable, as certified by `certify pattern WORD`.",
        "",
        f"- words: {s['words']}",
        f"- with feasible self-similar data: {len(s['feasible'])}",
        f"- with stable self-similar data: {len(s['stable'])}",
        f"- with undecided points: {len(s['undecided'])}" + (f" ({', '.join(s['undecided'])})" if s['undecided'] else ""),
        f"- analysis error: {len(s['errors'])}" + (f" ({', '.join(s['errors'])})" if s['errors'] else ""),
        f"- containing abcab cyclically (or its mirror cbacb): {s['abcab']['words']}, of which with feasible data: "
        f"{len(s['abcab']['feasible'])}" + (f" ({', '.join(s['abcab']['feasible'])})" if s['abcab']['feasible'] else "")
        + (f"; undecided or error: {', '.join(s['abcab']['undecided_or_error'])}"
           if s['abcab']['undecided_or_error'] else ""),
        "",
        "## Findings",
        "",
    ]
    f = s["stable_findings"]
    stable = [r for r in census.order(recs) if r["stable"]]
    lines += [
        "- stable patterns: " + ("; ".join(f"`{r['compact']}` on {_sets(r, 'stable')}" for r in stable) or "none"),
        "- stable patterns other than (ab)^n(cb)^n (and the three-particle ab): "
        + (", ".join(f"`{w}`" for w in f["other_than_ab_n_cb_n"]) or f"none up to length {L}"),
        "- stable windows reaching above 3-2√2 ≈ 0.171573 (compared on certified isolating intervals and minimal "
        "polynomials): " + (", ".join(f"`{w}`" for w in f["above_3-2√2"]) or f"none up to length {L}")
        + (f"; not decided: {', '.join(f['undecided_against_3-2√2'])}" if f["undecided_against_3-2√2"] else ""),
        "- T28 (l. 515, 'patterns containing abcab do not seem to have feasible self-similar data'): "
        + (f"refuted: {', '.join(f'`{w}`' for w in s['abcab']['feasible'])} contain abcab (cyclically, or its "
           "mirror cbacb) and have feasible self-similar data (certificate T28 re-checks the shortest and runs "
           "the exact dynamics from their data)" if s["abcab"]["feasible"]
           else f"no counterexample up to length {L}"),
        "",
    ]
    if figure:
        lines += [f"![every stable window on one r-axis]({figure})", ""]
    lines += ["## Every word", "", "Words with stable data first, then feasible, undecided, in error, the rest.", "",
              "| word | length | blocks | abcab | verdict | feasible r-sets | stable r-sets | note |",
              "|---|---:|---|:-:|---|---|---|---|"]
    for r in sorted(recs, key=rank):
        note = r["error"] if r["outcome"] == "error" else ("undecided points" if r["undecided"] else "")
        lines.append(f"| `{r['compact']}` | {r['length']} | {' '.join(r['blocks'])} | "
                     f"{'yes' if r['contains_abcab'] else ''} | {_cell(r['verdict'])} | "
                     f"{_cell(_sets(r, 'feasible')) if r['outcome'] == 'analysed' else '—'} | "
                     f"{_cell(_sets(r, 'stable')) if r['outcome'] == 'analysed' else '—'} | {_cell(note)} |")
    return "\n".join(lines) + "\n"


# --------------------------------------------------------------------------
# The figure: every stable window on one r-axis

def window_figure(doc: dict, path, marks: dict | None = None) -> Path | None:
    """One row per word with stable data, its stable windows drawn as bars on the r-axis
    (floats of certified ends: a drawing only); written atomically to ``path`` (PNG).
    Returns the path, or None when no word has stable data."""
    from .saving import pyplot
    plt = pyplot()
    from .saving import DPI
    from .files import atomic_path

    rows = [(r["compact"], census.windows(r)) for r in doc["words"] if r["stable"]]
    rows = [(name, w) for name, w in rows if w]
    if not rows:
        return None
    rows.sort(key=lambda row: (-max(hi for _, hi in row[1]), row[0]))
    fig, ax = plt.subplots(figsize=(7.2, 1.2 + 0.28 * len(rows)))
    for k, (name, wins) in enumerate(rows):
        for lo, hi in wins:
            ax.barh(k, hi - lo, left=lo, height=0.6, color="tab:blue")
    ax.set_yticks(range(len(rows)), [name for name, _ in rows], fontsize=7)
    ax.invert_yaxis()
    for label, value in (marks or {}).items():
        ax.axvline(value, color="grey", lw=0.6, ls="--")
        ax.annotate(label, (value, 1.0), xycoords=("data", "axes fraction"), fontsize=7, rotation=90,
                    va="top", ha="right")
    top = max(hi for _, w in rows for _, hi in w)
    ax.set_xlim(0, min(1.0, math.ceil(top * 20 + 1) / 20))
    ax.set_xlabel("r")
    ax.set_title(f"stable windows of the census up to length {doc['census']['max_length']}", fontsize=9)
    fig.tight_layout()
    path = Path(path)
    try:
        with atomic_path(path) as tmp:
            fig.savefig(tmp, format="png", dpi=DPI, metadata={"Software": None})
    finally:
        plt.close(fig)
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
    """OUT/CENSUS.md, OUT/census.json and OUT/census-windows.png; returns the document."""
    out = Path(out)
    doc = document(records, max_length)
    drawn = window_figure(doc, out / FIGURE, marks())
    if drawn is None and (out / FIGURE).exists():
        (out / FIGURE).unlink()
    write_atomic(out / "CENSUS.md", markdown(doc, FIGURE if drawn else None))
    write_atomic(out / "census.json", to_json(doc))
    return doc
