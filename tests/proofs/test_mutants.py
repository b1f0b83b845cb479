"""Every certificate turns FAIL when the printed statement it checks is altered: the mutants
declared beside each printed statement (``@certificate(mutants=...)``, :class:`Mutant`), run
over all certificates in the session's shared context (tests/shared.py).

- constant: a coefficient, a digit, a letter, a sign, a word altered: FAIL;
- wording: a printed condition reworded so that it is false: FAIL, and the altered text is
  shown in a failing printed check (the certificate read it, it did not only run);
- unread: a wording the grammar does not read, or the certificate cannot evaluate: FAIL with
  that reason, the text quoted (never a guess);
- committed: a committed finding the certificate re-certifies (a word, its r) altered: FAIL,
  for an observation too (the finding is ours, not the paper's).

An observation (Section 5) is never FAIL on the paper's figures: altered, it disagrees on one
more printed check.  Each certificate's status as printed is the one it declares (``expect``,
as the report labels it)."""
import pytest

from certify.run.report import status_label
from certify.run.runner import (
    CERTIFICATES,
    COMMITTED,
    CONSTANT,
    FAIL,
    MUTANT_KINDS,
    OBSERVED,
    UNREAD,
    WORDING,
    claim_key,
    holds,
)
from tests.shared import as_printed, outcome, read, registry

IDS = sorted(registry(), key=claim_key)          # collection needs the ids: the session's one registration
MUTANTS = [(id, k) for id in IDS for k in range(len(CERTIFICATES[id].mutants))]
# Certificates without a mutant, each with the reason; the list cannot grow silently.
UNMUTATED = {"N4": "it reads only n_from (its r_below and accumulate_above are not read), and as printed both "
                   "checks on n_from already disagree: an altered n_from cannot disagree on one more "
                   "(tests/numerics/test_figures_numerics.py::test_n4_reads_the_printed_n shows that it is read)"}


def failing(o) -> list:
    return [(c.statement, c.evidence[:1]) for c in o.printed if not holds(c)]


def shows(o, text: str) -> bool:
    """The text is in a failing printed check: its statement, or its evidence when the text
    could not be read and the certificate stopped with the reason."""
    return any(not holds(c) and (text in c.statement or any(text in e for e in c.evidence)) for c in o.printed)


@pytest.mark.parametrize("id", IDS)
def test_certificate_as_printed(id):
    o = as_printed(id)
    assert status_label(o) == CERTIFICATES[id].expect, failing(o)


@pytest.mark.parametrize("id, k", MUTANTS,
                         ids=[f"{id}-{CERTIFICATES[id].mutants[k].kind}-{k}" for id, k in MUTANTS])
def test_mutant_fails(id, k):
    m = CERTIFICATES[id].mutants[k]
    over = m.overrides(id)
    o = outcome(id, **over)
    if m.kind == COMMITTED:
        assert o.status == FAIL, (m.why, o.status, failing(o))
    elif CERTIFICATES[id].expect.startswith(OBSERVED):
        assert o.status == OBSERVED and o.agrees is False, (m.why, o.status, o.note)
        assert len(failing(o)) > len(failing(as_printed(id))), (m.why, failing(o))
    else:
        assert o.status == FAIL, (m.why, o.status, failing(o))
    name = m.changes[0][0]
    if m.kind == WORDING:
        assert shows(o, over[name]), (m.why, [(c.statement, holds(c), c.evidence[:1]) for c in o.printed])
    if m.kind == UNREAD:
        reasons = [e for c in o.printed if not holds(c) for e in c.evidence]
        assert any(over[name] in e and ("cannot read" in e or "cannot evaluate" in e) for e in reasons), reasons


def test_every_certificate_has_a_mutant():
    assert {id for id in IDS if not CERTIFICATES[id].mutants} == set(UNMUTATED)


@pytest.mark.parametrize("id", IDS)
def test_mutants_alter_the_print(id):
    """A mutant alters printed inputs that exist (a wording one, a printed text); no mutant
    leaves the print as it is, and no two of one certificate are the same alteration of a kind."""
    cert, seen = CERTIFICATES[id], set()
    for m in cert.mutants:
        assert m.kind in MUTANT_KINDS
        over = m.overrides(id)
        assert set(over) <= set(cert.printed), m
        assert any(over[n] != cert.printed[n] for n in over), f"{id}: {m} alters nothing"
        if m.kind != CONSTANT:
            assert len(over) == 1 and all(isinstance(cert.printed[n], str) for n in over), m
        key = (m.kind, tuple(sorted((n, repr(v)) for n, v in over.items())))
        assert key not in seen, f"{id}: {m} declared twice"
        seen.add(key)


@pytest.mark.parametrize("id", IDS)
def test_every_condition_read_in_words_has_a_wording_mutant(id):
    """Each printed text the certificate reads with the statement grammar (as printed: recorded
    by tests/shared.py) is reworded by a wording mutant; and a certificate with wording mutants
    does read printed text with the grammar (the recording sees it)."""
    reworded = {m.changes[0][0] for m in CERTIFICATES[id].mutants if m.kind == WORDING}
    assert read(id) <= reworded, sorted(read(id) - reworded)
    assert bool(read(id)) == bool(reworded), (read(id), reworded)
