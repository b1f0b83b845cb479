"""Writing output files safely: atomically, and only where we may write.

Every file that ``certify`` produces (REPORT.md, report.json, timings.json, the
figures) is first written to a temporary file in the same directory and then
moved over the target with :func:`os.replace`, which is atomic on POSIX and
Windows.  A run that crashes or is interrupted therefore leaves the previous
file intact, never a half-written one.
"""
from __future__ import annotations

import os
import re
import tempfile
from contextlib import contextmanager, suppress
from pathlib import Path

from certify.errors import UsageError

CHECKOUT = Path(__file__).resolve().parents[2]   # the source checkout (benchmarks/, the committed reports/)
REPORTS = CHECKOUT / "reports"

# The process umask, read once: mkstemp creates files readable by the owner
# only, and a report should get the same permissions as any other new file.
_UMASK = os.umask(0)
os.umask(_UMASK)


@contextmanager
def atomic_path(path):
    """Yield a temporary path next to ``path``; it replaces ``path`` on success.

    If the body raises (or the process dies), the temporary file is removed (or
    left as a hidden ``.NAME.*.tmp`` file) and ``path`` keeps its old content.
    """
    path = Path(path)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    os.close(fd)
    try:
        yield Path(tmp)
        os.chmod(tmp, 0o666 & ~_UMASK)
        os.replace(tmp, path)
    except BaseException:
        with suppress(OSError):
            os.unlink(tmp)
        raise


def write_atomic(path, data: str | bytes) -> None:
    """Write ``data`` (text as UTF-8, or bytes) to ``path`` atomically."""
    raw = data.encode("utf-8") if isinstance(data, str) else data
    with atomic_path(path) as tmp:
        tmp.write_bytes(raw)


def read_text_or_none(path) -> str | None:
    """The UTF-8 text of ``path``, or None when it does not exist or cannot be read."""
    try:
        return Path(path).read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError):
        return None


def first_member(text: str, key: str):
    """``json.loads(text)[key]`` for a JSON object, decoding only that member when it is the
    object's first (the rest of the text is not parsed: reports/census.json opens with its
    summary "census", 94 kB, before 6 MB of per-word records); KeyError without it,
    ValueError for text that is not JSON."""
    import json
    decoder, ws = json.JSONDecoder(), re.compile(r"[ \t\n\r]*")
    i = ws.match(text, 0).end()
    if text[i:i + 1] == "{":
        try:
            name, i = decoder.raw_decode(text, ws.match(text, i + 1).end())
            i = ws.match(text, i).end()
            if name == key and text[i:i + 1] == ":":
                return decoder.raw_decode(text, ws.match(text, i + 1).end())[0]
        except ValueError:          # not a member there: the whole text decides
            pass
    return json.loads(text)[key]


_MISSING = object()


def read_first_member(path, key: str, chunk: int = 1 << 16):
    """:func:`first_member` of the text of ``path``, reading only as much of the file as
    that member needs when it is the object's first (reports/census.json: its 94 kB
    summary, not the 6 MB after it); the whole file otherwise.  None when the file does
    not exist or cannot be read (as :func:`read_text_or_none`; a defect after the member
    is not read)."""
    import codecs
    decoder = codecs.getincrementaldecoder("utf-8")()
    parts: list[str] = []
    try:
        with open(path, "rb") as f:
            while True:
                raw = f.read(chunk)
                parts.append(decoder.decode(raw, final=not raw))
                if not raw:
                    break
                found = _complete_first_member("".join(parts), key)
                if found is not _MISSING:
                    return found
                chunk *= 2
    except (OSError, UnicodeDecodeError):
        return None
    return first_member("".join(parts), key)


def _complete_first_member(text: str, key: str):
    """The value of the first member of the JSON object that ``text`` begins, when it is
    named ``key`` and ends inside ``text`` with a character after it; else _MISSING."""
    import json
    decoder, ws = json.JSONDecoder(), re.compile(r"[ \t\n\r]*")
    try:
        i = ws.match(text, 0).end()
        if text[i:i + 1] != "{":
            return _MISSING
        name, i = decoder.raw_decode(text, ws.match(text, i + 1).end())
        i = ws.match(text, i).end()
        if name != key or text[i:i + 1] != ":":
            return _MISSING
        value, i = decoder.raw_decode(text, ws.match(text, i + 1).end())
    except ValueError:
        return _MISSING
    i = ws.match(text, i).end()
    return value if text[i:i + 1] in (",", "}") else _MISSING


