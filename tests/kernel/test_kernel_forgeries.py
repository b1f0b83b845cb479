"""Forgeries (issue 34, "Done when"): the run writes certificates.json (format 2) for T1, T5, T17
and S2; the kernel verifies it against the repository's statement files, and rejects, with a
message naming the certificate and the statement, every forgery of either side: a threshold,
printed digits, a coefficient or a closed form of the statement file changed; a status flipped
(ERRATUM → PASS), a verdict flipped, a statement missing or added, in either file; a witness
forged (it does not multiply out, a form not congruent, a sign read off terms of mixed signs).

The statement files are a copy of statements/ under tmp_path, changed there; the certificates
file is the run's, changed in memory.  A certificate whose engine checks do not yet name their
statements (an empty "statements" in the run's entry) is given the entry a correct run writes
(:func:`honest_entry`), so that the statement file's side is still tested."""
from __future__ import annotations

import copy
import json
import re
import shutil

import pytest

from certify_kernel.__main__ import main
from certify_kernel.statements import DEFAULT as STATEMENTS
from certify_kernel.statements import read
from tests.kernel.kernel_support import honest_entry
from tests.kernel.test_kernel_signs import BINDERS, TAMPERINGS, E, tampered, witness

IDS = ["T1", "T5", "T17", "S2"]


@pytest.fixture(scope="module")
def run_file() -> dict:
    """certificates.json of a run of IDS, as report.render_certificates writes it."""
    from certify.run import report, runner
    results, _ = runner.run_selected(IDS)
    data = json.loads(report.render_certificates(results))
    paper = read(STATEMENTS)
    mine = {c.id: c for c in paper.certificates}
    for k, c in enumerate(data["certificates"]):
        if not c["statements"] and c["id"] in mine:
            data["certificates"][k] = honest_entry(mine[c["id"]])
    return data


@pytest.fixture()
def statements(tmp_path):
    return shutil.copytree(STATEMENTS, tmp_path / "statements")


def kernel(tmp_path, data: dict, statements, ids=IDS, capsys=None) -> tuple[int, str]:
    path = tmp_path / "certificates.json"
    path.write_text(json.dumps(data, ensure_ascii=False), encoding="utf-8")
    code = main([str(path), "--statements", str(statements), "--only", *ids, "--jobs", "1"])
    return code, capsys.readouterr().out if capsys else ""


def entry(data: dict, cid: str) -> dict:
    return next(c for c in data["certificates"] if c["id"] == cid)


def edit(statements, name: str, old: str, new: str, count: int = 1) -> None:
    path = statements / name
    text = path.read_text(encoding="utf-8")
    assert text.count(old) >= 1, f"{old!r} is no longer in {name}: update the forgery"
    path.write_text(text.replace(old, new, count), encoding="utf-8")


def set_verdict(statements, name: str, sid: str, verdict: str) -> None:
    """The verdict of statement ``sid`` (whatever its line) rewritten."""
    path = statements / name
    text, n = re.subn(rf"^({re.escape(sid)}\s+l\.\s*\S+\s+)(holds|refuted by \S+|corrects \S+)", rf"\g<1>{verdict}",
                      path.read_text(encoding="utf-8"), flags=re.M)
    assert n == 1, f"{sid} is no longer in {name}: update the forgery"
    path.write_text(text, encoding="utf-8")


def all_verified(lines: list, cid: str, status: str) -> bool:
    """The certificate's line says STATUS, K/K statements verified."""
    m = next((re.match(rf"{cid}: {status}, (\d+)/(\d+) statements verified$", line) for line in lines
              if line.startswith(f"{cid}: ")), None)
    return bool(m) and m.group(1) == m.group(2)


def test_the_run_is_verified(run_file, statements, tmp_path, capsys):
    code, out = kernel(tmp_path, run_file, statements, capsys=capsys)
    assert code == 0, out
    lines = out.splitlines()
    assert all_verified(lines, "T1", "PASS") and all_verified(lines, "T5", "PASS")
    assert all_verified(lines, "T17", "ERRATUM") and all_verified(lines, "S2", "ERRATUM")
    assert lines[-1].startswith("4 certificates, 0 failed")


