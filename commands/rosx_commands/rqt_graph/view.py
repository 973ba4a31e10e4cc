"""`GraphView`: the drawing in a pane that pans, with the selection and the changes marked.

The drawing of a large graph is thousands of characters wide and hundreds of rows high, so the
view never builds it as one widget: it keeps the drawing's lines and, per row, the stretches
to colour, and cuts the visible window out of them each time a row is painted (textual's line
API). Panning costs the rows on screen, whatever the size of the graph.
"""

from __future__ import annotations

import sys
from collections.abc import Iterable
from dataclasses import dataclass, field

from rich.segment import Segment
from rich.style import Style
from textual.geometry import Region, Size  # noqa: TID253 - TUI code
from textual.scroll_view import ScrollView  # noqa: TID253 - TUI code
from textual.strip import Strip  # noqa: TID253 - TUI code

from rosx.graph.text import Box, Drawing, Stretch
from rosx.graph.view import Changes, Edge

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

NODE = Style(color="cyan")
FRAME = Style(dim=True)
SELECTED = Style(reverse=True, bold=True)
LINKED = Style(color="yellow", bold=True)  # the selected vertex's edges, as rqt_graph's hover
APPEARED = Style(color="green", bold=True)
VANISHED = Style(color="red", dim=True)

EMPTY = "(no nodes)"


@dataclass(frozen=True)
class Marks:
    """What to mark on a drawing: the last changes (what vanished is still drawn, faded) and
    the selected vertex."""

    changes: Changes = field(default_factory=Changes)
    selected: str | None = None


class GraphView(ScrollView, can_focus=True):
    """Pans with the arrow keys, page keys and the scroll bars; draws what `show` is given."""

    DEFAULT_CSS = "GraphView { height: 1fr; }"

    def __init__(self, *, id: str | None = None) -> None:
        super().__init__(id=id)
        self._lines: list[str] = [EMPTY]
        self._styles: dict[int, list[tuple[int, int, Style]]] = {}
        self._shown: tuple[object, ...] | None = None

    def show(self, drawing: Drawing, marks: Marks) -> None:
        """Draw ``drawing`` with ``marks`` (selection, changes), scrolling the selected box into
        view; a refresh that found the same graph does nothing."""
        shown = (drawing.lines, drawing.boxes, marks)
        if shown == self._shown:
            return  # a refresh that found the same graph: nothing to redraw
        self._shown = shown
        self._lines = drawing.lines or [EMPTY]
        self._styles = _styles(drawing, marks)
        self.virtual_size = Size(max(map(len, self._lines)), len(self._lines))
        self.refresh()
        box = drawing.boxes.get(marks.selected or "")
        if box is not None:
            self.scroll_to_region(Region(box.x, box.y, box.width, box.height), animate=False)

    def visible_text(self) -> list[str]:
        """The characters on screen, row by row (for tests and for copying)."""
        return [self.render_line(y).text for y in range(self.scrollable_content_region.height)]

    @override
    def render_line(self, y: int) -> Strip:
        scroll_x, scroll_y = self.scroll_offset
        row = scroll_y + y
        width = self.scrollable_content_region.width
        base = self.rich_style
        if row >= len(self._lines):
            return Strip.blank(width, base)
        text = self._lines[row][scroll_x : scroll_x + width]
        cells: list[Style | None] = [None] * len(text)
        for x0, x1, style in self._styles.get(row, ()):
            for x in range(max(x0 - scroll_x, 0), min(x1 + 1 - scroll_x, len(text))):
                cells[x] = style
        segments = []
        start = 0
        for x in range(1, len(text) + 1):
            if x == len(text) or cells[x] is not cells[start]:
                cell = cells[start]
                segments.append(Segment(text[start:x], base + cell if cell else base))
                start = x
        return Strip(segments, len(text)).extend_cell_length(width, base)


def _styles(drawing: Drawing, marks: Marks) -> dict[int, list[tuple[int, int, Style]]]:
    """Per row, the ``(first column, last column, style)`` stretches to colour, later ones
    painted over earlier ones."""
    rows: dict[int, list[tuple[int, int, Style]]] = {}
    changes = marks.changes

    def paint(stretches: Iterable[Stretch], style: Style) -> None:
        for y0, y1, x0, x1 in stretches:
            for y in range(y0, y1 + 1):
                rows.setdefault(y, []).append((x0, x1, style))

    for frame in drawing.frames:
        paint(_outline(frame.box), FRAME)
    for edge, stretches in drawing.paths.items():
        if edge in changes.vanished_edges:
            paint(stretches, VANISHED)
        elif edge in changes.appeared_edges:
            paint(stretches, APPEARED)
    for edge in _edges_of(drawing, marks.selected):
        paint(drawing.paths[edge], LINKED)
    for vertex_id, box in drawing.boxes.items():
        if vertex_id == marks.selected:
            style = SELECTED
        elif vertex_id in changes.vanished:
            style = VANISHED
        elif vertex_id in changes.appeared:
            style = APPEARED
        elif vertex_id.startswith("n:"):
            style = NODE
        else:
            continue
        paint([(box.y, box.y + box.height - 1, box.x, box.x + box.width - 1)], style)
    return rows


def _outline(box: Box) -> list[Stretch]:
    right, bottom = box.x + box.width - 1, box.y + box.height - 1
    return [(box.y, box.y, box.x, right), (bottom, bottom, box.x, right)] + [
        (box.y, bottom, x, x) for x in (box.x, right)
    ]


def _edges_of(drawing: Drawing, vertex_id: str | None) -> list[Edge]:
    if vertex_id is None:
        return []
    return [e for e in drawing.paths if vertex_id in (e.source, e.target)]
