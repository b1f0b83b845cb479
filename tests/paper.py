"""The paper's source beside the checkout, read as plain text for tests that compare
what a certificate quotes with the lines it cites.

The source is ``../shared/paper/inelastic-collapse-four-particles.tex`` beside the checkout, or
the file named by ``CERTIFY_PAPER``.  A plain clone has neither: it reads the lines the tests
quote from ``tests/data/paper-lines.json`` (CARRIED), which holds those lines exactly as the
source prints them (tests/proofs/test_citations.py checks them against the source when it is
there; ``python -m tests.paper`` rewrites the file from the source).  A test that needs a line
that is neither in the source nor carried is skipped, saying so."""
from __future__ import annotations

import json
import os
import re
from functools import cache
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PAPER = Path(os.environ.get("CERTIFY_PAPER")
             or ROOT.parent / "shared" / "paper" / "inelastic-collapse-four-particles.tex")


CARRIED = ROOT / "tests" / "data" / "paper-lines.json"
NO_SOURCE = f"the paper's source is not beside this checkout ({PAPER}; set CERTIFY_PAPER to the .tex)"


def have_source() -> bool:
    return PAPER.is_file()


def source_lines() -> list[str]:
    return PAPER.read_text(encoding="utf-8").splitlines()


@cache
def carried() -> dict[int, str]:
    """The lines of the source carried in the repository: {line number: text as printed}."""
    return {int(k): v for k, v in json.loads(CARRIED.read_text(encoding="utf-8"))["lines"].items()}


def source_line(n: int) -> str:
    """Line ``n`` (1-based) of the source as printed: from the source when it is beside the
    checkout, else from the carried lines; skips the test when it has neither."""
    if have_source():
        return source_lines()[n - 1]
    if n not in carried():
        import pytest
        pytest.skip(f"{NO_SOURCE}, and l. {n} is not carried in {CARRIED.name}")
    return carried()[n]


def plain(tex: str) -> str:
    """TeX as a reader sees it: \\mathfrak{abc} and \\frakB as abc and b, no $, braces
    or line-ending backslashes, runs of spaces made one."""
    t = re.sub(r"\\mathfrak\{(\w+)\}", r"\1", tex)
    t = re.sub(r"\\frak([ABC])", lambda m: m.group(1).lower(), t)
    t = re.sub(r"\\sqrt\{(\w+)\}", r"√\1", t)
    t = t.replace("$", "").replace("\\\\", " ").replace("\\,", " ").replace("``", '"').replace("''", '"')
    return " ".join(t.split())


def plain_line(n: int) -> str:
    """Line ``n`` (1-based) of the source, plain."""
    return plain(source_line(n))


def plain_lines(ranges) -> str:
    """The lines of ``ranges`` [(lo, hi), ...], plain, one after another."""
    return " ".join(plain(source_line(k)) for lo, hi in ranges for k in range(lo, hi + 1))


CITATION = re.compile(r"\bl\. (\d+(?:-\d+)?(?:, \d+(?:-\d+)?)*)")
QUOTED = re.compile(r"(?<![\w'’])(?:'([^'\n]+?)'|‘([^’\n]+?)’|\"([^\"\n]+?)\"|“([^”\n]+?)”)(?!\w)")


def line_ranges(cited: str) -> list[tuple[int, int]]:
    """``617-630, 686-690`` (what follows ``l. ``) as [(617, 630), (686, 690)]."""
    out = []
    for part in cited.split(", "):
        lo, _, hi = part.partition("-")
        out.append((int(lo), int(hi or lo)))
    return out


def quotations(text: str, line: str | None = None):
    """The paper's words that ``text`` quotes, with the lines it cites for them: for each
    citation ``l. N`` (or ``l. N-M, K``) the first phrase in quotes ('…', ‘…’, "…", “…”)
    after it and before the next citation (a phrase quoted after it, as in "'smaller'
    printed for 'larger'", is the correction); with ``line`` (a certificate's line, e.g.
    ``l. 513-516``), every phrase quoted before the first citation of ``text`` too.
    Yields (ranges, phrase)."""
    cites = list(CITATION.finditer(text))
    if line is not None:
        head = text[: cites[0].start()] if cites else text
        for m in QUOTED.finditer(head):
            yield line_ranges(line[3:]), next(g for g in m.groups() if g is not None)
    for k, c in enumerate(cites):
        end = cites[k + 1].start() if k + 1 < len(cites) else len(text)
        m = QUOTED.search(text, c.end(), end)
        if m:
            yield line_ranges(c.group(1)), next(g for g in m.groups() if g is not None)


def squeezed(text: str) -> str:
    """Plain text without any white space: what a quotation must match (the source writes
    `r=1` where a quotation writes `r = 1`)."""
    return "".join(plain(text).split())


def found_on(phrase: str, ranges) -> bool:
    """Whether ``phrase`` is printed on the lines ``ranges`` (plain, white space ignored; an
    ellipsis … stands for any text between its parts, in order)."""
    text, at = squeezed(plain_lines(ranges)), 0
    for part in phrase.split("…"):
        at = text.find(squeezed(part), at)
        if at < 0:
            return False
        at += len(squeezed(part))
    return True


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


def carry(lines: set[int]) -> None:
    """Write CARRIED: the lines ``lines`` of the source, exactly as printed."""
    source = source_lines()
    doc = {"source": "arXiv:2411.10324v1, inelastic-collapse-four-particles.tex (the lines the tests quote, "
                     "as printed; python -m tests.paper rewrites this file from the source)",
           "lines": {str(n): source[n - 1] for n in sorted(lines)}}
    CARRIED.parent.mkdir(exist_ok=True)
    CARRIED.write_text(json.dumps(doc, indent=1, ensure_ascii=False) + "\n", encoding="utf-8")


if __name__ == "__main__":       # python -m tests.paper: carry the lines the tests cite
    from tests.proofs.test_citations import cited_lines
    from tests.shared import registry
    registry()
    carry(cited_lines())
    print(f"wrote {CARRIED} ({len(carried())} lines)")
