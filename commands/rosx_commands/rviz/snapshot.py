"""A PNG of the view, for lab reports: the same scene painted at a higher resolution, with the
labels in Pillow's default font. Pillow is imported only when a snapshot is taken."""

from __future__ import annotations

from typing import TYPE_CHECKING

from rosx_commands.rviz.painter import Painter
from rosx_commands.rviz.view import View

if TYPE_CHECKING:
    from pathlib import Path

    from rosx_commands.rviz.manager import Manager

#: Picture pixels per terminal pixel in a snapshot.
ENLARGE = 8


def write_png(
    manager: Manager,
    view: View,
    background: tuple[int, int, int],
    path: Path,
    now: float,
    enlarge: int = ENLARGE,
) -> tuple[int, int]:
    """Paint what ``view`` shows into the PNG file ``path``; its size in pixels."""
    from PIL import Image, ImageDraw  # noqa: PLC0415 - only a snapshot needs Pillow

    big = View(view.x, view.y, view.pixels_per_metre * enlarge, view.angle)
    big.resize(view.width * enlarge, view.height * enlarge)
    layers = manager.layers(now, 1.0 / view.pixels_per_metre)  # shapes sized as on screen
    picture = Painter().paint(big, layers, background, thickness=max(1, enlarge // 3))
    image = Image.fromarray(picture.pixels, "RGB")
    draw = ImageDraw.Draw(image)
    for label in picture.labels:
        x, y = label.column + 4, label.row - 6
        if label.centred:
            x = label.column - draw.textlength(label.text) / 2
        draw.text((x, y), label.text, fill=label.colour)
    image.save(path, "PNG")
    return image.size


__all__ = ["write_png"]
