"""axserver.py in the terminal: `ServerPane` and the app `make_server_app` builds around it.

As ROS 1's axserver (a stand-in for a server not written yet): the goal received, the feedback
and the result to send as YAML editors (the action's empty ones to start with), SEND FEEDBACK,
SUCCEED, ABORT and PREEMPT (while a goal is held), and the state: ``Waiting For Goal...``,
``Received Goal.  Send feedback, succeed, or abort.``, ``Preempt requested...``. Ctrl-F sends
the feedback, Ctrl-S succeeds, Ctrl-B aborts, Ctrl-P preempts; Ctrl-C quits.

The goals are held by a `Standin`, whose events come on the server's thread and reach the
screen as messages.
"""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING, Any, ClassVar

from rich.text import Text
from textual.binding import Binding, BindingType  # noqa: TID253 - TUI code
from textual.containers import Horizontal, Vertical  # noqa: TID253 - TUI code
from textual.message import Message  # noqa: TID253 - TUI code
from textual.widgets import Button, Static, TextArea  # noqa: TID253 - TUI code

from rosx_commands.actionlib_tools.forms import FormError, from_yaml, to_yaml
from rosx_commands.actionlib_tools.standin import ABORT, PREEMPT, SEND_FEEDBACK, SUCCEED
from rosx_commands.paneapp import PaneApp

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    from collections.abc import Callable

    from textual.app import ComposeResult

    from rosx_commands.actionlib_tools.forms import ActionTypes
    from rosx_commands.actionlib_tools.standin import Standin

_BUTTONS = (
    ("SEND FEEDBACK", SEND_FEEDBACK),
    ("SUCCEED", SUCCEED),
    ("ABORT", ABORT),
    ("PREEMPT", PREEMPT),
)
_STATES = {
    "idle": ("Waiting For Goal...", "rgb(200,0,0)"),
    "goal": ("Received Goal.  Send feedback, succeed, or abort.", "rgb(0,200,0)"),
    "preempt": ("Preempt requested...", "rgb(0,200,200)"),
}


class ServerPane(Vertical):
    """One action's stand-in server (see the module docstring)."""

    DEFAULT_CSS = """
    ServerPane #title { height: 1; background: $boost; }
    ServerPane TextArea { height: 1fr; border: round $panel-lighten-2; }
    ServerPane TextArea:focus { border: heavy $accent; }
    ServerPane #buttons { height: 3; }
    ServerPane Button { width: 1fr; }
    ServerPane #status { height: 1; }
    """
    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("ctrl+f", "decide('feedback')", "Feedback", priority=True),
        Binding("ctrl+s", "decide('succeed')", "Succeed", priority=True),
        Binding("ctrl+b", "decide('abort')", "Abort", priority=True),
        Binding("ctrl+p", "decide('preempt')", "Preempt", priority=True),
    ]

    class Event(Message):
        """What the stand-in reports: ``goal``, ``preempt`` or ``idle``, with the goal."""

        def __init__(self, kind: str, goal: Any) -> None:
            super().__init__()
            self.kind = kind
            self.goal = goal

    def __init__(self, types: ActionTypes, name: str) -> None:
        super().__init__()
        self.types = types
        self.action_name = name
        self.standin: Standin | None = None
        self.holding = False

    @override
    def compose(self) -> ComposeResult:
        yield Static(f"{self.action_name} - {self.types.name} - Standin", id="title")
        goal = TextArea("", id="goal", read_only=True)
        goal.border_title = "Goal"
        yield goal
        feedback = TextArea(to_yaml(self.types.feedback()), id="feedback")
        feedback.border_title = "Feedback"
        yield feedback
        result = TextArea(to_yaml(self.types.result()), id="result")
        result.border_title = "Result"
        yield result
        with Horizontal(id="buttons"):
            for label, kind in _BUTTONS:
                yield Button(label, id=f"do-{kind}", disabled=True)
        yield Static(id="status")

    def attach(self, standin: Standin) -> None:
        """Hold the goals of ``standin`` (its events are to reach `report`)."""
        self.standin = standin

    def report(self, kind: str, goal: Any) -> None:
        """The stand-in's ``notify``: safe from any thread."""
        self.post_message(self.Event(kind, goal))

    def on_mount(self) -> None:
        """Show the stand-in as idle, its decision buttons disabled."""
        self._state("idle", None)

    def _state(self, kind: str, goal: Any) -> None:
        text, colour = _STATES[kind]
        self.query_one("#status", Static).update(Text(f" {text}", style=f"black on {colour}"))
        if kind == "preempt":
            return
        self.holding = kind == "goal"
        for _, button in _BUTTONS:
            self.query_one(f"#do-{button}", Button).disabled = not self.holding
        self.query_one("#goal", TextArea).text = to_yaml(goal) if self.holding else ""

    def on_server_pane_event(self, event: Event) -> None:
        """Show a goal's arrival or end, reported by the stand-in from its thread."""
        self._state(event.kind, event.goal)

    def action_decide(self, kind: str) -> None:
        """Answer the held goal with ``kind`` (feedback, succeed, abort or preempt), sending the
        editor's feedback or result; a form error goes on the status line and nothing is sent."""
        if not self.holding or self.standin is None:
            return
        message = None
        if kind in (SEND_FEEDBACK, SUCCEED):
            editor = "#feedback" if kind == SEND_FEEDBACK else "#result"
            cls = self.types.feedback if kind == SEND_FEEDBACK else self.types.result
            try:
                message = from_yaml(cls, self.query_one(editor, TextArea).text)
            except FormError as error:
                what = "feedback" if kind == SEND_FEEDBACK else "result"
                self.query_one("#status", Static).update(
                    Text(f" Error serializing {what}: {error}", style="black on rgb(200,0,0)")
                )
                return
        self.standin.decide(kind, message)

    def on_button_pressed(self, event: Button.Pressed) -> None:
        """The decision buttons do what their keys do (``do-<kind>`` ids)."""
        if event.button.id is not None:
            self.action_decide(event.button.id.removeprefix("do-"))


class ServerApp(PaneApp[ServerPane]):
    """axserver.py run alone."""

    TITLE = "axserver.py"


def make_server_app(
    types: ActionTypes, name: str, standin: Callable[[ServerPane], Standin]
) -> ServerApp:
    """The axserver app for the action ``name`` of ``types``; ``standin(pane)`` makes the
    stand-in server that reports to the pane."""
    pane = ServerPane(types, name)
    pane.attach(standin(pane))
    return ServerApp(pane)


__all__ = ["ServerApp", "ServerPane", "make_server_app"]
