"""`PondRenderer`: scenes to terminal rows, redoing only what changed since the last scene.

Per scene it (1) shrinks the bands of the trail canvas that changed (`raster.Shrinker`), (2) draws
the turtles over a copy (`sprite.stamp`), and (3) repaints only the terminal rows whose pixels
differ from the last picture (`halfblock.CellPainter`). It says which rows changed, so a widget
refreshes just those; a scene equal to the last one changes nothing. It has no terminal and no
event loop: the pond widget and the benchmark drive it the same way.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np  # noqa: TID253 - the view is array work; only the TUI imports it
from rich.segment import Segment
from rich.style import Style

from rosx_turtle.view.fit import PondFit, fit_square
from rosx_turtle.view.halfblock import CellPainter
from rosx_turtle.view.raster import Shrinker
from rosx_turtle.view.scene import CANVAS_SIZE, WORLD_SIZE, Scene
from rosx_turtle.view.sprite import palette_of, stamp

if TYPE_CHECKING:
    import numpy.typing as npt

    Image = npt.NDArray[np.uint8]

Row = list[Segment]

#: Canvas pixels per metre (turtlesim's sprites are 45 pixels tall).
CANVAS_PIXELS_PER_METRE = 45.0


class PondRenderer:
    """Renders scenes into an area of ``width`` x ``height`` cells (see the module docstring)."""

    def __init__(self, margin: Style | None = None) -> None:
        self.margin = margin or Style()
        self.fit: PondFit = fit_square(0, 0)
        self._painter = CellPainter()
        self._shrinker: Shrinker | None = None
        self._scene: Scene | None = None
        self._trails: Image | None = None
        self._picture: Image | None = None
        self._rows: list[Row] = []

    @property
    def scene(self) -> Scene | None:
        """The scene rendered last."""
        return self._scene

    def resize(self, width: int, height: int, margin: Style | None = None) -> list[int]:
        """Lay out for a new area (and margin style); every row changes."""
        self.margin = margin or self.margin
        self.fit = fit = fit_square(width, height)
        self._shrinker = Shrinker(fit.side, CANVAS_SIZE) if fit.side else None
        self._trails = self._picture = None
        blank = [Segment(" " * fit.width, self.margin)] if fit.width else []
        self._rows = [list(blank) for _ in range(fit.height)]
        if self._scene is not None:
            scene, self._scene = self._scene, None
            self.update(scene)
        return list(range(fit.height))

    def update(self, scene: Scene) -> list[int]:
        """Render ``scene``; the area rows that changed (none when nothing visible did)."""
        previous, self._scene = self._scene, scene
        shrinker = self._shrinker
        if shrinker is None:
            return []
        self._shrink_canvas(shrinker, previous, scene)
        assert self._trails is not None
        picture = self._trails.copy()
        scale = shrinker.side / CANVAS_SIZE
        pixels_per_metre = CANVAS_PIXELS_PER_METRE * scale
        for turtle in scene.turtles:
            row = (WORLD_SIZE - turtle.y) * pixels_per_metre
            col = turtle.x * pixels_per_metre
            palette = palette_of(turtle.name, turtle.sprite)
            stamp(picture, row, col, turtle.theta, palette, pixels_per_metre)
        return self._repaint(picture)

    def line(self, y: int) -> Row:
        """Area row ``y``, margins included."""
        return self._rows[y]

    def _shrink_canvas(self, shrinker: Shrinker, previous: Scene | None, scene: Scene) -> None:
        if self._trails is None or previous is None or previous.background != scene.background:
            self._trails = shrinker.shrink(scene.canvas, scene.background)
            return
        if previous.canvas_version == scene.canvas_version or previous.canvas is scene.canvas:
            return
        band = shrinker.changed_rows(previous.canvas, scene.canvas)
        if band is not None:
            self._trails[band] = shrinker.shrink(scene.canvas, scene.background, band)

    def _repaint(self, picture: Image) -> list[int]:
        fit, old = self.fit, self._picture
        self._picture = picture
        cells = picture.reshape(fit.rows, 2, fit.side, 3)
        if old is None:
            changed = np.arange(fit.rows)
        else:
            before = old.reshape(fit.rows, 2 * fit.side * 3)
            changed = np.flatnonzero(np.any(before != picture.reshape(before.shape), axis=1))
        left = [Segment(" " * fit.left, self.margin)] if fit.left else []
        right_width = fit.width - fit.left - fit.side
        right = [Segment(" " * right_width, self.margin)] if right_width else []
        dirty = []
        for row in changed.tolist():
            y = fit.top + row
            self._rows[y] = [*left, *self._painter.row(cells[row, 0], cells[row, 1]), *right]
            dirty.append(y)
        return dirty
