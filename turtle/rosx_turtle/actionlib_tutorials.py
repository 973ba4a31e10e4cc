"""actionlib_tutorials' C++ programs, in Python on rosx's rospy and actionlib, with roscpp's lines.

- ``fibonacci_server`` (node ``fibonacci``, action ``fibonacci``): the sequence grown one number
  a second from the seeds 0, 1 for orders 1 to N, so N + 2 numbers (the Python server gives
  N + 1); a cancel stops it between numbers.
- ``fibonacci_client`` (node ``test_fibonacci``): order 20, waits 30 s, logs the state and the
  numbers (``Action result: 0 1 1 2 …``, each followed by a space).
- ``fibonacci_callback_client`` (order 20) and ``fibonacci_class_client`` (order 10): done,
  active and feedback callbacks; done logs the state and the last number, then shuts down.
- ``averaging_server`` (node ``averaging``, action named after the node): a goal of N samples
  takes numbers from ``/random_number`` (std_msgs/Float32), sends the running mean and
  standard deviation as feedback, and past N samples ends, aborted when the mean is below 5.
- ``averaging_client`` (node ``test_averaging``): 100 samples, waits 30 s.

Each ``run_<program>(argv)`` takes the command line after the program's name and returns the
exit status.
"""

from __future__ import annotations

import math
import os
import sys
from typing import TYPE_CHECKING, Any

from rosx.msg.codec.classes import get_message_class
from rosx_turtle.console import Console, use_rosconsole

if TYPE_CHECKING:
    from collections.abc import Sequence
    from types import ModuleType

_PACKAGE = "actionlib_tutorials"


def start(program: str, node: str, argv: Sequence[str]) -> ModuleType:
    """``rospy`` (rosx's), initialised as ``node`` with ``argv``'s remappings and roscpp's
    console lines."""
    import rosx.client as rospy  # noqa: PLC0415 - the node starts with the program

    rospy.init_node(node, argv=[program, *argv])
    use_rosconsole(Console(sys.stdout, sys.stderr, os.environ))
    return rospy


def state_name(state: int) -> str:
    """A goal state as ``SimpleClientGoalState::toString`` writes it (``SUCCEEDED`` …)."""
    from rosx.actionlib.states import Status  # noqa: PLC0415 - with the program

    return Status.to_string(state)


def _types(action: str) -> dict[str, Any]:
    return {
        part: get_message_class(f"{_PACKAGE}/{action}{part}")
        for part in ("Action", "Goal", "Result", "Feedback")
    }


# -- Fibonacci ----------------------------------------------------------------------------------


def run_fibonacci_server(argv: Sequence[str]) -> int:
    """The C++ Fibonacci server."""
    rospy = start("fibonacci_server", "fibonacci", argv)
    from rosx.actionlib import SimpleActionServer  # noqa: PLC0415 - with the node

    types = _types("Fibonacci")
    name = "fibonacci"

    def execute(goal: Any) -> None:
        rate = rospy.Rate(1)
        numbers = [0, 1]
        rospy.loginfo(
            "%s: Executing, creating fibonacci sequence of order %i with seeds %i, %i",
            name,
            goal.order,
            numbers[0],
            numbers[1],
        )
        for _ in range(1, goal.order + 1):
            if server.is_preempt_requested() or rospy.is_shutdown():
                rospy.loginfo("%s: Preempted", name)
                server.set_preempted()
                return
            numbers.append(numbers[-1] + numbers[-2])
            server.publish_feedback(types["Feedback"](sequence=numbers))
            rate.sleep()
        rospy.loginfo("%s: Succeeded", name)
        server.set_succeeded(types["Result"](sequence=numbers))

    server = SimpleActionServer(name, types["Action"], execute_cb=execute, auto_start=False)
    server.start()
    rospy.spin()
    return 0


def _connect(rospy: ModuleType, types: dict[str, Any], name: str) -> Any:
    from rosx.actionlib import SimpleActionClient  # noqa: PLC0415 - with the node

    client = SimpleActionClient(name, types["Action"])
    rospy.loginfo("Waiting for action server to start.")
    client.wait_for_server()
    rospy.loginfo("Action server started, sending goal.")
    return client


def run_fibonacci_client(argv: Sequence[str]) -> int:
    """The C++ Fibonacci client: order 20, the result logged."""
    rospy = start("fibonacci_client", "test_fibonacci", argv)
    types = _types("Fibonacci")
    client = _connect(rospy, types, "fibonacci")
    client.send_goal(types["Goal"](order=20))
    if client.wait_for_result(rospy.Duration(30.0)):
        rospy.loginfo("Action finished: %s", state_name(client.get_state()))
        numbers = "".join(f"{n} " for n in client.get_result().sequence)
        rospy.loginfo("Action result: %s", numbers)
    else:
        rospy.loginfo("Action did not finish before the time out.")
    return 0


