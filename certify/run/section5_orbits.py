"""``certify identify --section5``: the orbits behind Section 5's discrete ω-limit sets,
classified once and committed (reports/section5-orbits.json).

For each r of :data:`PLAN` (the places where the paper sees discrete ω-limit sets, N2
near r = 1, N5 in 0.172-0.176, N6 at r ≈ 0.184525 and its stripes, and N2's region of
apparent chaos, 0.2 ≤ r ≤ 0.9), the tool's grid of 8 initial data (the paper does not
print its own) is classified by :func:`certify.run.identify.classify`: *island*
(quasi-periodic for ever, proved), *attracting periodic* (follows its word for ever,
proved) or *unresolved* (what the float64 run shows, observed).  Each word the float64
runs settle on is also decided exactly at r by
:func:`certify.patterns.reduction_orbits.orbit_at` (its type, in-plane pair and
multiplier modulus); its attracting window over ]0, 1[ (``certify orbit``) is added for
words of at most :data:`WINDOW_MAX` letters.  No timing is written (the file is committed).

The format (schema ``certify-section5-orbits``, version 2, certify/schemas/section5-orbits.schema.json)::

    {"schema", "version", "command", "grid", "period_search",
     "claims": {"N2" | "N5" | "N6": [
        {"r": "99/100", "collisions": 100000, "orbits": 8,
         "classes": {"island": k, "attracting periodic": m, "unresolved": u},
         "classified": [{"theta0", "phi0", "class", "certified_from", "word" (certified), "rotation",
                         "observed" (the word the float64 run repeats, or null)}]  (one per orbit),
         "words": [{"word": normal form, "compact", "period", "count" (orbits observed to settle on it),
                    "certified" (orbits proved to follow it for ever),
                    "kind": attracting | saddle | repelling | "" (no orbit, or modulus 1),
                    "branch", "pair": real | complex, "failed": the first condition that fails,
                    "modulus": the largest multiplier modulus (decimal, a certified ball's midpoint),
                    "modulus_one": |ν| = 1 exactly (λ³ = det M_w, a complex pair),
                    "window": {"branch", "pair", "lo", "hi"} (ends as in `orbit --json`) | null}],
         "unsettled": number of orbits with no word analysed (no period within the collisions, or a
                      block too long: an island orbit's quasi-period),
         "breaks": number of orbits that stopped on a break}]}}

What is certified and what is observed: a word is observed (the float64 run) unless an
orbit is proved to follow it for ever (``certified`` > 0); its type at r and its window
are exact; the classes island and attracting periodic are proved.  The certificates of
Section 5 (proofs) re-decide each committed word at its r with ``orbit_at``
(milliseconds) and re-check each committed class by the second route of
:func:`certify.run.identify.verify` (the state at the committed collision), so
``certify all`` never simulates for this.
"""
from __future__ import annotations

import json
from fractions import Fraction

import flint

from certify import caches
from certify.algebra.algebraic import Algebraic
from certify.errors import UsageError
from certify.numerics import grid
from certify.patterns import compact, read
from certify.patterns.reduction_orbits import orbit_at

from . import identify as ident
from .files import write_atomic
from .identify import orbit_analysis, window_at
from .runner import EXPLANATION, OBSERVATION, Check

FINDINGS = "section5-orbits.json"
SCHEMA = "certify-section5-orbits"
VERSION = 2
# the attracting window over ]0, 1[ (certify orbit) for words up to this length (minutes beyond)
WINDOW_MAX = 24
COMMAND = "python -m certify identify --section5"
PERIOD_SEARCH = ("the shortest period of the last half of each float64 run, at most a quarter of that half "
                 "(4 periods at least)")

# claim -> [(r, collisions)]: where the paper sees discrete ω-limit sets, and N2's apparent chaos
PLAN = {
    "N2": [(r, 10_000) for r in ("1/5", "3/10", "2/5", "1/2", "3/5", "7/10", "4/5", "9/10")]
          + [(r, 100_000) for r in ("9/10", "49/50", "99/100", "199/200", "999/1000")],
    "N5": [(r, 10_000) for r in ("43/250", "173/1000", "87/500", "7/40", "22/125")] + [("173/1000", 100_000)],
    "N6": [(r, 10_000) for r in ("7381/40000", "369/2000", "237/1250")],
}


