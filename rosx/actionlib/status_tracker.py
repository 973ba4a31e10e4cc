"""What an action server keeps per goal (``actionlib.status_tracker``,
``actionlib.handle_tracker_deleter``).

A `StatusTracker` holds a goal's ``GoalStatus`` (the message the server's ``status`` topic
lists), the goal itself, and ``handle_destruction_time``: from that time on, plus the server's
``status_list_timeout``, the goal leaves the status list. It is set when the goal reaches a
terminal status, and when a cancel or a repeated goal arrives for a goal no handle tracks.
"""

from __future__ import annotations

from typing import Any

from rosx.actionlib.goal_id_generator import GoalIDGenerator
from rosx.actionlib.protocol import msgs
from rosx.actionlib.states import Status
from rosx.client import timing


class StatusTracker:
    """A goal on the server: give either ``goal_id`` and ``status`` (a cancel request for a
    goal not seen yet), or ``goal`` (an ``XActionGoal`` received)."""

    def __init__(self, goal_id: Any = None, status: int | None = None, goal: Any = None) -> None:
        self.goal = None
        self.handle_tracker: HandleTrackerDeleter | None = None
        self.status = msgs().GoalStatus()
        self.handle_destruction_time = timing.Time()
        if goal_id:
            self.status.goal_id = goal_id
            self.status.status = status
            return
        self.goal = goal
        self.status.goal_id = goal.goal_id
        self.status.status = int(Status.PENDING)
        if self.status.goal_id.id == "":
            self.status.goal_id = GoalIDGenerator().generate_ID()
        if self.status.goal_id.stamp == timing.Time():
            self.status.goal_id.stamp = timing.Time.now()


class HandleTrackerDeleter:
    """Marks when the last handle of a goal went: the goal then leaves the status list after
    the server's ``status_list_timeout``."""

    def __init__(self, action_server: Any, status_tracker: StatusTracker) -> None:
        self.action_server = action_server
        self.status_tracker = status_tracker

    def __call__(self, ptr: object = None) -> None:
        """Record now as when the goal's last handle went, starting its ``status_list_timeout``."""
        if self.action_server:
            with self.action_server.lock:
                self.status_tracker.handle_destruction_time = timing.Time.now()


__all__ = ["HandleTrackerDeleter", "StatusTracker"]
