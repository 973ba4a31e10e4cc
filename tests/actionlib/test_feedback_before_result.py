"""A server's result never leaves before the feedback it published first.

Feedback published in a quick series is held back and written together (`rosx.node.outgoing`),
and the result travels on a connection of its own: unless the server writes out what is held
first, the result reaches the client while the last feedback is still in the server, and the
client (which hands over the feedback that has reached its host before acting on a result)
drops that feedback as coming after the goal's end.

A subscriber node watches both topics over a Unix socket, its feedback callback held so the
server sees it behind; the stream's clock is the test's, so the feedback is a flood however
loaded the machine, and only a pause or a flush writes what is held.
"""

from __future__ import annotations

import sys
import threading
from collections.abc import Callable
from types import ModuleType
from typing import Any

import pytest

from rosx.actionlib import SimpleActionClient, SimpleActionServer
from rosx.msg.codec.classes import get_message_class
from rosx.node import Node, local, outgoing
from tests.support.frames import FloodClock
from tests.support.procs import wait_for

Action = get_message_class("actionlib/TestAction")
Goal = get_message_class("actionlib/TestGoal")
Result = get_message_class("actionlib/TestResult")
Feedback = get_message_class("actionlib/TestFeedback")
ActionFeedback = get_message_class("actionlib/TestActionFeedback")
ActionResult = get_message_class("actionlib/TestActionResult")

FEEDBACK = 40

pytestmark = pytest.mark.skipif(
    not sys.platform.startswith("linux"), reason="holding frames needs a Unix socket's probe"
)


def test_the_feedback_held_in_a_flood_leaves_before_the_result(
    rospy: ModuleType, make_node: Callable[..., Node], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(local, "ENABLED", False)  # the watcher reads a socket
    monkeypatch.setattr(outgoing, "_clock", FloodClock())
    monkeypatch.setattr(outgoing, "HOLD_TICK", 30.0)  # the loop does not write what is held

    def execute(goal: Any) -> None:
        for number in range(FEEDBACK):
            server.publish_feedback(Feedback(feedback=number))
        server.set_succeeded(Result(result=goal.goal))

    server = SimpleActionServer("/held", Action, execute, auto_start=False)
    server.start()

    watcher = make_node("held_watcher")
    gate = threading.Event()
    feedback: list[int] = []
    drains: list[Any] = []

    def on_feedback(msg: Any) -> None:
        gate.wait(30)  # the server sees this subscriber behind, and holds what follows
        feedback.append(msg.feedback.feedback)

    watched = watcher.subscribe("/held/feedback", ActionFeedback, on_feedback, queue_size=None)
    # What of the feedback has reached this host when the result does.
    watcher.subscribe("/held/result", ActionResult, lambda _: drains.append(watched.drain()))

    client = SimpleActionClient("/held", Action)
    assert client.wait_for_server(rospy.Duration(30))
    wait_for(lambda: watched.get_num_connections() == 1, what="the watcher's connections")
    client.send_goal(Goal(goal=7))
    wait_for(lambda: drains, what="the result at the watcher")
    gate.set()
    wait_for(drains[0].done, what="the feedback that came before the result")
    assert feedback == list(range(FEEDBACK))
    assert client.wait_for_result(rospy.Duration(30))
    assert client.get_result().result == 7
