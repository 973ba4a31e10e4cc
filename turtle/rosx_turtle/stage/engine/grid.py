"""The world as an occupancy grid, and a distance field for casting rays through it.

`rasterise` turns a `World`'s blocks (boxes and floor-plan bitmaps, each posed, sized and
possibly rotated) into a `Grid` at the world's ``resolution``. As in Stage, a bitmap's pixel is
an obstacle when its first channel is at most 127, and the dark part of the bitmap (the bounding
box of its dark pixels) is stretched over the model's ``size``; ``boundary 1`` adds a wall along
the model's edges.

Rows of the grid run along +y (row 0 is the bottom), columns along +x. Two layers: ``solid``
(what robots bump into) and ``returns`` (what lasers see, with the ``ranger_return`` they read
as intensity; 0 where a laser sees nothing). `Grid.clearance` is a lower bound, in metres, of
the distance from each cell's centre to the nearest cell a laser sees: an L1 distance transform
over √2, which numpy computes in four vectorised sweeps.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np  # noqa: TID253 - the engine is numpy through and through

if TYPE_CHECKING:
    from collections.abc import Callable

    import numpy.typing as npt

    from rosx_turtle.stage.world.model import Block, World

#: Empty space left around the blocks and robots, so rays and robots start inside the grid.
MARGIN = 1.0
#: Rows rasterised at once (bounds the temporary arrays of a large floor plan).
_CHUNK_ROWS = 512
#: Stage's test of a dark pixel: first channel at most this.
DARK_MAX = 127


@dataclass(eq=False)
class Grid:
    """Occupancy layers over a rectangle whose lower-left corner is ``origin`` (metres)."""

    solid: npt.NDArray[np.bool_]
    returns: npt.NDArray[np.float32]
    origin: tuple[float, float]
    resolution: float
    _clearance: npt.NDArray[np.float32] | None = field(default=None, repr=False)

    @property
    def shape(self) -> tuple[int, int]:
        """(rows, columns)."""
        rows, cols = self.solid.shape
        return (rows, cols)

    @property
    def size(self) -> tuple[float, float]:
        """Width and height in metres."""
        rows, cols = self.shape
        return (cols * self.resolution, rows * self.resolution)

    @property
    def clearance(self) -> npt.NDArray[np.float32]:
        """A lower bound of each cell's distance to what lasers see (computed once)."""
        if self._clearance is None:
            self._clearance = distance_lower_bound(self.returns > 0) * np.float32(self.resolution)
        return self._clearance

    def cells(
        self, x: npt.NDArray[np.float64], y: npt.NDArray[np.float64]
    ) -> tuple[npt.NDArray[np.intp], npt.NDArray[np.intp], npt.NDArray[np.bool_]]:
        """Row and column of the cells holding points (x, y), and which are inside."""
        col = np.floor((x - self.origin[0]) / self.resolution).astype(np.intp)
        row = np.floor((y - self.origin[1]) / self.resolution).astype(np.intp)
        rows, cols = self.shape
        inside = (row >= 0) & (row < rows) & (col >= 0) & (col < cols)
        return np.clip(row, 0, rows - 1), np.clip(col, 0, cols - 1), inside

    def solid_at(
        self, x: npt.NDArray[np.float64], y: npt.NDArray[np.float64]
    ) -> npt.NDArray[np.bool_]:
        """Whether each point (x, y) is in a solid cell (outside the grid is free)."""
        row, col, inside = self.cells(x, y)
        hit: npt.NDArray[np.bool_] = self.solid[row, col] & inside
        return hit


def distance_lower_bound(seen: npt.NDArray[np.bool_]) -> npt.NDArray[np.float32]:
    """For each cell, L1 cells to the nearest ``seen`` cell over √2 (≤ the Euclidean
    distance between the centres); a large number where nothing is seen."""
    rows, cols = seen.shape
    big = float(rows + cols + 1)
    if not seen.any():
        return np.full(seen.shape, big, dtype=np.float32)
    # Vertical distance to the nearest seen cell of the column, exact (two running maxima).
    index = np.arange(rows, dtype=np.float32)[:, None]
    below = np.where(seen, index, -big)
    below = np.maximum.accumulate(below, axis=0)
    above = np.where(seen, index, 2 * big)
    above = np.minimum.accumulate(above[::-1], axis=0)[::-1]
    vertical = np.minimum(index - below, above - index)
    # Then min over columns x' of vertical(x') + |x - x'|, as two running minima.
    column = np.arange(cols, dtype=np.float32)[None, :]
    left = np.minimum.accumulate(vertical - column, axis=1) + column
    right = (np.minimum.accumulate((vertical + column)[:, ::-1], axis=1))[:, ::-1] - column
    l1 = np.minimum(np.minimum(left, right), big)
    bound: npt.NDArray[np.float32] = (l1 / np.float32(math.sqrt(2.0))).astype(np.float32)
    return bound


