"""What the kernel's tests share: a formula decided the way the kernel decides a statement, a
statement file written under a test's tmp_path, a certificates file (format 2) that agrees with
statement files, and the repository's statements.

The kernel keeps its declared variables in one list for the process (values.VARS): the variables
and angles the tests use are declared once here, before anything is evaluated; names are looked
up by name, so the order in which other statement files declare theirs changes nothing."""
from __future__ import annotations

import json
from pathlib import Path

import certify_kernel
from certify_kernel.evaluate import Context, truth, value
from certify_kernel.language import parse
from certify_kernel.statements import DEFAULT as STATEMENTS
from certify_kernel.statements import Statement
from certify_kernel.values import declare, declare_angle

ROOT = Path(__file__).resolve().parents[2]
VARIABLES, ANGLES = ("x", "u", "v"), ("θ", "φ")


def declared() -> None:
    for name in VARIABLES:
        declare(name)
    for name in ANGLES:
        declare_angle(name)


declared()


def truth_of(formula: str, lets: dict | None = None, witnesses=None) -> bool:
    """The kernel's decision of a closed formula (raises NotVerified, Undefined as the kernel does)."""
    declared()
    return truth(parse(formula), Context(dict(lets or {}), witnesses))


def value_of(expr: str, lets: dict | None = None):
    declared()
    return value(parse(expr), Context(dict(lets or {})))


def outcome(formula: str, verdict: str = "holds", lets: dict | None = None, witnesses=None) -> str:
    """What the kernel makes of a statement with this formula and verdict: "verified", "not
    verified: WHY" or "failed: MESSAGE" (the decision contradicts the verdict, or the formula is
    not one of the language)."""
    declared()
    s = Statement("Z9.1", "l. 1", verdict, "", "a test statement", formula=formula, where="test:1")
    try:
        ok, why = certify_kernel.check_statement(s, dict(lets or {}), witnesses)
    except ValueError as exc:
        return f"failed: {exc}"
    return "verified" if ok else f"not verified: {why}"


def write_statements(directory: Path, text: str, name: str = "1_test.txt") -> Path:
    directory.mkdir(parents=True, exist_ok=True)
    (directory / name).write_text(text, encoding="utf-8")
    return directory


ENGINE_VERDICT = {"holds": "holds", "corrects": "holds", "refuted": "refuted", "observed": "observed"}


def honest_entry(cert) -> dict:
    """The entry of certificates.json a correct run writes for a certificate of the statement
    files: the status its statements' verdicts give and each statement's verdict."""
    return {"id": cert.id, "status": certify_kernel.status_of(cert.statements),
            "statements": {s.id: {"verdict": ENGINE_VERDICT[s.verdict]} for s in cert.statements}}


def honest_file(paper, ids=None) -> dict:
    return {"format": certify_kernel.FORMAT, "paper": "test", "schema": "docs/verify.md",
            "certificates": [honest_entry(c) for c in paper.certificates if ids is None or c.id in ids]}


def dump(data: dict, path: Path) -> Path:
    path.write_text(json.dumps(data, ensure_ascii=False), encoding="utf-8")
    return path


def repository_statements():
    """The statement files of the checkout (statements/), read as the kernel reads them."""
    return certify_kernel.read(STATEMENTS)
