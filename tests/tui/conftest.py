"""Fixtures for the terminal UI: a live ``rosx sim`` world and client nodes on its master.

The live world is for pilot tests that assert on poses and messages, never on pictures; the
scripted ponds and fixed link of the snapshots are in `tests.support.tui`.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator

import pytest

from rosx.node import Node
from rosx_turtle.sim.host import SimHost
from tests.support.procs import free_port


@pytest.fixture
def host() -> Iterator[SimHost]:
    """``rosx sim``'s world on a free port, stopped after the test."""
    world = SimHost(free_port(), {}, seed=4).start()
    try:
        yield world
    finally:
        world.stop()


@pytest.fixture
def make_node(host: SimHost) -> Iterator[Callable[[str], Node]]:
    """Client nodes on the host's master, shut down after the test."""
    nodes: list[Node] = []

    def make(name: str) -> Node:
        node = Node(name, master_uri=host.master_uri, environ={}).start()
        nodes.append(node)
        return node

    yield make
    for node in nodes:
        node.shutdown("test over")
