"""actionlib_tutorials and turtle_actionlib under ``rosx rosrun`` and ``rosx roslaunch``: the
Fibonacci and averaging servers and clients print what ROS 1's print, and the shape server
draws a pentagon with turtlesim. The upstream packages build with ``rosx catkin_make`` and run.

The tutorials' servers work at one number a second; the clients are tested against a server of
the same answers in the test's process, and the servers with short goals, so no test waits the
tutorial's twenty seconds.
"""

from __future__ import annotations

import math
import re
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path
from types import ModuleType
from typing import Any

import pytest

from rosx.actionlib import SimpleActionClient, SimpleActionServer
from rosx.actionlib.states import Status
from rosx.msg.codec.classes import get_message_class
from tests.support.cli import rosx
from tests.support.client import fresh_rospy
from tests.support.fetched import fetched_tree
from tests.support.procs import wait_for
from tests.support.tutorial_nodes import ROSCPP_LINE, ROSPY_LINE, Runs, lines

FibonacciAction = get_message_class("actionlib_tutorials/FibonacciAction")
FibonacciGoal = get_message_class("actionlib_tutorials/FibonacciGoal")
FibonacciResult = get_message_class("actionlib_tutorials/FibonacciResult")
FibonacciFeedback = get_message_class("actionlib_tutorials/FibonacciFeedback")


@pytest.fixture
def runs(master: str, tmp_path: Path) -> Runs:
    return Runs(master, tmp_path)


@pytest.fixture
def rospy(master: str, monkeypatch: pytest.MonkeyPatch) -> Iterator[ModuleType]:
    for module in fresh_rospy(master, monkeypatch):
        module.init_node("tutorial_test", disable_signals=True)
        yield module


def _fibonacci(numbers: int) -> list[int]:
    sequence = [0, 1]
    while len(sequence) < numbers:
        sequence.append(sequence[-1] + sequence[-2])
    return sequence


def fast_fibonacci_server(extra: int) -> SimpleActionServer:
    """A ``/fibonacci`` server answering at once: ``order + extra`` numbers, with feedback."""

    def execute(goal: Any) -> None:
        for count in range(3, goal.order + extra + 1):
            server.publish_feedback(FibonacciFeedback(sequence=_fibonacci(count)))
        server.set_succeeded(FibonacciResult(sequence=_fibonacci(goal.order + extra)))

    server = SimpleActionServer("/fibonacci", FibonacciAction, execute, auto_start=False)
    server.start()
    return server


def _said(log: Path, pattern: str = ROSPY_LINE) -> list[str]:
    return [line.partition("]: ")[2] for line in lines(log) if re.match(pattern, line)]


def test_the_python_server_grows_the_sequence_and_stops_when_canceled(
    runs: Runs, rospy: ModuleType
) -> None:
    with runs.node("actionlib_tutorials", "fibonacci_server.py") as server:
        client = SimpleActionClient("fibonacci", FibonacciAction)
        assert client.wait_for_server(rospy.Duration(30))
        listed = rosx("rostopic", "list", environ=runs.env).out.split()
        assert [t for t in listed if t.startswith("/fibonacci/")] == [
            f"/fibonacci/{t}" for t in ("cancel", "feedback", "goal", "result", "status")
        ]
        feedback: list[list[int]] = []
        client.send_goal(
            FibonacciGoal(order=3), feedback_cb=lambda f: feedback.append(list(f.sequence))
        )
        assert client.wait_for_result(rospy.Duration(30))
        assert client.get_state() == Status.SUCCEEDED
        assert list(client.get_result().sequence) == [0, 1, 1, 2]
        assert feedback == [[0, 1, 1], [0, 1, 1, 2]]
        client.send_goal(FibonacciGoal(order=50))
        wait_for(lambda: client.get_state() == Status.ACTIVE, what="the second goal active")
        client.cancel_goal()
        assert client.wait_for_result(rospy.Duration(30))
        assert client.get_state() == Status.PREEMPTED
        wait_for(lambda: len(_said(server)) >= 4, what="the server's lines")
    assert _said(server) == [
        "/fibonacci: Executing, creating fibonacci sequence of order 3 with seeds 0, 1",
        "/fibonacci: Succeeded",
        "/fibonacci: Executing, creating fibonacci sequence of order 50 with seeds 0, 1",
        "/fibonacci: Preempted",
    ]


def test_the_python_client_prints_the_result(runs: Runs, rospy: ModuleType) -> None:
    fast_fibonacci_server(extra=1)  # as the Python server: order + 1 numbers
    done = runs.run("actionlib_tutorials", "fibonacci_client.py")
    assert (done.returncode, done.stdout) == (
        0,
        "Result: " + ", ".join(str(n) for n in _fibonacci(21)) + "\n",
    )