def word_entry(normal: str, count: int, certified: int, r: Fraction) -> dict:
    """One word seen at r: its exact decision at r (``orbit_at``: the feasible branch, else
    the first), and its attracting window containing r for short words."""
    points = orbit_at(normal, flint.fmpq(r.numerator, r.denominator))
    o = next((x for x in points if x.feasible), points[0] if points else None)
    entry = {"word": normal, "compact": compact(normal), "period": len(normal), "count": count,
             "certified": certified,
             "kind": o.kind if o else "", "branch": o.branch_name if o else "", "pair": o.pair if o else "",
             "failed": o.failed if o else "no real eigenvalue", "modulus": o.modulus.str(8, radius=False) if o else "",
             "modulus_one": bool(o and o.modulus_one), "window": None}
    if len(normal) <= WINDOW_MAX:
        window, _why = window_at(orbit_analysis(normal), Algebraic.rational(flint.fmpq(r.numerator, r.denominator)))
        entry["window"] = window
    return entry


def at(r: Fraction, collisions: int, orbits: int = 8) -> dict:
    """The tool's first ``orbits`` initial data at r: each orbit classified, and the words
    the float64 runs settle on, decided exactly."""
    theta0, phi0 = grid(orbits)
    counts, certified, unsettled, breaks, classified = {}, {}, 0, 0, []
    for t, p in zip(theta0, phi0):
        x = ident.classify(r, float(t), float(p), collisions)
        classified.append({"theta0": x.theta0, "phi0": x.phi0, "class": x.cls, "certified_from": x.certified_from,
                           "word": x.word if x.cls == ident.ATTRACTING else None, "rotation": x.rotation,
                           "observed": x.word})
        if x.breaks:
            breaks += 1
            continue
        try:
            normal = read(x.word)[0] if x.word else None
        except UsageError:
            normal = None
        if normal is None:
            unsettled += 1
            continue
        counts[normal] = counts.get(normal, 0) + 1
        certified[normal] = certified.get(normal, 0) + (x.cls == ident.ATTRACTING)
    words = [word_entry(w, k, certified[w], r) for w, k in sorted(counts.items(), key=lambda x: (-x[1], x[0]))]
    classes = {c: sum(o["class"] == c for o in classified) for c in ident.CLASSES}
    return {"r": str(r), "collisions": collisions, "orbits": orbits, "classes": classes, "classified": classified,
            "words": words, "unsettled": unsettled, "breaks": breaks}


def findings(plan=None, progress=None) -> dict:
    """Run the plan (:data:`PLAN`): the findings in the module docstring's format (no
    timing: the file is committed); ``progress(k, n, label)`` after each r."""
    plan = plan or PLAN
    claims, total, done = {}, sum(len(points) for points in plan.values()), 0
    for claim, points in plan.items():
        claims[claim] = []
        for r, collisions in points:
            claims[claim].append(at(Fraction(r), collisions))
            done += 1
            if progress is not None:
                progress(done, total, f"{claim} r = {r}")
    return {"schema": SCHEMA, "version": VERSION, "command": COMMAND, "grid": ident.GRID,
            "period_search": PERIOD_SEARCH, "claims": claims}


def write(found: dict, directory) -> str:
    """Write the findings to ``directory``/section5-orbits.json atomically; the path."""
    from pathlib import Path
    path = Path(directory) / FINDINGS
    write_atomic(path, json.dumps(found, ensure_ascii=False, indent=1, sort_keys=True) + "\n")
    return str(path)


