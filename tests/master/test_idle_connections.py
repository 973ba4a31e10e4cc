"""Idle connections cannot starve a master of file descriptors: with more idle connections than
its descriptor limit, a master still answers the next call at once, and says once in its log
that it closed idle connections.

The master runs in a process of its own limited to 1 024 descriptors (Linux's usual default)
with the shipped 30 s idle timeout, so only closing the oldest idle connections early can make
room; 1 100 connections, loopback only.
"""

from __future__ import annotations

import sys
import tempfile

from rosx.master.client import MasterClient, MasterUnreachable
from tests.support.cli import clean_environ
from tests.support.procs import free_port, running, wait_for
from tests.support.reserve import (
    CONNECTIONS,
    IDLE_WARNING,
    closed_by_peer,
    enough_descriptors,
    idle_connections,
)

MASTER = """
import resource, sys, threading
resource.setrlimit(resource.RLIMIT_NOFILE, (1024, 1024))
from rosx.core import Core
with Core(int(sys.argv[1]), {}) as core:
    threading.Event().wait()
"""


def _answers(uri: str) -> bool:
    try:
        MasterClient(uri, "/test").call("getPid", timeout=5.0)
    except MasterUnreachable:
        return False
    return True


def _started(uri: str) -> bool:
    try:
        return MasterClient(uri, "/test").lookup_node("/rosout") is not None
    except MasterUnreachable:
        return False


def test_master_answers_beside_more_idle_connections_than_descriptors() -> None:
    port = free_port()
    uri = f"http://127.0.0.1:{port}/"
    with (
        enough_descriptors(),
        tempfile.TemporaryFile() as log,
        running([sys.executable, "-c", MASTER, str(port)], clean_environ(), stderr=log),
    ):
        wait_for(lambda: _started(uri), timeout=30, what="the core and its /rosout")
        with idle_connections(("127.0.0.1", port)) as idle:
            # A 5 s call timeout, far below the 30 s idle timeout: answered because the master
            # closed the oldest idle connections, not because they timed out.
            assert _answers(uri)
            assert _answers(uri)
            assert MasterClient(uri, "/test").lookup_node("/rosout") is not None
            # At least as many as the limit could not hold.
            wait_for(
                lambda: closed_by_peer(idle) >= CONNECTIONS - 1024,
                timeout=60,
                what="idle connections to be closed",
            )
        log.seek(0)
        lines = log.read().decode().splitlines()
    assert [line for line in lines if IDLE_WARNING in line] == [
        next(line for line in lines if IDLE_WARNING in line)
    ]
    assert not [line for line in lines if "Traceback" in line]
