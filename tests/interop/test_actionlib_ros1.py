"""actionlib between rosx and ROS 1 (Debian's python3-actionlib), both ways: the same scenario
client, run against the same scenario server, sees the same goal transitions, states, texts and
results whichever side runs ROS 1.

The scenario is a rospy + actionlib program, run by Debian's Python (ROS 1's actionlib) or by
``rosx run-script`` (rosx's). The server serves ``/goals`` (an ActionServer whose goal number
says what to do with it) and ``/simple`` (a SimpleActionServer); the client drives each goal
through success, preemption, recall, rejection and abortion, and prints what it saw as JSON.
"""

from __future__ import annotations

import json
import subprocess
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from tests.support.cli import clean_environ
from tests.support.procs import running, wait_for
from tests.support.ros1 import needs_ros1, ros1_python_imports
from tests.support.ros1_procs import ROS1_PYTHON, ros_env
from tests.support.scripts import script_command

pytestmark = [
    needs_ros1,
    pytest.mark.skipif(
        not ros1_python_imports("actionlib", "actionlib.msg"),
        reason="Debian's python3-actionlib is absent",
    ),
]

SERVER = """
import rospy
import actionlib
from actionlib.msg import TestAction, TestFeedback, TestResult

rospy.init_node("scenario_server")
held = []

def on_goal(handle):
    number = handle.get_goal().goal
    if number == 1:
        handle.set_accepted()
        handle.set_succeeded(TestResult(10), "done")
    elif number == 2:
        handle.set_accepted("working")
    elif number == 3:
        held.append(handle)  # left pending until canceled
    elif number == 4:
        handle.set_rejected(TestResult(40), "no")
    elif number == 5:
        handle.set_accepted()
        for step in range(1, 6):
            handle.publish_feedback(TestFeedback(step))
            rospy.sleep(0.02)
        handle.set_aborted(TestResult(50), "failed")

def on_cancel(handle):
    handle.set_canceled(TestResult(handle.get_goal().goal * 10), "canceled")

server = actionlib.ActionServer("goals", TestAction, on_goal, on_cancel, auto_start=False)
server.start()

def execute(goal):
    while goal.goal == 2 and not simple.is_preempt_requested() and not rospy.is_shutdown():
        rospy.sleep(0.01)
    if simple.is_preempt_requested():
        simple.set_preempted(TestResult(-goal.goal), "preempted")
    else:
        simple.set_succeeded(TestResult(goal.goal), "simple done")

simple = actionlib.SimpleActionServer("simple", TestAction, execute, auto_start=False)
simple.start()
print("ready", flush=True)
rospy.spin()
"""

CLIENT = """
import json
import os
import time
import xmlrpc.client
import rospy
import actionlib
from actionlib.msg import TestAction, TestGoal
from actionlib_msgs.msg import GoalStatus

rospy.init_node("scenario_client")
client = actionlib.ActionClient("goals", TestAction)
assert client.wait_for_server(rospy.Duration(30))

def wait(predicate, what):
    deadline = time.monotonic() + 30
    while not predicate():
        assert time.monotonic() < deadline, f"timed out waiting for {what()}"
        time.sleep(0.005)

# wait_for_server trusts this side's view of the result topic; rospy's publisher lists the
# connection a moment later (16 ms seen on a loaded machine), and a result published in
# between is lost. So wait until the server itself lists this client as a subscriber.
master = xmlrpc.client.ServerProxy(os.environ["ROS_MASTER_URI"])
server = xmlrpc.client.ServerProxy(master.lookupNode("/scenario_client", "/scenario_server")[2])
def served(ns):
    rows = server.getBusInfo("/scenario_client")[2]
    topics = {row[4] for row in rows if row[1] == "/scenario_client" and row[2] == "o"}
    return {ns + "/result", ns + "/feedback"} <= topics
wait(lambda: served("/goals"), lambda: "the server to list this client on /goals")

report = {}
for number, cancel_in in [(1, None), (2, 2), (3, 1), (4, None), (5, None)]:
    states, feedback = [], []
    handle = client.send_goal(
        TestGoal(number),
        lambda h, states=states: states.append(h.get_comm_state()),
        lambda h, f, feedback=feedback: feedback.append(f.feedback),
    )
    def at(state, number=number, handle=handle):
        return lambda: f"goal {number} in comm state {state}, at {handle.get_comm_state()}"
    if cancel_in is not None:
        wait(lambda: handle.get_comm_state() == cancel_in, at(cancel_in))  # PENDING or ACTIVE
        handle.cancel()
    wait(lambda: handle.get_comm_state() == 7, at(7))
    result = handle.get_result()
    report[str(number)] = {
        "states": states,
        "terminal": handle.get_terminal_state(),
        "text": handle.get_goal_status_text(),
        "result": None if result is None else result.result,
        "feedback": feedback,
    }

first = actionlib.SimpleActionClient("simple", TestAction)
second = actionlib.SimpleActionClient("simple", TestAction)
assert first.wait_for_server(rospy.Duration(30)) and second.wait_for_server(rospy.Duration(30))
wait(lambda: served("/simple"), lambda: "the server to list this client on /simple")
calls = []
first.send_goal(TestGoal(1), lambda s, r: calls.append(["done", s, r.result]),
                lambda: calls.append(["active"]))
first.wait_for_result(rospy.Duration(30))
first.send_goal(TestGoal(2), lambda s, r: calls.append(["done", s, r.result]),
                lambda: calls.append(["active"]))
wait(lambda: first.get_state() == GoalStatus.ACTIVE,
     lambda: f"the simple client's goal 2 active, at {first.get_state()}")
second.send_goal(TestGoal(3))
second.wait_for_result(rospy.Duration(30))
first.wait_for_result(rospy.Duration(30))
report["simple"] = {
    "calls": calls,
    "first": [first.get_state(), first.get_goal_status_text(), first.get_result().result],
    "second": [second.get_state(), second.get_goal_status_text(), second.get_result().result],
    "waited": first.send_goal_and_wait(TestGoal(2), rospy.Duration(0.2), rospy.Duration(30)),
}
print(json.dumps(report), flush=True)
"""


