"""The statement files' format (certify_kernel.statements, docs/statements.md): declarations,
definitions continued on indented lines, certificates and their statements with a line, a
verdict and a text, comments outside quotes; and each malformed file refused with a FileError
that names the file and line."""
from __future__ import annotations

import pytest

import certify_kernel
from certify_kernel.statements import FileError, read
from tests.kernel.kernel_support import write_statements

GOOD = '''# a comment line
vars x, u                 # two variables
angles θ
let P = r^2 - 10*r + 1    # l. 291 (as printed)
let Q = r^3
        + 2*r             # a definition continued
let t0 = 5-2√6

certificate Z1  l. 290-292  "P has one root 5-2√6 in ]0,1[ (# inside quotes is text)."   # a comment
Z1.1  l. 291  holds  "P has exactly one root in ]0,1[ # not a comment"
      count(P, ]0, 1[) = 1
Z1.2  l. 291  refuted by Z1.3  "the root is 5-2√7"
      root(P, ]0, 1[) =
          5-2√7           # a formula continued
Z1.3  l. 291  corrects Z1.2  "the root is 5-2√6"
      root(P, ]0, 1[) = t0
Z1.4  l. 292  holds  "something the language cannot say"
      unformalised "the exact simulator"
Z1.5  l. 292  observed  "an observation"

certificate Z2  l. 300  "an observation"
Z2.1  l. 300  observed  "windows of stability"
'''


def test_a_good_file(tmp_path):
    paper = read(write_statements(tmp_path, GOOD))
    assert paper.vars == ["x", "u"] and paper.angles == ["θ"]
    assert paper.lets == {"P": "r^2 - 10*r + 1", "Q": "r^3 + 2*r", "t0": "5-2√6"}
    z1, z2 = paper.certificates
    assert (z1.id, z1.line, z2.id) == ("Z1", "l. 290-292", "Z2")
    assert z1.title == "P has one root 5-2√6 in ]0,1[ (# inside quotes is text)."
    s1, s2, s3, s4, s5 = z1.statements
    assert (s1.id, s1.line, s1.verdict, s1.formula) == ("Z1.1", "l. 291", "holds", "count(P, ]0, 1[) = 1")
    assert s1.text == "P has exactly one root in ]0,1[ # not a comment"
    assert (s2.verdict, s2.other, s2.formula) == ("refuted", "Z1.3", "root(P, ]0, 1[) = 5-2√7")
    assert (s3.verdict, s3.other) == ("corrects", "Z1.2")
    assert s4.unformalised == "the exact simulator" and not s4.formula
    assert s5.verdict == "observed" and not s5.printed and s1.printed and s2.printed and not s3.printed
    assert s1.where.endswith("1_test.txt:10")
    assert certify_kernel.status_of(z1.statements) == "ERRATUM"
    assert certify_kernel.status_of(z2.statements) == "OBSERVED"


def test_files_are_read_in_name_order_and_share_their_definitions(tmp_path):
    write_statements(tmp_path, "vars u\nlet P = r - 1/2\n", "1_a.txt")
    write_statements(tmp_path, "vars u, v\ncertificate Z1  l. 1  \"t\"\nZ1.1  l. 1  holds  \"t\"\n      P = r - 1/2\n",
                     "2_b.txt")
    paper = read(tmp_path)
    assert paper.vars == ["u", "u", "v"] and [c.id for c in paper.certificates] == ["Z1"]
    certify_kernel.prepare(paper)
    assert certify_kernel.check_statement(paper.certificates[0].statements[0], paper.lets) == (True, "")


HEADER = 'certificate Z1  l. 1  "t"\n'


@pytest.mark.parametrize("text, says", [
    ("let P = r\nlet P = r^2\n", "1_test.txt:2: P is defined twice"),
    ("let A = r\n", "A is both defined (let) and a variable or an object of the kernel"),
    ("vars u\nlet u = r\n", "u is both defined"),
    ("      r = r\n", "1_test.txt:1: an indented line that continues nothing"),
    ('Z1.1  l. 1  holds  "t"\n      r = r\n', "1_test.txt:1: the statement Z1.1 is not under its certificate"),
    (HEADER + 'Z2.1  l. 1  holds  "t"\n      r = r\n', "1_test.txt:2: the statement Z2.1 is not under its certificate"),
    (HEADER + 'Z1.1  l. 1  holds  "t"\n', "Z1.1 has no formal statement"),
    (HEADER + 'Z1.1  l. 1  holds  "t"\n      r = r\nZ1.1  l. 2  holds  "u"\n      r = r\n',
     "two statements share the id Z1.1"),
    (HEADER + 'Z1.1  l. 1  refuted by Z1.2  "t"\n      r = 1\n', "Z1.1 refuted Z1.2, but Z1.2 is not its correction"),
    (HEADER + 'Z1.1  l. 1  refuted by Z1.2  "t"\n      r = 1\nZ1.2  l. 1  holds  "u"\n      r = r\n',
     "Z1.2 is not its correction"),
    (HEADER + 'Z1.1  l. 1  refuted by Z1.2  "t"\n      r = 1\nZ1.2  l. 1  corrects Z1.3  "u"\n      r = r\n',
     "Z1.2 is not its correction"),
    (HEADER + 'Z1.2  l. 1  corrects Z1.1  "u"\n      r = r\n',
     "Z1.2 corrects Z1.1, but Z1.1 is not its refuted statement"),
    (HEADER + 'Z1.1  l. 1  proven  "t"\n      r = r\n', "1_test.txt:2: not a line of the statement format"),
    (HEADER + 'Z1.1  holds  "t"\n      r = r\n', "not a line of the statement format"),            # no line
    (HEADER + 'Z1.1  l. 1  holds  t\n      r = r\n', "not a line of the statement format"),           # no quotes
    ('certificate Z1  "t"\n', "1_test.txt:1: not a line of the statement format"),
    ("let 1P = r\n", "not a line of the statement format"),
    ("something else\n", "not a line of the statement format: 'something else'"),
])
def test_a_malformed_file_is_refused_with_its_file_and_line(tmp_path, text, says):
    with pytest.raises(FileError) as err:
        read(write_statements(tmp_path, text))
    assert says in str(err.value)
    assert "\n" not in str(err.value)


def test_an_empty_directory_is_refused(tmp_path):
    with pytest.raises(FileError, match="no statement files"):
        read(tmp_path)


def test_the_repository_statements_read():
    """statements/ of the checkout is well formed: ids unique, each refuted statement paired with its
    correction, every counted statement formal or marked unformalised (read raises otherwise)."""
    paper = read()
    ids = [s.id for c in paper.certificates for s in c.statements]
    assert len(ids) == len(set(ids)) and ids
    for c in paper.certificates:
        assert c.statements, c.id
        assert all(s.id.startswith(c.id + ".") for s in c.statements)
