"""N7.1, the island theorem: no text says the island's orbits are quasi-periodic at every r of
]3−2√2, 1[ (issue 34: at r = 2−√3 the rotation number is 1/3 and A³ = I, every island orbit is
periodic), and the kernel decides the formal statements of N7.1 and T25.2."""
import re
from pathlib import Path

import pytest

from certify.run import Check, conclude, report
from certify_kernel import check_statement, prepare, read
from proofs import section5_numerics as S
from tests.shared import as_printed, registry

ROOT = Path(__file__).resolve().parents[2]
EVERY_R = re.compile(r"every r (in|of) \]3[−-]2√2, 1\[")
QUASI = re.compile(r"quasi-periodic|dense on (its|their) ellipse|turn densely")

# the texts of issue 34, as they were: each says "quasi-periodic for every r" without the resonances
OLD = [
    "l. 95: \"the orbits of such a system might be quasi-periodic\": proved for the island, for every r in ]3−2√2, 1[ "
    "(r a symbol, every step an identity in Q(r) or a sign certified on the interval)",
    "explanation: quasi-periodic orbits exist for every r in ]3−2√2, 1[ (so at r ≈ 0.92): the orbits in the island "
    "U_r around [ac]b turn densely on invariant ellipses (the island theorem, N7.1)",
    "The cluster counts are evidence, not a proof; the explanations are ours and certified: the island theorem (N7.1) "
    "proves quasi-periodic orbits for every r in ]3−2√2, 1[.",
    "for every r in ]3-2√2, 1[ the b-to-b map around the orbit [ac]b is a rotation preserving a quadratic form Q; the "
    "island {Q < c_max} (a third of the b-section at r = 0.3) is invariant, every orbit in it dense on its ellipse.",
]


def quasi_periodic_everywhere(text: str) -> list[str]:
    """The sentences of ``text`` that put quasi-periodic (or dense) island orbits at every r of
    ]3−2√2, 1[ without naming the resonances, where they are periodic."""
    sentences = re.split(r"(?<=[.!?])\s+(?=[A-Z*`(\"“])|\n\n", text)
    return [s for s in sentences if EVERY_R.search(s) and QUASI.search(s) and "resonance" not in s]


@pytest.mark.parametrize("old", OLD)
def test_the_old_sentences_are_caught(old):
    assert quasi_periodic_everywhere(old)


def test_the_statements_say_it_right():
    paper = read(ROOT / "statements")
    texts = [c.title for c in paper.certificates] + [s.text for c in paper.certificates for s in c.statements]
    assert not [t for t in texts if quasi_periodic_everywhere(t)]
    n71 = {s.id: s for c in paper.certificates if c.id == "N7.1" for s in c.statements}
    assert "2−√3" in n71["N7.1.1"].text and "periodic" in n71["N7.1.9"].text


def test_the_docs_say_it_right():
    for name in ("README.md", "docs/island.md"):
        text = (ROOT / name).read_text(encoding="utf-8")
        assert not quasi_periodic_everywhere(text.replace("\n", " ")), name


def test_the_certificates_and_the_report_say_it_right():
    n71 = as_printed("N7.1")
    texts = [registry()["N7.1"].statement, n71.note, S.ISLAND_SENTENCE] + [str(c.statement) for c in n71.printed]
    texts += [str(c.statement) for c in S.island_explanations(
        {"symbolic": S.island.symbolic_theorem(), "at": {}}, "0.92")]
    theorem = conclude([Check("self-similar data iff r < 5-2√6", True)])        # a main result beside N7.1
    texts.append(report.main_results_line([(registry()["T25.1"], theorem), (registry()["N7.1"], n71)]))
    found = [s for t in texts for s in quasi_periodic_everywhere(t)]
    assert not found, found
    assert "resonances" in texts[-1] and "2−√3" in texts[-1]


@pytest.fixture(scope="module")
def paper():
    p = read(ROOT / "statements")
    prepare(p)
    return p


def _statement(paper, sid):
    return next(s for c in paper.certificates for s in c.statements if s.id == sid)


@pytest.mark.parametrize("sid", ["N7.1.2", "N7.1.4", "N7.1.5", "N7.1.6", "N7.1.7", "N7.1.8", "N7.1.9", "N7.1.10"])
def test_the_kernel_verifies_the_island_statements(paper, sid):
    assert check_statement(_statement(paper, sid), paper.lets) == (True, "")


def test_the_kernel_refuses_a_wrong_resonance(paper):
    """A³ = I at 3−2√2 (the end of the interval, ρ = 1/2) instead of 2−√3: refused."""
    s = _statement(paper, "N7.1.9")
    wrong = type(s)(**{**s.__dict__, "formula": s.formula.replace("{2-√3}", "{3-2√2}")})
    with pytest.raises(ValueError, match="finds it false"):
        check_statement(wrong, paper.lets)


@pytest.mark.parametrize("sid", [f"T25.2.{k}" for k in range(1, 9)])
def test_the_kernel_moves_the_particles(paper, sid):
    """T25.2: the exact dynamics (certify_kernel/particles.py) from the printed datum."""
    assert check_statement(_statement(paper, sid), paper.lets) == (True, "")


def test_the_kernel_refuses_another_word(paper):
    s = _statement(paper, "T25.2.4")
    wrong = type(s)(**{**s.__dict__, "formula": s.formula.replace("(ababcb)^20", "(ababcb)^19*abacbc")})
    with pytest.raises(ValueError, match="finds it false"):
        check_statement(wrong, paper.lets)
