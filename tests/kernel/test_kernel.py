"""The independent kernel (certify_kernel): a certificates file written by the run is verified,
every tampering of it is rejected with a message naming the obligation, and the kernel needs
nothing but the standard library.  The file is made from a few certificates (L1: digits and a
sign table; T1: a product of matrices; T4: a resultant; T5: Sturm counts; T9: an identity modulo cp;
T17: sign tables with √Δ; S2: signs by inspection; S3: trigonometric identities)."""
from __future__ import annotations

import ast
import json
import subprocess
import sys
from fractions import Fraction
from pathlib import Path

import pytest

import certify_kernel
from certify import cli
from certify.run import report, runner
from tests.shared import certificate_of, certificates_file

ROOT = Path(__file__).resolve().parents[2]
IDS = ["L1", "T1", "T4", "T5", "T9", "T17", "S2", "S3"]


@pytest.fixture(scope="module")
def data() -> dict:
    return certificates_file(IDS)


cert = certificate_of


def first(c: dict, kind: str, test=lambda ob: True) -> dict:
    return next(ob for ob in c["obligations"] if ob["kind"] == kind and test(ob))


def rejected(c: dict, oid: str) -> str:
    """The kernel rejects ``c``, naming obligation ``oid``; its message."""
    out = certify_kernel.verify_certificate(c)
    assert not out["ok"], "the tampered certificate was accepted"
    assert oid in out["failure"], out["failure"]
    return out["failure"]


def test_the_run_writes_obligations_that_the_kernel_verifies(data):
    assert data["format"] == certify_kernel.FORMAT
    for c in data["certificates"]:
        out = certify_kernel.verify_certificate(c)
        assert out["ok"], out["failure"]
        assert out["verified"] > 0, c["id"]
    kinds = {ob["kind"] for c in data["certificates"] for ob in c["obligations"]}
    assert {"digits", "root_count", "sign_table", "signs_query", "identity", "signed", "resultant"} <= kinds


@pytest.mark.slow
def test_the_file_is_deterministic(data):
    """A second run writes the same obligations (slow: CI's `certify all --check` regenerates the
    whole file and compares it with the committed one, and the fresh-clone test compares --jobs 1
    with every core)."""
    again, _ = runner.run_selected(IDS)
    assert json.loads(report.render_certificates(again)) == data


def test_a_changed_coefficient_is_rejected(data):
    c = cert(data, "L1")
    ob = first(c, "digits", lambda ob: isinstance(ob["number"], dict))
    ob["number"]["poly"][0] = str(int(ob["number"]["poly"][0]) + 1)
    rejected(c, ob["id"])


def test_a_changed_coefficient_of_cp_is_rejected(data):
    c = cert(data, "T17")
    ob = first(c, "sign_table")
    coef, exps = ob["cp"][0]
    ob["cp"][0] = [str(int(coef) + 7), exps]
    rejected(c, ob["id"])


def test_a_changed_root_count_is_rejected(data):
    c = cert(data, "T5")
    ob = first(c, "root_count")
    ob["count"] += 1
    assert "Sturm counts" in rejected(c, ob["id"])


def test_a_changed_sign_is_rejected(data):
    c = cert(data, "T17")
    ob = first(c, "sign_table", lambda ob: any(s in (1, -1) for row in ob["signs"] for s in row))
    row = next(row for row in ob["signs"] if any(s in (1, -1) for s in row))
    k = next(i for i, s in enumerate(row) if s in (1, -1))
    row[k] = -row[k]
    assert "the sign at r" in rejected(c, ob["id"])


def test_a_changed_interval_end_is_rejected(data):
    c = cert(data, "L1")
    ob = first(c, "digits", lambda ob: isinstance(ob["number"], dict))
    ob["number"]["hi"] = "14"          # r^2 - 14r + 1 has two roots in ]lo, 14]
    assert "not an isolated" in rejected(c, ob["id"]) or "roots" in rejected(c, ob["id"])


def test_a_moved_cell_end_is_rejected(data):
    """Two cells merged into one across a critical value: a bounding polynomial has a root inside."""
    c = cert(data, "T17")
    ob = first(c, "sign_table", lambda ob: len(ob["ends"]) >= 3)
    del ob["ends"][1], ob["samples"][1], ob["signs"][1]
    assert "root inside" in rejected(c, ob["id"])


def test_a_removed_obligation_is_rejected(data):
    c = cert(data, "S3")
    sub = next(s for s in c["subclaims"] if s["obligations"])
    gone = sub["obligations"][0]
    c["obligations"] = [ob for ob in c["obligations"] if ob["id"] != gone]
    assert "missing obligation" in rejected(c, gone)


def test_a_changed_identity_is_rejected(data):
    c = cert(data, "S3")
    ob = first(c, "identity", lambda ob: ob["holds"] and ob["lhs"][0]["num"])
    coef, exps = ob["lhs"][0]["num"][0]
    ob["lhs"][0]["num"][0] = [str(Fraction(coef) + 1), exps]
    assert "not equal" in rejected(c, ob["id"])


