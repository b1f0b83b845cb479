"""What every test module shares: the hypothesis profile.  (The certificates' shared
quantities and their runs as printed: tests/shared.py; their mutants: tests/test_mutants.py.)"""
import os

from hypothesis import settings

# Property tests must pass for any seed; CI runs them derandomised (the same draws every
# run, reproducible from the failure blob hypothesis prints).
settings.register_profile("ci", derandomize=True, print_blob=True)
if os.environ.get("CI"):
    settings.load_profile("ci")
