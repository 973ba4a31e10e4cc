"""Test-session setup: rosx under test sees no ROS environment unless a test gives it one.

CI exports the ROS 1 reference's variables (``ROS_PACKAGE_PATH`` …) for the whole run; tests that
run ROS 1 pass them explicitly (``tests.support.ros1.ros1_environ``), and everything else must not
depend on them.
"""

from __future__ import annotations

import os
import sys
import time
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest

from rosx.core import Core
from rosx.node import Node


def pytest_configure(config: pytest.Config) -> None:
    for name in [n for n in os.environ if n.startswith("ROS_")]:
        del os.environ[name]


#: The kind of test each folder holds (pyproject.toml registers the markers); any other
#: folder holds a layer's own tests.
KINDS = {
    "wire": "wire",
    "cli": "cli",
    "tui": "tui",
    "rqt": "tui",
    "interop": "interop",
    "e2e": "e2e",
}
TESTS = Path(__file__).resolve().parent


def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    for item in items:
        parts = item.path.relative_to(TESTS).parts
        kind = "tree" if len(parts) == 1 else KINDS.get(parts[0], "unit")
        item.add_marker(kind)


def _import_state() -> tuple[str | None, list[str], list[str]]:
    """What a program run in this process changes of its imports: ``PYTHONPATH``, which ROS 1's
    Python started later inherits, rosx's folders on ``sys.path`` (the shim folders), and
    rosx's import finders (``<package>.msg`` from the type store)."""
    rosx = str(Path(sys.modules["rosx"].__file__ or "").parent)
    return (
        os.environ.get("PYTHONPATH"),
        [entry for entry in sys.path if entry.startswith(rosx + os.sep)],
        [type(f).__qualname__ for f in sys.meta_path if type(f).__module__.startswith("rosx.")],
    )


@pytest.fixture(autouse=True)
def _imports_put_back() -> Iterator[None]:
    """Fail the test that leaves its changes to the process's imports to the tests after it
    (a program run in-process, as rosrun runs rosx's own): ROS 1's Python started by a later
    test would import rosx's shims, and a later test's imports would go through rosx's finders."""
    before = _import_state()
    saved = os.environ.get("PYTHONPATH"), list(sys.path), list(sys.meta_path)
    yield
    after = _import_state()
    if after != before:
        environ, sys.path[:], sys.meta_path[:] = saved
        if environ is None:
            os.environ.pop("PYTHONPATH", None)
        else:
            os.environ["PYTHONPATH"] = environ
        pytest.fail(f"the test left its imports changed: {before} -> {after}", pytrace=False)


@pytest.fixture(scope="module")
def master() -> Iterator[str]:
    """A rosx core (master, parameters, ``/rosout``) on a free port, shared by a test module;
    yields the master's URI."""
    with Core(0, {"ROS_IP": "127.0.0.1"}) as core:
        yield core.uri


@pytest.fixture
def make_node(master: str) -> Iterator[Callable[..., Node]]:
    """Start nodes on the test's master; every one is shut down after the test."""
    nodes: list[Node] = []

    def make(name: str, **options: object) -> Node:
        options.setdefault("environ", {})
        node = Node(name, master_uri=master, **options).start()  # type: ignore[arg-type]
        nodes.append(node)
        return node

    yield make
    for node in nodes:
        node.shutdown("test over")


@pytest.fixture
def utc() -> Iterator[None]:
    """Local time is UTC for the test (``TZ=UTC``), restored after it."""
    saved = os.environ.get("TZ")
    os.environ["TZ"] = "UTC"
    time.tzset()
    yield
    if saved is None:
        del os.environ["TZ"]
    else:
        os.environ["TZ"] = saved
    time.tzset()