def test_a_swapped_branch_is_rejected(data):
    c = cert(data, "T17")
    ob = first(c, "signs_query")
    table = next(t for t in c["obligations"] if t["id"] == ob["table"])
    ob["branch"] = next(k for k in range(3) if any(k != ob["branch"] and k < len(row) for row in table["signs"]))
    rejected(c, ob["id"])


def test_the_kernel_imports_only_the_standard_library():
    for path in (ROOT / "certify_kernel").glob("*.py"):
        for node in ast.walk(ast.parse(path.read_text())):
            names = [a.name for a in node.names] if isinstance(node, ast.Import) else \
                [node.module] if isinstance(node, ast.ImportFrom) and node.level == 0 else []
            for name in names:
                assert name.split(".")[0] in sys.stdlib_module_names or name == "__future__", (path, name)


def write(tmp_path: Path, data: dict, name: str = "certificates.json") -> Path:
    path = tmp_path / name
    path.write_text(json.dumps(data, ensure_ascii=False))
    return path


def test_a_bare_python_runs_the_kernel(tmp_path, data):
    """-S: no site-packages (neither SymPy nor python-flint importable), -E: no PYTHONPATH."""
    path = write(tmp_path, data)
    done = subprocess.run([sys.executable, "-S", "-E", "-m", "certify_kernel", str(path), "--only", "L1", "T5"],
                          cwd=ROOT, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stdout + done.stderr
    assert "L1: " in done.stdout and "T5: " in done.stdout and "T17" not in done.stdout


def test_certify_verify_exit_codes(tmp_path, data, capsys):
    good = write(tmp_path, {**data, "certificates": [cert(data, "L1"), cert(data, "T5")]}, "good.json")
    bad_cert = cert(data, "T5")
    first(bad_cert, "root_count")["count"] += 1
    bad = write(tmp_path, {**data, "certificates": [cert(data, "L1"), bad_cert]}, "bad.json")
    env = {"PYTHONPATH": str(ROOT), "PATH": "/usr/bin:/bin"}

    def verify(*args):
        return subprocess.run([sys.executable, "-m", "certify", "verify", *args, "--jobs", "1"], cwd=ROOT, env=env,
                              capture_output=True, text=True, timeout=300)

    def verify_here(*args) -> tuple[int, str]:         # the same command, without a new interpreter
        code = cli.main(["verify", *args, "--jobs", "1"])
        return code, capsys.readouterr().out
    ok = verify(str(good))                             # the real program, as a user runs it
    assert ok.returncode == 0, ok.stdout + ok.stderr
    code, out = verify_here(str(bad))
    assert code == 1 and "T5: FAILED: obligation T5:" in out
    assert verify_here(str(tmp_path / "none.json"))[0] == 2


def test_a_changed_entry_of_a_product_is_rejected(data):
    c = cert(data, "T1")
    ob = first(c, "identity", lambda ob: isinstance(ob["lhs"], dict) and ob["holds"])
    coef, exps = ob["lhs"]["product"][0]["entries"][0]["num"][0]
    ob["lhs"]["product"][0]["entries"][0]["num"][0] = [str(Fraction(coef) * 2), exps]
    assert "not equal" in rejected(c, ob["id"])


def test_a_changed_resultant_is_rejected(data):
    c = cert(data, "T4")
    ob = first(c, "resultant")
    ob["poly"][0] = str(Fraction(ob["poly"][0]) + 1)
    rejected(c, ob["id"])


def test_a_changed_sign_hypothesis_is_rejected(data):
    """A sign by inspection rests on the signs of the atoms: flip one it uses."""
    c = cert(data, "S2")
    ob = first(c, "signed", lambda ob: any(f["how"] == "terms" for f in ob["num"]["factors"] + ob["den"]["factors"])
               and ob["hyp"])
    used = next(name for name in ob["hyp"]
                if any(t[1][ob["vars"].index(name)] % 2 for f in ob["num"]["factors"] + ob["den"]["factors"]
                       if f["how"] == "terms" for t in f["form"]))
    ob["hyp"][used] = -ob["hyp"][used]
    rejected(c, ob["id"])


def test_the_file_follows_its_schema(data):
    jsonschema = pytest.importorskip("jsonschema")
    schema = json.loads((ROOT / "certify_kernel" / "certificates.schema.json").read_text())
    jsonschema.validate(data, schema)


def test_a_changed_modulus_is_rejected(data):
    c = cert(data, "T9")
    ob = first(c, "identity", lambda ob: "modulo" in ob)
    coef, exps = ob["modulo"]["poly"][0]
    ob["modulo"]["poly"][0] = [str(Fraction(coef) + 1), exps]
    rejected(c, ob["id"])
