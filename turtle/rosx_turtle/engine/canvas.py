"""`Canvas`: turtlesim's 500x500 px trail image as a numpy RGB array.

It holds the background and the pen trails, never the sprites: that is what the colour sensor
reads and what a view draws the turtles on. ``pixels[row, column]`` is the pixel at canvas
coordinates (column, row), row 0 at the top, as in turtlesim's internal frame scaled by 45.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np  # noqa: TID253 - the canvas is an array

from rosx_turtle.engine.constants import CANVAS_PX, DEFAULT_BACKGROUND, METER_PX
from rosx_turtle.engine.raster import Scratch, stroke_pixels

if TYPE_CHECKING:
    from collections.abc import Sequence

    import numpy.typing as npt

    from rosx_turtle.engine.segments import Segments


class Canvas:
    """The trail image. `fill` it, `draw` strokes on it, `sample` it under turtles.

    ``pixels`` is the (size, size, 3) RGB array (a view: each pixel is stored in 4 bytes, so
    that drawing writes whole pixels as one integer each). ``version`` counts the changes, so
    a reader can tell whether to look again.
    """

    def __init__(
        self, background: Sequence[int] = DEFAULT_BACKGROUND, size: int = CANVAS_PX
    ) -> None:
        self.size = size
        self._words = np.zeros((size, size), np.uint32)
        self.pixels: npt.NDArray[np.uint8] = self._words.view(np.uint8).reshape(size, size, 4)[
            :, :, :3
        ]
        self.version = 0
        self._scratch = Scratch()
        self.fill(background)

    def fill(self, rgb: Sequence[int]) -> None:
        """Paint the whole canvas ``rgb``, erasing every trail."""
        self.pixels[:, :] = np.asarray(rgb, np.uint8)
        self.version += 1

    def draw(self, strokes: Segments) -> None:
        """Paint ``strokes`` in order (a later stroke covers an earlier one)."""
        if not len(strokes):
            return
        flat, owner = stroke_pixels(strokes, self.size, self._scratch)
        colours = np.zeros((len(strokes), 4), np.uint8)
        colours[:, :3] = strokes.rgb
        self._words.reshape(-1)[flat] = colours.view(np.uint32).reshape(-1)[owner]
        self.version += 1

    def sample(self, x: npt.ArrayLike, y: npt.ArrayLike) -> npt.NDArray[np.uint8]:
        """The colours (n, 3) under internal positions ``x``, ``y`` in metres.

        As Qt's ``QPointF::toPoint``, the pixel is the position x 45 rounded half up; positions
        off the canvas read black, as ``QImage::pixel`` answers there.
        """
        column = np.floor(np.asarray(x, np.float64) * METER_PX + 0.5).astype(np.intp)
        row = np.floor(np.asarray(y, np.float64) * METER_PX + 0.5).astype(np.intp)
        inside = (column >= 0) & (column < self.size) & (row >= 0) & (row < self.size)
        colours = np.zeros((len(column), 3), np.uint8)
        colours[inside] = self.pixels[row[inside], column[inside]]
        return colours

    def snapshot(self) -> npt.NDArray[np.uint8]:
        """A contiguous RGB copy of the pixels, safe to keep while the canvas changes."""
        copy: npt.NDArray[np.uint8] = np.array(self.pixels, order="C", copy=True)
        return copy
