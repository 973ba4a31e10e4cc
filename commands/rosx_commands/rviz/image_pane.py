"""`ImagePane`: the picture of the first enabled Image display, fitted in half blocks under the
Displays panel (hidden while there is no Image display)."""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING

import numpy as np  # noqa: TID253 - TUI code
from rich.segment import Segment
from textual.strip import Strip  # noqa: TID253 - TUI code
from textual.widget import Widget  # noqa: TID253 - TUI code

from rosx_commands.rviz.cells import Cells
from rosx_commands.rviz.displays.image import Image
from rosx_commands.rviz.painter import Picture

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    import numpy.typing as npt

    from rosx_commands.rviz.manager import Manager


def fit(image: npt.NDArray[np.uint8], width: int, height: int) -> npt.NDArray[np.uint8]:
    """``image`` scaled (nearest pixel) to fit ``width`` by ``height`` pixels, aspect kept,
    centred on black."""
    rows, cols = image.shape[:2]
    scale = min(width / cols, height / rows)
    out_w, out_h = max(1, int(cols * scale)), max(1, int(rows * scale))
    picked = image[
        (np.arange(out_h) * rows // out_h)[:, None], (np.arange(out_w) * cols // out_w)[None, :]
    ]
    canvas = np.zeros((height, width, 3), dtype=np.uint8)
    top, left = (height - out_h) // 2, (width - out_w) // 2
    canvas[top : top + out_h, left : left + out_w] = picked
    return canvas


class ImagePane(Widget):
    """See the module docstring; `update_from` shows the manager's image now."""

    DEFAULT_CSS = """
    ImagePane { height: 12; width: 1fr; display: none; }
    ImagePane.shown { display: block; }
    """

    def __init__(self, manager: Manager, *, id: str | None = None) -> None:
        super().__init__(id=id)
        self.manager = manager
        self.cells = Cells()
        self.shown: tuple[int, int, tuple[int, ...]] | None = None
        self._strips: list[Strip] = []
        self._title = ""

    def _display(self) -> Image | None:
        return next((d for d in self.manager.displays if isinstance(d, Image) and d.enabled), None)

    def update_from(self) -> None:
        """Show the first enabled Image display's picture fitted to the pane (hidden when there
        is none); redraws only when the image, display or size changed."""
        with self.manager.lock:
            display = self._display()
            image = None if display is None else display.image
            key = None if display is None else (id(display), display.version, tuple(self.size))
        self.set_class(display is not None, "shown")
        if key == self.shown:
            return
        self.shown = key
        width, height = self.size
        if image is None or width <= 0 or height <= 1:
            self._strips = []
        else:
            title = f" {display.name}" if display is not None else ""
            pixels = fit(image, width, (height - 1) * 2)
            rows = self.cells.rows(Picture(pixels))
            self._strips = [Strip(row, width) for row in rows]
            self._title = title
        self.refresh()

    def on_resize(self) -> None:
        """Fit the image to the new size."""
        self.update_from()

    @override
    def render_line(self, y: int) -> Strip:
        if y == 0 and self._strips:
            return Strip([Segment(self._title[: self.size.width])], self.size.width)
        if 0 < y <= len(self._strips):
            return self._strips[y - 1]
        return Strip.blank(self.size.width, self.rich_style)


__all__ = ["ImagePane", "fit"]
