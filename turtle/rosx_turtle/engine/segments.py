"""`Segments`: pen strokes as data, what a tick asks a canvas to draw.

Each stroke is a straight line between two points in **canvas pixels** (metres x 45, y down
from the top, as turtlesim's Qt painter sees them), with its colour and width. Strokes are
ordered: a later one paints over an earlier one.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np  # noqa: TID253 - strokes are arrays

from rosx_turtle.engine.constants import METER_PX

if TYPE_CHECKING:
    import numpy.typing as npt

    from rosx_turtle.engine.state import Turtles

    F64 = npt.NDArray[np.float64]
    U8 = npt.NDArray[np.uint8]
    I32 = npt.NDArray[np.int32]
    Bools = npt.NDArray[np.bool_]


@dataclass(frozen=True, eq=False)
class Segments:
    """Strokes from (x0, y0) to (x1, y1) in pixels, with colour ``rgb`` (n, 3) and ``width``."""

    x0: F64
    y0: F64
    x1: F64
    y1: F64
    rgb: U8
    width: I32

    @classmethod
    def empty(cls) -> Segments:
        """No strokes."""
        nothing = np.zeros(0)
        return cls(
            nothing, nothing, nothing, nothing, np.zeros((0, 3), np.uint8), np.zeros(0, np.int32)
        )

    def __len__(self) -> int:
        return len(self.x0)

    def __add__(self, other: Segments) -> Segments:
        if not len(other):
            return self
        if not len(self):
            return other
        return Segments(
            np.concatenate((self.x0, other.x0)),
            np.concatenate((self.y0, other.y0)),
            np.concatenate((self.x1, other.x1)),
            np.concatenate((self.y1, other.y1)),
            np.concatenate((self.rgb, other.rgb)),
            np.concatenate((self.width, other.width)),
        )


def pen_strokes(turtles: Turtles, x0: F64, y0: F64, draw: Bools) -> Segments:
    """Strokes with each turtle's pen from (``x0``, ``y0``) (metres) to where it is now.

    Only the rows where ``draw`` is true give a stroke. Like turtlesim's ``drawLine(pos,
    old_pos)``, a stroke runs from the new position back to the old one.
    """
    rows = np.flatnonzero(draw)
    return Segments(
        turtles.x[rows] * METER_PX,
        turtles.y[rows] * METER_PX,
        x0[rows] * METER_PX,
        y0[rows] * METER_PX,
        turtles.pen_rgb[rows],
        turtles.pen_width[rows],
    )
