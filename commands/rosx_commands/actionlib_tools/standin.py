"""axserver's stand-in server: a simple action server whose goals the user ends by hand.

Each goal waits on the server's execute thread for the user's word (`decide`): feedback to send
(the goal keeps waiting), or success with a result, abortion, or preemption (the goal ends).
What happens is told to ``notify`` as events: ``("goal", goal)`` when a goal arrives,
``("preempt", None)`` once when a client asks to cancel it, ``("idle", None)`` when it has
ended. No screen here: the app turns events into what it shows.
"""

from __future__ import annotations

import threading
from collections import deque
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from collections.abc import Callable

    from rosx_commands.actionlib_tools.forms import ActionTypes

SEND_FEEDBACK, SUCCEED, ABORT, PREEMPT = "feedback", "succeed", "abort", "preempt"
#: How often a waiting goal looks for a cancel request.
_PREEMPT_CHECK = 0.05


class Standin:
    """A simple action server for ``name`` of ``types`` that the user drives (`decide`)."""

    def __init__(self, types: ActionTypes, name: str, notify: Callable[[str, Any], object]) -> None:
        from rosx.actionlib import SimpleActionServer  # noqa: PLC0415 - the tool's node is up

        self.notify = notify
        self.condition = threading.Condition()
        self.decisions: deque[tuple[str, Any]] = deque()
        self.closing = False
        self.preempt_told = False
        self.server = SimpleActionServer(name, types.action, self.execute, auto_start=False)
        self.server.start()

    def decide(self, kind: str, message: Any = None) -> None:
        """The user's word for the current goal: `SEND_FEEDBACK` (with the feedback),
        `SUCCEED` (with the result), `ABORT` or `PREEMPT`."""
        with self.condition:
            self.decisions.append((kind, message))
            self.condition.notify_all()

    def close(self) -> None:
        """Stop waiting: a goal in progress is aborted."""
        with self.condition:
            self.closing = True
            self.condition.notify_all()

    def _next(self) -> tuple[str, Any]:
        """The user's next word (waiting for it), or ABORT once closing."""
        with self.condition:
            while not self.decisions and not self.closing:
                if not self.preempt_told and self.server.is_preempt_requested():
                    self.preempt_told = True
                    self.notify("preempt", None)
                self.condition.wait(_PREEMPT_CHECK)
            return self.decisions.popleft() if self.decisions else (ABORT, None)

    def execute(self, goal: Any) -> None:
        """The execute callback: send feedback as the user says, until the user ends it."""
        with self.condition:
            self.decisions.clear()  # words given while no goal was held are for none
            self.preempt_told = False
        self.notify("goal", goal)
        kind, message = self._next()
        while kind == SEND_FEEDBACK:
            self.server.publish_feedback(message)
            kind, message = self._next()
        if kind == SUCCEED:
            self.server.set_succeeded(message)
        elif kind == PREEMPT:
            self.server.set_preempted()
        else:
            self.server.set_aborted()
        self.notify("idle", None)


__all__ = ["ABORT", "PREEMPT", "SEND_FEEDBACK", "SUCCEED", "Standin"]
