"""Where the square world goes in a terminal area of any shape.

A terminal cell is about twice as tall as it is wide, so a cell drawn with the upper half block
``▀`` holds two square pixels, one above the other. A world of ``side`` x ``side`` pixels then takes
``side`` columns and ``side / 2`` rows, and stays square on screen whatever the area's shape.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class PondFit:
    """The pond's place in an area of ``width`` x ``height`` cells.

    Attributes:
        width: The area's columns.
        height: The area's rows.
        side: The world's side in pixels (even; 0 when the area is too small to draw in).
        left: Columns of margin left of the world.
        top: Rows of margin above the world.
    """

    width: int
    height: int
    side: int
    left: int
    top: int

    @property
    def rows(self) -> int:
        """Rows the world takes (two pixels each)."""
        return self.side // 2


def fit_square(width: int, height: int) -> PondFit:
    """The largest square world that fits ``width`` x ``height`` cells, centred."""
    width, height = max(width, 0), max(height, 0)
    side = min(width, 2 * height)
    side -= side % 2
    return PondFit(width, height, side, (width - side) // 2, (height - side // 2) // 2)
