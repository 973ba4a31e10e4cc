"""ActionServer and ActionClient with goal handles: rejection, recall, cancel requests that
overtake their goals, the status list and its timing, lost goals."""

from __future__ import annotations

import itertools
from collections.abc import Callable
from types import ModuleType
from typing import Any

from rosx.actionlib import ActionClient, ActionServer, ClientGoalHandle, GoalIDGenerator
from rosx.actionlib.protocol import msgs
from rosx.actionlib.server_goal_handle import ServerGoalHandle
from rosx.actionlib.states import CommState, Status
from rosx.msg.codec.classes import get_message_class
from tests.support.procs import wait_for

Action = get_message_class("actionlib/TestAction")
ActionGoal = get_message_class("actionlib/TestActionGoal")
Goal = get_message_class("actionlib/TestGoal")
Result = get_message_class("actionlib/TestResult")

_names = (f"/server{n}" for n in itertools.count())


class Recorder:
    """A goal's comm states, as its transition callback sees them."""

    def __init__(self) -> None:
        self.states: list[CommState] = []

    def __call__(self, handle: ClientGoalHandle) -> None:
        self.states.append(CommState(handle.get_comm_state()))


def _server(
    rospy: ModuleType,
    goal_cb: Callable[[ServerGoalHandle], object],
    cancel_cb: Callable[[ServerGoalHandle], object] | None = None,
) -> tuple[ActionServer, ActionClient]:
    name = next(_names)
    server = ActionServer(name, Action, goal_cb, cancel_cb or (lambda handle: None), False)
    server.start()
    client = ActionClient(name, Action)
    assert client.wait_for_server(rospy.Duration(10))
    return server, client


def _done(handle: ClientGoalHandle) -> bool:
    return handle.get_comm_state() == CommState.DONE


def test_a_rejected_goal(rospy: ModuleType) -> None:
    _, client = _server(rospy, lambda handle: handle.set_rejected(Result(result=5), "no"))
    recorder = Recorder()
    handle = client.send_goal(Goal(goal=1), recorder)
    wait_for(lambda: _done(handle), what="the goal done")
    assert recorder.states == [CommState.PENDING, CommState.WAITING_FOR_RESULT, CommState.DONE]
    assert (handle.get_terminal_state(), handle.get_goal_status_text()) == (Status.REJECTED, "no")
    assert handle.get_result().result == 5


def test_a_goal_canceled_before_it_is_accepted_is_recalled(rospy: ModuleType) -> None:
    held: list[ServerGoalHandle] = []
    _, client = _server(rospy, held.append, lambda handle: handle.set_canceled())
    recorder = Recorder()
    handle = client.send_goal(Goal(goal=1), recorder)
    wait_for(lambda: handle.get_comm_state() == CommState.PENDING, what="the goal pending")
    handle.cancel()
    wait_for(lambda: _done(handle), what="the goal done")
    assert handle.get_terminal_state() == Status.RECALLED
    assert recorder.states[:2] == [CommState.PENDING, CommState.WAITING_FOR_CANCEL_ACK]
    assert recorder.states[-2:] == [CommState.WAITING_FOR_RESULT, CommState.DONE]
    held[0].set_accepted()  # refused: it is recalled
    assert held[0].get_goal_status().status == Status.RECALLED


def test_cancel_all_goals_reaches_every_goal(rospy: ModuleType) -> None:
    def cancel(handle: ServerGoalHandle) -> None:
        handle.set_canceled(Result(result=handle.get_goal().goal))

    _, client = _server(rospy, lambda handle: handle.set_accepted(), cancel)
    handles = [client.send_goal(Goal(goal=n)) for n in range(3)]
    wait_for(lambda: all(h.get_goal_status() == Status.ACTIVE for h in handles), what="active")
    client.cancel_all_goals()
    wait_for(lambda: all(_done(h) for h in handles), what="every goal done")
    assert [h.get_terminal_state() for h in handles] == [Status.PREEMPTED] * 3
    assert [h.get_result().result for h in handles] == [0, 1, 2]


def test_a_cancel_that_overtakes_its_goal_recalls_it(rospy: ModuleType) -> None:
    server, _ = _server(rospy, lambda handle: handle.set_accepted())
    results: list[Any] = []
    rospy.Subscriber(f"{server.ns}/result", server.ActionResult, results.append)
    cancel = rospy.Publisher(f"{server.ns}/cancel", msgs().GoalID, queue_size=10)
    goals = rospy.Publisher(f"{server.ns}/goal", ActionGoal, queue_size=10)
    wait_for(lambda: cancel.get_num_connections() and goals.get_num_connections())
    cancel.publish(msgs().GoalID(id="early"))
    wait_for(lambda: any(t.status.goal_id.id == "early" for t in server.status_list))
    assert server.status_list[-1].status.status == Status.RECALLING
    goals.publish(ActionGoal(goal_id=msgs().GoalID(id="early", stamp=rospy.Time(5))))
    wait_for(lambda: results, what="the result")
    assert (results[0].status.goal_id.id, results[0].status.status) == ("early", Status.RECALLED)


