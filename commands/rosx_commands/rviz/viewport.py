"""`Viewport`: the fixed frame seen from above, in half blocks, with the mouse's pan, zoom and
tool placement.

It redraws only when something changed (the manager's version, the view, the tool shown) and
at most `FPS` times a second: the node's threads `offer` to a feed, which sends the widget one
`FeedReady` at a time (`rosx_turtle.tui.feed`); idle, it costs nothing. A left click (with
no tool) and a drag pan; the wheel zooms about the pointer. With a tool chosen, a press
places it and dragging sets its heading; the release posts `Viewport.Placed`.
"""

from __future__ import annotations

import math
import sys
import time
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np  # noqa: TID253 - TUI code
from textual.geometry import Region  # noqa: TID253 - TUI code
from textual.message import Message  # noqa: TID253 - TUI code
from textual.strip import Strip  # noqa: TID253 - TUI code
from textual.widget import Widget  # noqa: TID253 - TUI code

from rosx_commands.rviz.cells import Cells
from rosx_commands.rviz.painter import Painter
from rosx_commands.rviz.primitives import Layer, Points, Polygon, Segments
from rosx_turtle.tui.feed import Follows

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    from collections.abc import Callable

    from rich.segment import Segment
    from textual import events

    from rosx_commands.rviz.manager import Manager
    from rosx_commands.rviz.painter import Picture
    from rosx_commands.rviz.view import View
    from rosx_turtle.tui.feed import Feed

#: The most pictures a second.
FPS = 30.0
TOOL_COLOURS = {"Goal": (255, 0, 255), "Pose": (0, 255, 0), "Point": (255, 255, 0)}


@dataclass
class Placing:
    """A tool being placed: where (fixed frame), its heading, and whether the mouse holds it."""

    word: str
    x: float
    y: float
    yaw: float = 0.0
    heading: bool = True


def arrow_layer(placing: Placing, metres_per_pixel: float) -> Layer:
    """The tool's mark: an arrow (pose tools) or a cross (the point tool)."""
    colour = TOOL_COLOURS.get(placing.word, (255, 255, 255))
    x, y = placing.x, placing.y
    if not placing.heading:
        r = 2.5 * metres_per_pixel
        ends = np.array([[[x - r, y], [x + r, y]], [[x, y - r], [x, y + r]]])
        return Layer(segments=[Segments(ends, colour)])
    length = 8.0 * metres_per_pixel
    c, s = math.cos(placing.yaw), math.sin(placing.yaw)
    tip = (x + c * length, y + s * length)
    back = (x + c * length * 0.55, y + s * length * 0.55)
    side = 0.25 * length
    head = np.array(
        [tip, (back[0] - s * side, back[1] + c * side), (back[0] + s * side, back[1] - c * side)]
    )
    return Layer(
        segments=[Segments(np.array([[(x, y), back]]), colour)],
        polygons=[Polygon(head, colour)],
        points=[Points(np.array([[x, y]]), colour, size=2)],
    )


