"""A picture to terminal rows: two pixels a cell (upper half block), labels written as text.

Each cell shows its upper pixel as the foreground of ``▀`` and its lower pixel as the
background. A label takes the cells to the right of its point (or centred on it), in its
colour over the cell's colours mixed; labels that would run off the picture are cut, and a
later label does not overwrite an earlier one. Runs of cells with one style become one
segment, and styles are made once per colour pair (`rosx_turtle.view.halfblock.CellPainter`).
"""

from __future__ import annotations

from itertools import pairwise
from typing import TYPE_CHECKING

import numpy as np  # noqa: TID253 - rviz's view is array work; only rviz imports it
from rich.segment import Segment

from rosx_turtle.view.halfblock import UPPER_HALF, CellPainter, packed

if TYPE_CHECKING:
    import numpy.typing as npt

    from rosx_commands.rviz.painter import Picture


class Cells:
    """Terminal rows of pictures (see the module docstring)."""

    def __init__(self) -> None:
        self.painter = CellPainter()

    def rows(self, picture: Picture) -> list[list[Segment]]:
        """One list of segments per terminal row (the picture's height halved)."""
        pixels = picture.pixels
        height, width = pixels.shape[0] // 2, pixels.shape[1]
        tops = packed(pixels[0 : 2 * height : 2])
        bottoms = packed(pixels[1 : 2 * height : 2])
        chars = np.full((height, width), UPPER_HALF, dtype="<U1")
        fore, back = tops.copy(), bottoms.copy()
        taken = np.zeros((height, width), dtype=np.bool_)
        for label in picture.labels:
            row = int(np.floor(label.row / 2.0))
            text = label.text
            start = int(np.floor(label.column)) - (len(text) // 2 if label.centred else -1)
            if not 0 <= row < height or start >= width or start + len(text) <= 0:
                continue
            first, last = max(0, start), min(width, start + len(text))
            if taken[row, first:last].any():
                continue
            taken[row, first:last] = True
            colour = (label.colour[0] << 16) | (label.colour[1] << 8) | label.colour[2]
            chars[row, first:last] = list(text[first - start : last - start])
            fore[row, first:last] = colour
            back[row, first:last] = _mix(tops[row, first:last], bottoms[row, first:last])
        return [self._row(chars[y], fore[y], back[y]) for y in range(height)]

    def _row(
        self, chars: npt.NDArray[np.str_], fore: npt.NDArray[np.int64], back: npt.NDArray[np.int64]
    ) -> list[Segment]:
        keys = (fore << 24) | back
        bounds = [0, *(np.flatnonzero(keys[1:] != keys[:-1]) + 1).tolist(), len(keys)]
        text = "".join(chars.tolist())
        fores, backs = fore.tolist(), back.tolist()
        style = self.painter.style
        return [
            Segment(text[begin:end], style(fores[begin], backs[begin]))
            for begin, end in pairwise(bounds)
        ]


def _mix(one: npt.NDArray[np.int64], two: npt.NDArray[np.int64]) -> npt.NDArray[np.int64]:
    """The average of packed colours, darkened so that a light label stays readable."""
    mixed = np.zeros_like(one)
    for shift in (16, 8, 0):
        channel = (((one >> shift) & 0xFF) + ((two >> shift) & 0xFF)) // 2
        mixed |= (channel * 3 // 5) << shift
    return mixed


__all__ = ["Cells"]
