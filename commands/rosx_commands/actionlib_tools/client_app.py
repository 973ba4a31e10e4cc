"""axclient.py in the terminal: `ClientPane` and the app `make_client_app` builds around it.

As ROS 1's axclient: the goal as YAML in an editor (the action's empty goal to start with),
the latest feedback and the result below it, SEND GOAL (enabled while a server is connected,
checked every second) and CANCEL GOAL (while a goal is pursued), the goal's status
(``No Goal``, ``Goal is pending``, ``Goal is active``, ``Canceling goal``, ``Goal finished with
status: SUCCEEDED``…, coloured as ROS 1's) and the server's (``Connected to server``). Ctrl-S
sends, Ctrl-X cancels, Tab moves between the parts, Ctrl-C (or q outside the editor) quits.

The client is a `SimpleActionClient` of the process's node; its callbacks come on its threads
and reach the screen as messages (`post_message` does not wait, so no lock of the client is
held while the screen is busy).
"""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING, Any, ClassVar

from rich.text import Text
from textual.binding import Binding, BindingType  # noqa: TID253 - TUI code
from textual.containers import Horizontal, Vertical  # noqa: TID253 - TUI code
from textual.message import Message  # noqa: TID253 - TUI code
from textual.widgets import Button, Static, TextArea  # noqa: TID253 - TUI code

from rosx_commands.actionlib_tools.forms import FormError, from_yaml, status_look, to_yaml
from rosx_commands.paneapp import PaneApp

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    from textual.app import ComposeResult

    from rosx.actionlib import SimpleActionClient
    from rosx_commands.actionlib_tools.forms import ActionTypes

#: How often the server's presence is checked (ROS 1's axclient: every second).
SERVER_CHECK = 1.0
_WAITING = "rgb(255,174,59)"
_RED = "rgb(200,0,0)"


