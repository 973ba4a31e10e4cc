"""rviz's Map: a ``nav_msgs/OccupancyGrid`` laid on the plane in rviz's palettes.

The grid is kept as it came (int8 cells); what the view shows is sampled from it at the
view's pixels, never coloured whole. Zoomed out, a pixel covers many cells: the grid is then
reduced once per zoom level (blocks of 2ⁿ cells, keeping the highest value: a wall stays a
wall, known beats unknown) and kept, so panning and redrawing cost a lookup per pixel.
"""

from __future__ import annotations

import math
import sys
from typing import TYPE_CHECKING, Any

import numpy as np  # noqa: TID253 - rviz's model is array work; only rviz imports it

from rosx_commands.rviz.displays.base import Display
from rosx_commands.rviz.geometry import compose, pose_transform, rotation_matrix
from rosx_commands.rviz.primitives import Layer

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    import numpy.typing as npt

    from rosx_commands.rviz.displays.base import Context
    from rosx_commands.rviz.geometry import Transform

    Floats = npt.NDArray[np.float64]
    Colours = npt.NDArray[np.uint8]


def _palettes() -> dict[str, tuple[Colours, Floats]]:
    """rviz's three palettes, indexed by the cell's value as an unsigned byte: colours and
    alphas."""
    values = np.arange(256)
    illegal_negative = np.stack(
        [np.full(127, 255), (255 * (np.arange(128, 255) - 128)) // 126, np.zeros(127)], axis=1
    )
    unknown = np.array([0x70, 0x89, 0x86])
    grey = 255 - (255 * values[:101]) // 100
    scheme_map = np.zeros((256, 3), dtype=np.int64)
    scheme_map[:101] = grey[:, None]
    scheme_map[101:128] = (0, 255, 0)
    scheme_map[128:255] = illegal_negative
    scheme_map[255] = unknown
    costmap = scheme_map.copy()
    cost = (255 * np.arange(1, 99)) // 100
    costmap[0] = (0, 0, 0)
    costmap[1:99] = np.stack([cost, np.zeros(98), 255 - cost], axis=1)
    costmap[99] = (0, 255, 255)
    costmap[100] = (255, 0, 255)
    raw = np.repeat(values[:, None], 3, axis=1)
    opaque = np.ones(256)
    costmap_alpha = opaque.copy()
    costmap_alpha[0] = 0.0
    return {
        "map": (scheme_map.astype(np.uint8), opaque),
        "costmap": (costmap.astype(np.uint8), costmap_alpha),
        "raw": (raw.astype(np.uint8), opaque),
    }


PALETTES = _palettes()


class MapImage:
    """One occupancy grid as a picture on the plane (`rosx_commands.rviz.primitives.Image`)."""

    def __init__(self, cells: npt.NDArray[np.int8], resolution: float, origin: Transform) -> None:
        self.cells = cells
        self.resolution = resolution
        self.origin = origin
        self.pose: Transform = origin
        self.palette, self.palette_alpha = PALETTES["map"]
        self.alpha = 1.0
        self.version = 0
        self._levels: dict[int, npt.NDArray[np.int8]] = {1: cells}

    def place(self, to_fixed: Transform, scheme: str, alpha: float) -> None:
        """Put the grid's frame at ``to_fixed`` in the fixed frame, in ``scheme``'s colours."""
        pose = compose(to_fixed, self.origin)
        palette, palette_alpha = PALETTES.get(scheme, PALETTES["map"])
        if pose != self.pose or palette is not self.palette or alpha != self.alpha:
            self.pose, self.palette, self.palette_alpha, self.alpha = (
                pose,
                palette,
                palette_alpha,
                alpha,
            )
            self.version += 1

    def level(self, factor: int) -> npt.NDArray[np.int8]:
        """The grid reduced by ``factor`` (a power of two) each way, made once."""
        found = self._levels.get(factor)
        if found is None:
            finer = self.level(factor // 2)
            rows, cols = finer.shape
            padded = np.full((rows + rows % 2, cols + cols % 2), -1, dtype=np.int8)
            padded[:rows, :cols] = finer
            found = padded.reshape(padded.shape[0] // 2, 2, padded.shape[1] // 2, 2).max(
                axis=(1, 3)
            )
            self._levels[factor] = found
        return found

    def sample(self, x: Floats, y: Floats, metres_per_pixel: float) -> tuple[Colours, Floats]:
        """The map's colour and alpha at fixed-frame points ``x``, ``y``, read from a coarser
        level of the grid when a pixel covers several cells (so a large map draws at the cost of
        the screen)."""
        factor = 1
        ratio = metres_per_pixel / self.resolution
        if ratio >= 2.0:
            factor = 2 ** min(int(math.log2(ratio)), 12)
        cells = self.level(factor)
        tx, ty, _, qx, qy, qz, qw = self.pose
        back = rotation_matrix(qx, qy, qz, qw).T
        dx, dy = x - tx, y - ty
        # Fixed-frame points on the plane z = tz, in the grid's frame (its plane is z = 0).
        gx = back[0, 0] * dx + back[0, 1] * dy
        gy = back[1, 0] * dx + back[1, 1] * dy
        size = self.resolution * factor
        col = np.floor(gx / size).astype(np.intp)
        row = np.floor(gy / size).astype(np.intp)
        inside = (col >= 0) & (col < cells.shape[1]) & (row >= 0) & (row < cells.shape[0])
        values = np.zeros(x.shape, dtype=np.uint8)
        values[inside] = cells[row[inside], col[inside]].view(np.uint8)
        colours = self.palette[values]
        alphas = np.where(inside, self.palette_alpha[values] * self.alpha, 0.0)
        return colours, alphas


class Map(Display):
    """rviz's Map display: an occupancy grid."""

    CLASSES = ("rviz/Map",)
    MESSAGE_TYPE = "nav_msgs/OccupancyGrid"
    DEFAULT_TOPIC = "map"

    @override
    def clear(self) -> None:
        self.image: MapImage | None = None
        self.frame = ""
        self.stamp = 0
        self.statuses.warn("Message", "No map received")

    @override
    def take(self, msg: Any, now: float) -> None:
        info = msg.info
        width, height = int(info.width), int(info.height)
        cells = np.asarray(msg.data, dtype=np.int8)
        if width * height == 0 or info.resolution <= 0:
            self.statuses.error("Map", f"Map is zero-sized ({width}x{height})")
            self.image = None
            return
        if cells.size != width * height:
            self.statuses.error(
                "Map",
                f"Data size doesn't match width*height: width = {width}, "
                f"height = {height}, data size = {cells.size}",
            )
            self.image = None
            return
        self.statuses.delete("Map")
        self.statuses.ok("Message", "Map received")
        self.image = MapImage(
            cells.reshape(height, width), float(info.resolution), pose_transform(info.origin)
        )
        self.frame = msg.header.frame_id

    @override
    def draw(self, context: Context) -> Layer:
        if self.image is None:
            return Layer()
        answer = context.frames.lookup(self.frame)
        if not self.transform_status(self.frame, answer) or isinstance(answer, str):
            return Layer()
        scheme = str(self.option("Color Scheme", "map"))
        self.image.place(answer, scheme, self.number("Alpha", 0.7))
        return Layer(images=[self.image])
