"""Fixtures for actionlib: servers and clients are parts of the process's rospy node."""

from __future__ import annotations

from collections.abc import Iterator
from types import ModuleType

import pytest

from tests.support.client import fresh_rospy


@pytest.fixture
def rospy(master: str, monkeypatch: pytest.MonkeyPatch) -> Iterator[ModuleType]:
    """``rosx.client`` as a script sees ``rospy``, initialised as node ``/actionlib_test``."""
    for module in fresh_rospy(master, monkeypatch):
        module.init_node("actionlib_test", disable_signals=True)
        yield module