def test_a_goal_stamped_before_a_cancel_stamp_is_canceled_on_arrival(rospy: ModuleType) -> None:
    accepted: list[ServerGoalHandle] = []
    server, client = _server(rospy, accepted.append)
    client.cancel_goals_at_and_before_time(rospy.Time(100))
    wait_for(lambda: server.last_cancel == rospy.Time(100), what="the cancel stamp")
    goals = rospy.Publisher(f"{server.ns}/goal", ActionGoal, queue_size=10)
    results: list[Any] = []
    rospy.Subscriber(f"{server.ns}/result", server.ActionResult, results.append)
    wait_for(goals.get_num_connections)
    goals.publish(ActionGoal(goal_id=msgs().GoalID(id="old", stamp=rospy.Time(99))))
    wait_for(lambda: results, what="the result")
    assert results[0].status.status == Status.RECALLED
    assert results[0].status.text == (
        "This goal handle was canceled by the action server because its timestamp is before "
        "the timestamp of the last cancel request"
    )
    assert accepted == []


def test_a_goal_sent_twice_is_handled_once(rospy: ModuleType) -> None:
    seen: list[ServerGoalHandle] = []
    server, _ = _server(rospy, seen.append)
    goals = rospy.Publisher(f"{server.ns}/goal", ActionGoal, queue_size=10)
    wait_for(goals.get_num_connections)
    twice = ActionGoal(goal_id=msgs().GoalID(id="twice", stamp=rospy.Time(1)))
    goals.publish(twice)
    goals.publish(twice)
    goals.publish(ActionGoal(goal_id=msgs().GoalID(id="then", stamp=rospy.Time(1))))
    wait_for(lambda: len(server.status_list) == 2, what="two goals listed")
    assert [h.get_goal_id().id for h in seen] == ["twice", "then"]


def test_status_is_latched_and_keeps_coming_and_ended_goals_leave_it(rospy: ModuleType) -> None:
    rospy.set_param("/timed/status_list_timeout", 0.3)
    server = ActionServer("/timed", Action, lambda h: h.set_accepted(), auto_start=False)
    server.start()
    client = ActionClient("/timed", Action)
    assert client.wait_for_server(rospy.Duration(10))
    handle = client.send_goal(Goal(goal=1))
    wait_for(lambda: handle.get_goal_status() == Status.ACTIVE, what="the goal active")
    arrays: list[Any] = []
    rospy.Subscriber("/timed/status", msgs().GoalStatusArray, arrays.append)
    wait_for(lambda: len(arrays) >= 3, what="three status messages")  # the latch, then the timer
    assert [s.status for s in arrays[0].status_list] == [Status.ACTIVE]
    server.status_list[0].status.status = Status.SUCCEEDED
    server.status_list[0].handle_destruction_time = rospy.Time.now()
    wait_for(lambda: not server.status_list, what="the ended goal to leave the list")
    wait_for(lambda: arrays[-1].status_list == [], what="an empty status list")


def test_a_goal_the_server_forgets_is_lost(rospy: ModuleType) -> None:
    server, client = _server(rospy, lambda handle: handle.set_accepted())
    recorder = Recorder()
    handle = client.send_goal(Goal(goal=1), recorder)
    wait_for(lambda: handle.get_goal_status() == Status.ACTIVE, what="the goal active")
    with server.lock:
        server.status_list.clear()
        server.publish_status()
    wait_for(lambda: _done(handle), what="the goal done")
    assert handle.get_terminal_state() == Status.LOST
    assert recorder.states == [CommState.ACTIVE, CommState.DONE]


def test_a_handle_of_no_goal_says_so(rospy: ModuleType) -> None:
    nothing = ServerGoalHandle()
    assert nothing.get_goal() is None
    assert nothing.get_goal_id().id == ""
    assert nothing != ServerGoalHandle() and nothing != "goal"
    idle = ClientGoalHandle(None)
    assert (idle.get_comm_state(), idle.get_result()) == (CommState.LOST, None)


def test_goal_ids_name_the_node_and_count_in_the_process(rospy: ModuleType) -> None:
    first, second = GoalIDGenerator().generate_ID(), GoalIDGenerator("/other").generate_ID()
    name, number, stamp = first.id.split("-")
    assert name == "/actionlib_test"
    assert stamp == f"{first.stamp.secs}.{first.stamp.nsecs}"
    other, next_number, _ = second.id.split("-")
    assert (other, int(next_number)) == ("/other", int(number) + 1)
