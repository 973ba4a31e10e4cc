"""The descriptor reserve: which connections a server gives up when descriptors run short.

Only idle connections are closed, the oldest first, across all of the process's servers, and
the log says so once; a connection whose call is being answered gets its answer.
"""

from __future__ import annotations

import asyncio
import http.client
import logging
import socket
import threading
from collections.abc import Callable, Iterator

import pytest

from rosx.transport import descriptors
from rosx.transport.loop_thread import ServerThread
from tests.support.procs import wait_for
from tests.support.reserve import closed_by_peer


class Idle:
    """A server with idle connections of given ages; records which it was asked to close."""

    def __init__(self, *ages: float) -> None:
        self.ages = ages
        self.closed: list[float] = []

    def idle_connections(self) -> Iterator[tuple[float, Callable[[], object]]]:
        for age in self.ages:
            yield age, lambda age=age: self.closed.append(age)  # type: ignore[misc]


@pytest.fixture
def warned_afresh() -> Iterator[None]:
    saved = descriptors._warned
    descriptors._warned = False
    yield
    descriptors._warned = saved


def test_the_oldest_idle_connections_of_all_servers_go_first(
    warned_afresh: None, caplog: pytest.LogCaptureFixture
) -> None:
    first, second = Idle(5.0, 1.0, 9.0), Idle(3.0, 7.0)
    descriptors.watch(first)
    descriptors.watch(second)
    try:
        # 1 024 descriptors keep 2 reserves of 64 free: 900 in use → 4 connections over.
        assert descriptors.shed(900, 1024) == 4
        assert sorted(first.closed + second.closed) == [1.0, 3.0, 5.0, 7.0]
        assert descriptors.shed(895, 1024) == 0
        assert descriptors.shed(1024, 1024) == 5
    finally:
        descriptors.forget(first)
        descriptors.forget(second)
    warnings = [r.getMessage() for r in caplog.records if r.levelno >= logging.WARNING]
    assert warnings == [
        "900 of 1024 file descriptors in use: closing the 4 oldest idle connections to keep "
        "serving (said once; raise the limit with `ulimit -n` if this is expected load)"
    ]


def test_reserve_scales_with_the_limit() -> None:
    assert [descriptors.reserve(n) for n in (64, 1024, 4096, 1 << 20)] == [8, 64, 128, 128]


_HOLD = threading.Event()
_RELEASE = threading.Event()


async def _hold() -> str:
    _HOLD.set()
    await asyncio.get_running_loop().run_in_executor(None, _RELEASE.wait, 10)
    return "answered"


def test_a_connection_being_answered_is_never_closed(warned_afresh: None) -> None:
    with ServerThread({"hold": _hold}) as server:
        idle = [socket.create_connection(("127.0.0.1", server.port), timeout=5) for _ in range(3)]
        busy = http.client.HTTPConnection("127.0.0.1", server.port, timeout=10)
        try:
            busy.request(
                "POST",
                "/",
                b"<?xml version='1.0'?><methodCall><methodName>hold</methodName>"
                b"<params></params></methodCall>",
            )
            assert _HOLD.wait(10)
            # Everything the server holds counts as over the limit.
            server.run(_shed_everything())
            wait_for(lambda: closed_by_peer(idle) == 3, what="the idle connections to close")
            _RELEASE.set()
            assert b"answered" in busy.getresponse().read()
        finally:
            busy.close()
            for sock in idle:
                sock.close()


async def _shed_everything() -> None:
    descriptors.shed(10_000, 1024)
