"""What the mutation tests of every part share: a printed condition altered in its wording
must FAIL and show the altered text in a failing printed check."""
import os

import pytest
from hypothesis import settings

from certify.run.runner import FAIL, altered

# Property tests must pass for any seed; CI runs them derandomised (the same draws every
# run, reproducible from the failure blob hypothesis prints).
settings.register_profile("ci", derandomize=True, print_blob=True)
if os.environ.get("CI"):
    settings.load_profile("ci")


def shows(outcome, text: str) -> bool:
    """The text is in a failing printed check: its statement, or its evidence when the text
    could not be read and the certificate stopped with the reason."""
    return any(not c.holds and (text in c.statement or any(text in e for e in c.evidence)) for c in outcome.printed)


@pytest.fixture
def wording_fails():
    """``check(run, id, name, old, new)``: the printed text ``name`` of ``id`` with ``old``
    replaced by ``new`` makes ``run(id, **overrides)`` FAIL, the altered text shown failing."""
    def check(run, id, name, old, new):
        over = altered(id, name, old, new)
        o = run(id, **over)
        assert o.status == FAIL
        assert shows(o, over[name]), [(c.statement, c.holds, c.evidence[:1]) for c in o.printed]
    return check


@pytest.fixture
def unread_fails():
    """``check(run, id, name, text)``: a printed text the grammar does not read, or that the
    certificate cannot evaluate, makes it FAIL with that reason, the text quoted."""
    def check(run, id, name, text):
        o = run(id, **{name: text})
        assert o.status == FAIL
        reasons = [e for c in o.printed if not c.holds for e in c.evidence]
        assert any(text in e and ("cannot read" in e or "cannot evaluate" in e) for e in reasons), reasons
    return check
