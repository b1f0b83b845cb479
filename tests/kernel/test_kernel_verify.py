"""A certificate against its entry of certificates.json (certify_kernel.__init__) and the command
(python3 -m certify_kernel): the status computed from the statements' verdicts, the run's status
and verdicts compared with the statement files', the statements of both sides the same, one line
per certificate; exit 0, 1 when a certificate fails, 2 on bad input with a one-line error and
never a traceback."""
from __future__ import annotations

import json
import subprocess
import sys

import pytest

import certify_kernel
from certify_kernel.__main__ import main
from certify_kernel.statements import Statement, read
from tests.kernel.kernel_support import ROOT, dump, honest_file, write_statements

TEXT = '''let P = r^2 - 10*r + 1                                   # l. 291
certificate Z1  l. 291  "P has one root in ]0,1[, 5-2√6 ≈ 0.10102."
Z1.1  l. 291  holds  "one root in ]0,1["
      count(P, ]0, 1[) = 1
Z1.2  l. 291  holds  "it is 5-2√6"
      root(P, ]0, 1[) = 5-2√6
Z1.3  l. 291  holds  "≈ 0.10102"
      5-2√6 ≈ 0.10102
Z1.4  l. 291  holds  "not yet said in the language"
      unformalised "a reason"
certificate Z2  l. 292  "P(r) > 0 below its root (printed: below 1/5)."
Z2.1  l. 292  refuted by Z2.2  "P > 0 for r < 1/5"
      forall r in ]0, 1/5[: P > 0
Z2.2  l. 292  corrects Z2.1  "P > 0 for r < 5-2√6"
      forall r in ]0, 5-2√6[: P > 0
certificate Z3  l. 293  "an observation"
Z3.1  l. 293  observed  "windows"
'''


@pytest.fixture()
def files(tmp_path):
    statements = write_statements(tmp_path / "statements", TEXT)
    paper = read(statements)
    return statements, paper, honest_file(paper)


def run(tmp_path, statements, data, *extra) -> tuple[int, str, str]:
    """main() on a certificates file holding ``data`` (or the text itself)."""
    path = tmp_path / "certificates.json"
    path.write_text(data if isinstance(data, str) else json.dumps(data), encoding="utf-8")
    return main([str(path), "--statements", str(statements), "--jobs", "1", *extra])


def S(verdict: str) -> Statement:
    return Statement("Z9.1", "l. 1", verdict, "", "t", formula="r = r")


def test_the_status_follows_from_the_verdicts():
    assert certify_kernel.status_of([S("holds"), S("holds")]) == "PASS"
    assert certify_kernel.status_of([S("holds"), S("refuted"), S("corrects")]) == "ERRATUM"
    assert certify_kernel.status_of([S("observed"), S("observed")]) == "OBSERVED"
    assert certify_kernel.status_of([S("observed"), S("holds")]) == "PASS"
    assert certify_kernel.status_of([S("observed"), S("refuted"), S("corrects")]) == "ERRATUM"


def test_an_honest_file_is_verified(files, tmp_path, capsys):
    statements, paper, data = files
    assert run(tmp_path, statements, data, "--verbose") == 0
    out = capsys.readouterr().out.splitlines()
    assert out[0] == "Z1: PASS, 3/4 statements verified; not verified: Z1.4 (not formalised: a reason)"
    assert "    Z1.1: verified" in out and "    Z1.4: not verified: not formalised: a reason" in out
    assert "Z2: ERRATUM, 2/2 statements verified" in out
    assert "Z3: OBSERVED (an observation: nothing to verify)" in out
    assert out[-1].startswith("3 certificates, 0 failed (") and out[-1].endswith("5/6 statements verified")


def entry(data: dict, cid: str) -> dict:
    return next(c for c in data["certificates"] if c["id"] == cid)


