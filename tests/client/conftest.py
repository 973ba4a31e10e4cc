"""Fixtures for the rospy-compatible API: a rosx master in this process, and a fresh
process-wide client state for each test (so each test has its own ``init_node``)."""

from __future__ import annotations

from collections.abc import Iterator
from types import ModuleType

import pytest

from tests.support.client import fresh_rospy


@pytest.fixture
def rospy(master: str, monkeypatch: pytest.MonkeyPatch) -> Iterator[ModuleType]:
    """``rosx.client`` as a script sees ``rospy``, with a client state of its own."""
    yield from fresh_rospy(master, monkeypatch)
