"""A server's handle on one goal (``actionlib.server_goal_handle``): the user accepts, rejects,
ends the goal and sends feedback through it.

Every transition follows `rosx.actionlib.states.SERVER`: a call the goal's status does not
allow is logged with ROS 1's text and changes nothing. A transition to a terminal status
publishes the result (and the status list); any other publishes the status list at once.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from rosx.actionlib.protocol import msgs
from rosx.actionlib.states import SERVER_REFUSALS, TERMINAL, ServerEvent, server_next
from rosx.client import logs, timing

if TYPE_CHECKING:
    from rosx.actionlib.action_server import ActionServer
    from rosx.actionlib.status_tracker import HandleTrackerDeleter, StatusTracker

_UNINITIALIZED = "Attempt to set status on an uninitialized ServerGoalHandle"


class ServerGoalHandle:
    """One goal of an `ActionServer`; a handle made with no arguments refers to no goal."""

    def __init__(
        self,
        status_tracker: StatusTracker | None = None,
        action_server: ActionServer | None = None,
        handle_tracker: HandleTrackerDeleter | None = None,
    ) -> None:
        self.status_tracker = status_tracker
        self.action_server = action_server
        self.handle_tracker = handle_tracker
        self.goal: Any = status_tracker.goal if status_tracker else None

    def get_default_result(self) -> Any:
        """An empty ``XResult``."""
        assert self.action_server is not None
        return self.action_server.ActionResultType()

    # -- transitions ---------------------------------------------------------------------------

    def _transition(self, event: ServerEvent, text: str | None, result: Any = None) -> bool:
        """Apply ``event``; publish the result or the status; False when it was not allowed."""
        if not self.goal:
            logs.logerr(_UNINITIALIZED)
            return False
        server, tracker = self.action_server, self.status_tracker
        assert server is not None and tracker is not None
        with server.lock:
            status = tracker.status
            after = server_next(status.status, event)
            if after is None:
                if event in SERVER_REFUSALS:
                    logs.logerr(SERVER_REFUSALS[event], status.status)
                return False
            status.status = int(after)
            if text is not None:
                status.text = text
            if after in TERMINAL:
                tracker.handle_destruction_time = timing.Time.now()
                server.publish_result(
                    status, self.get_default_result() if result is None else result
                )
            else:
                server.publish_status()
            return True

    def set_accepted(self, text: str = "") -> None:
        """Accept the goal: ACTIVE, or PREEMPTING when a cancel request came first."""
        self._transition(ServerEvent.ACCEPT, text)

    def set_canceled(self, result: Any = None, text: str = "") -> None:
        """End the goal as canceled: RECALLED before it was accepted, PREEMPTED after."""
        self._transition(ServerEvent.CANCEL, text, result)

    def set_rejected(self, result: Any = None, text: str = "") -> None:
        """Refuse the goal (it must not have been accepted)."""
        self._transition(ServerEvent.REJECT, text, result)

    def set_aborted(self, result: Any = None, text: str = "") -> None:
        """End the accepted goal as failed."""
        self._transition(ServerEvent.ABORT, text, result)

    def set_succeeded(self, result: Any = None, text: str = "") -> None:
        """End the accepted goal as done."""
        self._transition(ServerEvent.SUCCEED, text, result)

    def set_cancel_requested(self) -> bool:
        """A cancel request arrived: RECALLING or PREEMPTING. True when the user's cancel
        callback is to hear of it (the status changed)."""
        if not self.goal:
            return False
        return self._transition(ServerEvent.CANCEL_REQUEST, None)

    def publish_feedback(self, feedback: Any) -> None:
        """Send ``feedback`` (an ``XFeedback``) to the goal's clients."""
        if not self.goal:
            logs.logerr("Attempt to publish feedback on an uninitialized ServerGoalHandle")
            return
        server, tracker = self.action_server, self.status_tracker
        assert server is not None and tracker is not None
        with server.lock:
            server.publish_feedback(tracker.status, feedback)

    # -- accessors -------------------------------------------------------------------------------

    def get_goal(self) -> Any:
        """The goal (an ``XGoal``), or None for a handle of no goal."""
        return self.goal.goal if self.goal else None

    def get_goal_id(self) -> Any:
        """The goal's ``actionlib_msgs/GoalID``."""
        if not self.goal:
            logs.logerr("Attempt to get a goal id on an uninitialized ServerGoalHandle")
            return msgs().GoalID()
        assert self.action_server is not None and self.status_tracker is not None
        with self.action_server.lock:
            return self.status_tracker.status.goal_id

    def get_goal_status(self) -> Any:
        """The goal's ``actionlib_msgs/GoalStatus``."""
        if not self.goal:
            logs.logerr("Attempt to get goal status on an uninitialized ServerGoalHandle")
            return msgs().GoalStatus()
        assert self.action_server is not None and self.status_tracker is not None
        with self.action_server.lock:
            return self.status_tracker.status

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, ServerGoalHandle) or not self.goal or not other.goal:
            return False
        return bool(self.get_goal_id().id == other.get_goal_id().id)

    def __ne__(self, other: object) -> bool:
        return not self == other

    def __hash__(self) -> int:
        return hash(self.get_goal_id().id)


__all__ = ["ServerGoalHandle"]
