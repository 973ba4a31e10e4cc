"""Fixtures for the node runtime's tests: a rosx master in this process, nodes that always
shut down, and a way to wait for what happens on other threads."""

from __future__ import annotations

from collections.abc import Callable, Iterator

import pytest

from rosx.master.server import MasterThread
from rosx.node import Node


@pytest.fixture(scope="module")
def master() -> Iterator[str]:
    """A rosx master on a free port; yields its URI."""
    with MasterThread(port=0, host="127.0.0.1", advertised_host="127.0.0.1") as thread:
        yield thread.uri


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
