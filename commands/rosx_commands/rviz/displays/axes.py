"""rviz's Axes: the x and y axes of its ``Reference Frame`` (``Length`` metres)."""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING

from rosx_commands.rviz.displays.base import Display
from rosx_commands.rviz.displays.grid import FIXED_FRAME
from rosx_commands.rviz.displays.shapes import axes
from rosx_commands.rviz.primitives import Layer

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    from rosx_commands.rviz.displays.base import Context


class Axes(Display):
    """rviz's Axes display: a frame's x and y axes."""

    CLASSES = ("rviz/Axes",)

    @override
    def draw(self, context: Context) -> Layer:
        frame = str(self.option("Reference Frame", FIXED_FRAME) or FIXED_FRAME)
        if frame == FIXED_FRAME:
            frame = context.frames.fixed
        answer = context.frames.lookup(frame)
        if not self.transform_status(frame, answer) or isinstance(answer, str):
            return Layer()
        length = max(self.number("Length", 1.0), 3.0 * context.metres_per_pixel)
        return axes(answer, length, self.number("Alpha", 1.0))
