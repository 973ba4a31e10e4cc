"""Fixtures of the node layer's tests."""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from rosx.node import outgoing
from rosx.transport.loop_thread import LoopThread
from tests.support.frames import FloodClock


@pytest.fixture
def io() -> Iterator[LoopThread]:
    """An I/O loop on a thread of its own, stopped after the test."""
    loop = LoopThread("test-node-io").start()
    try:
        yield loop
    finally:
        loop.stop()


@pytest.fixture
def clock(monkeypatch: pytest.MonkeyPatch) -> FloodClock:
    """The streams' clock (`rosx.node.outgoing._clock`) made a `FloodClock`: every series of
    frames is a flood, however loaded the machine, unless the test pauses it."""
    fake = FloodClock()
    monkeypatch.setattr(outgoing, "_clock", fake)
    return fake
