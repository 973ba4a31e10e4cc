"""Idle connections cannot starve a node of file descriptors: with more idle connections to its
TCPROS and Slave API ports than its descriptor limit, a new subscriber still gets the node's
messages and the Slave API still answers.

The node (with a core) runs in a process of its own limited to 1 024 descriptors, with the
shipped 30 s idle and header timeouts, so only closing the oldest idle connections early can
make room: 1 100 connections that never send a header or a call, loopback only.
"""

from __future__ import annotations

import subprocess
import sys
import tempfile
import threading

from rosx.msg.codec.classes import get_message_class
from rosx.node import Node
from rosx.transport.client import XmlRpcClient
from tests.support.cli import clean_environ
from tests.support.procs import running, wait_for
from tests.support.reserve import (
    CONNECTIONS,
    IDLE_WARNING,
    closed_by_peer,
    enough_descriptors,
    idle_connections,
)

TALKER = """
import resource, sys, threading
resource.setrlimit(resource.RLIMIT_NOFILE, (1024, 1024))
from rosx.core import Core
from rosx.msg.codec.classes import get_message_class
from rosx.node import Node
String = get_message_class("std_msgs/String")
with Core(0, {}) as core:
    node = Node("/talker", master_uri=core.uri, environ={}).start()
    node.advertise("/chatter", String, latch=True).publish(String(data="still here"))
    print(core.uri, node.uri, node.tcpros_address()[1], flush=True)
    threading.Event().wait()
"""
STRING = get_message_class("std_msgs/String")


def test_node_serves_beside_more_idle_connections_than_descriptors() -> None:
    with (
        enough_descriptors(),
        tempfile.TemporaryFile() as log,
        running(
            [sys.executable, "-c", TALKER], clean_environ(), stdout=subprocess.PIPE, stderr=log
        ) as talker,
    ):
        assert talker.stdout is not None
        master_uri, slave_uri, tcpros_port = talker.stdout.readline().decode().split()
        slave_port = int(slave_uri.rstrip("/").rpartition(":")[2])
        with (
            idle_connections(("127.0.0.1", int(tcpros_port)), CONNECTIONS // 2) as on_tcpros,
            idle_connections(("127.0.0.1", slave_port), CONNECTIONS // 2) as on_slave,
        ):
            # More idle connections than the node could hold have been accepted and closed.
            wait_for(
                lambda: closed_by_peer(on_tcpros + on_slave) >= CONNECTIONS - 1024,
                what="idle connections to be closed",
            )
            code, _, pid = XmlRpcClient().call(slave_uri, "getPid", "/test", timeout=5.0)
            assert (code, pid) == (1, talker.pid)
            heard: list[str] = []
            got = threading.Event()

            def on_message(msg: object) -> None:
                heard.append(msg.data)  # type: ignore[attr-defined]
                got.set()

            listener = Node("/listener", master_uri=master_uri, environ={}).start()
            try:
                listener.subscribe("/chatter", STRING, on_message)
                assert got.wait(10)
            finally:
                listener.shutdown("test over")
            assert heard == ["still here"]
        log.seek(0)
        lines = log.read().decode().splitlines()
    assert len([line for line in lines if IDLE_WARNING in line]) == 1
    assert not [line for line in lines if "Traceback" in line]
