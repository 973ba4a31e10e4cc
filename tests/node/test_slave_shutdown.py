"""A node told to shut down through its Slave API answers, then takes no new calls at once."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from rosx.msg.codec.classes import get_message_class
from rosx.node import Node
from rosx.transport.client import XmlRpcClient
from rosx.transport.errors import ConnectError

String = get_message_class("std_msgs/String")


def test_no_new_connection_after_the_shutdown_reply(make_node: Callable[..., Node]) -> None:
    for attempt in range(20):  # the race the reply must not leave open, tried a few times
        node = make_node(f"/doomed{attempt}")
        node.advertise("/chatter", String, queue_size=1)
        client = XmlRpcClient(timeout=30.0)  # a generous deadline: the reply must come
        try:
            assert client.call(node.uri, "shutdown", "/test", "test over") == [1, "shutdown", 0]
        finally:
            client.close()
        fresh = XmlRpcClient(timeout=30.0)  # a new connection, as `rosnode ping` opens one
        try:
            with pytest.raises(ConnectError):
                fresh.call(node.uri, "getPid", "/test")
        finally:
            fresh.close()
        assert node.wait_for_shutdown(10.0)