# ------------------------------------------------------------------ the statement file changed

STATEMENT_FORGERIES = {
    "the threshold 5-2√6 → 5-2√7": ("3_theorem.txt", "let r1 = 5-2√6", "let r1 = 5-2√7", ["T17"],
                                    "T17: FAILED: T17.1 (3_theorem.txt:"),          # 5-2√7 < 0: ]0, r1[ is empty
    "the threshold 5-2√6 → 5-2√5": ("3_theorem.txt", "let r1 = 5-2√6", "let r1 = 5-2√5", ["T17"],
                                    "T17: FAILED: T17.1: the statement file says it holds; the kernel finds it false"),
    "the digits 0.11384 → 0.11390": ("3_theorem.txt", "rstar ≈ 0.11384", "rstar ≈ 0.11390", ["T5"],
                                     "T5: FAILED: T5.3: the statement file says it holds; the kernel finds it false"),
    "a coefficient of P0, 646 → 647": ("3_theorem.txt", "41*r^10 - 646*r^9", "41*r^10 - 647*r^9", ["T5"],
                                       "T5: FAILED: T5.1: the statement file says it holds; the kernel finds it false"),
    "an entry of the printed M": ("3_theorem.txt", "(r - 1)^3*(r^3 - 3*r^2 - 5*r - 9)/64",
                                  "(r - 1)^3*(r^3 - 3*r^2 - 5*r - 7)/64", ["T1"],
                                  "T1: FAILED: T1.1: the statement file says it holds; the kernel finds it false"),
    "the closed form (7-2√10)/3 → (7-2√11)/3": ("3_theorem.txt", "let r0 = (7-2√10)/3", "let r0 = (7-2√11)/3", ["T17"],
                                               "T17: FAILED: T17.6: the statement file says it holds; the kernel finds "
                                               "it false (at r = ≈0.2251"),
    "the erratum's correction weakened to the printed text": (
        "3_theorem.txt", "(a - d)^2 + 4*b*c < 0 or r = r0", "(a - d)^2 + 4*b*c < 0", ["T17"],
        "T17: FAILED: T17.6: the statement file says it holds; the kernel finds it false"),
    "a refuted statement said to hold (status ERRATUM → PASS)": ("3_theorem.txt", None, None, ["T17"], None),
    "a statement missing": ("3_theorem.txt", "T5.3  l. 350  holds  \"r* ≈ 0.11384\"\n      rstar ≈ 0.11384\n", "",
                            ["T5"], "T5: FAILED: statement T5.3: not in both certificates.json and the statement file"),
    "a statement added": ("3_theorem.txt", "T5.3  l. 350",
                          "T5.4  l. 350  holds  \"P0 ≠ 0\"\n      P0 ≠ 0\nT5.3  l. 350",
                          ["T5"], "T5: FAILED: statement T5.4: not in both certificates.json and the statement file"),
}


SLOW = {"the closed form (7-2√10)/3 → (7-2√11)/3", "the erratum's correction weakened to the printed text"}


@pytest.mark.parametrize("name", [pytest.param(n, marks=pytest.mark.slow) if n in SLOW else n
                                  for n in STATEMENT_FORGERIES])
def test_a_forged_statement_file_is_rejected(run_file, statements, tmp_path, capsys, name):
    file, old, new, ids, says = STATEMENT_FORGERIES[name]
    if old is None:                        # every refuted statement of T17 and its correction said to hold
        for sid in ("T17.5", "T17.6", "T17.7", "T17.8"):
            set_verdict(statements, file, sid, "holds")
        says = "T17: FAILED: the run says ERRATUM, its statements' verdicts make it PASS"
    else:
        edit(statements, file, old, new)
    code, out = kernel(tmp_path, run_file, statements, ids, capsys)
    assert code == 1 and says in out, out


