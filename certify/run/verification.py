"""The independent kernel's verdicts on a run (certify_kernel, docs/verify.md): reports/kernel.json.

After a run renders certificates.json, the kernel decides the statements of statements/*.txt with
its own definitions and the run's witnesses (:func:`certify_kernel.verify_all`).  Its results go
to kernel.json with a digest of what they depend on (certificates.json, the statement files, the
kernel's source): a later run whose inputs have the same digest reads them back instead of
deciding again (the kernel takes about a minute; the engine's run seconds).  ``certify verify
--check`` decides again and compares.
"""
from __future__ import annotations

import hashlib
import json
from pathlib import Path

import certify_kernel
from certify.run import progress
from certify.run.files import read_text_or_none, write_atomic
from certify_kernel.statements import DEFAULT as STATEMENTS

KERNEL = Path(certify_kernel.__file__).resolve().parent


def digest(certificates_text: str, statements: Path = STATEMENTS) -> str:
    """sha256 of certificates.json, the statement files and the kernel's source, by name."""
    h = hashlib.sha256(certificates_text.encode())
    for path in sorted(statements.glob("*.txt")) + sorted(KERNEL.glob("*.py")):
        h.update(path.name.encode() + b"\0" + path.read_bytes() + b"\0")
    return h.hexdigest()


def decide(certificates_text: str, jobs: int = 2, statements: Path = STATEMENTS) -> dict:
    """The kernel's results on a certificates text, as the data of kernel.json."""
    data = json.loads(certificates_text)
    paper = certify_kernel.read(statements)
    ids = {c["id"] for c in data["certificates"]}
    results = certify_kernel.verify_all(data, paper, jobs, ids, tick=progress.Bar("certificate"))
    known = {c.id for c in paper.certificates}
    results += [{"id": i, "status": "", "ok": False, "failure": "certificates.json has it, the statement files do not",
                 "counted": 0, "verified": 0, "statements": []} for i in sorted(ids - known)]
    k, n = certify_kernel.counts(results)
    return {"digest": digest(certificates_text, statements), "verified": k, "statements": n,
            "certificates": {r["id"]: {"status": r["status"], "ok": r["ok"], "failure": r["failure"],
                                       "counted": r["counted"], "verified": r["verified"],
                                       "statements": {sid: why for sid, ok, why in r["statements"]},
                                       "line": certify_kernel.line(r)} for r in results}}


def render(results: dict) -> str:
    return json.dumps(results, indent=1, ensure_ascii=False, sort_keys=True) + "\n"


def results_for(certificates_text: str, out_dir, jobs: int = 2, again: bool = False) -> dict:
    """kernel.json's data for this certificates text: read back from out_dir/kernel.json when its
    digest matches (unless ``again``), else decided now and written there."""
    path = Path(out_dir) / "kernel.json"
    old = read_text_or_none(path)
    if old and not again:
        try:
            data = json.loads(old)
            if data.get("digest") == digest(certificates_text):
                return data
        except ValueError:
            pass
    data = decide(certificates_text, jobs)
    write_atomic(path, render(data))
    return data


def cell(results: dict | None, cert_id: str) -> str:
    """The report table's Kernel column for a certificate: "K/N verified", "FAILED", "—"."""
    r = (results or {}).get("certificates", {}).get(cert_id)
    if r is None or not r["counted"] and r["ok"]:
        return "—"
    if not r["ok"]:
        return "FAILED"
    return f"{r['verified']}/{r['counted']} verified"


def why_not(results: dict | None, cert_id: str, ref: str) -> str | None:
    """"" when the kernel verified the statement, the reason when it did not, None when unknown."""
    r = (results or {}).get("certificates", {}).get(cert_id)
    return None if r is None else r["statements"].get(ref)
