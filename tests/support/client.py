"""The rospy-compatible API in a test's own process: a fresh process-wide client state."""

from __future__ import annotations

import sys
from collections.abc import Iterator
from types import ModuleType

import pytest

from rosx.client import state


def fresh_rospy(master: str, monkeypatch: pytest.MonkeyPatch) -> Iterator[ModuleType]:
    """``rosx.client`` as a script sees ``rospy``, with a client state of its own on ``master``
    (so each test has its own ``init_node``); shut down afterwards. For a fixture to yield from."""
    client = state.Client()
    monkeypatch.setattr(state, "CLIENT", client)
    monkeypatch.setenv("ROS_MASTER_URI", master)
    monkeypatch.delenv("ROS_NAMESPACE", raising=False)
    monkeypatch.setattr(sys, "argv", ["script.py"])
    import rosx.client

    yield rosx.client
    client.signal_shutdown("test over")
