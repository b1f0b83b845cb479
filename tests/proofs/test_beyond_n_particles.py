"""Beyond the paper, B1 (issue 39): the reduction for N particles.  The certificate passes as
written and turns FAIL when a printed matrix is altered; the kernel verifies its statements and
not an altered one; the kernel's K(N, i), wedge and compound are the engine's."""
from __future__ import annotations

import copy
import random

import pytest
import sympy as sp

import certify_kernel
from certify.algebra import r
from certify.run.runner import FAIL, PASS
from certify_kernel.evaluate import Context, value
from certify_kernel.language import parse
from certify_kernel.statements import read
from proofs import beyond_n_particles as B
from tests.kernel.kernel_support import STATEMENTS, declared
from tests.shared import as_printed, outcome


@pytest.fixture(scope="module")
def paper():
    declared()
    p = read(STATEMENTS)
    certify_kernel.prepare(p)
    return p


def b1(paper):
    return next(c for c in paper.certificates if c.id == "B1")


def test_b1_passes_with_every_statement_decided():
    o = as_printed("B1")
    assert o.status == PASS
    refs = [c.ref for c in o.printed if c.ref]
    assert refs == [f"B1.{k}" for k in range(1, 10)]


@pytest.mark.parametrize("name, old, new", [("K_b", "[0, h, 1, 0]", "[0, h, 2, 0]"),          # K_b e_3 ≠ e_3
                                            ("K_c", "-r", "-2*r"),
                                            ("K_a", "[0, 0, 0, 1]", "[0, 0, 1, 1]")])
def test_an_altered_printed_matrix_fails(name, old, new):
    text = B.K_PRINTED[name].replace("(1+r)/2", "h")
    assert old in text
    altered = text.replace(old, new, 1).replace("h", "(1+r)/2")
    assert outcome("B1", **{name: altered}).status == FAIL


def test_the_kernel_verifies_b1(paper):
    for s in b1(paper).statements:
        assert certify_kernel.check_statement(s, paper.lets) == (True, ""), s.id


@pytest.mark.parametrize("sid, old, new", [("B1.5", "compound(b1_Kb)", "compound(b1_Kc)"),
                                           ("B1.5", "b1_pa[1] = 0", "b1_pa[2] = 0"),
                                           ("B1.3", "wedge(b1_p, b1_q)", "wedge(b1_q, b1_p)"),
                                           ("B1.8", "(β*(-q_2/p_2) - γ)/α", "(β*(-q_2/p_2) + γ)/α"),
                                           ("B1.9", "K(6, 3)*b1_q6", "K(6, 4)*b1_q6"),
                                           ("B1.1", "K(5, 4) = b1_Kd", "K(5, 4) = b1_Kc")])
def test_an_altered_statement_is_not_verified(paper, sid, old, new):
    s = copy.copy(next(s for s in b1(paper).statements if s.id == sid))
    assert old in s.formula
    s.formula = s.formula.replace(old, new, 1)
    with pytest.raises(ValueError, match="finds it false"):
        certify_kernel.check_statement(s, paper.lets)


def kernel(expr: str, lets=None):
    declared()
    return value(parse(expr), Context(dict(lets or {})))


def as_sympy(x) -> sp.Expr:
    """A kernel rational function of r as a SymPy expression."""
    num = sum(c * r ** k[0] for k, c in x.num.items())
    den = sum(c * r ** k[0] for k, c in x.den.items())
    return sp.nsimplify(num) / sp.nsimplify(den)


@pytest.mark.parametrize("n", [4, 5, 6, 7])
def test_the_kernels_law_is_the_engines(n):
    for i in range(n - 1):
        K = kernel(f"K({n}, {i + 1})")
        E = B.engine_matrix(i, n)
        assert all(sp.simplify(as_sympy(a) - E[j, k]) == 0 for j, row in enumerate(K.rows) for k, a in enumerate(row))


def test_k_of_four_particles_is_a_b_c():
    from certify_kernel.evaluate import equal
    for i, name in enumerate("ABC"):
        assert equal(kernel(f"K(4, {i + 1})"), kernel(name))


def test_the_kernels_wedge_and_compound_are_the_engines():
    rng = random.Random(7)
    for n in (3, 4, 5):
        M = [[rng.randint(-5, 5) for _ in range(n)] for _ in range(n)]
        u, v = ([rng.randint(-5, 5) for _ in range(n)] for _ in range(2))
        text = lambda xs: "(" + ", ".join(map(str, xs)) + ")"                     # noqa: E731
        w = kernel(f"wedge({text(u)}, {text(v)})")
        C = kernel("compound([" + ", ".join("[" + ", ".join(map(str, row)) + "]" for row in M) + "])")
        assert [x.constant() for x in w] == list(B.wedge(u, v))
        assert [[a.constant() for a in row] for row in C.rows] == B.compound(sp.Matrix(M)).tolist()


@pytest.mark.parametrize("expr", ["K(2, 1)", "K(5, 5)", "K(5, 0)", "wedge((1, 2), (1, 2, 3))", "compound([[1, 2, 3]])"])
def test_the_kernel_refuses_what_is_not_defined(expr):
    from certify_kernel.values import Undefined
    with pytest.raises(Undefined):
        kernel(expr)
