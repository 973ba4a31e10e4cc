"""`GraphView`: the drawing in a scrollable pane, with the selection and the changes marked."""

from __future__ import annotations

from itertools import accumulate

from rich.text import Text
from textual.containers import ScrollableContainer  # noqa: TID253 - TUI code
from textual.widgets import Static  # noqa: TID253 - TUI code

from rosx.graph.text import Drawing
from rosx.graph.view import Changes


class GraphView(ScrollableContainer, can_focus=True):
    """Pans with the arrow keys and the scroll bars; draws what `show` is given."""

    DEFAULT_CSS = """
    GraphView { height: 1fr; }
    GraphView > Static { width: auto; height: auto; }
    """

    _shown: tuple[object, ...] | None = None

    def compose(self):  # type: ignore[no-untyped-def]
        yield Static(id="drawing")

    def show(self, drawing: Drawing, changes: Changes, selected: str | None) -> None:
        shown = (drawing.lines, drawing.boxes, changes, selected)
        if shown == self._shown:
            return  # a refresh that found the same graph: nothing to redraw
        self._shown = shown
        text = Text("\n".join(drawing.lines) if drawing.lines else "(no nodes)")
        offsets = list(accumulate((len(line) + 1 for line in drawing.lines), initial=0))
        for vertex_id, box in drawing.boxes.items():
            style = None
            if vertex_id == selected:
                style = "reverse bold"
            elif vertex_id in changes.appeared:
                style = "bold green"
            elif vertex_id.startswith("n:"):
                style = "cyan"
            if style is None:
                continue
            for row in range(box.height):
                start = offsets[box.y + row] + box.x
                text.stylize(style, start, start + box.width)
        self.query_one("#drawing", Static).update(text)
        if selected in drawing.boxes:
            box = drawing.boxes[selected]
            self.scroll_to_region_box(box.x, box.y, box.width, box.height)

    def scroll_to_region_box(self, x: int, y: int, width: int, height: int) -> None:
        from textual.geometry import Region

        self.scroll_to_region(Region(x, y, width, height), animate=False)