# ------------------------------------------------------------------ the certificates' side
def load(source, claim: str) -> dict | None:
    """The committed findings: ``source`` the file name under reports/, or ``(name, edits)``
    with ``edits`` applied to the first entry of ``claim`` that has a word (``word``: its
    first word replaced; ``r``: its r replaced): an altered finding, for the mutation tests."""
    from .files import load_findings
    name, edits = (source, {}) if isinstance(source, str) else source
    found = load_findings(name)
    if not found or not edits:
        return found
    found = json.loads(json.dumps(found))
    for e in found["claims"].get(claim, []):
        if e["words"]:
            if "word" in edits:
                e["words"][0]["word"] = edits["word"]
            if "r" in edits:
                e["r"] = edits["r"]
            return found
    return found


def _end(e: dict) -> str:
    return e["exact"] if e["exact"] is not None else "≈" + e["digits"][:8]


def _inside(r: flint.fmpq, window: dict) -> bool:
    """lo < r < hi, exactly: each end rational, or a root isolated in a rational interval
    that r lies strictly beyond (the committed end data of `orbit --json`)."""
    def cmp(e):                       # the sign of r - e, 0 when undecided by the interval
        if e["exact"] is not None:
            x = flint.fmpq(Fraction(e["exact"]).numerator, Fraction(e["exact"]).denominator)
            return (r > x) - (r < x)
        lo, hi = (flint.fmpq(Fraction(v).numerator, Fraction(v).denominator) for v in e["interval"])
        return 1 if r > hi else -1 if r < lo else 0
    return cmp(window["lo"]) > 0 and cmp(window["hi"]) < 0


def _modulus(o) -> str:
    """The certified largest multiplier modulus, as 1 + a ball near 1."""
    if o is None:
        return "-"
    if o.modulus_one:
        return "exactly 1"
    m = o.modulus
    return f"1 + {(m - 1).str(3)}" if abs(m - 1) < 1e-3 else m.str(6)


def decide(entry: dict, word: dict) -> tuple[bool, str, list[str]]:
    """(holds, statement, evidence): the committed word re-decided exactly at the committed r."""
    r_ = Fraction(entry["r"])
    r = flint.fmpq(r_.numerator, r_.denominator)
    w, k, n = word["word"], word["count"], entry["orbits"]
    try:
        normal = read(w)[0]
        points = ident.orbits_at(normal, r)
    except UsageError as exc:             # a word the grammar refuses: the finding cannot stand
        return False, (f"{EXPLANATION} at r = {entry['r']}, {k} of {n} orbits settle on {w}: "
                       f"cannot be decided ({exc})"), []
    o = next((x for x in points if x.feasible), None)
    proved = word.get("certified", 0)
    seen = (f"at r = {entry['r']}, {k} of {n} orbits settle on {w} in float64 (period {len(w)}; "
            f"{entry['collisions']} collisions; observed" +
            (f", and {proved} of them certified to follow it for ever" if proved else "") + ")")
    modulus = f"largest multiplier modulus {_modulus(o)}"
    if word["kind"] == "attracting":
        window = word["window"]
        holds = (normal == w and o is not None and o.kind == "attracting" and o.pair == word["pair"]
                 and o.branch_name == word["branch"] and (window is None or _inside(r, window)))
        where = f"; its window ]{_end(window['lo'])}, {_end(window['hi'])}[" if window else ""
        pair = "complex in-plane pair: not a collapse" if word["pair"] == "complex" else "real in-plane pair"
        text = (f"{EXPLANATION} {seen}, an attracting periodic orbit of the reduction "
                f"({word['branch']} branch, {pair}, "
                f"{modulus}), certified at r exactly{where}")
    elif word["kind"] in ("saddle", "repelling"):
        holds = normal == w and o is not None and o.kind == word["kind"] and not o.modulus_one
        kind = "a saddle" if word["kind"] == "saddle" else "repelling"
        text = (f"{EXPLANATION} {seen}: its periodic orbit of the reduction is {kind} "
                f"at r ({word['pair']} in-plane pair, {modulus}), certified at r exactly: the orbits are still a "
                "transient in that word after the collisions run, not on an attracting periodic orbit")
    else:
        holds = normal == w and o is None and any(x.modulus_one for x in points) == word["modulus_one"]
        one = ("; its eigen-normal's multipliers have modulus exactly 1 (λ³ = det M_w)" if word["modulus_one"] else "")
        failed = word["failed"] or "a condition"
        where = (f"lies on the boundary of the word's cell, {failed}" if failed.endswith("undecided")
                 else f"fails {failed}")
        text = (f"{EXPLANATION} {seen}: no periodic orbit of the reduction with this word at r (the eigen-normal n* "
                f"{where}){one}, certified at r exactly: the ω-limit set is not a periodic orbit of the reduction "
                "with this word")
    text += _island_note(entry, w)
    return holds, text, []


