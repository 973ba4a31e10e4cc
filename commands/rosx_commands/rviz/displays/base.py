"""`Display`: what every rviz display shares: its config, its topic, its statuses, and the
`Layer` it draws in the fixed frame.

A display is pure: messages come in through `receive` (any thread, under the manager's lock,
already decoded), and `layer` gives the drawing for a `Context` (tf into the fixed frame, the
time, the view's metres per pixel). ``version`` grows whenever what it would draw may have
changed, so the view redraws only then. Statuses follow rviz: ``Topic`` says "No messages
received" until the first message and then counts them; each display adds its own
(``Transform``, ``Points``…).
"""

from __future__ import annotations

import sys
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, ClassVar

from rosx_commands.rviz import status
from rosx_commands.rviz.config import parse_color
from rosx_commands.rviz.primitives import Layer

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    from rosx_commands.rviz.config import DisplaySpec
    from rosx_commands.rviz.frames import FixedFrame
    from rosx_commands.rviz.primitives import RGB


@dataclass
class Context:
    """What a display draws with: tf into the fixed frame, the time (seconds, the app's
    clock), and the size of a pixel of the view in metres."""

    frames: FixedFrame
    now: float
    metres_per_pixel: float


class Display:
    """One display of the Displays panel (see the module docstring)."""

    #: The rviz classes this display draws (the first is the one it saves as).
    CLASSES: ClassVar[tuple[str, ...]] = ()
    #: The message type of its topic (None: it subscribes to nothing).
    MESSAGE_TYPE: ClassVar[str | None] = None
    #: The option naming its topic, and rviz's default topic.
    TOPIC_KEY: ClassVar[str] = "Topic"
    DEFAULT_TOPIC: ClassVar[str] = ""
    #: Statuses worth showing when all is well, most telling first.
    PREFER: ClassVar[tuple[str, ...]] = ()

    def __init__(self, spec: DisplaySpec) -> None:
        self.spec = spec
        self.name = spec.name
        self.class_id = spec.class_id
        self.enabled = spec.enabled
        self.topic = str(spec.get(self.TOPIC_KEY, self.DEFAULT_TOPIC) or "")
        self.statuses = status.StatusList()
        self.messages = 0
        self.version = 0
        self.reset()

    # -- options -----------------------------------------------------------------------------

    def option(self, key: str, default: Any) -> Any:
        """The config's value of ``key``, or rviz's ``default``."""
        return self.spec.get(key, default)

    def number(self, key: str, default: float) -> float:
        """The config's ``key`` as a float; ``default`` when absent or not a number (rviz ignores
        bad values the same way)."""
        try:
            return float(self.spec.get(key, default))
        except (TypeError, ValueError):
            return default

    def colour(self, key: str, default: RGB) -> RGB:
        """The config's ``key`` as an RGB colour (rviz's ``"r; g; b"``), or ``default``."""
        return parse_color(self.spec.get(key), default)

    def flag(self, key: str, default: bool) -> bool:
        """The config's ``key`` as a bool; rviz's configs write ``true``/``false`` as text."""
        value = self.spec.get(key, default)
        if isinstance(value, str):
            return value.strip().lower() == "true"
        return bool(value)

    # -- messages ----------------------------------------------------------------------------

    @property
    def subscribes(self) -> bool:
        """Whether the display wants its topic's messages now."""
        return self.enabled and self.MESSAGE_TYPE is not None and bool(self.topic)

    def receive(self, msg: Any, now: float) -> None:
        """A message of the display's topic arrived at ``now``."""
        if not self.enabled:
            return
        self.messages += 1
        self.statuses.ok("Topic", status.received(self.messages))
        self.take(msg, now)
        self.version += 1

    def take(self, msg: Any, now: float) -> None:
        """Keep what ``msg`` says (the display's own part of `receive`)."""

    def reset(self) -> None:
        """Forget every message (rviz's ``reset``: when enabled, or the fixed frame changes)."""
        self.messages = 0
        self.statuses.clear()
        if self.MESSAGE_TYPE is not None:
            if self.topic:
                self.statuses.warn("Topic", status.NO_MESSAGES)
            else:
                self.statuses.error("Topic", "No topic set")
        self.clear()
        self.version += 1

    def clear(self) -> None:
        """Drop the display's own state (its part of `reset`)."""

    def set_enabled(self, enabled: bool) -> None:
        """Show or hide the display; a change resets it, as rviz does when a display is enabled."""
        if enabled != self.enabled:
            self.enabled = enabled
            self.reset()

    def expire(self, now: float) -> bool:
        """Drop what has timed out by ``now``; whether anything went."""
        return False

    # -- drawing -----------------------------------------------------------------------------

    def layer(self, context: Context) -> Layer:
        """What the display draws now (nothing when disabled)."""
        if not self.enabled:
            return Layer()
        return self.draw(context)

    def draw(self, context: Context) -> Layer:
        """What the display draws in ``context`` (its own part of `layer`); the base draws
        nothing."""
        return Layer()

    @property
    def summary(self) -> str:
        """The status line of the Displays panel."""
        if not self.enabled:
            return status.DISABLED
        return self.statuses.summary(self.PREFER)

    @property
    def level(self) -> status.Level:
        """The worst status of the display (OK when it is disabled), for the panel's mark."""
        return self.statuses.level if self.enabled else status.Level.OK

    def transform_status(self, frame: str, answer: object, key: str = "Transform") -> bool:
        """Record whether ``frame`` could be put in the fixed frame (``answer`` from
        `FixedFrame.lookup`: a transform or rviz's text); whether it could."""
        if isinstance(answer, str):
            self.statuses.error(key, answer)
            return False
        self.statuses.ok(key, "Transform OK")
        return True


class Unsupported(Display):
    """A class rosx cannot draw: listed, kept for saving, never subscribed."""

    @override
    def reset(self) -> None:
        self.statuses.clear()
        self.statuses.warn("Class", status.UNSUPPORTED)
        self.version += 1

    @property
    @override
    def summary(self) -> str:
        return status.UNSUPPORTED


__all__ = ["Context", "Display", "Unsupported"]
