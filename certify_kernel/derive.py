"""Derivations: how a sub-claim's obligations give its statement (docs/verify.md).  ``expect``:
each named obligation has the value the statement asserts; ``cover``: on ``branch`` the
condition takes only the allowed ``signs`` over ]lo, hi[, by queries of one condition that tile
it, each point they leave out given by a point fact; ``all``: a conjunction."""
from __future__ import annotations

import json

from .checks import Failed, Unsupported, _key, load_table
from .sturm import Algebraic


def concludes(d: dict, names: set, env: dict) -> bool:
    """What ``d`` concludes from the verified obligations among ``names``.  Failed: malformed, or
    naming what the sub-claim does not; Unsupported: resting on an unverified obligation."""
    if d.get("rule") == "all" and d.get("of"):
        return all([concludes(part, names, env) for part in d["of"]])   # every part checked
    if d.get("rule") == "expect" and d.get("facts"):
        return all([_expect(e, names, env) for e in d["facts"]])
    if d.get("rule") == "cover":
        return _cover(d, names, env)
    raise Failed(f"not a derivation: rule {d.get('rule')!r} with nothing to combine")


def _fact(i: str, names: set, env: dict, kinds: tuple = ()) -> dict:
    """The obligation ``i``: one the sub-claim names, of the expected kind, verified."""
    ob = env["obligations"][i] if i in names else None
    if ob is None or kinds and ob.get("kind") not in kinds:
        raise Failed(f"the derivation names {i}, which the sub-claim does not name" if ob is None
                     else f"{i} is a {ob.get('kind')}, not a {' or '.join(kinds)}")
    if i not in env["verified"]:
        raise Unsupported(f"{i} is not verified")
    return ob


def _expect(e: dict, names: set, env: dict) -> bool:
    """The obligation has the asserted value (compared as JSON: 1 is not true)."""
    (field, want), = [(k, v) for k, v in e.items() if k != "id"] or [(None, None)]
    ob = _fact(e["id"], names, env)
    got = [len(row) for row in ob["signs"]] if field == "branches" and ob["kind"] == "sign_table" else ob.get(field)
    if field in (None, "id", "kind") or got is None and field not in ob:
        raise Failed(f"{e['id']} has no value {field!r}")
    return json.dumps(got) == json.dumps(want)


def _condition(ob: dict) -> str:    # the condition of a table or a point fact: cp and g's parts
    return json.dumps([ob["cp"], ob["parts"]], sort_keys=True)


def _cover(d: dict, names: set, env: dict) -> bool:
    """The queries (and point facts, kind branch_signs_at: the signs on the branches at an algebraic r)
    give every point of ]lo, hi[ (and its ``closed`` ends) on one branch of one condition; the
    conclusion: every sign found is allowed."""
    allowed, branch, qs = {_key(s) for s in d["signs"]}, d["branch"], d["queries"]
    lo, hi = Algebraic.of(d["lo"]), Algebraic.of(d["hi"])
    if lo.compare(hi) >= 0 or not qs:
        raise Failed("an empty cover")
    at, need, found = lo, [], set()
    for k, i in enumerate(qs):
        q = _fact(i, names, env, ("signs_query",))
        table = env["obligations"][q["table"]]
        if _condition(table) != _condition(env["obligations"][env["obligations"][qs[0]]["table"]]):
            raise Failed(f"{i} reads another condition than {qs[0]}")
        if q["branch"] != branch:
            raise Failed(f"{i} is on branch {q['branch']}, not {branch}")
        ends = load_table(table)[2]
        a, b = (Algebraic.of(q[e]) if q[e] is not None else ends[j] for e, j in (("lo", 0), ("hi", -1)))
        if a.compare(at) != 0:
            raise Failed(f"{i} does not start {'at lo' if k == 0 else 'where ' + qs[k - 1] + ' ends'}")
        need += ([at] if k else []) + ([] if q["include_points"] else
                                       [e for e in ends[1:-1] if a.compare(e) < 0 < b.compare(e)])
        found |= {_key(s) for s in q["result"]}
        at = b
    if at.compare(hi) != 0:
        raise Failed(f"the last query, {qs[-1]}, does not end at hi")
    need += [e for e, c in zip((lo, hi), d.get("closed", [False, False])) if c]
    points = [_fact(i, names, env, ("branch_signs_at",)) for i in d.get("points", [])]
    for e in need:
        row = next((p["signs"] for p in points if _condition(p) == _condition(table)
                    and Algebraic.of(p["r"]).compare(e) == 0), [])
        got = row[branch] if branch < len(row) else "missing" if row else "?"
        if got == "?":
            raise Failed(f"no point fact gives branch {branch} at r ≈ {float(e.lo):.6f}, which the queries leave out")
        found.add(_key(got))
    return found <= allowed
