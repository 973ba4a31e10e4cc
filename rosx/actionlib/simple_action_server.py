"""The simple action server (``actionlib.simple_action_server``): one goal at a time.

Its policy (ROS 1's): a new goal preempts the current one if its stamp is not earlier (the
current goal's ``is_preempt_requested`` turns true, the preempt callback runs, and accepting
the new goal ends the old one as preempted); a goal stamped before the current or the next
goal is canceled at once; a cancel request for the current goal sets the preempt request, for
the next goal marks it so that it starts preempted.

With an execute callback, goals are run one after the other on a thread of the server's own:
the callback must end each goal (`set_succeeded`, `set_aborted`, `set_preempted`); a goal it
leaves running is aborted, with ROS 1's warning, and one whose callback raises is aborted with
the exception's text. Without one, the user accepts goals from the goal callback
(`accept_new_goal`).

Locks: the action server's lock first, then this server's (the action server calls in here
holding its own).
"""

from __future__ import annotations

import threading
import traceback
from typing import TYPE_CHECKING, Any

from rosx.actionlib.action_server import ActionServer
from rosx.actionlib.server_goal_handle import ServerGoalHandle
from rosx.actionlib.states import Status
from rosx.client import lifecycle, logs

if TYPE_CHECKING:
    from collections.abc import Callable

#: How long the execute thread sleeps between checks for a goal when nothing wakes it.
_LOOP = 0.1
_PREEMPTED_BY_NEW_GOAL = (
    "This goal was canceled because another goal was received by the simple action server"
)