def _run_callback_client(program: str, node: str, argv: Sequence[str], order: int) -> int:
    rospy = start(program, node, argv)
    types = _types("Fibonacci")
    client = _connect(rospy, types, "fibonacci")

    def done(state: int, result: Any) -> None:
        rospy.loginfo("Finished in state [%s]", state_name(state))
        rospy.loginfo("Answer: %i", result.sequence[-1])
        rospy.signal_shutdown("done")

    if program == "fibonacci_callback_client":
        client.send_goal(
            types["Goal"](order=order),
            done_cb=done,
            active_cb=lambda: rospy.loginfo("Goal just went active"),
            feedback_cb=lambda fb: rospy.loginfo("Got Feedback of length %lu", len(fb.sequence)),
        )
    else:
        client.send_goal(types["Goal"](order=order), done_cb=done)
    rospy.spin()
    return 0


def run_fibonacci_callback_client(argv: Sequence[str]) -> int:
    """The C++ client with done, active and feedback callbacks (order 20)."""
    return _run_callback_client("fibonacci_callback_client", "test_fibonacci_callback", argv, 20)


def run_fibonacci_class_client(argv: Sequence[str]) -> int:
    """The C++ client whose done callback is a method (order 10)."""
    return _run_callback_client("fibonacci_class_client", "test_fibonacci_class_client", argv, 10)


# -- Averaging ----------------------------------------------------------------------------------


class _Averaging:
    """The averaging server's goal: samples counted, their sum and sum of squares."""

    def __init__(self, rospy: ModuleType, name: str) -> None:
        from rosx.actionlib import SimpleActionServer  # noqa: PLC0415 - with the node

        self.rospy = rospy
        self.name = name
        self.types = _types("Averaging")
        self.goal = self.count = 0
        self.total = self.squares = 0.0
        self.server = SimpleActionServer(name, self.types["Action"], auto_start=False)
        self.server.register_goal_callback(self.on_goal)
        self.server.register_preempt_callback(self.on_preempt)
        float32 = get_message_class("std_msgs/Float32")
        rospy.Subscriber("/random_number", float32, self.on_number, queue_size=1)
        self.server.start()

    def on_goal(self) -> None:
        self.count, self.total, self.squares = 0, 0.0, 0.0
        self.goal = self.server.accept_new_goal().samples

    def on_preempt(self) -> None:
        self.rospy.loginfo("%s: Preempted", self.name)
        self.server.set_preempted()

    def on_number(self, msg: Any) -> None:
        if not self.server.is_active():
            return
        self.count += 1
        self.total += msg.data
        self.squares += msg.data**2
        mean = self.total / self.count
        std_dev = math.sqrt(abs(self.squares / self.count - mean**2))
        feedback = self.types["Feedback"](
            sample=self.count, data=msg.data, mean=mean, std_dev=std_dev
        )
        self.server.publish_feedback(feedback)
        if self.count > self.goal:
            result = self.types["Result"](mean=mean, std_dev=std_dev)
            if mean < 5.0:
                self.rospy.loginfo("%s: Aborted", self.name)
                self.server.set_aborted(result)
            else:
                self.rospy.loginfo("%s: Succeeded", self.name)
                self.server.set_succeeded(result)


def run_averaging_server(argv: Sequence[str]) -> int:
    """The averaging server."""
    rospy = start("averaging_server", "averaging", argv)
    _Averaging(rospy, rospy.get_name())
    rospy.spin()
    return 0


def run_averaging_client(argv: Sequence[str]) -> int:
    """The averaging client: 100 samples, 30 s."""
    rospy = start("averaging_client", "test_averaging", argv)
    types = _types("Averaging")
    client = _connect(rospy, types, "averaging")
    client.send_goal(types["Goal"](samples=100))
    if client.wait_for_result(rospy.Duration(30.0)):
        rospy.loginfo("Action finished: %s", state_name(client.get_state()))
    else:
        rospy.loginfo("Action did not finish before the time out.")
    rospy.signal_shutdown("done")
    return 0


__all__ = [
    "run_averaging_client",
    "run_averaging_server",
    "run_fibonacci_callback_client",
    "run_fibonacci_class_client",
    "run_fibonacci_client",
    "run_fibonacci_server",
    "start",
    "state_name",
]
