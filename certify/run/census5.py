"""The five-particle census (issue 39): every word class of :func:`certify.patterns.five.word_classes`
up to a length, each analysed by :func:`certify.patterns.five.census_record` (the κ route of
``certify pattern``), streamed to a state file through :func:`.census_report.run_census` (any
executor, ``--resume``), and written atomically as DIR/CENSUS5.md and DIR/census5.json
(schema certify/schemas/census5.schema.json).

The summary is computed from the records alone (:func:`document`), so a file rendered from a state
and one from a fresh run are the same bytes; :func:`check` analyses the words again and compares
each record, and recomputes the summary from the committed records.  The largest r are exact
(algebraic numbers compared exactly: :func:`certify.algebra.branches.less`); they are certified for
the factors of cp(Λ²M) that were analysed: the factors not analysed are listed, word by word.
"""
from __future__ import annotations

import json
from pathlib import Path

from certify.algebra.branches import less
from certify.patterns import five, five_orbits
from certify.patterns.census import REDUCTION, REDUCTION_SECONDS, SECONDS
from certify.patterns.island_theorem import algebraic_of

from . import census_report
from .files import write_atomic

SCHEMA = "certify-census5"
VERSION = 2          # 2: each record has its part on the periodic orbits of the reduction (REDUCTION)
JSON = "census5.json"
MARKDOWN = "CENSUS5.md"
STAGES = ("stable", "feasible", "undecided")
MARK = "engine"      # a state record's engine (:func:`record`); census5.json's records do not carry it
ENGINE = 3           # the engine of five.census_record: raise it when a change alters a record (its content or
                     # its keys), and say in CHANGED which records of the engine before it alters
UNMARKED = 1         # a state record without the mark is taken as engine 1's: the engine of the committed census to
                     # 9 and of the states written before the mark (docs/census.md, "Five particles": why)
# engine e -> the records of engine e - 1 that engine e alters (a resume analyses those again, :func:`current`).
# 2: five.REPEATED_ROUTE analyses the repeated factors of cp(Λ²M), which engine 1 listed in "not_analysed"
# (every other record is made by the same code: five_candidate and its requirements are unchanged).
# 3: the part on the periodic orbits of the reduction (REDUCTION, five_orbits.census_part) is added to every
# record; the self-similar part is unchanged, so an older record is kept and completed (:func:`complete`).
CHANGED = {2: lambda rec: bool(rec["not_analysed"]), 3: lambda rec: False}


def record(word: str) -> dict:
    """:func:`certify.patterns.five.census_record` of ``word`` and its :data:`REDUCTION` part, marked with
    :data:`ENGINE` (the state's records carry the mark, census5.json's do not: :func:`run` drops it).  The
    two parts share the word's sextic and candidates (:func:`certify.patterns.five.built`)."""
    shared: dict = {}
    return complete(five.census_record(word, shared), shared)


def complete(rec: dict, shared: dict | None = None) -> dict:
    """The record with its :data:`REDUCTION` part (:func:`certify.patterns.five_orbits.census_part`, the
    periodic orbits of the five-particle reduction) computed, its CPU seconds in :data:`REDUCTION_SECONDS`
    (state file only), marked with :data:`ENGINE`; the self-similar part is left as it is: a state record
    of an older engine, which lacks the part, is completed without redoing the rest."""
    import time
    start = time.process_time()
    part = five_orbits.census_part(rec["word"], shared)
    return {**rec, REDUCTION: part, REDUCTION_SECONDS: round(time.process_time() - start, 3), MARK: ENGINE}


def current(rec: dict) -> bool:
    """Whether a state record is this engine's record: its mark (:data:`UNMARKED` when it has none) is
    :data:`ENGINE`, or an older engine's that no engine since alters (:data:`CHANGED`)."""
    mark = rec.get(MARK, UNMARKED)
    return mark == ENGINE or (mark < ENGINE and not any(CHANGED[e](rec) for e in range(mark + 1, ENGINE + 1)))


