"""`TeleopPad`: keyboard teleop in a pane; while it has the focus, the arrow keys drive a turtle.

Each key press sends one command, as ``turtle_teleop_key`` sends one Twist per arrow byte: Up and
Down set ``linear.x`` to ±``scale_linear``, Left and Right set ``angular.z`` to ±``scale_angular``
(2.0 by default), every other field 0. Capital A, B, C and D do the same, as they do in
turtle_teleop_key (they end the arrows' escape sequences). The pad does not publish itself: it
calls ``drive(linear, angular)``, which the host wires to its ``/teleop_turtle`` node, and posts
`TeleopPad.Sent` for whoever wants to know.

Whether the arrow keys drive the turtle now is said in full words, in the pane itself: its lit
border and "arrow keys drive the turtle" while it has the focus; otherwise (Tab moved the keys
to a table, where the arrows move a cursor) that they do not, and how to get them back. Every
line fits the narrowest side column whole (`rosx_turtle.view.layout.SIDE_MIN`), so nothing is
cut mid-word on an 80x24 terminal.
"""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING, ClassVar

from textual.binding import Binding, BindingType  # noqa: TID253 - TUI code
from textual.message import Message  # noqa: TID253 - TUI code
from textual.widgets import Static  # noqa: TID253 - TUI code

from rosx_turtle.teleop import KEYS

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    from collections.abc import Callable

_FOCUSED = "arrow keys drive the turtle"
#: The first lines while another pane has the keys (each at most 36 columns: the narrowest
#: side column, less the border and the padding).
_NOT_DRIVING = (
    "Arrow keys do not drive the turtle.",
    "To drive: Tab until this is lit.",
)


class KeyPad(Static, can_focus=True):
    """A pane whose keys drive something while it has the focus: lit then, with ``focused``
    as its subtitle, and its text (`describe`) told which; ``driving`` says whether it has it.
    The teleop panes of ``rosx sim`` and of the robot lab are these."""

    DEFAULT_CSS = """
    KeyPad {
        padding: 0 1;
        border: round $panel-lighten-2;
        border-title-color: $text-muted;
        border-subtitle-color: $text-muted;
        &:focus {
            border: heavy $accent;
            border-title-color: $accent;
            border-subtitle-color: $accent;
        }
    }
    """

    def __init__(self, focused: str, *, id: str | None = None) -> None:
        super().__init__("", id=id, markup=False)
        self.focused = focused
        #: Whether the keys drive now (the pane has the focus).
        self.driving = False
        self.border_subtitle = ""

    def describe(self) -> None:
        """Put the pane's text for `driving` and what was sent."""
        raise NotImplementedError

    def on_mount(self) -> None:
        """Show the pane's text (not driving yet)."""
        self.describe()

    def on_focus(self) -> None:
        """Light the pane: its keys drive now."""
        self.driving = True
        self.border_subtitle = self.focused
        self.describe()

    def on_blur(self) -> None:
        """Dim the pane: its keys no longer drive."""
        self.driving = False
        self.border_subtitle = ""
        self.describe()


class TeleopPad(KeyPad):
    """Arrow keys to commands for ``drive(linear, angular)``; see the module docstring."""

    # Each key stands for the byte turtle_teleop_key reads (the arrows' escape sequences end
    # in A, B, C or D), and that byte's meaning comes from turtle_teleop_key's own table.
    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("up", "drive('A')", "Forward"),
        Binding("down", "drive('B')", "Back"),
        Binding("left", "drive('D')", "Turn left"),
        Binding("right", "drive('C')", "Turn right"),
        *(Binding(byte, f"drive('{byte}')", show=False) for byte in "ABCD"),
    ]

    DEFAULT_CSS = """
    TeleopPad { height: 5; }
    """

    class Sent(Message):
        """A command was sent: ``linear`` (linear.x) and ``angular`` (angular.z)."""

        def __init__(self, linear: float, angular: float) -> None:
            super().__init__()
            self.linear = linear
            self.angular = angular

    def __init__(
        self,
        drive: Callable[[float, float], None],
        *,
        scale_linear: float = 2.0,
        scale_angular: float = 2.0,
        node: str = "/teleop_turtle",
        topic: str = "/turtle1/cmd_vel",
        id: str | None = None,
    ) -> None:
        super().__init__(_FOCUSED, id=id)
        self.drive = drive
        self.scale_linear = scale_linear
        self.scale_angular = scale_angular
        self.sent = 0
        self.last: tuple[float, float] | None = None
        self.border_title = f"Teleop → {topic}"
        self.tooltip = f"{node} publishes one Twist on {topic} per arrow key"

    def action_drive(self, byte: str) -> None:
        """Send the command turtle_teleop_key sends for key byte ``byte``."""
        forward, turn = KEYS[byte.encode()]
        linear, angular = forward * self.scale_linear, turn * self.scale_angular
        self.drive(linear, angular)
        self.sent += 1
        self.last = (linear, angular)
        self.describe()
        self.post_message(self.Sent(linear, angular))

    @override
    def describe(self) -> None:
        # Each line fits the narrowest side column (`rosx_turtle.view.layout.SIDE_MIN`).
        if self.driving:
            lines = [
                f"↑ ↓  forward / back   linear.x ±{self.scale_linear}",
                f"← →  turn left/right  angular.z ±{self.scale_angular}",
            ]
        else:
            lines = list(_NOT_DRIVING)
        if self.last is None:
            lines.append("nothing sent yet")
        else:
            linear, angular = self.last
            lines.append(f"#{self.sent} linear.x={linear} angular.z={angular}")
        self.update("\n".join(lines))
