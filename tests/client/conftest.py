"""Fixtures for the rospy-compatible API: a rosx master in this process, and a fresh
process-wide client state for each test (so each test has its own ``init_node``)."""

from __future__ import annotations

import sys
from collections.abc import Callable, Iterator
from types import ModuleType

import pytest

from rosx.client import state
from rosx.master.server import MasterThread
from rosx.node import Node


@pytest.fixture(scope="module")
def master() -> Iterator[str]:
    """A rosx master on a free port; yields its URI."""
    with MasterThread(port=0, host="127.0.0.1", advertised_host="127.0.0.1") as thread:
        yield thread.uri


@pytest.fixture
def rospy(master: str, monkeypatch: pytest.MonkeyPatch) -> Iterator[ModuleType]:
    """``rosx.client`` as a script sees ``rospy``, with a client state of its own."""
    client = state.Client()
    monkeypatch.setattr(state, "CLIENT", client)
    monkeypatch.setenv("ROS_MASTER_URI", master)
    monkeypatch.delenv("ROS_NAMESPACE", raising=False)
    monkeypatch.setattr(sys, "argv", ["script.py"])
    import rosx.client

    yield rosx.client
    client.signal_shutdown("test over")


@pytest.fixture
def peer(master: str) -> Iterator[Callable[[str], Node]]:
    """Other nodes on the test's master, shut down after the test."""
    nodes: list[Node] = []

    def make(name: str) -> Node:
        node = Node(name, master_uri=master, environ={}).start()
        nodes.append(node)
        return node

    yield make
    for node in nodes:
        node.shutdown("test over")
