"""The simple action client (``actionlib.simple_action_client``): one goal at a time, seen as
PENDING, ACTIVE or DONE (`SimpleGoalState`), with done, active and feedback callbacks.

Sending a goal forgets the previous one (it is not canceled). The goal's comm state changes
move the simple state by `rosx.actionlib.states.SIMPLE`; `wait_for_result` wakes as soon as the
goal is done. The new goal is tracked before it is sent (`ActionClient.send_goal`'s
``before_send``), so its first transitions and feedback always reach the callbacks.
"""

from __future__ import annotations

import threading
import time
from typing import TYPE_CHECKING, Any

from rosx.actionlib.action_client import ActionClient, ClientGoalHandle
from rosx.actionlib.protocol import seconds_of
from rosx.actionlib.states import CommState, SimpleEffect, SimpleGoalState, Status, simple_next
from rosx.client import lifecycle, logs, names

if TYPE_CHECKING:
    from collections.abc import Callable


class SimpleActionClient:
    """A client of the action ``ns`` (of type ``ActionSpec``) that pursues one goal at a time."""

    def __init__(self, ns: str, ActionSpec: Any) -> None:  # noqa: N803 - actionlib's name
        self.action_client = ActionClient(ns, ActionSpec)
        self.simple_state = SimpleGoalState.DONE
        self.gh: ClientGoalHandle | None = None
        self.done_condition = threading.Condition()
        self.done_cb: Callable[[int, Any], object] | None = None
        self.active_cb: Callable[[], object] | None = None
        self.feedback_cb: Callable[[Any], object] | None = None

    def wait_for_server(self, timeout: Any = None) -> bool:
        """Wait for the server (a zero or absent ``timeout`` waits for ever); True once it
        is connected."""
        return self.action_client.wait_for_server(timeout)

    def send_goal(
        self,
        goal: Any,
        done_cb: Callable[[int, Any], object] | None = None,
        active_cb: Callable[[], object] | None = None,
        feedback_cb: Callable[[Any], object] | None = None,
    ) -> None:
        """Send ``goal``, forgetting any earlier one. ``done_cb(state, result)`` is called when
        it ends, ``active_cb()`` when it goes active, ``feedback_cb(feedback)`` per feedback."""
        self.stop_tracking_goal()
        self.done_cb = done_cb
        self.active_cb = active_cb
        self.feedback_cb = feedback_cb
        self.simple_state = SimpleGoalState.PENDING

        def track(handle: ClientGoalHandle) -> None:
            self.gh = handle

        self.action_client.send_goal(
            goal, self._handle_transition, self._handle_feedback, before_send=track
        )

    def send_goal_and_wait(
        self, goal: Any, execute_timeout: Any = None, preempt_timeout: Any = None
    ) -> int:
        """Send ``goal`` and wait for it; past ``execute_timeout`` cancel it and wait
        ``preempt_timeout`` more. The goal's state (`get_state`)."""
        self.send_goal(goal)
        if not self.wait_for_result(execute_timeout):
            logs.logdebug("Canceling goal")
            self.cancel_goal()
            if self.wait_for_result(preempt_timeout):
                logs.logdebug(
                    "Preempt finished within specified preempt_timeout [%.2f]",
                    seconds_of(preempt_timeout),
                )
            else:
                logs.logdebug(
                    "Preempt didn't finish specified preempt_timeout [%.2f]",
                    seconds_of(preempt_timeout),
                )
        return self.get_state()

    def wait_for_result(self, timeout: Any = None) -> bool:
        """Wait until the goal is done (a zero or absent ``timeout`` waits for ever); True when
        it is."""
        if not self.gh:
            logs.logerr("Called wait_for_result when no goal exists")
            return False
        seconds = seconds_of(timeout)
        deadline = time.monotonic() + seconds
        with self.done_condition:
            while not lifecycle.is_shutdown() and self.simple_state != SimpleGoalState.DONE:
                left = deadline - time.monotonic()
                if seconds > 0.0 and left <= 0.0:
                    break
                # Short waits: a shutdown ends the wait without a notification.
                self.done_condition.wait(0.1 if seconds <= 0.0 else min(left, 0.1))
        return self.simple_state == SimpleGoalState.DONE

    def get_result(self) -> Any:
        """The goal's result (an ``XResult``), or None."""
        if not self.gh:
            logs.logerr("Called get_result when no goal is running")
            return None
        return self.gh.get_result()

    def get_state(self) -> int:
        """The goal's status: PENDING, ACTIVE, RECALLED, REJECTED, PREEMPTED, ABORTED,
        SUCCEEDED or LOST (``actionlib_msgs/GoalStatus``'s numbers); LOST with no goal."""
        if not self.gh:
            return int(Status.LOST)
        status = self.gh.get_goal_status()
        if status == Status.RECALLING:
            return int(Status.PENDING)
        if status == Status.PREEMPTING:
            return int(Status.ACTIVE)
        return status

    def get_goal_status_text(self) -> str:
        """The text the server gave with the goal's status."""
        if not self.gh:
            logs.logerr("Called get_goal_status_text when no goal is running")
            return "ERROR: Called get_goal_status_text when no goal is running"
        return self.gh.get_goal_status_text()

    def cancel_all_goals(self) -> None:
        """Ask the server to cancel every goal it has."""
        self.action_client.cancel_all_goals()

    def cancel_goals_at_and_before_time(self, time: Any) -> None:
        """Ask the server to cancel every goal stamped at or before ``time``."""
        self.action_client.cancel_goals_at_and_before_time(time)

    def cancel_goal(self) -> None:
        """Ask the server to cancel the goal being pursued."""
        if self.gh:
            self.gh.cancel()

    def stop_tracking_goal(self) -> None:
        """Forget the goal (its callbacks stop); it is not canceled."""
        self.gh = None

    def _handle_transition(self, gh: ClientGoalHandle) -> None:
        if gh != self.gh:
            logs.logerr("Got a transition callback on a goal handle that we're not tracking")
            return
        comm = CommState(gh.get_comm_state())
        after, effect = simple_next(self.simple_state, comm)
        if effect == SimpleEffect.UNEXPECTED:
            logs.logerr(
                "Received comm state %s when in simple state %s with SimpleActionClient in NS %s",
                CommState.to_string(comm),
                SimpleGoalState.to_string(self.simple_state),
                names.resolve_name(self.action_client.ns),
            )
        elif effect == SimpleEffect.DONE_TWICE:
            logs.logerr("SimpleActionClient received DONE twice")
        elif effect == SimpleEffect.ACTIVE_CALLBACK:
            self.simple_state = after
            if self.active_cb:
                self.active_cb()
        elif effect == SimpleEffect.DONE_CALLBACK:
            if self.done_cb:
                self.done_cb(gh.get_goal_status(), gh.get_result())
            with self.done_condition:
                self.simple_state = after
                self.done_condition.notify_all()

    def _handle_feedback(self, gh: ClientGoalHandle, feedback: Any) -> None:
        if not self.gh:
            return  # the goal was forgotten; feedback of it may still be on its way
        if gh != self.gh:
            machine, mine = gh.comm_state_machine, self.gh.comm_state_machine
            logs.logerr(
                "Got a feedback callback on a goal handle that we're not tracking. %s vs %s",
                mine.action_goal.goal_id.id if mine else "",
                machine.action_goal.goal_id.id if machine else "",
            )
            return
        if self.feedback_cb:
            self.feedback_cb(feedback)


__all__ = ["SimpleActionClient", "SimpleGoalState"]
