"""The layering of certify/: each layer imports only the layers below it.

The contract is `[tool.importlinter]` in pyproject.toml (layers: proofs → cli → run →
patterns → dynamics → algebra → errors | caches; inside certify/algebra its own floors, branches …
printing | balls).  These tests run import-linter on the tree as it is (kept) and on a copy with
one upward import added (broken), and check that proofs/ imports only the layers' public faces.
"""
import ast
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
LAYERS = ("algebra", "dynamics", "patterns", "numerics", "run")
CONTRACTS = 4      # pyproject.toml: the layers, the floors of algebra, the kernel alone, the floors of the kernel


def lint(tree: Path) -> subprocess.CompletedProcess:
    """Run import-linter on the package tree at ``tree`` (its pyproject.toml)."""
    pytest.importorskip("importlinter")
    code = "import sys; from importlinter.cli import lint_imports_command; sys.exit(lint_imports_command())"
    env = {"PYTHONPATH": str(tree), "PATH": "/usr/bin:/bin"}
    return subprocess.run([sys.executable, "-c", code, "--no-cache"], cwd=tree, env=env,
                          capture_output=True, text=True)


def copy_tree(dst: Path) -> Path:
    for name in ("certify", "proofs", "certify_kernel"):
        shutil.copytree(ROOT / name, dst / name, ignore=shutil.ignore_patterns("__pycache__"))
    shutil.copy(ROOT / "pyproject.toml", dst / "pyproject.toml")
    return dst


def test_the_layering_contract_is_kept():
    result = lint(ROOT)
    assert result.returncode == 0, result.stdout + result.stderr
    assert f"{CONTRACTS} kept, 0 broken" in result.stdout


@pytest.mark.parametrize("module, upward, broken", [
    ("certify/algebra/poly.py", "from certify.dynamics import model", 1),
    ("certify/dynamics/model.py", "from certify.run import runner", 1),
    ("certify/run/report.py", "import proofs.section2_model", 1),
    ("certify/cli/options.py", "from certify import api", 1),       # the notebook's face sits on the commands'
    # the ground floor on algebra: also algebra.balls -> errors -> algebra.poly, up a floor of algebra
    ("certify/errors.py", "from certify.algebra import poly", 2),
    ("certify_kernel/poly.py", "from certify.algebra import poly as engine", 1),
    ("certify_kernel/sturm.py", "import sympy", 1),
    # inside certify/algebra: the circle of issue 38 (sturm, algebraic, facts, branches, numberfield)
    ("certify/algebra/sturm.py", "from .algebraic import Algebraic", 1),
    ("certify/algebra/algebraic.py", "from . import numberfield", 1),
    ("certify/algebra/facts.py", "from .branches import UPPER", 1),
    ("certify/algebra/numberfield.py", "from .branches import UPPER", 1),
    ("certify/algebra/poly.py", "from .sturm import isolate", 1),
    # inside the kernel: the circle evaluate ↔ signs (signs registers its quantifier instead)
    ("certify_kernel/evaluate.py", "from . import signs", 1),
    ("certify_kernel/poly.py", "from . import sturm", 1),
])
def test_an_upward_import_breaks_the_contract(tmp_path, module, upward, broken):
    tree = copy_tree(tmp_path)
    path = tree / module
    path.write_text(path.read_text() + f"\n{upward}  # an upward import\n")
    result = lint(tree)
    assert result.returncode != 0
    assert "BROKEN" in result.stdout and f"{CONTRACTS - broken} kept, {broken} broken" in result.stdout


def imports_inside_functions(path: Path):
    """The imports of ``path`` made inside a function, with their line numbers."""
    tree = ast.parse(path.read_text(), filename=str(path))
    for node in ast.walk(tree):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            for inner in ast.walk(node):
                if isinstance(inner, (ast.Import, ast.ImportFrom)):
                    yield inner.lineno


@pytest.mark.parametrize("package", ["certify/algebra", "certify_kernel"])
def test_the_floored_packages_import_their_own_modules_at_the_top(package):
    """An import of a sibling module inside a function is how a circle hides from the reader (the
    module reads as independent, and loads only when called): every module of certify/algebra and of
    the kernel imports its siblings at the top, where the floors of the contract can be seen."""
    name = package.replace("/", ".")
    hidden = [f"{path.name}:{line}" for path in sorted((ROOT / package).glob("*.py"))
              for line in imports_inside_functions(path)
              if "from ." in path.read_text().splitlines()[line - 1]
              or name in path.read_text().splitlines()[line - 1]]
    assert not hidden, hidden


def certify_imports(path: Path):
    """Every module of certify that ``path`` imports, with its line number."""
    tree = ast.parse(path.read_text(), filename=str(path))
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            if node.module.split(".")[0] == "certify":
                yield node.module, node.lineno
        elif isinstance(node, ast.Import):
            for alias in node.names:
                if alias.name.split(".")[0] == "certify":
                    yield alias.name, node.lineno


def test_proofs_import_only_the_faces_of_the_layers():
    seen = []
    for path in sorted((ROOT / "proofs").glob("*.py")):
        for module, line in certify_imports(path):
            seen.append(module)
            assert module in {f"certify.{layer}" for layer in LAYERS}, \
                f"{path.name}:{line} imports {module}, not a layer's face"
    assert {f"certify.{layer}" for layer in LAYERS} <= set(seen)


def test_every_layer_is_a_folder_with_a_face():
    for layer in LAYERS:
        face = ROOT / "certify" / layer / "__init__.py"
        assert face.is_file()
        assert "__all__" in face.read_text()


def test_no_module_name_appears_twice_under_certify():
    """One name per job: a module's name says which module it is (only the packages'
    ``__init__.py`` repeat)."""
    seen: dict[str, list[str]] = {}
    for path in sorted((ROOT / "certify").rglob("*.py")):
        if path.name != "__init__.py":
            seen.setdefault(path.stem, []).append(str(path.relative_to(ROOT)))
    for path in sorted((ROOT / "certify").rglob("__init__.py")):
        if path.parent != ROOT / "certify":
            seen.setdefault(path.parent.name, []).append(str(path.parent.relative_to(ROOT)))
    twice = {name: where for name, where in seen.items() if len(where) > 1}
    assert not twice, twice
