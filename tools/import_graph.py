"""The house in words: the floors of the layering contract, the arrows between them,
the largest modules.  Run from the repository root:

    python tools/import_graph.py            # floors, arrows, the 12 largest modules
    python tools/import_graph.py --top 25

Floors are the layers of ``[tool.importlinter]`` in pyproject.toml, top first; an
arrow ``A -> B  (n)`` says that there are n direct imports of a module of B by a module of A (grimp, the
library under import-linter, reads the imports).  An arrow that runs up a floor
would break the contract, and ``lint-imports`` reports it.
"""
from __future__ import annotations

import argparse
import sys
from collections import Counter
from pathlib import Path

import grimp

try:
    import tomllib
except ModuleNotFoundError:        # Python 3.10: import-linter brings tomli
    import tomli as tomllib

ROOT = Path(__file__).resolve().parent.parent


def floors() -> list[list[str]]:
    """The layers of the contract, top first, each a list of packages or modules."""
    config = tomllib.loads((ROOT / "pyproject.toml").read_text())
    layers = config["tool"]["importlinter"]["contracts"][0]["layers"]
    return [[name.strip() for name in layer.split("|")] for layer in layers]


def room(module: str, names: list[str]) -> str | None:
    """The floor entry that holds ``module`` (the longest matching prefix)."""
    best = None
    for name in names:
        if module == name or module.startswith(name + "."):
            if best is None or len(name) > len(best):
                best = name
    return best


def lines(module: str) -> int:
    path = ROOT / Path(*module.split("."))
    file = path / "__init__.py" if path.is_dir() else path.with_suffix(".py")
    return len(file.read_text(encoding="utf-8").splitlines()) if file.is_file() else 0


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--top", type=int, default=12, help="how many of the largest modules to list")
    args = parser.parse_args(argv)
    sys.path.insert(0, str(ROOT))
    graph = grimp.build_graph("certify", "proofs")
    levels = floors()
    names = [name for level in levels for name in level]
    modules = sorted(graph.modules)
    size: Counter = Counter()
    count: Counter = Counter()
    for m in modules:
        home = room(m, names)
        size[home] += lines(m)
        count[home] += 1
    print("floors, top first (lines, modules):")
    for k, level in enumerate(levels):
        cells = ", ".join(f"{n} ({size[n]}, {count[n]})" for n in level)
        print(f"  {len(levels) - k:2d}  {cells}")
    arrows: Counter = Counter()
    for m in modules:
        a = room(m, names)
        for imported in graph.find_modules_directly_imported_by(m):
            b = room(imported, names)
            if a and b and a != b:
                arrows[(a, b)] += 1
    floor_of = {n: len(levels) - k for k, level in enumerate(levels) for n in level}
    print(f"arrows between floors ({len(arrows)}; n = module-to-module imports):")
    for (a, b), n in sorted(arrows.items(), key=lambda kv: (-floor_of[kv[0][0]], kv[0][0], -floor_of[kv[0][1]])):
        up = "  UP" if floor_of[b] >= floor_of[a] else ""
        print(f"  {a} -> {b}  ({n}){up}")
    print(f"largest modules (lines), of {len(modules)}:")
    for m in sorted(modules, key=lambda m: -lines(m))[:args.top]:
        print(f"  {lines(m):5d}  {m}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
