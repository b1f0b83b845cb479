"""One context for the whole test session: the mutation harness (tests/proofs/test_mutants.py) and
the tests of each part run certificates with the same shared quantities (section4_data,
ab_cb_patterns, spectrum, ...), each computed once per session, and the same run of each
certificate as printed.  While a certificate runs as printed, the printed texts it reads
with the statement grammar (certify.algebra.statements) are recorded: a certificate that
reads a condition in words must have wording mutants."""
from functools import cache

from certify.algebra import statements
from certify.run.runner import CERTIFICATES, Context, load_all, run_certificate

CONTEXT = Context()
READERS = ("relation", "statement", "range_of", "count", "extent", "branch", "product_equation", "word_rule")
_PRINTED: dict = {}          # id -> (outcome as printed, the printed names read by the grammar)


@cache
def registry() -> dict:
    """Every certificate of proofs/, registered once per session (the ``certificates``
    fixture of tests/conftest.py; a module that parametrizes over them calls it at
    collection)."""
    return load_all()


_ALTERED: dict = {}          # (id, the overrides) -> outcome: a mutant and a test that alter alike share one run


def outcome(id: str, **overrides):
    """Certificate ``id`` run in the session's context, its printed inputs replaced by ``overrides``
    (each alteration run once per session: the certificates are deterministic)."""
    if not overrides:
        return as_printed(id)
    key = (id, repr(sorted(overrides.items())))
    if key not in _ALTERED:
        _ALTERED[key] = run_certificate(registry()[id], CONTEXT, overrides)
    return _ALTERED[key]


def as_printed(id: str):
    """The outcome of certificate ``id`` on the paper as printed, run once per session."""
    if id not in _PRINTED:
        registry()
        _PRINTED[id] = _traced(id)
    return _PRINTED[id][0]


def read(id: str) -> set:
    """The names of the printed inputs of ``id`` that the statement grammar read, as printed."""
    as_printed(id)
    return _PRINTED[id][1]


def _traced(id: str):
    """Run ``id`` as printed with the grammar's entry points recording the texts they are given."""
    texts, saved = [], {name: getattr(statements, name) for name in READERS}

    def recording(func):
        def reader(text, *args, **kwargs):
            texts.append(text)
            return func(text, *args, **kwargs)
        return reader
    try:
        for name, func in saved.items():
            setattr(statements, name, recording(func))
        out = run_certificate(CERTIFICATES[id], CONTEXT)
    finally:
        for name, func in saved.items():
            setattr(statements, name, func)
    printed = CERTIFICATES[id].printed
    return out, {n for n, v in printed.items() if isinstance(v, str) and v in texts}


def strings(value):
    """Every string inside a JSON value or a certificate's printed inputs."""
    if isinstance(value, str):
        yield value
    elif isinstance(value, (tuple, list)):
        for v in value:
            yield from strings(v)
    elif isinstance(value, dict):
        for v in value.values():
            yield from strings(v)


def certificates_file(ids) -> dict:
    """reports/certificates.json as `certify all` would write it, for the certificates ``ids``
    alone (the kernel's tests tamper with copies of it)."""
    import json

    from certify.run import report, runner
    results, _ = runner.run_selected(list(ids))
    return json.loads(report.render_certificates(results))


def certificate_of(data: dict, cid: str) -> dict:
    """A deep copy of certificate ``cid`` of a certificates file (to tamper with)."""
    import copy
    return copy.deepcopy(next(c for c in data["certificates"] if c["id"] == cid))
