"""`TwistPad`: teleop_twist_keyboard in a pane; while it has the focus, its keys drive the robot.

The keys and speeds are teleop_twist_keyboard's (`rosx_turtle.teleop_twist.TwistKeys`): ``u i o
/ j k l / m , .`` move and turn, the same with Shift strafe (omni robots), ``t``/``b`` go up and
down, ``w``/``x`` and ``e``/``c`` scale the linear and angular speeds by 10 %, ``z`` both down.
``q`` quits, as in every rosx screen, so ``+`` scales both up (teleop_twist_keyboard's ``q``);
the arrow keys stand for ``i``, ``,``, ``j`` and ``l``. As teleop_twist_keyboard with
``~repeat_rate 10`` and ``~key_timeout 0.5``, the command is sent again ten times a second
while a key is held (the terminal repeats it) and stops half a second after the last key, so
stageros's watchdog never stops the robot mid-drive. The pad stops the robot when it loses the
focus. It does not publish itself: it calls ``drive(x, y, z, turn)``.
"""

from __future__ import annotations

import sys
import time
from typing import TYPE_CHECKING, ClassVar

from textual.binding import Binding, BindingType  # noqa: TID253 - TUI code

from rosx_turtle.teleop_twist import MOVES, SPEEDS, TwistKeys
from rosx_turtle.tui.teleop import KeyPad

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    from collections.abc import Callable

    from textual.timer import Timer

#: Seconds between two sends of a held command (teleop_twist_keyboard's ``~repeat_rate`` 10).
REPEAT = 0.1
#: Seconds after the last key when a moving robot is stopped (``~key_timeout``).
KEY_TIMEOUT = 0.5
#: textual's names of the keys that are not letters, and the teleop's key each stands for.
_NAMED = {
    "comma": ",", "full_stop": ".", "less_than_sign": "<", "greater_than_sign": ">",
    "plus": "q", "up": "i", "down": ",", "left": "j", "right": "l", "space": "k",
}  # fmt: skip
_FOCUSED = "keys drive the robot"
#: Each line fits the narrowest side column (36 columns inside the border).
_HELP = (
    "u i o   ↑    forward, turning",
    "j k l  ← →   turn   (k: stop)",
    "m , .   ↓    back, turning",
    "+ z both  w x linear  e c angular",
)
_NOT_DRIVING = ("Keys do not drive the robot.", "To drive: Tab until this is lit.")


def _key_bindings() -> list[BindingType]:
    letters = [key for key in (*MOVES, *SPEEDS) if key.isalpha() and key != "q"]
    bindings: list[BindingType] = [
        Binding(key, f"press('{key}')", show=False) for key in sorted(set(letters))
    ]
    bindings += [Binding(name, f"press('{key}')", show=False) for name, key in _NAMED.items()]
    return bindings


class TwistPad(KeyPad):
    """teleop_twist_keyboard's keys to ``drive(x, y, z, turn)``; see the module docstring."""

    BINDINGS: ClassVar[list[BindingType]] = _key_bindings()

    DEFAULT_CSS = """
    TwistPad { height: 8; }
    """

    def __init__(
        self,
        drive: Callable[[float, float, float, float], None],
        *,
        topic: str = "/cmd_vel",
        clock: Callable[[], float] = time.monotonic,
        id: str | None = None,
    ) -> None:
        super().__init__(_FOCUSED, id=id)
        self.drive = drive
        self.keys = TwistKeys()
        self.sent = 0
        self.last: tuple[float, float, float, float] | None = None
        self._clock = clock
        self._pressed = 0.0
        self._repeat: Timer | None = None
        self.border_title = f"Teleop → {topic}"
        self.tooltip = f"/teleop_twist_keyboard publishes geometry_msgs/Twist on {topic}"

    # textual runs KeyPad's handlers of these messages as well (every class's, in turn).
    def on_mount(self) -> None:
        """Repeat the held key's command every `REPEAT` seconds until it times out (after
        KeyPad's handler has shown the help)."""
        self._repeat = self.set_interval(REPEAT, self._tick)

    def on_blur(self) -> None:
        """Stop the robot when the pane loses the focus with a key still held."""
        if self.keys.direction != (0, 0, 0, 0):
            self.action_press("k")

    def action_press(self, key: str) -> None:
        """What teleop_twist_keyboard does for ``key``: a new direction or speed, then a send."""
        self._pressed = self._clock()
        self.keys, _lines, send = self.keys.press(key)
        if send:
            self._send()
        self.describe()

    def _tick(self) -> None:
        if self.keys.direction == (0, 0, 0, 0):
            return
        if self._clock() - self._pressed >= KEY_TIMEOUT:
            self.keys, _lines, _send = self.keys.press("")
            self._send()
            self.describe()
        else:
            self._send()

    def _send(self) -> None:
        command = self.keys.command()
        self.drive(*command)
        self.sent += 1
        self.last = command

    @override
    def describe(self) -> None:
        lines = list(_HELP) if self.driving else list(_NOT_DRIVING)
        keys = self.keys
        lines.append(f"speed {keys.speed:.2f}  turn {keys.turn:.2f}")
        if self.last is None:
            lines.append("nothing sent yet")
        else:
            x, _y, _z, turn = self.last
            lines.append(f"#{self.sent} linear.x={x:.2f} angular.z={turn:.2f}")
        self.update("\n".join(lines))
