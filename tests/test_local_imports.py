"""Every import made inside a function says why it is not at the top of its module.

A function-local import hides a dependency from a reader of the module's head, so it must earn
its place: start-up (a short command must not load what only one path needs), a heavy or
optional dependency, a platform-only module. ``# noqa: PLC0415 - <why>`` says which. The heavy
modules that may never be imported at module level (ruff's ``banned-module-level-imports``)
are exempt from PLC0415, so they say why in a plain comment. Imports for type checkers only
(under ``if TYPE_CHECKING:``) never run and need no reason.
"""

from __future__ import annotations

import ast
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PACKAGES = ("rosx", "commands/rosx_commands", "turtle/rosx_turtle")
SHIPPED = ROOT / "rosx" / "packages" / "noetic"
#: A noqa comment naming PLC0415 (other codes may stand beside it), then `` - <a reason>``.
REASONED = re.compile(r"#\s*noqa:\s*[A-Z0-9, ]*PLC0415[A-Z0-9, ]* - \S")
#: A comment that says something (for the banned heavy modules).
COMMENTED = re.compile(r"#\s*(?!noqa)\S")
#: What pyproject.toml bans at module level.
BANNED = ("textual", "numpy", "rosbags", "grandalf", "textual_plot")


def _banned(node: ast.Import | ast.ImportFrom) -> bool:
    name = node.names[0].name if isinstance(node, ast.Import) else node.module or ""
    return name.split(".")[0] in BANNED


def _type_checking(node: ast.If) -> bool:
    test = node.test
    return (isinstance(test, ast.Name) and test.id == "TYPE_CHECKING") or (
        isinstance(test, ast.Attribute) and test.attr == "TYPE_CHECKING"
    )


def _local_imports(tree: ast.Module) -> list[ast.Import | ast.ImportFrom]:
    found: list[ast.Import | ast.ImportFrom] = []

    def visit(node: ast.AST, in_function: bool) -> None:
        for child in ast.iter_child_nodes(node):
            if isinstance(child, ast.If) and _type_checking(child):
                for other in child.orelse:
                    visit(other, in_function)
                continue
            if isinstance(child, ast.Import | ast.ImportFrom) and in_function:
                found.append(child)
            inner = in_function or isinstance(child, ast.FunctionDef | ast.AsyncFunctionDef)
            visit(child, inner)

    visit(tree, False)
    return found


def _unexplained(source: str, name: str) -> list[str]:
    lines = source.splitlines()
    return [
        f"{name}:{node.lineno}: {lines[node.lineno - 1].strip()}"
        for node in _local_imports(ast.parse(source))
        if not (COMMENTED if _banned(node) else REASONED).search(lines[node.lineno - 1])
    ]


def test_every_function_local_import_gives_its_reason() -> None:
    unexplained = []
    for package in PACKAGES:
        for path in sorted((ROOT / package).rglob("*.py")):
            if SHIPPED not in path.parents:
                unexplained += _unexplained(path.read_text(), path.relative_to(ROOT).as_posix())
    assert unexplained == []


def test_the_check_tells_a_reason_from_a_bare_noqa() -> None:
    source = (
        "TYPE_CHECKING = False\n"
        "def f():\n"
        "    import json  # noqa: PLC0415 - only f writes JSON\n"
        "    import csv  # noqa: PLC0415\n"
        "    import numpy  # arrays only here\n"
        "    import textual\n"
        "    if TYPE_CHECKING:\n"
        "        import typing\n"
        "import os\n"
    )
    assert _unexplained(source, "x.py") == [
        "x.py:4: import csv  # noqa: PLC0415",
        "x.py:6: import textual",
    ]