#: What the scenario client saw (its JSON), by (server side, client side).
Reports = dict[tuple[str, str], dict[str, Any]]


@pytest.fixture(scope="module")
def scripts(tmp_path_factory: pytest.TempPathFactory) -> Path:
    folder = tmp_path_factory.mktemp("scenario")
    (folder / "scenario_server.py").write_text(SERVER)
    (folder / "scenario_client.py").write_text(CLIENT)
    return folder


def _command(side: str, script: Path) -> list[str]:
    if side == "ros1":
        return [str(ROS1_PYTHON), str(script)]
    return script_command(script)


def _environ(side: str, master: str, home: Path) -> dict[str, str]:
    if side == "ros1":
        return ros_env(master, home)
    return clean_environ(ROS_MASTER_URI=master, HOME=str(home))


@pytest.fixture(scope="module")
def reports(
    master: str, scripts: Path, tmp_path_factory: pytest.TempPathFactory
) -> Iterator[Reports]:
    """What the client saw, for each (server side, client side)."""
    found: Reports = {}
    home = tmp_path_factory.mktemp("home")
    for server_side in ("ros1", "rosx"):
        log = home / f"server-{server_side}.log"
        with (
            log.open("w") as out,
            running(
                _command(server_side, scripts / "scenario_server.py"),
                _environ(server_side, master, home),
                stdout=out,
                stderr=subprocess.STDOUT,
            ),
        ):
            wait_for(lambda: "ready" in log.read_text(), 60, "the scenario server")  # noqa: B023 - called at once
            for client_side in ("ros1", "rosx"):
                done = subprocess.run(
                    _command(client_side, scripts / "scenario_client.py"),
                    env=_environ(client_side, master, home),
                    capture_output=True,
                    text=True,
                    timeout=120,
                    check=False,
                )
                # The end of the client's traceback says which goal stuck, and where.
                tail = done.stderr.strip().splitlines()[-3:]
                assert done.returncode == 0, (server_side, client_side, tail)
                found[server_side, client_side] = json.loads(done.stdout.splitlines()[-1])
    yield found


SUCCEEDED, PREEMPTED, ABORTED, REJECTED, RECALLED = 3, 2, 4, 5, 8
# comm states
PENDING, ACTIVE, WAITING_FOR_RESULT, WAITING_FOR_CANCEL_ACK, RECALLING, PREEMPTING, DONE = (
    1, 2, 3, 4, 5, 6, 7,
)  # fmt: skip


def _comparable(report: dict[str, Any]) -> dict[str, Any]:
    """What ROS 1's client reports reliably: not the feedback (it may drop what comes after
    the result) nor the simple client's callbacks (it may miss a goal's first transition)."""
    skipped = ("feedback", "calls")
    return {
        goal: {k: v for k, v in seen.items() if k not in skipped} for goal, seen in report.items()
    }


def test_every_pairing_sees_what_ros1_alone_sees(
    reports: Reports,
) -> None:
    ros1_alone = _comparable(reports["ros1", "ros1"])
    for pairing, report in reports.items():
        assert _comparable(report) == ros1_alone, pairing


def test_the_goals_went_through_actionlibs_transitions(
    reports: Reports,
) -> None:
    seen = reports["rosx", "rosx"]
    assert seen["1"] == {
        "states": [ACTIVE, WAITING_FOR_RESULT, DONE],
        "terminal": SUCCEEDED, "text": "done", "result": 10, "feedback": [],
    }  # fmt: skip
    assert seen["2"]["states"] == [
        ACTIVE, WAITING_FOR_CANCEL_ACK, PREEMPTING, WAITING_FOR_RESULT, DONE,
    ]  # fmt: skip
    assert (seen["2"]["terminal"], seen["2"]["result"]) == (PREEMPTED, 20)
    assert seen["3"]["states"] == [
        PENDING, WAITING_FOR_CANCEL_ACK, RECALLING, WAITING_FOR_RESULT, DONE,
    ]  # fmt: skip
    assert (seen["3"]["terminal"], seen["3"]["text"]) == (RECALLED, "canceled")
    assert seen["4"]["states"] == [PENDING, WAITING_FOR_RESULT, DONE]
    assert (seen["4"]["terminal"], seen["4"]["result"]) == (REJECTED, 40)
    assert (seen["5"]["terminal"], seen["5"]["text"]) == (ABORTED, "failed")
    assert {k: v for k, v in seen["simple"].items() if k != "calls"} == {
        "first": [PREEMPTED, "preempted", -2],
        "second": [SUCCEEDED, "simple done", 3],
        "waited": PREEMPTED,
    }


def test_a_rosx_client_misses_no_feedback_and_no_callback(
    reports: Reports,
) -> None:
    for server_side in ("ros1", "rosx"):
        seen = reports[server_side, "rosx"]
        assert seen["5"]["feedback"] == [1, 2, 3, 4, 5]
        assert seen["simple"]["calls"] == [
            ["active"], ["done", SUCCEEDED, 1], ["active"], ["done", PREEMPTED, -2],
        ]  # fmt: skip