class ClientPane(Vertical):
    """One action's goal editor, feedback, result and status (see the module docstring)."""

    DEFAULT_CSS = """
    ClientPane #title { height: 1; background: $boost; }
    ClientPane TextArea { height: 1fr; border: round $panel-lighten-2; }
    ClientPane TextArea:focus { border: heavy $accent; }
    ClientPane #buttons { height: 3; }
    ClientPane Button { width: 1fr; }
    ClientPane #status, ClientPane #server { height: 1; }
    """
    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("ctrl+s", "send_goal", "Send goal", priority=True),
        Binding("ctrl+x", "cancel_goal", "Cancel goal", priority=True),
    ]

    class Update(Message):
        """News of the goal from the client's threads: a status line and its colour, and the
        feedback or result to show (None: unchanged)."""

        def __init__(
            self,
            status: str | None,
            colour: str = "",
            feedback: str | None = None,
            result: str | None = None,
            done: bool = False,
        ) -> None:
            super().__init__()
            self.status = status
            self.colour = colour
            self.feedback = feedback
            self.result = result
            self.done = done

    class Server(Message):
        """Whether the action's server is connected, as a check on a thread found it."""

        def __init__(self, up: bool) -> None:
            super().__init__()
            self.up = up

    def __init__(self, types: ActionTypes, name: str, client: SimpleActionClient) -> None:
        super().__init__()
        self.types = types
        self.action_name = name
        self.client = client
        self.connected = False
        self.pursuing = False

    @override
    def compose(self) -> ComposeResult:
        yield Static(f"{self.action_name} - {self.types.name} - GUI Client", id="title")
        goal = TextArea(to_yaml(self.types.goal()), id="goal", language=None)
        goal.border_title = "Goal"
        yield goal
        feedback = TextArea("", id="feedback", read_only=True)
        feedback.border_title = "Feedback"
        yield feedback
        result = TextArea("", id="result", read_only=True)
        result.border_title = "Result"
        yield result
        with Horizontal(id="buttons"):
            yield Button("SEND GOAL", id="send", disabled=True)
            yield Button("CANCEL GOAL", id="cancel", disabled=True)
        yield Static(id="status")
        yield Static(id="server")

    def on_mount(self) -> None:
        """Show "No Goal" and "Disconnected", focus the goal editor, and ask whether the server
        is up now and every `SERVER_CHECK` seconds."""
        self._show("#status", "No Goal", _RED)
        self._show("#server", "Disconnected from server.", _RED)
        self.query_one("#goal", TextArea).focus()
        self.check_server()
        self.set_interval(SERVER_CHECK, self.check_server)

    def _show(self, where: str, text: str, colour: str) -> None:
        self.query_one(where, Static).update(Text(f" {text}", style=f"black on {colour}"))

    # -- the server ----------------------------------------------------------------------------

    def check_server(self) -> None:
        """Ask (on a thread) whether the server is connected; the answer updates the screen."""

        def job() -> None:
            self.post_message(self.Server(self.client.wait_for_server(0.01)))

        self.run_worker(job, thread=True, exclusive=True, group="server")

    def on_client_pane_server(self, message: Server) -> None:
        """Show whether the action server is connected; SEND GOAL is enabled only while it is."""
        self.connected = up = message.up
        if up:
            self._show("#server", "Connected to server", "rgb(192,252,253)")
        else:
            self._show("#server", "Disconnected from server", _RED)
        self.query_one("#send", Button).disabled = not up

    # -- the goal ------------------------------------------------------------------------------

    def action_send_goal(self) -> None:
        """Ctrl+S: send the goal editor's YAML as a goal; a form error goes on the status line
        instead. Does nothing while the server is not connected."""
        if not self.connected:
            return
        try:
            goal = from_yaml(self.types.goal, self.query_one("#goal", TextArea).text)
        except FormError as error:
            self._show("#status", f"Error serializing goal: {error}", _RED)
            return
        self.pursuing = True
        self.query_one("#cancel", Button).disabled = False
        self._show("#status", "Goal is pending", _WAITING)
        self.client.send_goal(goal, self._done, self._active, self._feedback)

    def action_cancel_goal(self) -> None:
        """Ctrl+X: ask the server to cancel the goal being pursued (axclient's CANCEL GOAL)."""
        if not self.pursuing:
            return
        self.client.cancel_goal()
        self._show("#status", "Canceling goal", "rgb(211,34,243)")

    def on_button_pressed(self, event: Button.Pressed) -> None:
        """The SEND GOAL and CANCEL GOAL buttons do what Ctrl+S and Ctrl+X do."""
        if event.button.id == "send":
            self.action_send_goal()
        elif event.button.id == "cancel":
            self.action_cancel_goal()

    # -- the client's threads ------------------------------------------------------------------

    def _done(self, state: int, result: Any) -> None:
        word, colour = status_look(state)
        shown = "" if result is None else to_yaml(result)
        update = self.Update(f"Goal finished with status: {word}", colour, result=shown, done=True)
        self.post_message(update)

    def _active(self) -> None:
        self.post_message(self.Update("Goal is active", "rgb(0,200,0)"))

    def _feedback(self, feedback: Any) -> None:
        self.post_message(self.Update(None, feedback=to_yaml(feedback)))

    def on_client_pane_update(self, update: Update) -> None:
        """Show feedback, result and status from the client's callbacks (which run on its
        threads); CANCEL GOAL is disabled once the goal is done."""
        if update.feedback is not None:
            self.query_one("#feedback", TextArea).text = update.feedback
        if update.result is not None:
            self.query_one("#result", TextArea).text = update.result
        if update.status is not None:
            self._show("#status", update.status, update.colour)
        if update.done:
            self.pursuing = False
            self.query_one("#cancel", Button).disabled = True


class ClientApp(PaneApp[ClientPane]):
    """axclient.py run alone."""

    TITLE = "axclient.py"


def make_client_app(types: ActionTypes, name: str, client: SimpleActionClient) -> ClientApp:
    """The axclient app for the action ``name`` of ``types``, through ``client``."""
    return ClientApp(ClientPane(types, name, client))


__all__ = ["ClientApp", "ClientPane", "make_client_app"]