class SimpleActionServer:
    """Serves the action ``name`` of type ``ActionSpec``, one goal at a time; ``execute_cb(goal)``
    runs each goal on the server's thread. Give ``auto_start=False`` and call `start`."""

    def __init__(
        self,
        name: str,
        ActionSpec: Any,  # noqa: N803 - actionlib's name
        execute_cb: Callable[[Any], object] | None = None,
        auto_start: bool = True,
    ) -> None:
        self.new_goal = False
        self.preempt_request = False
        self.new_goal_preempt_request = False
        self.execute_callback = execute_cb
        self.goal_callback: Callable[[], object] | None = None
        self.preempt_callback: Callable[[], object] | None = None
        self.need_to_terminate = False
        self.terminate_mutex = threading.RLock()
        self.lock = threading.RLock()
        self.execute_condition = threading.Condition(self.lock)
        self.current_goal = ServerGoalHandle()
        self.next_goal = ServerGoalHandle()
        self.execute_thread: threading.Thread | None = None
        if execute_cb is not None:
            self.execute_thread = threading.Thread(
                target=self.executeLoop, name="rosx-action-execute", daemon=True
            )
            self.execute_thread.start()
        self.action_server = ActionServer(
            name,
            ActionSpec,
            self.internal_goal_callback,
            self.internal_preempt_callback,
            auto_start,
        )

    def __del__(self) -> None:
        if getattr(self, "execute_callback", None) is not None:
            with self.terminate_mutex:
                self.need_to_terminate = True

    # -- the goal ------------------------------------------------------------------------------

    def accept_new_goal(self) -> Any:
        """Make the new goal the current one (preempting the current goal) and accept it;
        the goal (an ``XGoal``), or None when there is no new goal."""
        with self.action_server.lock, self.lock:
            if not self.new_goal or not self.next_goal.get_goal():
                logs.logerr("Attempting to accept the next goal when a new goal is not available")
                return None
            if (
                self.is_active()
                and self.current_goal.get_goal()
                and self.current_goal != self.next_goal
            ):
                self.current_goal.set_canceled(None, _PREEMPTED_BY_NEW_GOAL)
            self.current_goal = self.next_goal
            self.new_goal = False
            self.preempt_request = self.new_goal_preempt_request
            self.new_goal_preempt_request = False
            self.current_goal.set_accepted(
                "This goal has been accepted by the simple action server"
            )
            return self.current_goal.get_goal()

    def is_new_goal_available(self) -> bool:
        """Whether a goal arrived that `accept_new_goal` has not taken yet."""
        return self.new_goal

    def is_preempt_requested(self) -> bool:
        """Whether the active goal was asked to stop (canceled, or a newer goal is waiting); an
        execute callback polls this and calls `set_preempted`."""
        return self.preempt_request

    def is_active(self) -> bool:
        """Whether the current goal is ACTIVE or PREEMPTING."""
        if not self.current_goal.get_goal():
            return False
        status = self.current_goal.get_goal_status().status
        return status in (Status.ACTIVE, Status.PREEMPTING)

    def set_succeeded(self, result: Any = None, text: str = "") -> None:
        """End the current goal as succeeded, with ``result`` (an ``XResult``)."""
        with self.action_server.lock, self.lock:
            self.current_goal.set_succeeded(self._result(result), text)

    def set_aborted(self, result: Any = None, text: str = "") -> None:
        """End the current goal as aborted."""
        with self.action_server.lock, self.lock:
            self.current_goal.set_aborted(self._result(result), text)

    def set_preempted(self, result: Any = None, text: str = "") -> None:
        """End the current goal as preempted."""
        with self.action_server.lock, self.lock:
            self.current_goal.set_canceled(self._result(result), text)

    def _result(self, result: Any) -> Any:
        return self.get_default_result() if result is None else result

    def publish_feedback(self, feedback: Any) -> None:
        """Send ``feedback`` (an ``XFeedback``) for the current goal."""
        self.current_goal.publish_feedback(feedback)

    def get_default_result(self) -> Any:
        """A fresh, zero-valued result message of the action's type."""
        return self.action_server.ActionResultType()

    # -- callbacks -----------------------------------------------------------------------------

    def register_goal_callback(self, cb: Callable[[], object]) -> None:
        """Call ``cb()`` when a new goal is available (not with an execute callback)."""
        if self.execute_callback:
            logs.logwarn(
                "Cannot call SimpleActionServer.register_goal_callback() because an "
                "executeCallback exists. Not going to register it."
            )
        else:
            self.goal_callback = cb

    def register_preempt_callback(self, cb: Callable[[], object]) -> None:
        """Call ``cb()`` when the current goal is asked to stop."""
        self.preempt_callback = cb

    def start(self) -> None:
        """Start serving (with ``auto_start=False``)."""
        self.action_server.start()

    def internal_goal_callback(self, goal: ServerGoalHandle) -> None:
        """The action server's goal callback: the new goal becomes the next one, if its stamp
        allows."""
        with self.execute_condition:
            try:
                stamp = goal.get_goal_id().stamp
                current, upcoming = self.current_goal, self.next_goal
                if (not current.get_goal() or stamp >= current.get_goal_id().stamp) and (
                    not upcoming.get_goal() or stamp >= upcoming.get_goal_id().stamp
                ):
                    if upcoming.get_goal() and (not current.get_goal() or upcoming != current):
                        upcoming.set_canceled(None, _PREEMPTED_BY_NEW_GOAL)
                    self.next_goal = goal
                    self.new_goal = True
                    self.new_goal_preempt_request = False
                    if self.is_active():
                        self.preempt_request = True
                        if self.preempt_callback:
                            self.preempt_callback()
                    if self.goal_callback:
                        self.goal_callback()
                    self.execute_condition.notify()
                else:
                    goal.set_canceled(None, _PREEMPTED_BY_NEW_GOAL)
            except Exception as exc:  # a user's callback: logged, as ROS 1 does
                logs.logerr("SimpleActionServer.internal_goal_callback - exception %s", str(exc))

    def internal_preempt_callback(self, preempt: ServerGoalHandle) -> None:
        """The action server's cancel callback."""
        with self.lock:
            if preempt == self.current_goal:
                self.preempt_request = True
                if self.preempt_callback:
                    self.preempt_callback()
            elif preempt == self.next_goal:
                self.new_goal_preempt_request = True

    def executeLoop(self) -> None:  # noqa: N802 - actionlib's name
        """The execute thread: run the execute callback for each new goal until shutdown."""
        while not lifecycle.is_shutdown():
            with self.terminate_mutex:
                if self.need_to_terminate:
                    break
            if self.is_active():
                logs.logerr("Should never reach this code with an active goal")
                return
            if self.is_new_goal_available():
                goal = self.accept_new_goal()
                callback = self.execute_callback
                if callback is None:
                    logs.logerr("execute_callback_ must exist. This is a bug in SimpleActionServer")
                    return
                self._execute(callback, goal)
            with self.execute_condition:
                if not self.new_goal:
                    self.execute_condition.wait(_LOOP)

    def _execute(self, callback: Callable[[Any], object], goal: Any) -> None:
        try:
            callback(goal)
            if self.is_active():
                logs.logwarn(
                    "Your executeCallback did not set the goal to a terminal status.  "
                    "This is a bug in your ActionServer implementation. Fix your code!  "
                    "For now, the ActionServer will set this goal to aborted"
                )
                self.set_aborted(None, "No terminal state was set.")
        except Exception as exc:  # a user's callback: logged, as ROS 1 does
            logs.logerr(
                "Exception in your execute callback: %s\n%s", str(exc), traceback.format_exc()
            )
            self.set_aborted(None, f"Exception in execute callback: {exc}")


__all__ = ["SimpleActionServer"]
