"""``certify schema [NAME] [--validate FILE]``: the JSON Schema of every JSON output, shipped
with the package (certify/patterns/*.schema.json, certify/schemas/*.schema.json,
certify_kernel/certificates.schema.json), each valid
alone with plain ``jsonschema`` (no reference outside its file).

    certify schema                                  every schema: name, file, what writes it
    certify schema orbit                            the path of one schema
    certify orbit abcb --json | certify schema orbit --validate -
"""
from __future__ import annotations

import json
import sys
from pathlib import Path

from certify.errors import UsageError

from .options import add_command

FOLDER = Path(__file__).resolve().parent.parent / "schemas"
KERNEL = Path(__file__).resolve().parents[2] / "certify_kernel"      # its package folder, not imported
WRITERS = {"pattern": "certify pattern WORD --json", "orbit": "certify orbit WORD --json",
           "trap": "certify orbit WORD --trap R --json", "census": "certify census: DIR/census.json",
           "census5": "certify census --particles 5: DIR/census5.json",
           "report": "certify all: reports/report.json", "timings": "certify all: reports/timings.json",
           "numerics-paper": "certify figures --resolution paper: reports/numerics-paper.json",
           "numerics-n4": "certify figures --n4 NMAX: reports/numerics-n4.json",
           "identify": "certify identify --json", "section5-orbits": "certify identify --section5: "
           "reports/section5-orbits.json", "island": "certify island --json",
           "atlas": "certify atlas: DIR/atlas.json", "chaos": "certify chaos --r R --json",
           "family": "certify family --n-max N: DIR/family.json (the engine's windows, L5's second route)",
           "family-window": "certify pattern '(ab)^n(cb)^n' --json for n > 30 (the theorem's window)",
           "certificates": "certify all: reports/certificates.json, read by python3 -m certify_kernel"}


def schemas() -> dict[str, Path]:
    """Every shipped schema by name (the file name without ``.schema.json``)."""
    from certify.patterns import SCHEMA_PATH
    from certify.patterns.island_theorem import SCHEMA_PATH as ISLAND
    from certify.patterns.reduction_orbits import SCHEMA_PATH as ORBIT
    found = {"pattern": SCHEMA_PATH, "orbit": ORBIT, "island": ISLAND}
    found.update({p.name.removesuffix(".schema.json"): p for p in sorted(FOLDER.glob("*.schema.json"))})
    found["certificates"] = KERNEL / "certificates.schema.json"       # the kernel's input, shipped with it
    return found


def validate(name: str, text: str) -> list[str]:
    """The errors of the JSON ``text`` against schema ``name`` (empty when valid), one line each."""
    try:
        import jsonschema
    except ImportError:
        raise UsageError("--validate needs jsonschema (pip install jsonschema, or certify[test])") from None
    try:
        doc = json.loads(text)
    except ValueError as exc:
        return [f"not JSON: {exc}"]
    schema = json.loads(schemas()[name].read_text(encoding="utf-8"))
    validator = jsonschema.Draft202012Validator(schema)
    return [f"at /{'/'.join(map(str, e.absolute_path))}: {' '.join(e.message.split())[:200]}"
            for e in sorted(validator.iter_errors(doc), key=lambda e: list(map(str, e.absolute_path)))]


def cmd_schema(args) -> int:
    """List the schemas, print one's path, or validate a file against it (exit 1 if invalid)."""
    known = schemas()
    if args.name is None:
        if args.validate is not None:
            raise UsageError("--validate FILE needs the NAME of a schema")
        w = max(map(len, known))
        for name, path in known.items():
            print(f"{name:<{w}}  {path}  ({WRITERS.get(name, '')})")
        return 0
    if args.name not in known:
        raise UsageError(f"unknown schema {args.name!r} (one of {', '.join(known)})")
    if args.validate is None:
        print(known[args.name])
        return 0
    source = "stdin" if args.validate == "-" else args.validate
    try:
        text = sys.stdin.read() if args.validate == "-" else Path(args.validate).read_text(encoding="utf-8")
    except OSError as exc:
        raise UsageError(f"cannot read {args.validate}: {exc.strerror}") from None
    errors = validate(args.name, text)
    for line in errors[:20]:
        print(f"{source}: {line}")
    print(f"{source}: {'not valid' if errors else 'valid'} against {known[args.name].name}"
          + (f" ({len(errors)} error{'s' if len(errors) != 1 else ''})" if errors else ""))
    return 1 if errors else 0


def register(commands) -> None:
    """The parser of ``schema``."""
    p = add_command(commands, "schema", cmd_schema, help="the JSON Schema of each JSON output; validate a file",
                    description="Every JSON output has a JSON Schema (draft 2020-12) shipped with the package, "
                    "valid alone with plain jsonschema.  Without NAME: list them; with NAME: print its path; "
                    "with --validate FILE (- for stdin): check FILE against it (exit 1 if it is not valid).")
    p.add_argument("name", nargs="?", default=None, metavar="NAME", help="pattern, orbit, trap, census, report, ...")
    p.add_argument("--validate", default=None, metavar="FILE", help="a JSON file to check, - for stdin")