def run(max_length: int, executor, state=None, resume: bool = False, progress=None, notice=None) -> list[dict]:
    """The records of every class up to ``max_length``, in census order (shortest first, then
    lexicographic), without their seconds and mark; the state file and ``resume`` as the four-particle
    census's, except that a state record made by another engine (:func:`current`) is analysed again:
    ``notice(text)`` says how many, before the first word."""
    stale: list[str] = []

    def reused(rec: dict) -> bool:
        if current(rec):
            return True
        stale.append(rec["word"])
        return False

    def told(k: int, n: int, word: str) -> None:
        if notice is not None and stale:
            notice(f"{len(stale)} state record(s) made by another engine than {ENGINE} "
                   f"(first {stale[0]}): analysed again")
            stale.clear()
        if progress:
            progress(k, n, word)

    records = census_report.run_census(max_length, executor, state, resume, told, job=record,
                                       complete=complete, words=five.word_classes, current=reused)
    return [{k: v for k, v in rec.items() if k not in (MARK, REDUCTION_SECONDS)} for rec in records]


def _largest(records: list[dict], stage: str, part=lambda rec: rec) -> dict | None:
    """{"r": end, "word": w} for the largest ``top[stage]`` of ``part(record)`` over the records (exact
    comparison; the first word in census order on a tie), or None."""
    best, value = None, None
    for rec in records:
        end = part(rec)["top"][stage]
        if end is None:
            continue
        a = algebraic_of(end)
        if value is None or less(value, a):
            best, value = {"r": end, "word": rec["word"]}, a
    return best


def document(records: list[dict], max_length: int) -> dict:
    """census5.json: the summary (counts by length, the largest r of stable and of feasible
    self-similar collapse and the largest undecided point, the stable words and their windows, the
    words with a factor of cp(Λ²M) not analysed) and the records (without seconds)."""
    records = [{k: v for k, v in rec.items() if k not in (SECONDS, REDUCTION_SECONDS)} for rec in records]
    lengths: dict = {}
    for rec in records:
        entry = lengths.setdefault(str(rec["length"]), {"words": 0, "exists": 0, "feasible": 0, "stable": 0,
                                                        "undecided": 0, "not_analysed": 0, "orbit_feasible": 0,
                                                        "orbit_attracting_real": 0, "orbit_attracting_complex": 0})
        entry["words"] += 1
        for key in ("exists", "feasible", "stable", "undecided", "not_analysed"):
            entry[key] += bool(rec[key])
        for key in ("feasible", "attracting_real", "attracting_complex"):
            entry[f"orbit_{key}"] += bool(rec[REDUCTION][key])
    summary = {"particles": 5, "max_length": max_length, "words": len(records), "lengths": lengths,
               "stable_words": [{"word": r["word"], "windows": r["stable"]} for r in records if r["stable"]],
               "feasible_words": [r["word"] for r in records if r["feasible"]],
               "not_analysed": [{"word": r["word"], "factors": r["not_analysed"]} for r in records
                                if r["not_analysed"]],
               "undecided_words": len([r for r in records if r["undecided"]]),
               "stable_complete": all(f["multiplicity"] > 1 for r in records for f in r["not_analysed"])}
    for stage in STAGES:
        summary[f"largest_{stage}"] = _largest(records, stage)
    summary["attracting_orbits"] = [{"word": r["word"], "real": r[REDUCTION]["attracting_real"],
                                     "complex": r[REDUCTION]["attracting_complex"]} for r in records
                                    if r[REDUCTION]["attracting_real"] or r[REDUCTION]["attracting_complex"]]
    for key in ("attracting_real", "attracting_complex"):
        summary[f"largest_orbit_{key}"] = _largest(records, key, lambda rec: rec[REDUCTION])
    return {"schema": SCHEMA, "version": VERSION, "census": summary, "words": records}


def to_json(doc: dict) -> str:
    return json.dumps(doc, ensure_ascii=False, indent=1, sort_keys=True) + "\n"


