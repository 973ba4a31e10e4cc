"""The test tree's own rules, which pytest does not check until two modules collide."""

from __future__ import annotations

from collections import defaultdict
from pathlib import Path

TESTS = Path(__file__).resolve().parent


def test_test_modules_have_unique_names() -> None:
    # The test folders are not packages, so pytest imports each module by its file name: two
    # modules of one name in different folders stop the whole run at collection.
    folders: defaultdict[str, list[str]] = defaultdict(list)
    for path in sorted(TESTS.rglob("test_*.py")):
        folders[path.name].append(str(path.parent.relative_to(TESTS)))
    assert {name: where for name, where in folders.items() if len(where) > 1} == {}