REJECTIONS = {
    "a status flip ERRATUM → PASS": (lambda d: entry(d, "Z2").update(status="PASS"),
                                     "Z2: FAILED: the run says PASS, its statements' verdicts make it ERRATUM"),
    "a status flip PASS → ERRATUM": (lambda d: entry(d, "Z1").update(status="ERRATUM"),
                                     "Z1: FAILED: the run says ERRATUM, its statements' verdicts make it PASS"),
    "a status flip OBSERVED → PASS": (lambda d: entry(d, "Z3").update(status="PASS"), "Z3: FAILED: the run says PASS"),
    "a verdict flip holds → refuted": (lambda d: entry(d, "Z1")["statements"]["Z1.2"].update(verdict="refuted"),
                                       "Z1: FAILED: statement Z1.2: the run's verdict 'refuted' is not the statement "
                                       "file's holds"),
    "a verdict flip refuted → holds": (lambda d: entry(d, "Z2")["statements"]["Z2.1"].update(verdict="holds"),
                                       "Z2: FAILED: statement Z2.1: the run's verdict 'holds' is not the statement "
                                       "file's refuted"),
    "a corrected statement said refuted": (lambda d: entry(d, "Z2")["statements"]["Z2.2"].update(verdict="refuted"),
                                           "statement Z2.2: the run's verdict 'refuted'"),
    "an observation said to hold": (lambda d: entry(d, "Z3")["statements"]["Z3.1"].update(verdict="holds"),
                                    "statement Z3.1: the run's verdict 'holds' is not the statement file's observed"),
    "a verdict that is not a record": (lambda d: entry(d, "Z1")["statements"].update({"Z1.1": "holds"}),
                                       "statement Z1.1: the field '(not an object)': the kernel reads verdicts"),
    "a verdict missing": (lambda d: entry(d, "Z1")["statements"]["Z1.3"].pop("verdict"),
                          "statement Z1.3: the run's verdict None is not"),
    "a statement missing": (lambda d: entry(d, "Z1")["statements"].pop("Z1.3"),
                            "Z1: FAILED: statement Z1.3: not in both certificates.json and the statement file"),
    "a statement added": (lambda d: entry(d, "Z1")["statements"].update({"Z1.5": {"verdict": "holds"}}),
                          "Z1: FAILED: statement Z1.5: not in both"),
    "a certificate missing": (lambda d: d["certificates"].remove(entry(d, "Z2")),
                              "Z2: FAILED: certificates.json has no entry for it"),
    "a certificate added": (lambda d: d["certificates"].append({"id": "Z4", "status": "PASS", "statements": {}}),
                            "Z4: FAILED: certificates.json has it, the statement files do not"),
}


@pytest.mark.parametrize("name", list(REJECTIONS))
def test_a_forged_certificates_file_is_rejected(files, tmp_path, capsys, name):
    statements, paper, data = files
    edit, says = REJECTIONS[name]
    edit(data)
    assert run(tmp_path, statements, data) == 1
    out = capsys.readouterr().out
    assert says in out, out
    assert " 1 failed " in out.splitlines()[-1] or out.splitlines()[-1].startswith("3 certificates, 1 failed")


def test_witnesses_of_a_kind_the_kernel_reads_change_nothing_elsewhere(files, tmp_path, capsys):
    statements, paper, data = files
    for w in ([], [{"kind": "signed", "num": 1}], [{"kind": "factors", "factors": 5}]):
        entry(data, "Z1")["statements"]["Z1.1"]["witness"] = w
        assert run(tmp_path, statements, data) == 0, capsys.readouterr().out


def test_witnesses_of_another_shape_are_rejected(files, tmp_path, capsys):
    statements, paper, data = files
    for w in (5, "a", {"num": 1}, [None, 1, "x", {"vars": 5}], [{"kind": "sign_table"}]):
        entry(data, "Z1")["statements"]["Z1.1"]["witness"] = w
        assert run(tmp_path, statements, data) == 1
        assert "statement Z1.1: a witness of no kind the kernel reads" in capsys.readouterr().out


@pytest.mark.parametrize("edit, says", [
    (("Z1.2", "5-2√6", "5-2√7"), "Z1: FAILED: Z1.2: the statement file says it holds; the kernel finds it false"),
    (("Z1.3", "0.10102", "0.10103"), "Z1: FAILED: Z1.3: the statement file says it holds; the kernel finds it false"),
    (("Z1.1", "= 1", "= 2"), "Z1: FAILED: Z1.1: the statement file says it holds"),
    (("Z2.2", "]0, 5-2√6[", "]0, 1/5["), "Z2: FAILED: Z2.2: the statement file says it holds; the kernel finds it "
                                        "false (at r = ≈0.1010205144)"),
    (("Z2.1", "]0, 1/5[", "]0, 1/11["),
     "Z2: FAILED: Z2.1: the statement file says it is refuted; the kernel finds it true"),
    (("let P", "10*r", "11*r"), "FAILED"),
    (("Z1.2", "root(P, ]0, 1[)", "root(P, ]0, 1)"), "Z1: FAILED: Z1.2 (1_test.txt:5): an interval ends with"),
    (("Z1.2", "root(P, ]0, 1[)", "root(Q, ]0, 1[)"), "Z1: FAILED: Z1.2 (1_test.txt:5): Q is not defined"),
    (("Z1.2", "root(P, ]0, 1[) = 5-2√6", "roots(P) = {5-2√6}"), "Z1: FAILED: Z1.2 (1_test.txt:5): the kernel cannot"),
])
def test_a_changed_statement_file_fails_naming_the_statement(tmp_path, capsys, edit, says):
    """The run's file is the honest one of the original statements; the statement file is then changed."""
    where, old, new = edit
    data = honest_file(read(write_statements(tmp_path / "original", TEXT)))
    lines = TEXT.splitlines(keepends=True)
    k = next(i for i, line in enumerate(lines) if line.startswith(where))
    k = k if where.startswith("let") else k + 1                    # the formula under the header
    assert old in lines[k]
    lines[k] = lines[k].replace(old, new)
    statements = write_statements(tmp_path / "changed", "".join(lines))
    assert run(tmp_path, statements, data) == 1
    out = capsys.readouterr().out
    assert says in out, out
    assert "Traceback" not in out


