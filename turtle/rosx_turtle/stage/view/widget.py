"""`WorldView`: the simulated world in half blocks, repainted on each step it is offered."""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING

from textual.strip import Strip  # noqa: TID253 - TUI code
from textual.widget import Widget  # noqa: TID253 - TUI code

from rosx_turtle.stage.view.picture import WorldPainter, laser_hits
from rosx_turtle.tui.feed import Follows
from rosx_turtle.view.halfblock import CellPainter

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    import numpy as np
    import numpy.typing as npt
    from textual import events

    from rosx_turtle.stage.engine.grid import Grid
    from rosx_turtle.stage.engine.simulation import StepReport
    from rosx_turtle.stage.world.model import World
    from rosx_turtle.tui.feed import Feed


class WorldView(Follows["StepReport"], Widget):
    """The world, the robots and their lasers' hits; shows each step ``feed`` offers.

    The lasers' hits stay on screen until the laser scans again (a step without a scan keeps
    the last one's)."""

    DEFAULT_CSS = """
    WorldView {
        width: 1fr;
        height: 1fr;
    }
    """

    def __init__(
        self,
        world: World,
        grid: Grid,
        feed: Feed[StepReport] | None = None,
        *,
        id: str | None = None,
    ) -> None:
        super().__init__(id=id)
        self.feed = feed
        self.painter = WorldPainter(world, grid)
        self.cells = CellPainter()
        self.report: StepReport | None = None
        self.frames = 0
        self._hits: dict[
            tuple[int, int], tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]
        ] = {}
        self._image: npt.NDArray[np.uint8] | None = None
        self._strips: dict[int, Strip] = {}

    def on_resize(self, event: events.Resize) -> None:
        """Repaint the world at the new size (two pixel rows per terminal row)."""
        self._repaint()

    def show(self, value: StepReport) -> None:
        """Draw step ``value``."""
        self.report = value
        for scan, points in zip(value.scans, laser_hits(value), strict=True):
            self._hits[scan.robot, scan.laser] = points
        self._repaint()

    def _repaint(self) -> None:
        width, height = self.size
        if width <= 0 or height <= 0:
            return
        self.painter.resize(width, height * 2)
        self._image = self.painter.paint(self.report, list(self._hits.values()))
        self._strips.clear()
        self.frames += 1
        self.refresh()

    @override
    def render_line(self, y: int) -> Strip:
        strip = self._strips.get(y)
        if strip is not None:
            return strip
        image = self._image
        if image is None or 2 * y + 1 >= image.shape[0]:
            return Strip.blank(self.size.width, self.rich_style)
        strip = Strip(self.cells.row(image[2 * y], image[2 * y + 1]), image.shape[1])
        self._strips[y] = strip
        return strip
