"""`Canvas`: a grid of characters where lines join into box-drawing junctions.

Lines are kept as sets of directions per cell (up, down, left, right) and turned into
characters at the end, so a line meeting another becomes ``┬``, ``├`` or ``┼`` by itself;
text written on top (boxes, labels, arrowheads) wins over lines.
"""

from __future__ import annotations

UP, DOWN, LEFT, RIGHT = 1, 2, 4, 8

_JUNCTIONS = {
    0: " ",
    UP: "│",
    DOWN: "│",
    UP | DOWN: "│",
    LEFT: "─",
    RIGHT: "─",
    LEFT | RIGHT: "─",
    DOWN | RIGHT: "┌",
    DOWN | LEFT: "┐",
    UP | RIGHT: "└",
    UP | LEFT: "┘",
    UP | DOWN | RIGHT: "├",
    UP | DOWN | LEFT: "┤",
    LEFT | RIGHT | DOWN: "┬",
    LEFT | RIGHT | UP: "┴",
    UP | DOWN | LEFT | RIGHT: "┼",
}


class Canvas:
    """A growing character grid."""

    def __init__(self) -> None:
        self._lines: dict[tuple[int, int], int] = {}
        self._text: dict[tuple[int, int], str] = {}
        self.width = 0
        self.height = 0

    def _grow(self, x: int, y: int) -> None:
        self.width = max(self.width, x + 1)
        self.height = max(self.height, y + 1)

    def _join(self, x: int, y: int, directions: int) -> None:
        self._lines[x, y] = self._lines.get((x, y), 0) | directions
        self._grow(x, y)

    def hline(self, y: int, x0: int, x1: int) -> None:
        """A horizontal line from column ``x0`` to ``x1`` (either order), ends included."""
        x0, x1 = min(x0, x1), max(x0, x1)
        for x in range(x0, x1 + 1):
            self._join(x, y, (LEFT if x > x0 else 0) | (RIGHT if x < x1 else 0) or LEFT | RIGHT)

    def vline(self, x: int, y0: int, y1: int) -> None:
        """A vertical line from row ``y0`` to ``y1`` (either order), ends included."""
        y0, y1 = min(y0, y1), max(y0, y1)
        if y0 == y1:
            return
        for y in range(y0, y1 + 1):
            self._join(x, y, (UP if y > y0 else 0) | (DOWN if y < y1 else 0))

    def write(self, x: int, y: int, text: str) -> None:
        for offset, char in enumerate(text):
            self._text[x + offset, y] = char
        self._grow(x + len(text) - 1, y)

    def lines(self) -> list[str]:
        rows = [[" "] * self.width for _ in range(self.height)]
        for (x, y), directions in self._lines.items():
            rows[y][x] = _JUNCTIONS[directions]
        for (x, y), char in self._text.items():
            rows[y][x] = char
        return ["".join(row).rstrip() for row in rows]