def load_findings(name: str, directory=REPORTS) -> dict | None:
    """The committed findings ``directory/name`` (``numerics-paper.json``, ``numerics-n4.json``,
    which ``certify figures`` writes), or None when they are absent or unreadable."""
    import json
    text = read_text_or_none(Path(directory) / name)
    try:
        return json.loads(text) if text is not None else None
    except ValueError:
        return None


TIMINGS = ("seconds",)      # wall times: printed on the terminal, never in a committed file


def timeless(doc):
    """``doc`` without its timings (the keys in TIMINGS, at any depth): committed findings
    hold what was found, not how long it took on one machine."""
    if isinstance(doc, dict):
        return {k: timeless(v) for k, v in doc.items() if k not in TIMINGS}
    if isinstance(doc, list):
        return [timeless(v) for v in doc]
    return doc


def write_findings(path, doc: dict) -> None:
    """Write the findings ``doc`` as JSON at ``path``, atomically and without timings."""
    import json
    write_atomic(Path(path), json.dumps(timeless(doc), indent=1) + "\n")


def ensure_writable(directory) -> Path:
    """Create ``directory`` if needed and prove that a file can be written there.

    Raises :class:`UsageError` (exit code 2) with a one-line reason otherwise, so
    that the CLI can refuse an output directory *before* running certificates: "not a
    directory" (a file there, or on its path), "not writable" (the probe failed), or why
    it cannot be created.  The one way a bad output path is reported.
    """
    directory = Path(directory)

    def refuse(why: str):
        raise UsageError(f"cannot write to output directory {str(directory)!r}: {why}")
    blocking = next((p for p in (directory, *directory.parents) if p.exists() and not p.is_dir()), None)
    if blocking is not None:
        refuse("not a directory" + ("" if blocking == directory else f" ({str(blocking)!r} is a file)"))
    try:
        directory.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        refuse(f"cannot be created ({exc.strerror or type(exc).__name__})")
    try:
        with tempfile.NamedTemporaryFile(dir=directory, prefix=".certify-probe-"):
            pass
    except OSError as exc:
        refuse(f"not writable ({exc.strerror or type(exc).__name__})")
    return directory


def ensure_writable_file(path, option: str) -> Path:
    """An output file ``path`` (given by ``option``): its directory as :func:`ensure_writable`
    checks it, and not a directory itself; a UsageError (one line, exit 2) otherwise."""
    path = Path(path)
    if path.is_dir():
        raise UsageError(f"{option} {str(path)!r} is a directory, not a file")
    ensure_writable(path.parent if str(path.parent) else Path("."))
    return path


def _covers(new, old) -> bool:
    """A measure of a result's size covers another: a number at least as large, an interval
    (lo, hi) containing the other."""
    if isinstance(old, tuple):
        return new[0] <= old[0] and old[1] <= new[1]
    return new >= old


def _shown(value) -> str:
    return f"]{value[0]}, {value[1]}[" if isinstance(value, tuple) else str(value)


def keep_larger(path, what: str, committed: dict | None, new: dict, force: bool, option: str = "--out DIR") -> None:
    """Refuse to replace a larger result: ``path`` holds a ``what`` (census, atlas, ...) whose
    size is ``committed`` (name -> a number, larger is more, or an interval (lo, hi) of r;
    None when there is no readable result there); the run about to replace it has the size
    ``new``.  Unless ``force``, a run smaller in one measure is a UsageError (one line, exit 2)
    naming the measures, ``option`` (where to write instead) and --force.  Every command
    that writes into reports/ by default calls this before any work."""
    if force or not committed:
        return
    smaller = [name for name, old in committed.items() if name in new and not _covers(new[name], old)]
    if smaller:
        sizes = lambda doc: ", ".join(f"{name} {_shown(doc[name])}" for name in smaller)    # noqa: E731
        raise UsageError(f"{path} holds a larger {what} ({sizes(committed)}) than this run's ({sizes(new)}), which "
                         f"would replace it: write it elsewhere with {option}, or pass --force")


def write_section(path, title: str, body: str) -> None:
    """Replace (or add) the section ``## title`` of the Markdown file ``path`` by ``body``,
    atomically; the other sections are kept.  Benchmarks share one file this way."""
    path = Path(path)
    text = read_text_or_none(path) or "# Benchmarks\n\nWritten by the benchmark commands; see README.\n"
    head = f"## {title}\n"
    start = text.find(head)
    section = f"{head}\n{body.strip()}\n"
    if start < 0:
        text = text.rstrip("\n") + "\n\n" + section
    else:
        end = text.find("\n## ", start + len(head))
        text = text[:start] + section + (text[end:] if end >= 0 else "")
    path.parent.mkdir(parents=True, exist_ok=True)
    write_atomic(path, text)
