"""What a client makes of the server's status arrays when they arrive late.

Status, feedback and result are three topics, three connections: a status array the server
sent just before it accepted a goal can arrive after the goal's first feedback, which already
told the client of the acceptance. Such an array does not list the goal; it must not make the
goal lost (a goal the server forgets, in an array sent later, still is). The messages are
handed to the client as its subscribers hand them, in the order a loaded machine may give.
"""

from __future__ import annotations

from types import ModuleType
from typing import Any

from rosx.actionlib import ActionClient
from rosx.actionlib.protocol import msgs
from rosx.actionlib.states import CommState, Status
from rosx.msg.codec.classes import get_message_class

Action = get_message_class("actionlib/TestAction")
Goal = get_message_class("actionlib/TestGoal")
ActionFeedback = get_message_class("actionlib/TestActionFeedback")


def _array(rospy: ModuleType, secs: int, *listed: tuple[str, Status]) -> Any:
    array = msgs().GoalStatusArray()
    array.header.stamp = rospy.Time(secs)
    array.status_list = [
        msgs().GoalStatus(goal_id=msgs().GoalID(id=goal), status=int(status))
        for goal, status in listed
    ]
    return array


def _feedback(rospy: ModuleType, secs: int, goal: str) -> Any:
    feedback = ActionFeedback()
    feedback.header.stamp = rospy.Time(secs)
    feedback.status = msgs().GoalStatus(goal_id=msgs().GoalID(id=goal), status=int(Status.ACTIVE))
    return feedback


def test_an_array_sent_before_the_goals_acceptance_does_not_lose_it(rospy: ModuleType) -> None:
    client = ActionClient("late_status", Action)
    sent: list[Any] = []
    client.manager.register_send_goal_fn(sent.append)
    transitions: list[int] = []
    handle = client.send_goal(Goal(goal=1), lambda gh: transitions.append(gh.get_comm_state()))
    goal = sent[0].goal_id.id
    manager = client.manager

    manager.update_feedbacks(_feedback(rospy, 11, goal))  # accepted at 10, feedback at 11
    assert handle.get_comm_state() == CommState.ACTIVE
    manager.update_statuses(_array(rospy, 9))  # sent before the acceptance, arriving now
    manager.update_statuses(_array(rospy, 11))  # sent with the feedback: still older news
    assert handle.get_comm_state() == CommState.ACTIVE
    manager.update_statuses(_array(rospy, 12, (goal, Status.ACTIVE)))
    assert handle.get_comm_state() == CommState.ACTIVE
    manager.update_statuses(_array(rospy, 20))  # the server forgot it: lost, as in ROS 1
    assert (handle.get_comm_state(), handle.get_goal_status()) == (CommState.DONE, Status.LOST)
    assert transitions == [CommState.ACTIVE, CommState.DONE]


def test_without_feedback_an_array_that_does_not_list_an_active_goal_loses_it(
    rospy: ModuleType,
) -> None:
    client = ActionClient("lost_status", Action)
    sent: list[Any] = []
    client.manager.register_send_goal_fn(sent.append)
    handle = client.send_goal(Goal(goal=1))
    goal = sent[0].goal_id.id
    client.manager.update_statuses(_array(rospy, 5))  # before the acknowledgement: normal
    assert handle.get_comm_state() == CommState.WAITING_FOR_GOAL_ACK
    client.manager.update_statuses(_array(rospy, 6, (goal, Status.ACTIVE)))
    assert handle.get_comm_state() == CommState.ACTIVE
    client.manager.update_statuses(_array(rospy, 7))
    assert (handle.get_comm_state(), handle.get_goal_status()) == (CommState.DONE, Status.LOST)
