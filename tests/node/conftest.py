"""Fixtures of the node layer's tests."""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from rosx.transport.loop_thread import LoopThread


@pytest.fixture
def io() -> Iterator[LoopThread]:
    """An I/O loop on a thread of its own, stopped after the test."""
    loop = LoopThread("test-node-io").start()
    try:
        yield loop
    finally:
        loop.stop()
