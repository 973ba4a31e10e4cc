"""rviz's TF: every frame tf knows, drawn at its place in the fixed frame: its x (red) and y
(green) axes, its name, and an arrow to its parent.

Options as rviz's: ``Show Names``, ``Show Axes``, ``Show Arrows``, ``Marker Scale`` (axes 0.2 m
long at scale 1, drawn at least a few pixels long so a frame shows at any zoom), ``Frames``
(each frame's ``Value``; ``All Enabled`` is only the tick box over them, as in rviz). Each
frame's status is rviz's: ``Transform OK``, or ``No transform from [F] to frame [FIXED]`` (a
warning: the TF display shows what connects).
"""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING

import numpy as np  # noqa: TID253 - rviz's model is array work; only rviz imports it

from rosx_commands.rviz.displays.base import Display
from rosx_commands.rviz.geometry import apply
from rosx_commands.rviz.primitives import Label, Layer, Segments

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    from rosx_commands.rviz.displays.base import Context

AXES_LENGTH = 0.2
#: The shortest axis drawn, in pixels.
MIN_AXIS_PIXELS = 3.0
X_COLOUR, Y_COLOUR = (255, 0, 0), (0, 255, 0)
SHAFT_COLOUR, HEAD_COLOUR = (204, 204, 76), (255, 25, 153)
NAME_COLOUR = (255, 255, 255)


class TF(Display):
    """rviz's TF display: each frame's axes and its link to its parent."""

    CLASSES = ("rviz/TF",)

    @override
    def clear(self) -> None:
        self.frames_shown = 0

    def _disabled_frames(self) -> set[str]:
        """The frames the config turns off. ``All Enabled`` is rviz's tick box over the frames
        it lists when saving: false means some frame was off, not that new frames are (rviz
        loads it before any frame exists, and every frame it discovers starts enabled)."""
        frames = self.option("Frames", {}) or {}
        if not hasattr(frames, "items"):
            return set()
        return {
            name
            for name, value in frames.items()
            if name != "All Enabled" and hasattr(value, "get") and value.get("Value", True) is False
        }

    @override
    def draw(self, context: Context) -> Layer:
        frames = context.frames
        disabled = self._disabled_frames()
        scale = self.number("Marker Scale", 1.0)
        length = max(AXES_LENGTH * scale, MIN_AXIS_PIXELS * context.metres_per_pixel)
        names, axes = self.flag("Show Names", True), self.flag("Show Axes", True)
        arrows = self.flag("Show Arrows", True)
        origins: dict[str, tuple[float, float]] = {}
        x_axes, y_axes, labels = [], [], []
        for name in sorted(frames.frames()):
            self.statuses.delete(name)
            if name in disabled:
                continue
            answer = frames.lookup(name)
            if isinstance(answer, str):
                self.statuses.warn(name, f"{answer.rsplit(' to ', 1)[0]} to frame [{frames.fixed}]")
                continue
            ends = apply(
                answer, np.array([[0.0, 0.0, 0.0], [length, 0.0, 0.0], [0.0, length, 0.0]])
            )
            origin = ends[0, :2]
            origins[name] = (float(origin[0]), float(origin[1]))
            if axes:
                x_axes.append([origin, ends[1, :2]])
                y_axes.append([origin, ends[2, :2]])
            if names:
                labels.append(Label(float(origin[0]), float(origin[1]), name, NAME_COLOUR))
        self.frames_shown = len(origins)
        layer = Layer(labels=labels)
        if arrows:
            shafts, heads = [], []
            for name, (x, y) in origins.items():
                parent = frames.parent(name)
                if parent is None or parent not in origins:
                    continue
                px, py = origins[parent]
                middle = ((x + px) / 2.0, (y + py) / 2.0)
                shafts.append([(x, y), middle])
                heads.append([middle, (px, py)])
            if shafts:
                layer.segments.append(Segments(np.array(shafts), SHAFT_COLOUR))
                layer.segments.append(Segments(np.array(heads), HEAD_COLOUR))
        if x_axes:
            layer.segments.append(Segments(np.array(x_axes), X_COLOUR))
            layer.segments.append(Segments(np.array(y_axes), Y_COLOUR))
        return layer

    @property
    @override
    def summary(self) -> str:
        text = super().summary
        if text == "OK" and self.enabled:
            return f"OK ({self.frames_shown} frames)"
        return text
