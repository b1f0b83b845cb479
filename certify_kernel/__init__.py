"""certify_kernel: re-checks reports/certificates.json with the Python standard library alone.

A certificate lists its obligations (facts over Z and Q: polynomial identities, root counts,
algebraic numbers, signs, digits, sign tables of eigenvalue branches) and its sub-claims, each
naming the obligations it rests on and how they give it (its derivation).  :func:`verify_certificate`
checks every obligation with :mod:`certify_kernel.checks` and every derivation with
:mod:`certify_kernel.derive` (its conclusion must be the sub-claim's verdict); a sub-claim is
*independently verified* when it names at least one obligation and every one it names is
verified (and its derivation, if any, checked).  The schema is in docs/verify.md and
certify_kernel/certificates.schema.json.
"""
from __future__ import annotations

import json

from .checks import CHECKERS, Failed, Unsupported
from .derive import concludes

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
    that read it), then every sub-claim's references and derivation.  Returns {"id", "ok",
    "failure", "subclaims", "verified", "derived", "unsupported": {obligation id: reason}}."""
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
            return {**out, "ok": False, "failure": f"obligation {ob['id']} ({ob.get('kind')}): {_why(exc)}"}
    counted = verified = derived = 0
    for k, sub in enumerate(cert["subclaims"]):
        names, where = sub.get("obligations", []), f"sub-claim {k + 1} ({sub['statement'][:60]})"
        missing = [i for i in names if i not in obligations]
        if missing:
            return {**out, "ok": False, "failure": f"{where} names the missing obligation {missing[0]}"}
        got = None
        try:
            got = None if sub.get("derivation") is None else concludes(sub["derivation"], set(names), env)
        except Unsupported:
            pass
        except Exception as exc:        # a derivation that does not give the statement, or malformed
            return {**out, "ok": False, "failure": f"{where}: its derivation: {_why(exc)}"}
        if got is not None and got != sub["holds"]:
            return {**out, "ok": False, "failure": f"{where} says holds = {str(sub['holds']).lower()}, "
                    f"its derivation concludes {str(got).lower()}"}
        if not sub.get("counts", True):
            continue
        counted += 1
        if names and not sub.get("uncovered") and all(i in env["verified"] for i in names):
            verified += 1
            derived += got is not None
    return {**out, "subclaims": counted, "verified": verified, "derived": derived}


def _why(exc: Exception) -> str:
    return str(exc) if isinstance(exc, Failed) else f"malformed ({type(exc).__name__}: {exc})"


def line(result: dict) -> str:
    """One line per certificate: verified (how many sub-claims, with a derivation), or the first failure."""
    if not result["ok"]:
        return f"{result['id']}: FAILED: {result['failure']}"
    n, k, d = result["subclaims"], result["verified"], result["derived"]
    word = "independently verified" if n and k == n else "obligations hold"
    return f"{result['id']}: {word} ({k}/{n} sub-claims independently verified, {d} with a derivation checked)"


__all__ = ["FORMAT", "load", "verify_certificate", "line", "Failed", "Unsupported", "json"]
