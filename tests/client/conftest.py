"""Fixtures for the rospy-compatible API: a rosx master in this process, and a fresh
process-wide client state for each test (so each test has its own ``init_node``)."""

from __future__ import annotations

import sys
from collections.abc import Iterator
from types import ModuleType

import pytest

from rosx.client import state


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