def test_the_cpp_clients_log_what_roscpp_logs(runs: Runs, rospy: ModuleType) -> None:
    fast_fibonacci_server(extra=2)  # as the C++ server: order + 2 numbers
    plain = runs.run("actionlib_tutorials", "fibonacci_client")
    said = _said_text(plain.stdout)
    assert said == [
        "Waiting for action server to start.",
        "Action server started, sending goal.",
        "Action finished: SUCCEEDED",
        "Action result: " + "".join(f"{n} " for n in _fibonacci(22)),
    ]
    callbacks = runs.run("actionlib_tutorials", "fibonacci_callback_client")
    assert _said_text(callbacks.stdout) == [
        "Waiting for action server to start.",
        "Action server started, sending goal.",
        "Goal just went active",
        *(f"Got Feedback of length {n}" for n in range(3, 23)),
        "Finished in state [SUCCEEDED]",
        "Answer: 10946",
    ]
    assert callbacks.returncode == 0


def _said_text(text: str) -> list[str]:
    found = []
    for line in text.splitlines():
        assert re.match(ROSCPP_LINE, line), line
        found.append(line.partition("]: ")[2])
    return found


def test_averaging_launch_averages_the_random_numbers(runs: Runs) -> None:
    with runs.tool("roslaunch", "actionlib_tutorials", "averaging.launch") as log:
        wait_for(lambda: "Action finished: " in log.read_text(), 60, "the client's answer")
    said = _said(log, ROSCPP_LINE)
    finished = next(line for line in said if line.startswith("Action finished: "))
    verdict = {"Action finished: SUCCEEDED": "Succeeded", "Action finished: ABORTED": "Aborted"}
    assert f"/averaging: {verdict[finished]}" in said
    assert said[:2] == [
        "Waiting for action server to start.",
        "Action server started, sending goal.",
    ]
    assert "]: Generating random numbers" in log.read_text()


def test_the_shape_server_draws_a_pentagon(runs: Runs, rospy: ModuleType) -> None:
    pose_type = get_message_class("turtlesim/Pose")
    results: list[Any] = []
    rospy.Subscriber(
        "/turtle_shape/result",
        get_message_class("turtle_actionlib/ShapeActionResult"),
        results.append,
    )
    with (
        runs.node("turtlesim", "turtlesim_node", "--headless"),
        runs.node("turtle_actionlib", "shape_server") as server,
    ):
        start = rospy.wait_for_message("/turtle1/pose", pose_type, timeout=30)
        client = runs.run("turtle_actionlib", "shape_client")
        end = rospy.wait_for_message("/turtle1/pose", pose_type, timeout=30)
        wait_for(lambda: results, what="the result")
    assert _said_text(client.stdout) == [
        "Waiting for action server to start.",
        "Action server started, sending goal.",
        "Action finished: SUCCEEDED",
    ]
    assert _said(server, ROSCPP_LINE) == ["/turtle_shape: Succeeded"]
    assert math.hypot(end.x - start.x, end.y - start.y) < 0.01
    result = results[0].result
    assert result.interior_angle == pytest.approx(3 * math.pi / 5)  # five edges
    assert result.apothem == pytest.approx(1.3 * math.cos(math.pi / 5))


def test_the_upstream_tutorials_build_and_run(
    runs: Runs, rospy: ModuleType, tmp_path: Path
) -> None:
    workspace = tmp_path / "ws"
    for package in ("actionlib_tutorials", "turtle_actionlib"):
        fetched_tree("ros/common_tutorials", package, workspace / "src")
    built = subprocess.run(
        [sys.executable, "-m", "rosx_commands", "catkin_make"],
        cwd=workspace, env={**runs.env, "PWD": str(workspace)}, capture_output=True,
        text=True, timeout=120, check=False,
    )  # fmt: skip
    assert built.returncode == 0, built.stderr
    assert "-- actionlib_tutorials: 14 messages, 0 services" in built.stdout
    assert "-- turtle_actionlib: 8 messages, 0 services" in built.stdout
    assert built.stderr == ""
    runs.env["ROS_PACKAGE_PATH"] = str(workspace / "src")
    with runs.node("actionlib_tutorials", "scripts/fibonacci_server.py") as server:
        client = SimpleActionClient("fibonacci", FibonacciAction)
        assert client.wait_for_server(rospy.Duration(30))
        client.send_goal(FibonacciGoal(order=2))
        assert client.wait_for_result(rospy.Duration(30))
        assert list(client.get_result().sequence) == [0, 1, 1]
    assert _said(server)[-1] == "/fibonacci: Succeeded"
    fast_fibonacci_server(extra=1)
    done = runs.run("actionlib_tutorials", "scripts/fibonacci_client.py")
    assert (done.returncode, done.stdout) == (
        0,
        "Result: " + ", ".join(str(n) for n in _fibonacci(21)) + "\n",
    )
