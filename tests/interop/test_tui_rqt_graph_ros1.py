"""rosx rqt_graph's live view on rospy nodes, on ROS 1's roscore and on rosx's: the connections
come from rospy's getBusInfo, the details from rospy's Slave API, the rate from messages a
rospy talker sends to rosx's hidden subscriber."""

from __future__ import annotations

from contextlib import ExitStack

import pytest

from tests.support.graph_nodes import LISTENER, TALKER
from tests.support.graph_pilot import talker_chatter_listener
from tests.support.pilot import run
from tests.support.procs import running, stop
from tests.support.ros1 import ROS1_PYTHON, ROSCORES, needs_ros1, ros1_environ, roscore

pytestmark = needs_ros1


@pytest.mark.parametrize("kind", ROSCORES)
def test_talker_chatter_listener_of_rospy_nodes(kind: str) -> None:
    with roscore(kind) as uri, ExitStack() as stack:
        env = ros1_environ(ROS_MASTER_URI=uri)
        talker = stack.enter_context(running([ROS1_PYTHON, "-c", TALKER], env))
        stack.enter_context(running([ROS1_PYTHON, "-c", LISTENER], env))
        run(talker_chatter_listener(uri, lambda: stop(talker)))
