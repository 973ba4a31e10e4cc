"""Test modules share helpers through tests/support only: none imports another test module.

A test that imports another test module's helper (or a folder's conftest) ties the two suites
together: moving or deleting one breaks the other, and pytest may collect the imported tests
twice. What several suites need lives in `tests.support`.
"""

from __future__ import annotations

import ast
from pathlib import Path

TESTS = Path(__file__).resolve().parent
ROOT = TESTS.parent


def _imported(tree: ast.AST) -> list[tuple[int, str]]:
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            found += [(node.lineno, alias.name) for alias in node.names]
        elif isinstance(node, ast.ImportFrom) and node.module and not node.level:
            found.append((node.lineno, node.module))
    return found


def _crossings(source: str, name: str) -> list[str]:
    return [
        f"{name}:{line}: {module}"
        for line, module in _imported(ast.parse(source))
        if module.split(".")[0] == "tests" and not module.startswith("tests.support")
    ]


def test_no_test_module_imports_another() -> None:
    crossings = []
    for path in sorted(TESTS.rglob("*.py")):
        if "corpus" not in path.parts:
            crossings += _crossings(path.read_text(), path.relative_to(ROOT).as_posix())
    assert crossings == []


def test_the_check_sees_imports_of_test_modules_only() -> None:
    source = (
        "from tests.support.procs import wait_for\n"
        "from tests.tui.conftest import run\n"
        "import tests.graph.test_builder\n"
        "from rosx.node import Node\n"
    )
    assert _crossings(source, "x.py") == [
        "x.py:2: tests.tui.conftest",
        "x.py:3: tests.graph.test_builder",
    ]


def test_no_two_test_modules_share_a_name() -> None:
    # The test folders are not packages: pytest imports each test module by its file name, and
    # a second module of that name fails to import ("import file mismatch").
    names: dict[str, list[str]] = {}
    for path in TESTS.rglob("test_*.py"):
        if "corpus" not in path.parts:
            names.setdefault(path.name, []).append(path.relative_to(ROOT).as_posix())
    assert {name: paths for name, paths in names.items() if len(paths) > 1} == {}
