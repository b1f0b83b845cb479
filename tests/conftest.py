"""What every test module shares: the hypothesis profile and the session's certificates.
(The certificates' shared quantities and their runs as printed: tests/shared.py; their
mutants: tests/proofs/test_mutants.py.)

The tests mirror the layers: tests/algebra, tests/dynamics, tests/patterns,
tests/numerics, tests/run, tests/cli, tests/proofs; tests/test_layers.py checks the house.
The layers' docstring examples run too (``--doctest-modules`` on certify/algebra,
certify/dynamics, certify/patterns and certify/numerics: pyproject.toml)."""
import os

import pytest
from hypothesis import settings

from tests.shared import registry

# Property tests must pass for any seed; CI runs them derandomised (the same draws every
# run, reproducible from the failure blob hypothesis prints).
settings.register_profile("ci", derandomize=True, print_blob=True)
if os.environ.get("CI"):
    settings.load_profile("ci")


@pytest.fixture(scope="session", autouse=True)
def certificates() -> dict:
    """Every certificate of proofs/ by id, registered once for the whole session, before
    the first test runs (``runner.CERTIFICATES`` is then complete for every test)."""
    return registry()
