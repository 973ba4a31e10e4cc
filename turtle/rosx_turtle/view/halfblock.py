"""Pixels to terminal cells: two pixels per cell with the upper half block, in true colour.

Each cell shows its upper pixel as the foreground of ``▀`` and its lower pixel as the background.
Runs of equal cells become one segment, so a plain stretch of pond costs one segment however wide
it is, and styles are made once per colour pair and reused.
"""

from __future__ import annotations

from itertools import pairwise
from typing import TYPE_CHECKING

import numpy as np  # noqa: TID253 - the view is array work; only the TUI imports it
from rich.color import Color
from rich.segment import Segment
from rich.style import Style

if TYPE_CHECKING:
    import numpy.typing as npt

    Image = npt.NDArray[np.uint8]

UPPER_HALF = "\u2580"
_MAX_STYLES = 8192


def packed(pixels: Image) -> npt.NDArray[np.int64]:
    """Each RGB pixel of a ``(..., 3)`` array as one integer ``0xRRGGBB``."""
    wide = pixels.astype(np.int64)
    return (wide[..., 0] << 16) | (wide[..., 1] << 8) | wide[..., 2]


def _color(rgb: int) -> Color:
    return Color.from_rgb(rgb >> 16, (rgb >> 8) & 0xFF, rgb & 0xFF)


class CellPainter:
    """Turns rows of pixel pairs into rich segments, caching one style per colour pair."""

    def __init__(self) -> None:
        self._styles: dict[int, Style] = {}

    def style(self, upper: int, lower: int) -> Style:
        """The style of a cell whose upper pixel is ``upper`` and lower pixel ``lower``."""
        key = (upper << 24) | lower
        style = self._styles.get(key)
        if style is None:
            if len(self._styles) >= _MAX_STYLES:
                self._styles.clear()
            style = Style(color=_color(upper), bgcolor=_color(lower))
            self._styles[key] = style
        return style

    def row(self, upper: Image, lower: Image) -> list[Segment]:
        """One terminal row from its upper and lower pixel rows (each ``(width, 3)``)."""
        tops, bottoms = packed(upper), packed(lower)
        keys = (tops << 24) | bottoms
        starts = np.flatnonzero(keys[1:] != keys[:-1]) + 1
        segments = []
        for begin, end in pairwise([0, *starts.tolist(), len(keys)]):
            top, bottom = int(tops[begin]), int(bottoms[begin])
            segments.append(Segment(UPPER_HALF * (end - begin), self.style(top, bottom)))
        return segments