class Viewport(Follows[int], Widget, can_focus=True):
    """The view of ``manager``'s displays (see the module docstring)."""

    DEFAULT_CSS = """
    Viewport { width: 1fr; height: 1fr; }
    """

    class Placed(Message):
        """The user placed a tool at (``x``, ``y``) with heading ``yaw``."""

        def __init__(self, x: float, y: float, yaw: float) -> None:
            super().__init__()
            self.x, self.y, self.yaw = x, y, yaw

    class Drawn(Message):
        """A new picture is on screen (the panel refreshes its statuses)."""

    def __init__(
        self,
        manager: Manager,
        view: View,
        background: tuple[int, int, int],
        feed: Feed[int] | None = None,
        clock: Callable[[], float] = time.monotonic,
        *,
        id: str | None = None,
    ) -> None:
        super().__init__(id=id)
        self.manager, self.view, self.background = manager, view, background
        self.feed = feed
        self.clock = clock
        self.painter = Painter()
        self.cells = Cells()
        self.picture: Picture | None = None
        self.frames = 0
        self.tool: Placing | None = None
        self.follow: str | None = None
        self._strips: list[Strip] = []
        self._rows: list[list[Segment]] = []
        self._drawn: object = None
        self._timer: Any = None
        self._last = 0.0
        self._drag: tuple[float, float] | None = None
        self.pressed = False

    # -- when to draw ------------------------------------------------------------------------

    def show(self, value: int) -> None:
        """Something changed (the feed's value is the manager's version): redraw soon."""
        self.schedule()

    def schedule(self) -> None:
        """Redraw once `FPS` allows (one timer at most is pending)."""
        if self._timer is not None:
            return
        wait = self._last + 1.0 / FPS - time.monotonic()
        if wait > 0.001:
            self._timer = self.set_timer(wait, self._timed)
        else:  # textual's timers take no zero delay
            self._timer = True
            self.call_later(self._timed)

    def _timed(self) -> None:
        self._timer = None
        self.redraw()

    def on_resize(self, event: events.Resize) -> None:
        """Size the camera to the widget (two pixels per cell vertically) and redraw."""
        self.view.resize(self.size.width, self.size.height * 2)
        self.redraw(force=True)

    def redraw(self, force: bool = False) -> None:
        """Paint a new picture if anything it shows changed (or ``force``)."""
        width, height = self.size
        if width <= 0 or height <= 0:
            return
        view = self.view
        if view.width != width or view.height != height * 2:
            view.resize(width, height * 2)
        if self.follow is not None:
            answer = self.manager.frames.lookup(self.follow)
            if not isinstance(answer, str):
                view.centre_on(answer[0], answer[1])
        tool = (
            None if self.tool is None else (self.tool.x, self.tool.y, self.tool.yaw, self.tool.word)
        )
        key = (self.manager.version, view.key, tool)
        if key == self._drawn and not force:
            return
        self._drawn = key
        self._last = time.monotonic()
        metres = 1.0 / view.pixels_per_metre
        layers = self.manager.layers(self.clock(), metres)
        if self.tool is not None:
            layers.append(arrow_layer(self.tool, metres))
        self.picture = self.painter.paint(view, layers, self.background)
        rows = self.cells.rows(self.picture)
        old, self._rows = self._rows, rows
        self._strips = [Strip(segments, width) for segments in rows]
        self.frames += 1
        if len(old) != len(rows):
            self.refresh()
        else:  # only the rows that changed go to the terminal
            for y, (before, after) in enumerate(zip(old, rows, strict=True)):
                if before != after:
                    self.refresh(Region(0, y, width, 1))
        self.post_message(self.Drawn())

    @override
    def render_line(self, y: int) -> Strip:
        if y < len(self._strips):
            return self._strips[y]
        return Strip.blank(self.size.width, self.rich_style)

    # -- the mouse ---------------------------------------------------------------------------

    def _point(self, event: events.MouseEvent) -> tuple[float, float]:
        return self.view.point_at(event.x, event.y * 2 + 0.5)

    def on_mouse_down(self, event: events.MouseDown) -> None:
        """Left button down: start a drag, or put the tool down where pressed."""
        if event.button != 1:
            return
        self.capture_mouse()
        self.pressed = True
        if self.tool is not None:
            self.tool.x, self.tool.y = self._point(event)
            self.redraw()
        else:
            self._drag = (event.x, event.y)

    def on_mouse_move(self, event: events.MouseMove) -> None:
        """Drag: pan the view, or with a tool, aim its heading at the pointer."""
        if not self.pressed:
            return
        if self.tool is not None:
            x, y = self._point(event)
            if self.tool.heading and (x, y) != (self.tool.x, self.tool.y):
                self.tool.yaw = math.atan2(y - self.tool.y, x - self.tool.x)
                self.redraw()
        elif self._drag is not None:
            dx, dy = event.x - self._drag[0], event.y - self._drag[1]
            if dx or dy:
                self.view.pan(dx, dy * 2)
                self._drag = (event.x, event.y)
                self.follow = None
                self.redraw()

    def on_mouse_up(self, event: events.MouseUp) -> None:
        """Left button up: end the drag; with a tool, post `Placed` so the pane publishes it."""
        if not self.pressed:
            return
        self.pressed = False
        self.release_mouse()
        self._drag = None
        if self.tool is not None and event.button == 1:
            self.post_message(self.Placed(self.tool.x, self.tool.y, self.tool.yaw))

    def on_mouse_scroll_up(self, event: events.MouseScrollUp) -> None:
        """Wheel up: zoom in around the pointer."""
        self.view.zoom(1, (event.x + 0.5, event.y * 2 + 1.0))
        self.redraw()

    def on_mouse_scroll_down(self, event: events.MouseScrollDown) -> None:
        """Wheel down: zoom out around the pointer."""
        self.view.zoom(-1, (event.x + 0.5, event.y * 2 + 1.0))
        self.redraw()


__all__ = ["Placing", "Viewport", "arrow_layer"]
