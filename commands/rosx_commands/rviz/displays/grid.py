"""rviz's Grid: ``Plane Cell Count`` cells of ``Cell Size`` metres on a plane of the
``Reference Frame`` (the fixed frame by default), around ``Offset``."""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING

import numpy as np  # noqa: TID253 - rviz's model is array work; only rviz imports it

from rosx_commands.rviz.displays.base import Display
from rosx_commands.rviz.geometry import apply
from rosx_commands.rviz.primitives import Layer, Segments

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    from rosx_commands.rviz.displays.base import Context

FIXED_FRAME = "<Fixed Frame>"
#: Which two axes each of rviz's planes spans.
PLANES = {"XY": (0, 1), "XZ": (0, 2), "YZ": (1, 2)}


class Grid(Display):
    """rviz's Grid display: cells around a frame's origin."""

    CLASSES = ("rviz/Grid",)

    @override
    def draw(self, context: Context) -> Layer:
        frame = str(self.option("Reference Frame", FIXED_FRAME) or FIXED_FRAME)
        if frame == FIXED_FRAME:
            frame = context.frames.fixed
        answer = context.frames.lookup(frame)
        if not self.transform_status(frame, answer) or isinstance(answer, str):
            return Layer()
        count = max(0, int(self.number("Plane Cell Count", 10)))
        size = self.number("Cell Size", 1.0)
        if count == 0 or size <= 0:
            return Layer()
        offset = self.option("Offset", {}) or {}
        centre = np.array(
            [float(offset.get(axis, 0.0) or 0.0) for axis in ("X", "Y", "Z")]
            if hasattr(offset, "get")
            else [0.0, 0.0, 0.0]
        )
        first, second = PLANES.get(str(self.option("Plane", "XY")), (0, 1))
        half = count * size / 2.0
        ticks = np.linspace(-half, half, count + 1)
        ends = np.zeros((2 * (count + 1), 2, 3))
        ends[: count + 1, :, first] = ticks[:, None]
        ends[: count + 1, 0, second] = -half
        ends[: count + 1, 1, second] = half
        ends[count + 1 :, :, second] = ticks[:, None]
        ends[count + 1 :, 0, first] = -half
        ends[count + 1 :, 1, first] = half
        ends += centre
        moved = apply(answer, ends.reshape(-1, 3))[:, :2].reshape(-1, 2, 2)
        colour = self.colour("Color", (160, 160, 164))
        alpha = self.number("Alpha", 0.5)
        return Layer(segments=[Segments(moved, colour, alpha=alpha)])