def test_the_erratum_cannot_be_hidden_by_changing_both_files(run_file, statements, tmp_path, capsys):
    """T17's refuted statements (l. 436-437) said to hold in the statement file and in the run's
    file: the statuses agree (PASS), the verdicts agree, and the kernel decides T17.5 false: the
    certificate fails."""
    data = copy.deepcopy(run_file)
    entry(data, "T17").update(status="PASS")
    for sid in ("T17.5", "T17.6", "T17.7", "T17.8"):
        set_verdict(statements, "3_theorem.txt", sid, "holds")
        entry(data, "T17")["statements"][sid]["verdict"] = "holds"
    code, out = kernel(tmp_path, data, statements, ["T17"], capsys)
    assert code == 1 and "T17: FAILED: T17.5: the statement file says it holds; the kernel finds it false (at r = " \
        "≈0.2251" in out, out


# ------------------------------------------------------------------ the run's file changed

RUN_FORGERIES = {
    "a status flip ERRATUM → PASS (T17)": (lambda d: entry(d, "T17").update(status="PASS"), ["T17"],
                                           "T17: FAILED: the run says PASS, its statements' verdicts make it ERRATUM"),
    "a status flip ERRATUM → PASS (S2)": (lambda d: entry(d, "S2").update(status="PASS"), ["S2"],
                                          "S2: FAILED: the run says PASS, its statements' verdicts make it ERRATUM"),
    "a status flip PASS → ERRATUM": (lambda d: entry(d, "T5").update(status="ERRATUM"), ["T5"],
                                     "T5: FAILED: the run says ERRATUM, its statements' verdicts make it PASS"),
    "a verdict flip holds → refuted": (lambda d: entry(d, "T5")["statements"]["T5.2"].update(verdict="refuted"), ["T5"],
                                       "T5: FAILED: statement T5.2: the run's verdict 'refuted' is not the statement "
                                       "file's holds"),
    "a verdict flip refuted → holds": (lambda d: entry(d, "S2")["statements"]["S2.8"].update(verdict="holds"), ["S2"],
                                       "S2: FAILED: statement S2.8: the run's verdict 'holds' is not the statement "
                                       "file's refuted"),
    "a correction said refuted": (lambda d: entry(d, "S2")["statements"]["S2.9"].update(verdict="refuted"), ["S2"],
                                  "S2: FAILED: statement S2.9: the run's verdict 'refuted' is not the statement "
                                  "file's holds"),
    "a statement missing": (lambda d: entry(d, "T1")["statements"].pop("T1.9"), ["T1"],
                            "T1: FAILED: statement T1.9: not in both certificates.json and the statement file"),
    "a statement added": (lambda d: entry(d, "T1")["statements"].update({"T1.99": {"verdict": "holds"}}), ["T1"],
                          "T1: FAILED: statement T1.99: not in both certificates.json and the statement file"),
    "a certificate missing": (lambda d: d["certificates"].remove(entry(d, "T5")), ["T5"],
                              "T5: FAILED: certificates.json has no entry for it"),
    "a certificate of no statement file": (lambda d: d["certificates"].append(
        {"id": "T99", "status": "PASS", "statements": {}}), ["T1"],
        "T99: FAILED: certificates.json has it, the statement files do not"),
    # the old format's forgeries (issue 34): the run chose an object, a modulus, a cover, a count; none is read
    "an object replaced in every fact (P0 for T5)": (lambda d: entry(d, "T5").update(
        obligations=[{"id": "T5:1", "kind": "root_count", "poly": ["11384", "-100000"], "count": 1}]), ["T5"],
        "T5: FAILED: the field 'obligations': the kernel reads verdicts and witnesses only"),
    "a file-chosen modulus": (lambda d: entry(d, "T17")["statements"]["T17.1"].update(
        modulo={"var": "r", "poly": [["1", [1, 0]], ["-1/2", [0, 0]]]}), ["T17"],
        "T17: FAILED: statement T17.1: the field 'modulo': the kernel reads verdicts and witnesses only"),
    "a '?' cover": (lambda d: entry(d, "T17")["statements"]["T17.5"].update(
        derivation={"rule": "cover", "signs": ["?"], "branch": 0}), ["T17"],
        "T17: FAILED: statement T17.5: the field 'derivation': the kernel reads verdicts and witnesses only"),
    "a reversed count": (lambda d: entry(d, "T5")["statements"]["T5.2"].update(
        witness=[{"kind": "root_count", "lo": "1", "hi": "0", "count": -1}]), ["T5"],
        "T5: FAILED: statement T5.2: a witness of no kind the kernel reads"),
}


