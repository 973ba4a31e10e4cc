"""ARCHITECTURE.md names what the code has, where a list in it can be checked."""

from __future__ import annotations

import ast
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
HANDLES = ROOT / "rosx" / "node" / "handles.py"


def _public_names(path: Path) -> dict[str, set[str]]:
    """Each class of ``path``: its public methods as ``name()``, properties and aliases bare."""
    classes = {}
    for node in ast.parse(path.read_text(encoding="utf-8")).body:
        if not isinstance(node, ast.ClassDef):
            continue
        names = set()
        for item in node.body:
            if isinstance(item, ast.FunctionDef) and not item.name.startswith("_"):
                is_property = any(
                    isinstance(d, ast.Name) and d.id == "property" for d in item.decorator_list
                )
                names.add(item.name if is_property else f"{item.name}()")
            elif isinstance(item, ast.Assign) and isinstance(item.value, ast.Name):
                names |= {f"{t.id}()" for t in item.targets if isinstance(t, ast.Name)}
        classes[node.name] = names
    return classes


def _listed_handles() -> dict[str, set[str]]:
    """The handles' methods as ARCHITECTURE.md lists them (``- `Class`: `name()`, …``)."""
    text = (ROOT / "ARCHITECTURE.md").read_text(encoding="utf-8")
    listed = {}
    for item in re.finditer(r"^  - `(\w+)`: (.*?)[;.]$(?=\n  -|\n\n)", text, re.M | re.S):
        listed[item[1]] = set(re.findall(r"`(\w+(?:\(\))?)`", item[2]))
    return listed


def test_the_handles_methods_are_the_ones_architecture_lists() -> None:
    # Libraries above the node runtime may use these and nothing else of it: a method added
    # for one of them (actionlib's subscriber_ids()) is a door the document must name.
    assert _listed_handles() == _public_names(HANDLES)
