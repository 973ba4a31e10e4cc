"""SimpleActionServer and SimpleActionClient in one process: goals succeed with their feedback,
are canceled, preempted by newer goals, aborted by failing callbacks."""

from __future__ import annotations

import threading
from collections.abc import Callable
from types import ModuleType
from typing import Any

import pytest

from rosx.actionlib import SimpleActionClient, SimpleActionServer
from rosx.actionlib.states import Status
from rosx.msg.codec.classes import get_message_class
from tests.support.procs import wait_for

Action = get_message_class("actionlib/TestAction")
Goal = get_message_class("actionlib/TestGoal")
Result = get_message_class("actionlib/TestResult")
Feedback = get_message_class("actionlib/TestFeedback")

_counter = iter(range(1_000_000))


def _pair(
    rospy: ModuleType, execute: Callable[[SimpleActionServer, Any], None] | None
) -> tuple[SimpleActionServer, SimpleActionClient]:
    """A server (with ``execute(server, goal)`` as its execute callback) and a connected
    client, on an action of its own."""
    name = f"act{next(_counter)}"
    holder: list[SimpleActionServer] = []
    callback = None if execute is None else (lambda goal: execute(holder[0], goal))
    server = SimpleActionServer(name, Action, execute_cb=callback, auto_start=False)
    holder.append(server)
    server.start()
    client = SimpleActionClient(name, Action)
    assert client.wait_for_server(rospy.Duration(10))
    return server, client


def _until_preempted(server: SimpleActionServer, goal: Any) -> None:
    event = threading.Event()
    while not server.is_preempt_requested():
        event.wait(0.005)
    server.set_preempted(Result(result=-goal.goal), "stopped")


def test_a_goal_succeeds_after_its_feedback_in_order(rospy: ModuleType) -> None:
    def execute(server: SimpleActionServer, goal: Any) -> None:
        for number in range(1, goal.goal + 1):
            server.publish_feedback(Feedback(feedback=number))
        server.set_succeeded(Result(result=goal.goal * 2), "done")

    _, client = _pair(rospy, execute)
    seen: list[Any] = []
    client.send_goal(
        Goal(goal=200),
        done_cb=lambda state, result: seen.append(("done", state, result.result)),
        active_cb=lambda: seen.append("active"),
        feedback_cb=lambda feedback: seen.append(feedback.feedback),
    )
    assert client.wait_for_result(rospy.Duration(10))
    assert seen == ["active", *range(1, 201), ("done", Status.SUCCEEDED, 400)]
    assert (client.get_state(), client.get_goal_status_text()) == (Status.SUCCEEDED, "done")
    assert client.get_result().result == 400


def test_a_goal_answered_before_send_goal_returns_still_finishes(rospy: ModuleType) -> None:
    # Noetic's client notes the goal's handle after sending the goal, and drops an answer that
    # comes first ("Got a transition callback on a goal handle that we're not tracking"): the
    # goal then never finishes for it (ros/actionlib#206). Here send_goal returns only once the
    # server's whole answer has been handled.
    _, client = _pair(rospy, lambda server, goal: server.set_succeeded(Result(result=1), "quick"))
    manager = client.action_client.manager
    send = manager.send_goal_fn
    assert send is not None
    done = threading.Event()

    def send_then_wait_for_the_answer(action_goal: Any) -> None:
        send(action_goal)
        done.wait(10)

    manager.register_send_goal_fn(send_then_wait_for_the_answer)
    client.send_goal(Goal(goal=1), done_cb=lambda state, result: done.set())
    assert done.is_set()
    assert client.wait_for_result(rospy.Duration(10))
    assert (client.get_state(), client.get_goal_status_text()) == (Status.SUCCEEDED, "quick")


