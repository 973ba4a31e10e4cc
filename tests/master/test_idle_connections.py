"""Idle connections cannot starve a master of file descriptors: with more idle connections than
its descriptor limit, a master still answers the next call at once, and says once in its log
that it closed idle connections.

The master runs in a process of its own limited to 1 024 descriptors (Linux's usual default)
with the shipped 30 s idle timeout, so only closing the oldest idle connections early can make
room; 1 100 connections, loopback only.
"""

from __future__ import annotations

import contextlib
import os
import signal
import sys
import tempfile
from pathlib import Path

import pytest

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
                what="idle connections to be closed",
            )
        log.seek(0)
        lines = log.read().decode().splitlines()
    assert [line for line in lines if IDLE_WARNING in line] == [
        next(line for line in lines if IDLE_WARNING in line)
    ]
    assert not [line for line in lines if "Traceback" in line]


def _held(pid: int, ports: set[int]) -> int:
    """How many of process ``pid``'s TCP sockets are connected to one of loopback's ``ports``
    (its end of those clients' connections, read from ``/proc``)."""
    inodes = set()
    for fd in Path(f"/proc/{pid}/fd").iterdir():
        with contextlib.suppress(OSError):  # closed while listed
            link = str(fd.readlink())
            if link.startswith("socket:["):
                inodes.add(link[len("socket:[") : -1])
    held = 0
    for line in Path("/proc/net/tcp").read_text().splitlines()[1:]:
        fields = line.split()
        remote_port = int(fields[2].rpartition(":")[2], 16)
        held += fields[9] in inodes and remote_port in ports
    return held


@pytest.mark.skipif(not Path("/proc/net/tcp").is_file(), reason="reads sockets from /proc")
def test_a_master_behind_closes_what_it_gives_up_of_a_burst() -> None:
    # A master that falls behind (a loaded machine) accepts the connections waiting for it in
    # one go, and gives up the oldest of them before it has begun to serve them: those must be
    # closed too, and not stay listed as idle, held open for good.
    port = free_port()
    uri = f"http://127.0.0.1:{port}/"
    queued = 1000  # fewer than its listen backlog: all wait in the kernel's queue
    somaxconn = int(Path("/proc/sys/net/core/somaxconn").read_text())
    if somaxconn < queued:
        pytest.skip(f"needs a listen backlog of {queued}; net.core.somaxconn is {somaxconn}")
    with (
        enough_descriptors(),
        running([sys.executable, "-c", MASTER, str(port)], clean_environ()) as master,
    ):
        wait_for(lambda: _started(uri), timeout=30, what="the core and its /rosout")
        os.kill(master.pid, signal.SIGSTOP)
        try:
            with idle_connections(("127.0.0.1", port), queued) as waiting:
                os.kill(master.pid, signal.SIGCONT)
                with idle_connections(("127.0.0.1", port), CONNECTIONS - queued) as more:
                    assert _answers(uri)
                    wait_for(
                        lambda: closed_by_peer(waiting + more) >= CONNECTIONS - 1024,
                        what="idle connections to be closed",
                    )
                    ports = {sock.getsockname()[1] for sock in waiting + more}
        finally:
            os.kill(master.pid, signal.SIGCONT)
        # Only the burst's own connections are counted: the core's nodes open and close
        # connections to the master of their own meanwhile (one it shed is made again).
        wait_for(
            lambda: _held(master.pid, ports) == 0,
            what="the master to let go of every connection of the clients gone",
        )
