"""certify_kernel: re-checks reports/certificates.json with the Python standard library alone.

A certificate lists its obligations (facts over Z and Q: polynomial identities, root counts,
algebraic numbers, signs, digits, sign tables of eigenvalue branches) and its sub-claims, each
naming the obligations it rests on.  :func:`verify_certificate` checks every obligation with
the checkers of :mod:`certify_kernel.checks`; a sub-claim is *independently verified* when it
names at least one obligation and every one it names is verified.  The schema is in
docs/verify.md and certify_kernel/certificates.schema.json.
"""
from __future__ import annotations

import json

from .checks import CHECKERS, Failed, Unsupported

FORMAT = "certify-certificates/1"


def load(path: str) -> dict:
    """The certificates file, read as JSON (no code is evaluated)."""
    with open(path, encoding="utf-8") as f:
        data = json.load(f)
    if data.get("format") != FORMAT:
        raise ValueError(f"{path}: not a certificates file of format {FORMAT}")
    return data


def verify_certificate(cert: dict) -> dict:
    """Check every obligation of one certificate, in order (a sign table before the queries
    that read it), then every sub-claim's references.  Returns {"id", "ok", "failure",
    "subclaims", "verified", "unsupported": {obligation id: reason}}."""
    obligations = {ob["id"]: ob for ob in cert["obligations"]}
    env: dict = {"obligations": obligations, "verified": set()}
    unsupported: dict = {}
    out = {"id": cert["id"], "status": cert.get("status", ""), "ok": True, "failure": "", "unsupported": unsupported}
    if len(obligations) != len(cert["obligations"]):
        return {**out, "ok": False, "failure": "two obligations share an id"}
    for ob in cert["obligations"]:
        checker = CHECKERS.get(ob.get("kind"))
        try:
            if checker is None:
                raise Failed(f"unknown kind {ob.get('kind')!r}")
            checker(ob, env)
            env["verified"].add(ob["id"])
        except Unsupported as exc:
            unsupported[ob["id"]] = str(exc)
        except Exception as exc:     # a false obligation, or a malformed one
            why = str(exc) if isinstance(exc, Failed) else f"malformed ({type(exc).__name__}: {exc})"
            return {**out, "ok": False, "failure": f"obligation {ob['id']} ({ob.get('kind')}): {why}"}
    counted = verified = 0
    for k, sub in enumerate(cert["subclaims"]):
        missing = [i for i in sub.get("obligations", []) if i not in obligations]
        if missing:
            return {**out, "ok": False,
                    "failure": f"sub-claim {k + 1} ({sub['statement'][:60]}) names the missing obligation {missing[0]}"}
        if not sub.get("counts", True):
            continue
        counted += 1
        names = sub.get("obligations", [])
        if names and not sub.get("uncovered") and all(i in env["verified"] for i in names):
            verified += 1
    return {**out, "subclaims": counted, "verified": verified}


def line(result: dict) -> str:
    """One line per certificate: verified (with how many sub-claims), or the first failure."""
    if not result["ok"]:
        return f"{result['id']}: FAILED: {result['failure']}"
    n, k = result["subclaims"], result["verified"]
    word = "independently verified" if n and k == n else "obligations hold"
    return f"{result['id']}: {word} ({k}/{n} sub-claims independently verified)"


__all__ = ["FORMAT", "load", "verify_certificate", "line", "Failed", "Unsupported", "json"]