def test_a_canceled_goal_is_preempted(rospy: ModuleType) -> None:
    _, client = _pair(rospy, _until_preempted)
    client.send_goal(Goal(goal=7))
    wait_for(lambda: client.get_state() == Status.ACTIVE, what="the goal active")
    client.cancel_goal()
    assert client.wait_for_result(rospy.Duration(10))
    assert (client.get_state(), client.get_goal_status_text()) == (Status.PREEMPTED, "stopped")
    assert client.get_result().result == -7


def test_a_newer_goal_preempts_the_current_one(rospy: ModuleType) -> None:
    def execute(server: SimpleActionServer, goal: Any) -> None:
        if goal.goal == 1:
            _until_preempted(server, goal)
        else:
            server.set_succeeded(Result(result=goal.goal))

    _, first = _pair(rospy, execute)
    ended: list[tuple[int, int]] = []
    first.send_goal(Goal(goal=1), done_cb=lambda state, result: ended.append((state, 1)))
    wait_for(lambda: first.get_state() == Status.ACTIVE, what="the first goal active")
    second = SimpleActionClient(first.action_client.ns, Action)
    assert second.wait_for_server(rospy.Duration(10))
    second.send_goal(Goal(goal=2))
    assert second.wait_for_result(rospy.Duration(10)) and first.wait_for_result(rospy.Duration(10))
    assert (first.get_state(), second.get_state()) == (Status.PREEMPTED, Status.SUCCEEDED)
    assert ended == [(Status.PREEMPTED, 1)]


def test_a_goal_the_callback_leaves_running_is_ended_for_it(rospy: ModuleType) -> None:
    def execute(server: SimpleActionServer, goal: Any) -> None:
        if goal.goal == 1:
            raise RuntimeError("boom")

    _, client = _pair(rospy, execute)
    for goal, text in [
        (1, "Exception in execute callback: boom"),
        (2, "No terminal state was set."),
    ]:
        client.send_goal(Goal(goal=goal))
        assert client.wait_for_result(rospy.Duration(10))
        assert (client.get_state(), client.get_goal_status_text()) == (Status.ABORTED, text)
        assert client.get_result().result == 0


def test_send_goal_and_wait_cancels_a_goal_past_its_time(rospy: ModuleType) -> None:
    _, client = _pair(rospy, _until_preempted)
    state = client.send_goal_and_wait(
        Goal(goal=3), rospy.Duration(0, 100_000_000), rospy.Duration(10)
    )
    assert state == Status.PREEMPTED


def test_goal_and_preempt_callbacks_serve_without_an_execute_thread(rospy: ModuleType) -> None:
    server, client = _pair(rospy, None)
    events: list[str] = []

    def on_goal() -> None:
        events.append(f"goal {server.accept_new_goal().goal}")

    def on_preempt() -> None:
        events.append("preempt")
        server.set_preempted()

    server.register_goal_callback(on_goal)
    server.register_preempt_callback(on_preempt)
    client.send_goal(Goal(goal=5))
    wait_for(lambda: client.get_state() == Status.ACTIVE, what="the goal active")
    assert server.is_active() and not server.is_new_goal_available()
    client.cancel_goal()
    assert client.wait_for_result(rospy.Duration(10))
    assert client.get_state() == Status.PREEMPTED
    assert events == ["goal 5", "preempt"]


def test_a_client_without_a_server_or_a_goal(rospy: ModuleType) -> None:
    client = SimpleActionClient("nobody_serves_this", Action)
    assert not client.wait_for_server(rospy.Duration(0, 200_000_000))
    assert client.get_state() == Status.LOST
    assert not client.wait_for_result(rospy.Duration(1))
    assert client.get_result() is None


def test_an_execute_callback_cannot_be_replaced_by_a_goal_callback(
    rospy: ModuleType, capsys: pytest.CaptureFixture[str]
) -> None:
    server, _ = _pair(rospy, lambda server, goal: server.set_succeeded())
    server.register_goal_callback(lambda: None)
    assert server.goal_callback is None
    assert "Cannot call SimpleActionServer.register_goal_callback()" in capsys.readouterr().err