def _end(best: dict | None) -> str:
    if best is None:
        return "none"
    r = best["r"]
    exact = r["exact"] if r["exact"] is not None else (f"the root of {r['minimal_polynomial']} in "
                                                        f"]{r['interval'][0]}, {r['interval'][1]}[")
    return f"≈{r['digits']} ({exact}), {best['word']}"


def markdown(doc: dict) -> str:
    """CENSUS5.md: the certified answers first, then the counts by length, the stable and feasible
    words, and what is not decided."""
    s = doc["census"]
    L = s["max_length"]
    lines = [f"# The five-particle census to {L} collisions", "",
             f"Written by `certify census --particles 5 --max-length {L} --out DIR`; checked by "
             f"`certify census --particles 5 --check` (docs/census.md).  {s['words']} word classes (rotations, "
             "mirror image a<->d, b<->c; every pair used, no pair twice in a row, not a proper power), each "
             "analysed exactly over ]0, 1[ by the κ = λμ route of `certify pattern` (docs/pattern.md, \"five "
             "particles\").", "",
             "## Certified answers", "",
             f"- Largest r of stable self-similar collapse up to {L}: {_end(s['largest_stable'])}",
             f"- Largest r of feasible self-similar collapse up to {L}: {_end(s['largest_feasible'])}",
             f"- Largest undecided point (stable stage): {_end(s['largest_undecided'])}",
             f"- Largest r of an attracting periodic orbit of the five-particle reduction up to {L}, real in-plane "
             f"pair: {_end(s['largest_orbit_attracting_real'])}",
             f"- Largest r of an attracting periodic orbit of the reduction up to {L}, complex in-plane pair (not a "
             f"collapse): {_end(s['largest_orbit_attracting_complex'])}", "",
             "These hold on ]0, 1[ less the words' undecided points, each an isolated r (an end of a region where "
             "two κ branches meet, or 0/0) listed in census5.json"
             + (", and less the factors not analysed (below), on the whole range: there nothing is claimed but what "
                "is proved of a repeated factor (never stable)." if s["not_analysed"] else
                ".  Every factor of cp(Λ²M) is analysed: a repeated one (κ = ±r^(n/2), of multiplicity 2) by the "
                "route of certify.patterns.five.REPEATED_ROUTE (existence and feasibility on its two planes; never "
                "stable: REPEATED_NOT_STABLE)."), "",
             "The periodic orbits of the reduction are the second way (`certify orbit WORD`, "
             "certify/patterns/five_orbits.py): a plane Π with Λ²M Π = κΠ, κ > 0, in the face of the last letter, "
             "whose run follows the word; attracting when κ = λμ strictly dominates the other products of two "
             "eigenvalues (less the undecided points of that part, in census5.json).  With a real pair λ, μ > 0 "
             "whose datum exists it is the stable self-similar collapse; with a complex pair it is not a collapse.  "
             "A repeated factor of cp(Λ²M) is never attracting, so these largest r hold for every word; the counts "
             "of feasible orbits are those of the factors analysed (a repeated κ = κ₀ > 0 is not: "
             f"{sum(bool(r[REDUCTION]['not_analysed']) for r in doc['words'])} words).", ""]
    if s["not_analysed"]:
        lines += [f"{len(s['not_analysed'])} words have a factor of cp(Λ²M) that was not analysed (listed below). "
                  + ("Each is a repeated factor, which holds no stable datum (proved: "
                     "certify.patterns.five.REPEATED_NOT_STABLE), so the largest r of stable collapse holds for every "
                     "word; the largest r of feasible collapse holds for the factors analysed only."
                     if s["stable_complete"] else "Both largest r hold for the factors analysed only."), ""]
    lines += ["## By length", "", "| length | words | exists (factors analysed) | feasible (factors analysed) | "
              "stable | with undecided points | with a factor not analysed | orbit of the reduction feasible | "
              "attracting, real pair | attracting, complex pair |", "|" + "---:|" * 10]
    lines += [f"| {n} | {e['words']} | {e['exists']} | {e['feasible']} | {e['stable']} | {e['undecided']} | "
              f"{e['not_analysed']} | {e['orbit_feasible']} | {e['orbit_attracting_real']} | "
              f"{e['orbit_attracting_complex']} |" for n, e in sorted(s["lengths"].items(), key=lambda ne: int(ne[0]))]
    union = "(each the r-set of one κ branch and ordering x₊ or x₋; the same set for several is shown once)"
    lines += ["", "## Stable words", "", union, ""]
    lines += [f"- {w['word']}: {'; '.join(dict.fromkeys(w['windows']))}" for w in s["stable_words"]] or ["None."]
    lines += ["", "## Feasible words", "", union, ""]
    by = {r["word"]: r for r in doc["words"]}
    lines += [f"- {w}: {'; '.join(dict.fromkeys(by[w]['feasible']))}" for w in s["feasible_words"]] or ["None."]
    lines += ["", "## Attracting periodic orbits of the reduction", "",
              "(per κ branch: where the plane's periodic orbit attracts, with a real or a complex in-plane pair)", ""]
    lines += [f"- {a['word']}: " + "; ".join([f"real pair {t}" for t in a["real"]]
                                            + [f"complex pair {t}" for t in a["complex"]])
              for a in s["attracting_orbits"]] or ["None."]
    lines += ["", "## Not analysed", ""]
    lines += [f"- {n['word']}: " + "; ".join(f"{f['factor']} of multiplicity {f['multiplicity']}, stable: {f['stable']}"
                                          for f in n["factors"]) for n in s["not_analysed"]] or ["None."]
    lines += ["", f"{s['undecided_words']} words have undecided points (ends of regions where branches meet, "
              "0/0, or a factor not analysed); `certify pattern WORD` lists them, and census5.json keeps them.", ""]
    return "\n".join(lines)


