"""`Canvas`: a grid of characters where lines join into box-drawing junctions.

Lines are kept as sets of directions per cell (up, down, left, right) and turned into
characters at the end, so a line meeting another becomes ``┬``, ``├`` or ``┼`` by itself;
text written on top (boxes, labels, arrowheads) wins over lines.

Each row is a `bytearray` of direction bits: a horizontal line ORs its bits into a slice of
the row in one `bytes.translate` call, and a row becomes text with one `str.translate`, so a
drawing thousands of characters wide costs no Python object per cell.
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

#: ``_OR[bits]`` maps every byte ``b`` to ``b | bits`` (a `bytes.translate` table).
_OR = [bytes(b | bits for b in range(256)) for bits in range(16)]
#: Direction bits (as latin-1 characters) to their junction character.
_TO_TEXT = str.maketrans({chr(bits): char for bits, char in _JUNCTIONS.items()})


class Canvas:
    """A character grid, ``width`` by ``height`` to begin with, growing to hold what is drawn."""

    def __init__(self, width: int = 0, height: int = 0) -> None:
        self._rows = [bytearray(width) for _ in range(height)]
        self._text: dict[int, list[tuple[int, str]]] = {}
        self.width = 0
        self.height = 0

    def _row(self, y: int, x: int) -> bytearray:
        """Row ``y``, long enough for column ``x``; the canvas grows to hold it."""
        rows = self._rows
        while len(rows) <= y:
            rows.append(bytearray())
        row = rows[y]
        if len(row) <= x:
            row.extend(bytes(x + 1 - len(row)))
        if x >= self.width:
            self.width = x + 1
        if y >= self.height:
            self.height = y + 1
        return row

    def hline(self, y: int, x0: int, x1: int) -> None:
        """A horizontal line from column ``x0`` to ``x1`` (either order), ends included."""
        if x0 > x1:
            x0, x1 = x1, x0
        rows = self._rows
        row = rows[y] if y < len(rows) and x1 < len(rows[y]) else self._row(y, x1)
        if x1 >= self.width or y >= self.height:
            self._row(y, x1)
        if x0 == x1:
            row[x0] |= LEFT | RIGHT
            return
        row[x0] |= RIGHT
        if x1 - x0 > 1:
            row[x0 + 1 : x1] = row[x0 + 1 : x1].translate(_OR[LEFT | RIGHT])
        row[x1] |= LEFT

    def vline(self, x: int, y0: int, y1: int) -> None:
        """A vertical line from row ``y0`` to ``y1`` (either order), ends included."""
        y0, y1 = min(y0, y1), max(y0, y1)
        if y0 == y1:
            return
        self._row(y1, x)
        rows = self._rows
        self._row(y0, x)[x] |= DOWN
        for y in range(y0 + 1, y1):
            row = rows[y] if len(rows[y]) > x else self._row(y, x)
            row[x] |= UP | DOWN
        rows[y1][x] |= UP

    def write(self, x: int, y: int, text: str) -> None:
        self._text.setdefault(y, []).append((x, text))
        self._row(y, x + len(text) - 1)

    def lines(self) -> list[str]:
        width = self.width
        out = []
        for y, row in enumerate(self._rows[: self.height]):
            line = row.decode("latin-1").translate(_TO_TEXT).ljust(width)
            for x, text in self._text.get(y, ()):
                line = line[:x] + text + line[x + len(text) :]
            out.append(line.rstrip())
        return out
