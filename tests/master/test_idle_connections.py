"""Idle connections cannot starve a master of file descriptors: more idle connections than
its descriptor limit, and once the idle timeout has passed it serves again.

The master runs in a process of its own with a limit of 64 descriptors and a 1 s idle
timeout (the shipped timeout is `rosx.transport.server.IDLE_TIMEOUT`), so the test stays
small: 80 connections, loopback only.
"""

from __future__ import annotations

import contextlib
import socket
import sys

from rosx.master.client import MasterClient, MasterUnreachable
from tests.support.cli import clean_environ
from tests.support.procs import free_port, running, wait_for

MASTER = """
import resource, sys, threading
import rosx.transport.server
resource.setrlimit(resource.RLIMIT_NOFILE, (64, 64))
rosx.transport.server.IDLE_TIMEOUT = 1.0
from rosx.core import Core
with Core(int(sys.argv[1]), {}) as core:
    threading.Event().wait()
"""
CONNECTIONS = 80


def _answers(uri: str) -> bool:
    try:
        MasterClient(uri, "/test").call("getPid", timeout=0.5)
    except MasterUnreachable:
        return False
    return True


def _started(uri: str) -> bool:
    try:
        return MasterClient(uri, "/test").lookup_node("/rosout") is not None
    except MasterUnreachable:
        return False


def test_master_serves_again_once_idle_connections_time_out() -> None:
    port = free_port()
    uri = f"http://127.0.0.1:{port}/"
    with running([sys.executable, "-c", MASTER, str(port)], clean_environ()):
        wait_for(lambda: _started(uri), timeout=30, what="the core and its /rosout")
        with contextlib.ExitStack() as stack:
            for _ in range(CONNECTIONS):
                stack.enter_context(socket.create_connection(("127.0.0.1", port), timeout=5))
            # More idle connections than the master has descriptors: it cannot serve now…
            assert not _answers(uri)
            # …and once they have been idle past the timeout, it serves again.
            wait_for(lambda: _answers(uri), timeout=20, what="the master to serve again")
