"""rosx rqt_graph's live view on a live graph of rosx nodes (the same scenario runs on rospy
nodes in ``tests/interop/test_tui_rqt_graph_ros1.py``)."""

from __future__ import annotations

import threading

from rosx.msg.codec.classes import get_message_class
from rosx.node import Node
from tests.support.graph_pilot import talker_chatter_listener
from tests.support.pilot import run


def test_talker_chatter_listener_of_rosx_nodes(master: str) -> None:
    string = get_message_class("std_msgs/String")
    talker = Node("talker", master_uri=master, environ={}).start()
    listener = Node("listener", master_uri=master, environ={}).start()
    publisher = talker.advertise("/chatter", string)
    listener.subscribe("/chatter", string, lambda _: None)
    stop = threading.Event()

    def talk() -> None:
        while not stop.wait(0.1):
            publisher.publish(string(data="hello"))

    thread = threading.Thread(target=talk, daemon=True)
    thread.start()

    def stop_talker() -> None:
        stop.set()
        thread.join()
        talker.shutdown("talker stopped")

    try:
        run(talker_chatter_listener(master, stop_talker))
    finally:
        stop.set()
        thread.join()
        talker.shutdown("test over")
        listener.shutdown("test over")