# ------------------------------------------------------------------ bad input: exit 2, one line

@pytest.mark.parametrize("content, says", [
    ("[]", "not a certificates file of format certify-certificates/2"),
    ('{"format": "certify-certificates/1", "certificates": []}', "not a certificates file of format"),
    ('{"format": "certify-certificates/2", "certificates": {"Z1": 1}}', "not a certificates file of format"),
    ('{"format": "certify-certificates/2", "certificates": [{"id": "Z1"}]}',
     "a certificate without an id or statements"),
    ('{"format": "certify-certificates/2", "certificates": [{"statements": {}}]}', "without an id"),
    ('{"format": "certify-certificates/2", "certificates": [{"id": "Z1", "statements": []}]}',
     "without an id or statements"),
    ('{"format": "certify-certificates/2", "certificates": ["Z1"]}', "without an id or statements"),
    ("{", "Expecting property name"),
    ("", "Expecting value"),
    (b"\xff\xfe", "codec can't decode"),
])
def test_bad_input_exits_2_with_one_line(files, tmp_path, capsys, content, says):
    statements, _, _ = files
    path = tmp_path / "certificates.json"
    path.write_bytes(content if isinstance(content, bytes) else content.encode())
    assert main([str(path), "--statements", str(statements), "--jobs", "1"]) == 2
    err = capsys.readouterr().err
    assert err.startswith("error: ") and says in err and err.count("\n") == 1, err


def test_missing_files_and_unknown_ids_exit_2(files, tmp_path, capsys):
    statements, _, data = files
    path = dump(data, tmp_path / "certificates.json")
    cases = [([str(tmp_path / "nothing.json"), "--statements", str(statements)], "No such file"),
             ([str(path), "--statements", str(tmp_path / "none")], "no statement files"),
             ([str(path), "--statements", str(statements), "--only", "Z7"], "no certificate Z7 in the statement files")]
    bad = write_statements(tmp_path / "bad", "let P = r\nlet P = r\n")
    cases.append(([str(path), "--statements", str(bad)], "P is defined twice"))
    for argv, says in cases:
        assert main(argv + ["--jobs", "1"]) == 2
        err = capsys.readouterr().err
        assert err.startswith("error: ") and says in err and err.count("\n") == 1, err


def test_only_checks_the_named_certificates(files, tmp_path, capsys):
    statements, _, data = files
    entry(data, "Z2").update(status="PASS")
    assert run(tmp_path, statements, data, "--only", "z1", "Z3") == 0
    out = capsys.readouterr().out
    assert "Z2" not in out and out.splitlines()[-1].startswith("2 certificates, 0 failed")


def bare(*args) -> subprocess.CompletedProcess:
    """python3 -m certify_kernel ARGS in a bare Python: -I (no PYTHON* variables, no user site) and -S
    (no site-packages at all: nothing installed is importable), the checkout alone on the path."""
    code = ("import runpy, sys; sys.path.insert(0, sys.argv.pop(1)); "
            "runpy.run_module('certify_kernel', run_name='__main__', alter_sys=True)")
    return subprocess.run([sys.executable, "-I", "-S", "-c", code, str(ROOT), *map(str, args)], cwd=ROOT,
                          capture_output=True, text=True, timeout=300)


def test_the_command_in_a_bare_python(files, tmp_path):
    """The command as a referee runs it, with the standard library alone: its exit codes and its
    lines, with one process and with two."""
    statements, _, data = files
    path = dump(data, tmp_path / "certificates.json")
    for jobs in ("1", "2"):
        out = bare(path, "--statements", statements, "--jobs", jobs)
        assert out.returncode == 0, out.stdout + out.stderr
        assert "Z2: ERRATUM, 2/2 statements verified" in out.stdout and not out.stderr
    entry(data, "Z2")["statements"]["Z2.1"]["verdict"] = "holds"
    out = bare(dump(data, path), "--statements", statements, "--jobs", "2")
    assert out.returncode == 1 and "Z2: FAILED: statement Z2.1" in out.stdout and "Traceback" not in out.stderr
    out = bare(tmp_path / "none.json")
    assert out.returncode == 2 and out.stderr.startswith("error: ") and "Traceback" not in out.stderr
    out = subprocess.run([sys.executable, "-I", "-S", "-c", "import sympy"], capture_output=True, text=True)
    assert out.returncode == 1, "a bare Python imports sympy: the test above proves nothing"


def test_the_kernel_imports_nothing_but_the_standard_library():
    """Every module of certify_kernel/ imports only the standard library and itself (import-linter
    checks it too; this test needs nothing installed)."""
    import ast
    allowed = set(sys.stdlib_module_names) | {"certify_kernel"}
    for path in sorted((ROOT / "certify_kernel").glob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Import):
                names = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom):
                names = [node.module or ""] if not node.level else []
            else:
                continue
            for name in names:
                assert name.split(".")[0] in allowed, f"{path.name} imports {name}"
