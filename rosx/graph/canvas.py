"""`Canvas`: a grid of characters where lines join into box-drawing junctions.

Lines are kept as sets of directions per cell (up, down, left, right) and turned into
characters at the end, so a line meeting another becomes ``┬``, ``├`` or ``┼`` by itself;
text written on top (boxes, labels, arrowheads) wins over lines.

The cells are one `bytearray` of direction bits, row after row, each row ``stride`` cells
long: a line ORs its bits into a slice of it (a vertical line's slice steps by ``stride``) in
one `bytes.translate` call, and the whole grid becomes text through UTF-16 (two more
translations), so a drawing thousands of characters wide and tall costs no Python work per
cell.
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
#: Direction bits to the low and the high byte of their junction character in UTF-16.
_CHARS = [ord(_JUNCTIONS.get(b, chr(b))) for b in range(256)]
_LOW = bytes(c & 0xFF for c in _CHARS)
_HIGH = bytes(c >> 8 for c in _CHARS)


class Canvas:
    """A character grid, ``width`` by ``height`` to begin with, growing to hold what is drawn."""

    def __init__(self, width: int = 0, height: int = 0) -> None:
        self._stride = max(width, 1)
        self._cells = bytearray(self._stride * height)
        self._text: dict[int, list[tuple[int, str]]] = {}
        self.width = 0
        self.height = 0

    def _reach(self, x: int, y: int) -> None:
        """Make cell ``(x, y)`` part of the canvas, growing the cells to hold it."""
        if x >= self._stride:
            self._widen(max(x + 1, 2 * self._stride))
        end = (y + 1) * self._stride
        if end > len(self._cells):
            self._cells.extend(bytes(end - len(self._cells)))
        self.width = max(self.width, x + 1)
        self.height = max(self.height, y + 1)

    def _widen(self, stride: int) -> None:
        old, cells = self._stride, self._cells
        wider = bytearray(stride * (len(cells) // old))
        for y in range(len(cells) // old):
            wider[y * stride : y * stride + old] = cells[y * old : (y + 1) * old]
        self._stride, self._cells = stride, wider

    def hline(self, y: int, x0: int, x1: int) -> None:
        """A horizontal line from column ``x0`` to ``x1`` (either order), ends included."""
        if x0 > x1:
            x0, x1 = x1, x0
        if x1 >= self.width or y >= self.height:
            self._reach(x1, y)
        cells = self._cells
        start = y * self._stride + x0
        end = start + x1 - x0
        if start == end:
            cells[start] |= LEFT | RIGHT
            return
        cells[start] |= RIGHT
        if end - start > 1:
            cells[start + 1 : end] = cells[start + 1 : end].translate(_OR[LEFT | RIGHT])
        cells[end] |= LEFT

    def vline(self, x: int, y0: int, y1: int) -> None:
        """A vertical line from row ``y0`` to ``y1`` (either order), ends included."""
        y0, y1 = min(y0, y1), max(y0, y1)
        if y0 == y1:
            return
        if x >= self.width or y1 >= self.height:
            self._reach(x, y1)
        cells, stride = self._cells, self._stride
        top = y0 * stride + x
        bottom = y1 * stride + x
        cells[top] |= DOWN
        inner = slice(top + stride, bottom, stride)
        cells[inner] = cells[inner].translate(_OR[UP | DOWN])
        cells[bottom] |= UP

    def write(self, x: int, y: int, text: str) -> None:
        """Place ``text`` at column ``x`` of row ``y``, over any box-drawing cells there."""
        self._text.setdefault(y, []).append((x, text))
        self._reach(x + len(text) - 1, y)

    def lines(self) -> list[str]:
        """The drawing as text rows, labels written over the lines, trailing spaces stripped."""
        width, stride = self.width, self._stride
        cells = self._cells[: stride * self.height]
        utf16 = bytearray(2 * len(cells))
        utf16[0::2] = cells.translate(_LOW)
        utf16[1::2] = cells.translate(_HIGH)
        grid = utf16.decode("utf-16-le")
        out = []
        for y in range(self.height):
            line = grid[y * stride : y * stride + width]
            for x, text in self._text.get(y, ()):
                line = line[:x] + text + line[x + len(text) :]
            out.append(line.rstrip())
        return out
