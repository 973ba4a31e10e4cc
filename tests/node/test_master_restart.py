"""A master killed and restarted on its port: rosx nodes register again, traffic never stops.

The master is ``rosx roscore`` in a process of its own, killed with SIGKILL; the talker is a
rosx node in another process; the listener and the late subscriber are nodes of this one.
"""

from __future__ import annotations

import contextlib
import os
import signal
import threading
from typing import Any

import pytest

from rosx.core import Core
from rosx.master.client import MasterClient, MasterUnreachable
from rosx.msg.codec.classes import get_message_class, get_service_class
from rosx.node import Node
from tests.support.cli import ROSX_COMMAND, clean_environ, rosx
from tests.support.procs import free_port, running, wait_for

Int32 = get_message_class("std_msgs/Int32")

ROSX = ROSX_COMMAND

TALKER = """
import sys, time
from rosx.core import Core
from rosx.msg.codec.classes import get_message_class, get_service_class
from rosx.node import Node
Int32 = get_message_class("std_msgs/Int32")
node = Node("talker", master_uri=sys.argv[1], environ={}).start()
pub = node.advertise("/chatter", Int32, queue_size=1000)
count = 0
while not node.is_shutdown():
    pub.publish(Int32(data=count))
    count += 1
    time.sleep(0.02)
"""


class Received:
    """The numbers a subscriber received, in order."""

    def __init__(self) -> None:
        self.numbers: list[int] = []
        self._lock = threading.Lock()

    def __call__(self, msg: Any) -> None:
        with self._lock:
            self.numbers.append(msg.data)

    def __len__(self) -> int:
        with self._lock:
            return len(self.numbers)

    def snapshot(self) -> list[int]:
        with self._lock:
            return list(self.numbers)


@pytest.fixture
def port() -> int:
    return free_port()


def _roscore(port: int) -> Any:
    return running([*ROSX, "roscore", "-p", str(port)], clean_environ())


def _answers(uri: str) -> bool:
    try:
        MasterClient(uri, "/test").call("getPid", timeout=1.0)
    except MasterUnreachable:
        return False
    return True


def _graph_shows(uri: str, nodes: set[str], topics: set[str]) -> bool:
    env = clean_environ(ROS_MASTER_URI=uri)
    listed_nodes = rosx("rosnode", "list", environ=env)
    listed_topics = rosx("rostopic", "list", environ=env)
    return nodes <= set(listed_nodes.out.split()) and topics <= set(listed_topics.out.split())


def test_graph_and_traffic_survive_a_master_restart(port: int) -> None:
    uri = f"http://127.0.0.1:{port}/"
    received = Received()
    with contextlib.ExitStack() as stack:
        first = stack.enter_context(_roscore(port))
        wait_for(lambda: _answers(uri), timeout=30, what="the first master")
        stack.enter_context(running([*ROSX[:2], TALKER, uri], clean_environ()))
        listener = stack.enter_context(Node("listener", master_uri=uri, environ={}))
        listener.subscribe("/chatter", Int32, received)
        wait_for(lambda: len(received) >= 10, timeout=30, what="the talker's first messages")
        first_pid = MasterClient(uri, "/test").call("getPid")
        os.killpg(first.pid, signal.SIGKILL)
        first.wait()
        wait_for(lambda: not _answers(uri), what="the master to die")
        during = len(received)
        wait_for(lambda: len(received) >= during + 10, what="traffic without a master")
        with _roscore(port):
            wait_for(lambda: _answers(uri), what="the new master")
            assert MasterClient(uri, "/test").call("getPid") != first_pid
            wait_for(
                lambda: _graph_shows(uri, {"/talker", "/listener"}, {"/chatter"}),
                what="the graph on the new master",
            )
            late = Received()
            with Node("late", master_uri=uri, environ={}) as newcomer:
                newcomer.subscribe("/chatter", Int32, late)
                wait_for(lambda: len(late) >= 10, what="the talker's messages at a new subscriber")
            before = len(received)
            wait_for(lambda: len(received) >= before + 10, what="traffic after the restart")
    numbers = received.snapshot()
    assert numbers == list(range(numbers[0], numbers[0] + len(numbers)))
    late_numbers = late.snapshot()
    assert late_numbers == list(range(late_numbers[0], late_numbers[0] + len(late_numbers)))


def test_services_and_parameter_subscriptions_come_back(port: int) -> None:
    """A core restarted in this process forgot the node: its service is found again and its
    cached parameter follows the new master's updates."""
    trigger = get_service_class("std_srvs/Trigger")
    with Core(port, {}) as core, Node("server", master_uri=core.uri, environ={}) as node:
        node.advertise_service("/poke", trigger, lambda req: trigger._response_class(True, "hi"))
        node.params.set("/gain", 1)
        assert node.params.get_cached("/gain") == 1
        core.stop()
        with Core(port, {}) as again:
            master = MasterClient(again.uri, "/test")
            wait_for(lambda: master.lookup_service("/poke") is not None, what="the service")
            reply = node.service_client("/poke", trigger).call(trigger._request_class())
            assert reply.message == "hi"
            master.call("setParam", "/gain", 2)
            wait_for(lambda: node.params.get_cached("/gain") == 2, what="the parameter update")
