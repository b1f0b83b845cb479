"""The five-particle stable windows over r beside the four-particle ones (issue 39): one figure,
``five-windows.png``, drawn from certified windows only.

* five particles: the stable sets of ``certify pattern WORD`` (:func:`certify.patterns.five.analyse_five`,
  exact ends; the JSON of a pattern result), for the words given;
* four particles: the stable windows of the committed census (reports/census.json, every word of at
  most its length; :func:`certify.patterns.census.windows`).

Floats of the certified ends (12 digits) are a drawing only.  The thresholds of four particles
(7 − 4√3, 3 − 2√2, abcb's r_exist ≈ 0.19166) and 2 − √3 are marked.

    python tools/five_particle_figure.py abadcbcabc        # writes reports/five-windows.png
"""
from __future__ import annotations

import math
from pathlib import Path

from certify.patterns import census

NAME = "five-windows.png"            # next to CENSUS.md (reports/figures is pruned by `certify all`)


def marks() -> dict:
    """{label: r} of the vertical lines: the four-particle thresholds and 2 − √3."""
    from certify.numerics.thresholds import r_exist
    return {"7−4√3": 7 - 4 * math.sqrt(3), "3−2√2": 3 - 2 * math.sqrt(2), "r_exist ≈ 0.19166 (abcb)": float(r_exist()),
            "2−√3": 2 - math.sqrt(3)}


def four_particle_windows(doc: dict) -> list[tuple[str, list]]:
    """(word, its stable windows) for every word of a census document with a stable window."""
    return [(r["compact"], census.windows(r)) for r in doc["words"] if r["stable"] and census.windows(r)]


def five_particle_windows(results: dict) -> list[tuple[str, list]]:
    """(word, its stable windows) from {word: the JSON of its pattern result} (certified windows)."""
    rows = [(word, census.windows({"result": doc})) for word, doc in results.items()]
    return [(w, s) for w, s in rows if s]


def family_rows(results: dict, core: str, ks, j: int = 1) -> list[tuple[int, str, list | None]]:
    """(k, word, its stable windows or None when no result is committed) for the members
    ``certify.patterns.five.family_word(core, k, j)``, k in ``ks``."""
    from certify.patterns.five import family_word
    rows = []
    for k in ks:
        word = family_word(core, k, j)
        rows.append((k, word, census.windows({"result": results[word]}) if word in results else None))
    return rows


def family_problems(results: dict, core: str, ks, j: int = 1) -> list[str]:
    """What keeps the members k in ``ks`` of a family from being certified with their windows in
    order and where the rule puts them (empty: each has a certified stable window, one interval, each
    lies strictly below the one before, compared on the results' isolating intervals, exact rationals,
    and each lies in its interval ]r_{(p+1)/(q+2)}, r_{p/q}[ of the island's resonances,
    :func:`certify.patterns.five_rule.rule_problems`)."""
    from fractions import Fraction

    from certify.patterns.five import family_word
    from certify.patterns.five_rule import rule_problems
    problems, previous = [], None
    for k in ks:
        word = family_word(core, k, j)
        doc = results.get(word)
        pieces = [p for s in doc["stable"] for p in s["pieces"] if p["kind"] == "interval"] if doc else []
        if len(pieces) != 1:
            problems.append(f"k = {k}: {word} has no certified stable window (one interval)")
            previous = None
            continue
        lo, hi = (tuple(Fraction(x) for x in pieces[0][end]["interval"]) for end in ("lo", "hi"))
        if previous is not None and not hi[1] < previous[0]:
            problems.append(f"k = {k}: the window of {word} does not lie below member k - 1's")
        problems += [f"k = {k}: {p}" for p in rule_problems(core, k, j, pieces[0]["lo"], pieces[0]["hi"])]
        previous = lo
    return problems


LABEL = 40         # a longer word is labelled by its first letters and its length


def label(word: str) -> str:
    """A row's label: the word, or for a word longer than :data:`LABEL` letters its first 24 letters,
    an ellipsis and its length (the whole words are in the result files)."""
    return word if len(word) <= LABEL else f"{word[:24]}… ({len(word)} letters)"


NARROW = 1 / 150   # a window narrower than this fraction of the axis also gets a mark


def figure(four: list, five: list, path, lines: dict | None = None, census_length: int | None = None) -> Path | None:
    """Two panels on one axis of r: the five-particle words' stable windows (top) and the
    four-particle census's (bottom), one row per word, highest window first; ``lines`` the
    thresholds.  A window narrower than NARROW of the axis is also marked at its middle (a diamond),
    so that it shows.  Written through :mod:`.saving` to ``path``; None when nothing is to be drawn."""
    from . import plots, saving
    if not four and not five:
        return None
    plt = saving.pyplot()
    four = sorted(four, key=lambda row: -max(hi for _lo, hi in row[1]))
    five = sorted(five, key=lambda row: -max(hi for _lo, hi in row[1]))
    fig, (ax, bx) = plt.subplots(2, 1, sharex=False, figsize=(7.2, 2.6 + 0.28 * (len(four) + len(five))),
                                 gridspec_kw={"height_ratios": [max(len(five), 1) + 1, max(len(four), 1) + 1]})
    lines = lines or {}
    top = max([hi for _w, s in four + five for _lo, hi in s] + list(lines.values()))
    right = math.ceil(top * 50 + 1) / 50
    for panel, rows, colour in ((ax, five, "tab:purple"), (bx, four, "tab:blue")):
        for k, (_word, windows) in enumerate(rows):
            for lo, hi in windows:
                panel.barh(k, hi - lo, left=lo, height=0.5, color=colour)
            narrow = [(lo + hi) / 2 for lo, hi in windows if hi - lo < right * NARROW]
            if narrow:   # a window thinner than a pixel or two: a mark at its middle as well
                panel.plot(narrow, [k] * len(narrow), ls="none", marker="D", ms=3, color=colour)
        panel.set_yticks(range(len(rows)), [label(w) for w, _s in rows], fontsize=7)
        panel.set_ylim(len(rows) - 0.5, -0.5 - (0 if rows else 0.5))
        panel.set_xlim(0, right)
        for value in lines.values():
            panel.axvline(value, color="grey", lw=0.6, ls="--")
        panel.set_xlabel("r")
    fig.tight_layout()
    rows = plots.label_lines(ax, lines, color="grey", fontsize=6)
    words = f"{len(five)} word{'' if len(five) == 1 else 's'}"
    ax.set_title(f"five particles: stable self-similar windows\n(certify pattern; {words})", fontsize=9,
                 pad=plots.label_pad(rows))
    length = f"words of at most {census_length} collisions" if census_length else "the census"
    bx.set_title(f"four particles: stable self-similar windows\n({length}, certified)", fontsize=9)
    fig.tight_layout()
    path = Path(path)
    with saving.output_dir(path.parent):
        saving.save_figure(fig, path.name)
    return path
