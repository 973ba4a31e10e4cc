"""`PondView`: the pond, drawn with half blocks in true colour, kept square, redrawn as it changes.

The widget takes scenes from a `Feed` (the simulator's thread offers one per tick) and hands them
to a `PondRenderer`, which says which rows changed; only those rows are refreshed, each cached as
a strip until it changes again. A scene that changes nothing visible costs no repaint.
"""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING

from textual.geometry import Region  # noqa: TID253 - TUI code
from textual.strip import Strip  # noqa: TID253 - TUI code
from textual.widget import Widget  # noqa: TID253 - TUI code

from rosx_turtle.tui.feed import Follows
from rosx_turtle.view.renderer import PondRenderer

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    from textual import events

    from rosx_turtle.tui.feed import Feed
    from rosx_turtle.view.scene import Scene


class PondView(Follows["Scene"], Widget):
    """The pond; shows each scene `feed` offers (or the ones given to `show`)."""

    DEFAULT_CSS = """
    PondView {
        width: 1fr;
        height: 1fr;
        background: $background;
    }
    """

    def __init__(
        self,
        feed: Feed[Scene] | None = None,
        *,
        name: str | None = None,
        id: str | None = None,
        classes: str | None = None,
    ) -> None:
        super().__init__(name=name, id=id, classes=classes)
        self.feed = feed
        self.renderer = PondRenderer()
        #: How many scenes changed the picture (each repainted some rows).
        self.frames = 0
        self._strips: dict[int, Strip] = {}

    def on_resize(self, event: events.Resize) -> None:
        """Fit the pond to the new size and drop the cached lines."""
        width, height = self.size
        self.renderer.resize(width, height, self.rich_style)
        self._strips.clear()
        self.refresh()

    def show(self, value: Scene) -> None:
        """Draw scene ``value``; repaints only the rows it changes."""
        if self.renderer.scene is value:
            return
        rows = self.renderer.update(value)
        if not rows:
            return
        self.frames += 1
        width = self.size.width
        for y in rows:
            self._strips.pop(y, None)
        first = last = rows[0]
        for y in rows[1:]:
            if y != last + 1:
                self.refresh(Region(0, first, width, last - first + 1))
                first = y
            last = y
        self.refresh(Region(0, first, width, last - first + 1))

    @override
    def render_line(self, y: int) -> Strip:
        strip = self._strips.get(y)
        if strip is None:
            if y >= self.renderer.fit.height:
                return Strip.blank(self.size.width, self.rich_style)
            strip = Strip(self.renderer.line(y), self.renderer.fit.width)
            self._strips[y] = strip
        return strip
