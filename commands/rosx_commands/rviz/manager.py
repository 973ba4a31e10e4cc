"""`Manager`: rviz's VisualizationManager without the drawing: the fixed frame, the displays
and what they draw, safe to feed from any thread.

Messages arrive on the node's threads (`receive`); the view asks for the layers on its own
(`layers`). One lock keeps the two apart, and ``version`` (the sum of the displays' versions
and tf's) tells the view whether anything changed since it last drew.
"""

from __future__ import annotations

import threading
from typing import TYPE_CHECKING, Any

from rosx_commands.rviz.displays import make_display
from rosx_commands.rviz.displays.base import Context
from rosx_commands.rviz.frames import FixedFrame, clean

if TYPE_CHECKING:
    from rosx.tf.core import BufferCore
    from rosx_commands.rviz.config import RvizConfig
    from rosx_commands.rviz.displays.base import Display
    from rosx_commands.rviz.primitives import Layer


class Manager:
    """The displays of ``config`` over the transforms of ``core`` (see the module docstring)."""

    def __init__(self, config: RvizConfig, core: BufferCore, fixed_frame: str | None = None):
        self.config = config
        self.lock = threading.RLock()
        self.frames = FixedFrame(core, fixed_frame or config.fixed_frame)
        self.displays: list[Display] = [make_display(spec) for spec in config.displays]
        self._changes = 0

    @property
    def fixed_frame(self) -> str:
        """The fixed frame's name, as tf keeps it."""
        return self.frames.fixed

    def set_fixed_frame(self, frame: str) -> None:
        """Draw in ``frame`` from now on (every display starts over, as in rviz)."""
        with self.lock:
            if clean(frame) == self.frames.fixed:
                return
            self.frames.set_fixed(frame)
            for display in self.displays:
                display.reset()
            self._changes += 1

    @property
    def version(self) -> int:
        """Grows with every change to what would be drawn."""
        with self.lock:
            return self._changes + self.frames.version + sum(d.version for d in self.displays)

    def receive(self, display: Display, msg: Any, now: float) -> None:
        """``msg`` arrived for ``display`` (any thread)."""
        with self.lock:
            display.receive(msg, now)

    def layers(self, now: float, metres_per_pixel: float) -> list[Layer]:
        """What each display draws, in the Displays panel's order (the first underneath)."""
        with self.lock:
            context = Context(self.frames, now, metres_per_pixel)
            return [display.layer(context) for display in self.displays]

    def expire(self, now: float) -> bool:
        """Let displays drop what timed out; whether any did."""
        with self.lock:
            expired = [display.expire(now) for display in self.displays]  # each must look
            return any(expired)

    def toggle(self, index: int) -> Display | None:
        """Enable or disable the display at ``index``."""
        with self.lock:
            if not 0 <= index < len(self.displays):
                return None
            display = self.displays[index]
            display.set_enabled(not display.enabled)
            self._changes += 1
            return display

    def add(self, display: Display) -> None:
        """Add ``display`` after the others (thread-safe); the view redraws."""
        with self.lock:
            self.displays.append(display)
            self._changes += 1

    def fixed_frame_problem(self) -> str | None:
        """rviz's global status when the fixed frame is not in tf (None when it is, or tf
        is still empty)."""
        with self.lock:
            frames = self.frames
            if frames.frames() and not frames.exists(frames.fixed):
                return f"Fixed Frame [{frames.fixed}] does not exist"
            return None


__all__ = ["Manager"]
