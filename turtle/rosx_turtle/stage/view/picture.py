"""The world as a picture: the map, the robots with their headings, the laser's hits.

`WorldPainter` fits the occupancy grid into a picture of a given size (square pixels: a
terminal cell holds two, one above the other), keeping the aspect ratio and centring it. The
map is reduced once per size (a pixel is a wall if any cell under it is solid); each frame
copies it and draws the laser hits and the robots on top. Pure numpy: state in, pixels out.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np  # noqa: TID253 - the view is array work; only the TUI imports it

if TYPE_CHECKING:
    import numpy.typing as npt

    from rosx_turtle.stage.engine.grid import Grid
    from rosx_turtle.stage.engine.simulation import StepReport
    from rosx_turtle.stage.world.model import World

    Image = npt.NDArray[np.uint8]

FLOOR = (236, 236, 236)
WALL = (60, 60, 60)
OUTSIDE = (20, 20, 28)
HIT = (230, 40, 40)
NOSE = (255, 255, 255)
#: Stage's colour names that worlds use most; others draw as the default robot colour.
COLOURS = {
    "red": (220, 40, 40), "green": (40, 170, 60), "blue": (40, 90, 220), "black": (0, 0, 0),
    "white": (250, 250, 250), "yellow": (230, 200, 30), "orange": (240, 140, 20),
    "cyan": (30, 200, 210), "magenta": (200, 40, 200), "gray": (128, 128, 128),
    "grey": (128, 128, 128), "purple": (130, 50, 170), "brown": (140, 90, 40),
}  # fmt: skip
ROBOT = (40, 90, 220)


def colour(name: str) -> tuple[int, int, int]:
    """An X11-style colour name as RGB (``grayNN`` too); unknown names give `ROBOT`."""
    name = name.lower()
    if name.startswith(("gray", "grey")) and name[4:].isdigit():
        level = round(int(name[4:]) * 255 / 100)
        return (level, level, level)
    return COLOURS.get(name, ROBOT)


class WorldPainter:
    """Pictures of one world at one size (see the module docstring)."""

    def __init__(self, world: World, grid: Grid) -> None:
        self.world = world
        self.grid = grid
        self.width = self.height = 0
        self.scale = 1.0  # metres per pixel
        self.offset = (0.0, 0.0)  # the world point at the picture's lower-left corner
        self._base: Image = np.zeros((0, 0, 3), dtype=np.uint8)
        self._colours = [colour(robot.color) for robot in world.robots]

    def resize(self, width: int, height: int) -> None:
        """Paint pictures of ``width`` by ``height`` pixels from now on."""
        width, height = max(1, width), max(1, height)
        if (width, height) == (self.width, self.height):
            return
        self.width, self.height = width, height
        grid_w, grid_h = self.grid.size
        self.scale = max(grid_w / width, grid_h / height)
        x0, y0 = self.grid.origin
        self.offset = (
            x0 + grid_w / 2 - width * self.scale / 2,
            y0 + grid_h / 2 - height * self.scale / 2,
        )
        self._base = self._map()

    def _map(self) -> Image:
        """The grid reduced to the picture: a pixel is a wall if a solid cell is under it
        (the grid max-pooled into blocks about a pixel wide, then sampled at the pixels)."""
        grid = self.grid
        rows, cols = grid.shape
        k = max(1, math.floor(self.scale / grid.resolution))
        padded = np.zeros((-(-rows // k) * k, -(-cols // k) * k), dtype=np.bool_)
        padded[:rows, :cols] = grid.solid
        blocks = padded.reshape(padded.shape[0] // k, k, padded.shape[1] // k, k)
        coarse = np.asarray(blocks.any(axis=(1, 3)), dtype=np.bool_)
        size = k * grid.resolution
        xs = self.offset[0] + (np.arange(self.width) + 0.5) * self.scale
        ys = self.offset[1] + (np.arange(self.height)[::-1] + 0.5) * self.scale  # top row first
        col = np.floor((xs - grid.origin[0]) / size).astype(np.intp)
        row = np.floor((ys - grid.origin[1]) / size).astype(np.intp)
        col_in = (col >= 0) & (col < coarse.shape[1])
        row_in = (row >= 0) & (row < coarse.shape[0])
        walls = coarse[
            np.clip(row, 0, coarse.shape[0] - 1)[:, None],
            np.clip(col, 0, coarse.shape[1] - 1)[None, :],
        ]
        image = np.empty((self.height, self.width, 3), dtype=np.uint8)
        image[:] = np.where(walls[:, :, None], np.array(WALL, np.uint8), np.array(FLOOR, np.uint8))
        image[~(row_in[:, None] & col_in[None, :])] = OUTSIDE
        return image

    def pixel(
        self, x: npt.NDArray[np.float64], y: npt.NDArray[np.float64]
    ) -> tuple[npt.NDArray[np.intp], npt.NDArray[np.intp], npt.NDArray[np.bool_]]:
        """Picture row and column of world points, and which are inside the picture."""
        col = np.floor((x - self.offset[0]) / self.scale).astype(np.intp)
        row = self.height - 1 - np.floor((y - self.offset[1]) / self.scale).astype(np.intp)
        inside = (row >= 0) & (row < self.height) & (col >= 0) & (col < self.width)
        return row, col, inside

    def paint(
        self,
        report: StepReport | None,
        hits: list[tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]] | None = None,
    ) -> Image:
        """The picture: the map, then the laser hits ``hits`` (world x, y arrays), then the
        robots of ``report``."""
        image: Image = self._base.copy()
        for x, y in hits or []:
            row, col, inside = self.pixel(x, y)
            image[row[inside], col[inside]] = HIT
        if report is None:
            return image
        for index, (px, py, yaw) in enumerate(report.pose.tolist()):
            robot = self.world.robots[index]
            radius = max(robot.size[0], robot.size[1]) / 2
            steps = max(1, math.ceil(radius / self.scale))
            offsets = np.linspace(-radius, radius, 2 * steps + 1)
            gx, gy = np.meshgrid(offsets, offsets)
            disc = gx**2 + gy**2 <= radius**2 + 1e-12
            row, col, inside = self.pixel(px + gx[disc], py + gy[disc])
            image[row[inside], col[inside]] = self._colours[index]
            row, col, inside = self.pixel(np.array([px]), np.array([py]))
            image[row[inside], col[inside]] = self._colours[index]
            nose = max(radius, 1.5 * self.scale)
            row, col, inside = self.pixel(
                np.array([px + nose * math.cos(yaw)]), np.array([py + nose * math.sin(yaw)])
            )
            image[row[inside], col[inside]] = NOSE
        return image


def laser_hits(report: StepReport) -> list[tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]]:
    """The world points each scan of ``report`` hit (beams that read below range_max)."""
    points = []
    for scan in report.scans:
        spec = scan.spec
        px, py, pa = report.pose[scan.robot]
        lx, ly, la = spec.pose
        ox = px + lx * math.cos(pa) - ly * math.sin(pa)
        oy = py + lx * math.sin(pa) + ly * math.cos(pa)
        angles = pa + la - spec.fov / 2 + np.arange(spec.samples) * spec.angle_increment
        ranges = scan.ranges.astype(np.float64)
        hit = ranges < spec.range_max
        points.append(
            (ox + ranges[hit] * np.cos(angles[hit]), oy + ranges[hit] * np.sin(angles[hit]))
        )
    return points


__all__ = ["WorldPainter", "colour", "laser_hits"]