@pytest.mark.parametrize("name", list(RUN_FORGERIES))
def test_a_forged_run_file_is_rejected(run_file, statements, tmp_path, capsys, name):
    change, ids, says = RUN_FORGERIES[name]
    data = copy.deepcopy(run_file)
    change(data)
    code, out = kernel(tmp_path, data, statements, ids, capsys)
    assert code == 1 and says in out, out


def test_forged_witnesses_in_the_run_change_no_decision(run_file, statements, tmp_path, capsys):
    """S2's witnesses (the engine's signed facts), every one forged: the numbers of every factor
    doubled.  The kernel uses none of them (none multiplies out) and decides S2 as before."""
    data = copy.deepcopy(run_file)
    n = 0
    for rec in entry(data, "S2")["statements"].values():
        for w in rec.get("witness", []):
            for part in ("num", "den"):
                for f in w[part]["factors"]:
                    f["poly"] = [[str(2 * int(c.split("/")[0])) + ("/" + c.split("/")[1] if "/" in c else ""), e]
                                 for c, e in f["poly"]]
                    n += 1
    assert n > 0
    honest = kernel(tmp_path, run_file, statements, ["S2"], capsys)
    forged = kernel(tmp_path, data, statements, ["S2"], capsys)
    assert honest[0] == forged[0] == 0
    assert honest[1].splitlines()[0] == forged[1].splitlines()[0]


WITNESSED = f'''angles θ, φ
certificate Z8  l. 1  "a strict sign over several variables that needs its witness"
Z8.1  l. 1  holds  "E > 0"
      {BINDERS}: {E} > 0
Z8.2  l. 1  holds  "cos θ - sin θ > 0 (false at θ = π/3: terms of mixed signs)"
      {BINDERS}: cos(θ) - sin(θ) > 0
'''


@pytest.mark.parametrize("name", ["none", "factors that do not multiply to the form",
                                  "a form not congruent to the numerator",
                                  "a factor's form of mixed signs (its own terms)",
                                  "a factor's form not congruent to it"])
def test_a_forged_witness_is_rejected_naming_the_statement(statements, tmp_path, capsys, name):
    (statements / "9_witnessed.txt").write_text(WITNESSED, encoding="utf-8")
    w = witness() if name == "none" else tampered(TAMPERINGS[name])
    data = {"format": "certify-certificates/2", "certificates": [
        {"id": "Z8", "status": "PASS", "statements": {"Z8.1": {"verdict": "holds", "witness": [w]},
                                                      "Z8.2": {"verdict": "holds", "witness": [witness()]}}}]}
    code, out = kernel(tmp_path, data, statements, ["Z8"], capsys)
    assert code == 0, out                                 # nothing contradicts: the signs are not shown
    first = out.splitlines()[0]
    if name == "none":
        assert first == "Z8: PASS, 1/2 statements verified; not verified: Z8.2 (no witness shows the sign of an atom)"
    else:
        assert first == "Z8: PASS, 0/2 statements verified; not verified: " \
            "Z8.1 (no witness shows the sign of an atom), " \
            "Z8.2 (no witness shows the sign of an atom)"
