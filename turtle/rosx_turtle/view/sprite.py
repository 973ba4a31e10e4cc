"""Turtle sprites in pond pixels: a shell with a pattern, four legs and a head that shows the
heading.

A sprite is drawn to scale (turtlesim's sprites are one metre long), but never smaller than
`MIN_PIXELS_PER_METRE`, and turned to the nearest of `DIRECTIONS` headings; each (scale,
direction) pair is rasterised once and cached as pixel offsets. Small sprites leave out the legs,
which would blur the outline, and always keep a head pixel ahead of the shell, drawn last, so the
heading reads at any size. Colours come from the sprite number the simulator picked (or else
from the turtle's name), so a turtle keeps its look from frame to frame.
"""

from __future__ import annotations

import math
import zlib
from functools import lru_cache
from typing import TYPE_CHECKING

import numpy as np  # noqa: TID253 - the view is array work; only the TUI imports it

if TYPE_CHECKING:
    import numpy.typing as npt

    Image = npt.NDArray[np.uint8]
    Offsets = tuple[npt.NDArray[np.intp], npt.NDArray[np.intp], npt.NDArray[np.intp]]
    Palette = tuple[tuple[int, int, int], ...]

DIRECTIONS = 16
#: The smallest scale a sprite is drawn at (about 7 pixels long).
MIN_PIXELS_PER_METRE = 7.0
#: Below this scale sprites have no legs.
LEGS_FROM_PIXELS_PER_METRE = 10.0

#: Parts of a sprite, in drawing order (later parts cover earlier ones).
LEGS, SHELL, PATTERN, HEAD = 0, 1, 2, 3

#: (legs, shell, shell pattern, head) colours; a turtle gets one set.
PALETTES: tuple[Palette, ...] = (
    ((120, 180, 70), (46, 125, 50), (27, 84, 33), (190, 240, 110)),
    ((200, 160, 90), (141, 93, 44), (96, 60, 24), (255, 220, 140)),
    ((100, 190, 180), (0, 121, 107), (0, 77, 64), (170, 245, 235)),
    ((220, 170, 60), (200, 120, 20), (130, 70, 10), (255, 230, 110)),
    ((170, 140, 210), (106, 27, 154), (74, 20, 110), (230, 205, 255)),
    ((230, 130, 110), (183, 28, 28), (120, 20, 20), (255, 195, 175)),
)

# In metres, in the turtle's frame (forward, left): legs and head as circles (x, y, radius),
# shell and pattern as ellipses (half length, half width).
_LEGS = ((0.22, 0.27, 0.1), (0.22, -0.27, 0.1), (-0.22, 0.27, 0.1), (-0.22, -0.27, 0.1))
_HEAD = (0.45, 0.0, 0.16)
_SHELL = (0.34, 0.27)
_PATTERN = (0.17, 0.12)


def direction_of(theta: float) -> int:
    """The nearest of the `DIRECTIONS` headings to ``theta`` (0 faces +x, counting CCW)."""
    return round(theta / (2 * math.pi) * DIRECTIONS) % DIRECTIONS


def palette_of(name: str, sprite: int = -1) -> Palette:
    """The colours of sprite number ``sprite``, or (when it is negative) of the name ``name``."""
    look = sprite if sprite >= 0 else zlib.crc32(name.encode())
    return PALETTES[look % len(PALETTES)]


@lru_cache(maxsize=256)
def sprite_offsets(pixels_per_metre: float, direction: int) -> Offsets:
    """Row offsets (down), column offsets (right) and parts of a sprite centred on (0, 0)."""
    scale = max(pixels_per_metre, MIN_PIXELS_PER_METRE)
    angle = direction * 2 * math.pi / DIRECTIONS
    cos, sin = math.cos(angle), math.sin(angle)
    reach = math.ceil(0.65 * scale) + 1
    grid = np.arange(-reach, reach + 1, dtype=np.float64)
    dy, dx = np.meshgrid(grid, grid, indexing="ij")
    east, north = dx / scale, -dy / scale
    forward, left = east * cos + north * sin, -east * sin + north * cos
    parts = np.full(dy.shape, -1, dtype=np.intp)

    def circle(x: float, y: float, radius: float) -> npt.NDArray[np.bool_]:
        inside: npt.NDArray[np.bool_] = (forward - x) ** 2 + (left - y) ** 2 <= radius**2
        return inside

    if scale >= LEGS_FROM_PIXELS_PER_METRE:
        for leg in _LEGS:
            parts[circle(*leg)] = LEGS
    for part, (half_length, half_width) in ((SHELL, _SHELL), (PATTERN, _PATTERN)):
        parts[(forward / half_length) ** 2 + (left / half_width) ** 2 <= 1.0] = part
    parts[reach, reach] = max(parts[reach, reach], SHELL)
    parts[circle(*_HEAD)] = HEAD
    head_row = reach - round(_HEAD[0] * scale * sin)
    head_col = reach + round(_HEAD[0] * scale * cos)
    parts[head_row, head_col] = HEAD
    rows, cols = np.nonzero(parts >= 0)
    return rows - reach, cols - reach, parts[rows, cols]


def stamp(
    image: Image, row: float, col: float, theta: float, palette: Palette, pixels_per_metre: float
) -> None:
    """Draw a turtle in ``palette`` on ``image`` (in place), centred on pixel (row, col)."""
    rows, cols, parts = sprite_offsets(pixels_per_metre, direction_of(theta))
    rows = rows + math.floor(row)
    cols = cols + math.floor(col)
    inside = (rows >= 0) & (rows < image.shape[0]) & (cols >= 0) & (cols < image.shape[1])
    colours = np.asarray(palette, dtype=np.uint8)
    image[rows[inside], cols[inside]] = colours[parts[inside]]
