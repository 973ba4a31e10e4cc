"""The descriptor reserve: which connections a server gives up when descriptors run short;
and a client that keeps no connection to a server that went away.

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
from pathlib import Path

import pytest

from rosx.transport import descriptors
from rosx.transport.aclient import AsyncXmlRpcClient
from rosx.transport.loop_thread import ServerThread
from rosx.transport.server import XmlRpcServer
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


_FDS = Path("/proc/self/fd")


def _open_descriptors() -> int:
    return len(list(_FDS.iterdir()))


@pytest.mark.skipif(not _FDS.is_dir(), reason="counts descriptors in /proc")
def test_kept_connections_to_servers_that_went_away_are_closed() -> None:
    # What /rosout and the master do: call many nodes once each; the nodes die. Their kept
    # connections must not stay open (CLOSE_WAIT) for good, one descriptor per dead node.
    async def scenario() -> None:
        client = AsyncXmlRpcClient(timeout=5.0)
        before = _open_descriptors()
        for _ in range(20):
            server = XmlRpcServer({"ping": lambda: "pong"})
            await server.start()
            assert await client.call(server.uri, "ping") == "pong"
            await server.close()
        alive = XmlRpcServer({"ping": lambda: "pong"})
        await alive.start()
        for _ in range(3):  # the server's closing reaches the client within a turn or two
            await asyncio.sleep(0)
        assert await client.call(alive.uri, "ping") == "pong"
        # The live server's listening socket, its end of the call, and the client's.
        assert _open_descriptors() <= before + 3
        await alive.close()
        await client.close()

    asyncio.run(scenario())