def write_outputs(records: list[dict], max_length: int, out) -> dict:
    """DIR/census5.json and DIR/CENSUS5.md, atomically; returns the document."""
    out = Path(out)
    doc = document(records, max_length)
    write_atomic(out / JSON, to_json(doc))
    write_atomic(out / MARKDOWN, markdown(doc))
    return doc


def written_length(out) -> int | None:
    """The longest period of the census already in DIR/census5.json, or None."""
    try:
        return int(json.loads((Path(out) / JSON).read_text(encoding="utf-8"))["census"]["max_length"])
    except (OSError, ValueError, KeyError, TypeError):
        return None


def check(out, executor, max_length: int | None = None, progress=None) -> list[str]:
    """The differences between DIR/census5.json (and CENSUS5.md) and a recomputation: every record up
    to ``max_length`` (default: the census's) analysed again and compared; the summary and the Markdown
    recomputed from the committed records and compared.  An empty list: the files stand."""
    out = Path(out)
    try:
        doc = json.loads((out / JSON).read_text(encoding="utf-8"))
        L = int(doc["census"]["max_length"])
    except (OSError, ValueError, KeyError, TypeError) as exc:
        return [f"{out / JSON}: cannot read the census ({exc})"]
    problems = []
    again = document(doc["words"], L)
    if again["census"] != doc["census"]:
        problems.append("the summary differs from the one recomputed from the records")
    if (out / MARKDOWN).is_file() and (out / MARKDOWN).read_text(encoding="utf-8") != markdown(doc):
        problems.append(f"{MARKDOWN} differs from the one rendered from {JSON}")
    upto = L if max_length is None else min(L, max_length)
    fresh = run(upto, executor, progress=progress)
    committed = {r["word"]: r for r in doc["words"] if r["length"] <= upto}
    if [r["word"] for r in fresh] != list(committed):
        problems.append(f"the word classes to {upto} differ from the committed ones")
    for rec in fresh:
        old = committed.get(rec["word"])
        if old is not None and old != rec:
            keys = sorted(k for k in set(rec) | set(old) if rec.get(k) != old.get(k))
            problems.append(f"{rec['word']}: the record differs ({', '.join(keys)})")
    return problems