def _bounds(world: World) -> tuple[float, float, float, float]:
    xs: list[float] = []
    ys: list[float] = []
    for block in world.blocks:
        for x, y in _corners(block):
            xs.append(x)
            ys.append(y)
    for robot in world.robots:
        xs.append(robot.pose[0])
        ys.append(robot.pose[1])
    if not xs:
        return (-MARGIN, -MARGIN, MARGIN, MARGIN)
    return (min(xs) - MARGIN, min(ys) - MARGIN, max(xs) + MARGIN, max(ys) + MARGIN)


def body_pose(block: Block) -> tuple[float, float, float]:
    """The pose of a block's body: its pose moved by its ``origin``."""
    x, y, a = block.pose
    ox, oy, oa = block.origin
    return (
        x + ox * math.cos(a) - oy * math.sin(a),
        y + ox * math.sin(a) + oy * math.cos(a),
        a + oa,
    )


def _corners(block: Block) -> list[tuple[float, float]]:
    x, y, a = body_pose(block)
    hx, hy = block.size[0] / 2, block.size[1] / 2
    c, s = math.cos(a), math.sin(a)
    return [(x + u * c - v * s, y + u * s + v * c) for u in (-hx, hx) for v in (-hy, hy)]


def crop_dark(image: npt.NDArray[np.uint8]) -> npt.NDArray[np.bool_]:
    """The dark pixels of a bitmap, cropped to their bounding box (Stage's normalisation)."""
    dark = image <= DARK_MAX
    rows = np.flatnonzero(dark.any(axis=1))
    cols = np.flatnonzero(dark.any(axis=0))
    if rows.size == 0:
        return np.zeros((0, 0), dtype=np.bool_)
    cropped: npt.NDArray[np.bool_] = dark[rows[0] : rows[-1] + 1, cols[0] : cols[-1] + 1]
    return cropped


def rasterise(world: World, bitmap: Callable[[Block], npt.NDArray[np.uint8]] | None = None) -> Grid:
    """The `Grid` of ``world``; ``bitmap(block)`` gives a floor plan's pixels (grey, top row
    first) for blocks that name one (without it such blocks are drawn as boxes)."""
    res = world.resolution
    x0, y0, _, _ = _bounds(world)
    rows, cols = grid_shape(world)
    grid = Grid(
        np.zeros((rows, cols), dtype=np.bool_),
        np.zeros((rows, cols), dtype=np.float32),
        (x0, y0),
        res,
    )
    for block in world.blocks:
        dark = crop_dark(bitmap(block)) if block.bitmap and bitmap is not None else None
        _draw(grid, block, dark)
    return grid


def grid_shape(world: World) -> tuple[int, int]:
    """The rows and columns of ``world``'s grid (what `rasterise` will allocate)."""
    x0, y0, x1, y1 = _bounds(world)
    res = world.resolution
    return max(1, math.ceil((y1 - y0) / res)), max(1, math.ceil((x1 - x0) / res))


def _draw(grid: Grid, block: Block, dark: npt.NDArray[np.bool_] | None) -> None:
    res = grid.resolution
    corners = _corners(block)
    xs = [c[0] for c in corners]
    ys = [c[1] for c in corners]
    rows, cols = grid.shape
    c0 = max(0, math.floor((min(xs) - grid.origin[0]) / res))
    c1 = min(cols, math.ceil((max(xs) - grid.origin[0]) / res) + 1)
    r0 = max(0, math.floor((min(ys) - grid.origin[1]) / res))
    r1 = min(rows, math.ceil((max(ys) - grid.origin[1]) / res) + 1)
    if c0 >= c1 or r0 >= r1:
        return
    bx, by, ba = body_pose(block)
    cos, sin = math.cos(ba), math.sin(ba)
    hx, hy = block.size[0] / 2, block.size[1] / 2
    xc = grid.origin[0] + (np.arange(c0, c1) + 0.5) * res - bx
    for start in range(r0, r1, _CHUNK_ROWS):
        stop = min(r1, start + _CHUNK_ROWS)
        yc = grid.origin[1] + (np.arange(start, stop) + 0.5) * res - by
        u = xc[None, :] * cos + yc[:, None] * sin  # the body's frame
        v = -xc[None, :] * sin + yc[:, None] * cos
        inside = (np.abs(u) <= hx) & (np.abs(v) <= hy)
        if dark is None:
            filled = inside
        elif dark.size == 0:
            filled = np.zeros_like(inside)
        else:
            height, width = dark.shape
            px = np.clip(((u / block.size[0] + 0.5) * width).astype(np.intp), 0, width - 1)
            py = np.clip(((0.5 - v / block.size[1]) * height).astype(np.intp), 0, height - 1)
            filled = inside & dark[py, px]
        if block.boundary:
            edge = inside & ((np.abs(u) > hx - res) | (np.abs(v) > hy - res))
            filled = filled | edge
        window = (slice(start, stop), slice(c0, c1))
        if block.obstacle_return:
            grid.solid[window] |= filled
        if block.ranger_return > 0:
            grid.returns[window] = np.where(
                filled, np.float32(block.ranger_return), grid.returns[window]
            )


__all__ = [
    "DARK_MAX",
    "MARGIN",
    "Grid",
    "body_pose",
    "crop_dark",
    "distance_lower_bound",
    "grid_shape",
    "rasterise",
]
