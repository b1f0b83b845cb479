"""Reading the statement files (statements/*.txt, docs/statements.md): the paper's claims as data.

A file holds, line by line: ``vars NAME, ...`` and ``angles NAME, ...`` (declarations), ``let NAME
= EXPR`` (a definition, as printed), ``certificate ID  l. LINES  "TITLE"`` (a claim of CLAIMS.md),
and under it its statements: a header ``ID  l. LINES  VERDICT  "TEXT"`` with VERDICT one of
``holds``, ``refuted by ID``, ``corrects ID``, ``observed``, followed by the formal statement on
indented lines (or ``unformalised "WHY"``).  A line whose first character is a space continues
the previous definition or statement; ``#`` starts a comment (outside quotes).
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path

DEFAULT = Path(__file__).resolve().parent.parent / "statements"

_HEADER = re.compile(r'^(?P<id>[A-Z]\d+(?:\.\d+)*)\s+(?P<line>l\.\s*[0-9][0-9\-–, ]*?)\s+'
                     r'(?P<verdict>holds|observed|refuted by [A-Z][\w.]*|corrects [A-Z][\w.]*)\s+"(?P<text>.*)"\s*$')
_CERT = re.compile(r'^certificate\s+(?P<id>[A-Z]\d+(?:\.\d+)?)\s+(?P<line>l\.\s*[0-9][0-9\-–, ]*?)\s+'
                   r'"(?P<title>.*)"\s*$')
_LET = re.compile(r"^let\s+(?P<name>[^\W\d][\w′']*)\s*=\s*(?P<expr>.+)$")


class FileError(ValueError):
    """A statement file that does not follow the format (the message names the file and line)."""


@dataclass
class Statement:
    id: str
    line: str
    verdict: str                 # holds, refuted, corrects, observed
    other: str                   # the correction (refuted by) or the corrected statement (corrects)
    text: str
    formula: str = ""
    unformalised: str = ""
    where: str = ""

    @property
    def printed(self) -> bool:
        return self.verdict in ("holds", "refuted")


@dataclass
class Certificate:
    id: str
    line: str
    title: str
    statements: list = field(default_factory=list)
    where: str = ""


@dataclass
class Paper:
    vars: list = field(default_factory=list)
    angles: list = field(default_factory=list)
    lets: dict = field(default_factory=dict)
    certificates: list = field(default_factory=list)


def _strip(line: str) -> str:
    """The line without its comment (a # outside double quotes)."""
    quoted = False
    for k, ch in enumerate(line):
        if ch == '"':
            quoted = not quoted
        elif ch == "#" and not quoted:
            return line[:k].rstrip()
    return line.rstrip()


def read(directory: Path | str = DEFAULT) -> Paper:
    """Every *.txt file of the directory, in name order, into one Paper."""
    paper = Paper()
    files = sorted(Path(directory).glob("*.txt"))
    if not files:
        raise FileError(f"no statement files (*.txt) in {directory}")
    for path in files:
        _read_file(path, paper)
    clash = sorted(set(paper.lets) & (set(paper.vars) | set(paper.angles) | {"r", "λ", "A", "B", "C", "I", "e_x", "e_y",
                                                                            "e_z", "π"}))
    if clash:
        raise FileError(f"{clash[0]} is both defined (let) and a variable or an object of the kernel")
    certs = [c.id for c in paper.certificates]
    if len(set(certs)) != len(certs):
        raise FileError(f"two certificates share the id {sorted(i for i in certs if certs.count(i) > 1)[0]}")
    ids = [s.id for c in paper.certificates for s in c.statements]
    dup = {i for i in ids if ids.count(i) > 1}
    if dup:
        raise FileError(f"two statements share the id {sorted(dup)[0]}")
    by_id = {s.id: s for c in paper.certificates for s in c.statements}
    for c in paper.certificates:
        for s in c.statements:
            if s.verdict in ("refuted", "corrects"):
                o = by_id.get(s.other)
                want = "corrects" if s.verdict == "refuted" else "refuted"
                if o is None or o.verdict != want or o.other != s.id:
                    raise FileError(f"{s.where}: {s.id} {s.verdict} {s.other}, but {s.other} is not its "
                                    f"{'correction' if s.verdict == 'refuted' else 'refuted statement'}")
    return paper


def _read_file(path: Path, paper: Paper) -> None:
    current = None                      # the item (let name or Statement) that indented lines continue
    cert = None
    for n, raw in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        line, where = _strip(raw), f"{path.name}:{n}"
        if not line.strip():
            continue
        if line[0] in " \t":
            if current is None:
                raise FileError(f"{where}: an indented line that continues nothing")
            if isinstance(current, Statement):
                text = line.strip()
                if text.startswith("unformalised "):
                    current.unformalised = text[len("unformalised "):].strip().strip('"')
                else:
                    current.formula = (current.formula + " " + text).strip()
            else:
                paper.lets[current] += " " + line.strip()
            continue
        if line.startswith(("vars ", "angles ")):
            kind, names = line.split(None, 1)
            getattr(paper, kind).extend(x.strip() for x in names.split(","))
            current = None
            continue
        m = _LET.match(line)
        if m:
            if m["name"] in paper.lets:
                raise FileError(f"{where}: {m['name']} is defined twice")
            paper.lets[m["name"]] = m["expr"].strip()
            current = m["name"]
            continue
        m = _CERT.match(line)
        if m:
            cert = Certificate(m["id"], m["line"], m["title"], where=where)
            paper.certificates.append(cert)
            current = None
            continue
        m = _HEADER.match(line)
        if m:
            if cert is None or not m["id"].startswith(cert.id + "."):
                raise FileError(f"{where}: the statement {m['id']} is not under its certificate")
            verdict, _, other = m["verdict"].partition(" by ") if "by" in m["verdict"] else \
                m["verdict"].partition(" ")
            current = Statement(m["id"], m["line"], verdict, other.strip(), m["text"], where=where)
            cert.statements.append(current)
            continue
        raise FileError(f"{where}: not a line of the statement format: {line.strip()[:60]!r}")
    for c in paper.certificates:
        for s in c.statements:
            if s.verdict != "observed" and not s.formula and not s.unformalised:
                raise FileError(f"{s.where}: {s.id} has no formal statement (or `unformalised \"why\"`)")