def _island_note(entry: dict, w: str) -> str:
    """", m of them island orbits (...)" for the orbits that repeat w in float64 and are
    proved island orbits (their check follows, :func:`classes_check`)."""
    m = sum(o.get("observed") == w and o["class"] == "island" for o in entry.get("classified", []))
    if not m:
        return ""
    return (f"; {m} of the orbits that repeat it are island orbits, quasi-periodic for ever (proved below): "
            "the word codes the island's rotation for a while")


verify = caches.for_a_run(ident.verify)    # once per run of the caches


def classes_check(entry: dict) -> list:
    """The checks of one committed entry's classes: each island and attracting orbit
    re-checked by :func:`certify.run.identify.verify` at its committed collision (the
    second route: milliseconds), one check per class; the unresolved orbits as an
    observation."""
    r, n, out = Fraction(entry["r"]), entry["orbits"], []
    for cls, says in ((ident.ISLAND, "island orbits: the state at b after collision {ks}, in arb balls from each "
                                     "datum, lies in the island U_r = {{Q < c_max}}, so each orbit is quasi-periodic "
                                     "for ever (the island theorem)"),
                      (ident.ATTRACTING, "attracting periodic orbits: the state after collision {ks}, in arb balls "
                                         "from each datum, lies in the certified trapping ellipse of {words}, so each "
                                         "orbit follows its word for ever (certified)")):
        mine = [o for o in entry["classified"] if o["class"] == cls]
        if not mine:
            continue
        refused = [f"θ0 = {o['theta0']:.6f}, φ0 = {o['phi0']:.6f}: {why}" for o in mine
                   if (why := verify(r, o["theta0"], o["phi0"], cls, o["certified_from"], o["rotation"]))]
        ks = ", ".join(sorted({str(o["certified_from"]) for o in mine}, key=int))
        words = ", ".join(sorted({o["word"] for o in mine if o["word"]}))
        text = f"{EXPLANATION} at r = {entry['r']}, {len(mine)} of {n} orbits are " + says.format(ks=ks, words=words)
        out.append(Check(text, not refused, refused, counts=False))
    rest = []
    left = [o for o in entry["classified"] if o["class"] == ident.UNRESOLVED]
    if left:
        rest.append(f"{len(left)} of {n} orbits unresolved (neither in the island nor proved inside a trapping "
                    f"ellipse within {entry['collisions']} collisions)")
    if entry["breaks"]:
        rest.append(f"{entry['breaks']} of {n} orbits stopped on a break")
    if rest:
        out.append(Check(f"{OBSERVATION} at r = {entry['r']}, " + "; ".join(rest), True, [], counts=False))
    return out


def explanations(claim: str, source) -> list:
    """The checks "explanation: ..." of claim ``claim`` (N2, N5, N6) from the committed
    findings: each word re-decided exactly at its r, each proved class re-checked
    (:func:`classes_check`) (consistency checks: they FAIL the certificate when a committed
    finding does not hold; they are ours, not the paper's); what stays unresolved, as an
    observation."""
    found = load(source, claim)
    if not found or claim not in found.get("claims", {}):
        return [Check(f"{EXPLANATION} the committed findings {FINDINGS} hold an entry for {claim}", False,
                      [f"run `{COMMAND}`"], counts=False)]
    out = []
    for entry in found["claims"][claim]:
        for word in entry["words"]:
            holds, text, ev = decide(entry, word)
            out.append(Check(text, holds, ev, counts=False))
        out += classes_check(entry)
    return out
