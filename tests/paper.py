"""The paper's source beside the checkout, read as plain text for tests that compare
what a certificate quotes with the lines it cites."""
from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PAPER = ROOT.parent / "shared" / "paper" / "inelastic-collapse-four-particles.tex"


def source_lines() -> list[str]:
    return PAPER.read_text(encoding="utf-8").splitlines()


def plain(tex: str) -> str:
    """TeX as a reader sees it: \\mathfrak{abc} and \\frakB as abc and b, no $, braces
    or line-ending backslashes, runs of spaces made one."""
    t = re.sub(r"\\mathfrak\{(\w+)\}", r"\1", tex)
    t = re.sub(r"\\frak([ABC])", lambda m: m.group(1).lower(), t)
    t = t.replace("$", "").replace("\\\\", " ").replace("\\,", " ")
    return " ".join(t.split())


def plain_line(n: int) -> str:
    """Line ``n`` (1-based) of the source, plain."""
    return plain(source_lines()[n - 1])


def plain_lines(ranges) -> str:
    """The lines of ``ranges`` [(lo, hi), ...], plain, one after another."""
    lines = source_lines()
    return " ".join(plain(lines[k - 1]) for lo, hi in ranges for k in range(lo, hi + 1))


THEOREM_LIKE = ("theorem", "proposition", "corollary", "remark", "lemma")


def numbering() -> dict:
    """What the compiled paper prints, from its LaTeX counters read in source order:
    ``{("Theorem", "4.1"): line, ...}`` for theorem-like environments (one counter per
    section, shared: ``\\newtheorem{theorem}{Theorem}[section]``, the others ``[theorem]``)
    and ``{("Figure", "8a"): "fig:Simul_2_zoom_1", ...}`` for figures (one counter through
    the paper; a subfigure's caption is (a), (b), ... of the figure whose caption follows)."""
    section, theorem, figure = 0, 0, 0
    out, pending, in_figure = {}, [], False
    for n, line in enumerate(source_lines(), 1):
        if re.match(r"\s*\\section\{", line):
            section, theorem = section + 1, 0
        m = re.match(r"\s*\\begin\{(" + "|".join(THEOREM_LIKE) + r")\}", line)
        if m:
            theorem += 1
            out[(m.group(1).capitalize(), f"{section}.{theorem}")] = n
        if re.match(r"\s*\\begin\{figure\}", line):
            in_figure, pending, sub = True, [], 0
        if re.match(r"\s*\\begin\{subfigure\}", line):
            sub += 1
            pending.append([chr(ord("a") + sub - 1), None])
        in_sub = pending and pending[-1][1] is None and not re.search(r"\\end\{subfigure\}", line)
        for label in re.findall(r"\\label\{([^}]*)\}", line):
            if pending and pending[-1][1] is None and in_sub:
                pending[-1][1] = label
            elif in_figure and out.get(("Figure", str(figure))) is None and figure:
                out[("Figure", str(figure))] = label
        if re.search(r"\\end\{subfigure\}", line) and pending and pending[-1][1] is None:
            pending[-1][1] = ""
        if in_figure and re.search(r"\\caption(of\{figure\})?\{", line) and not in_sub:
            figure += 1
            out[("Figure", str(figure))] = None
            for letter, label in pending:
                out[("Figure", f"{figure}{letter}")] = label
            pending = []
        if re.match(r"\s*\\end\{figure\}", line):
            in_figure = False
    return out
