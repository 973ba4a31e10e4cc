"""Driving textual apps in tests: run a pilot coroutine, wait for the state a test asserts."""

from __future__ import annotations

import asyncio
import time
from collections.abc import Callable, Coroutine
from typing import Any, TypeVar

from textual.pilot import Pilot

T = TypeVar("T")


def run(coro: Coroutine[Any, Any, T]) -> T:
    """Run a pilot coroutine to completion (the suite has no asyncio plugin)."""
    return asyncio.run(coro)


async def until(
    pilot: Pilot[Any], ready: Callable[[], object], what: str, timeout: float = 30.0
) -> None:
    """Let the app run until ``ready()`` is true; fail naming ``what`` after ``timeout`` s."""
    deadline = time.monotonic() + timeout
    while not ready():
        if time.monotonic() > deadline:
            raise AssertionError(f"timed out waiting for {what}")
        await pilot.pause(0.05)
