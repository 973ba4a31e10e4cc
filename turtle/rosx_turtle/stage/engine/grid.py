"""The world as an occupancy grid, and a distance field for casting rays through it.

`rasterise` turns a `World`'s blocks (boxes and floor-plan bitmaps, each posed, sized and
possibly rotated) into a `Grid` at the world's ``resolution``. As in Stage, a bitmap's pixel is
an obstacle when its first channel is at most 127, and the dark part of the bitmap (the bounding
box of its dark pixels) is stretched over the model's ``size``; ``boundary 1`` adds a wall along
the model's edges.

Rows of the grid run along +y (row 0 is the bottom), columns along +x. Two layers: ``solid``
(what robots bump into) and ``returns`` (what lasers see, with the ``ranger_return`` they read
as intensity; 0 where a laser sees nothing). `Grid.clearance` is the Euclidean distance, in
cells, from each cell's centre to the centre of the nearest cell a laser sees, and
`Grid.room` the same to the nearest solid cell: exact distance transforms
(`distance_transform`), computed once per world.
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
#: Cells read from the distance transform's envelopes at once (bounds its temporary arrays).
_ENVELOPE_CELLS = 1 << 20
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
    _room: npt.NDArray[np.float32] | None = field(default=None, repr=False)

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
        """Each cell's distance in cells, between centres, to the nearest cell lasers see
        (computed once)."""
        if self._clearance is None:
            self._clearance = distance_transform(self.returns > 0)
        return self._clearance

    @property
    def room(self) -> npt.NDArray[np.float32]:
        """Each cell's distance in cells, between centres, to the nearest solid cell (computed
        once)."""
        if self._room is None:
            self._room = distance_transform(self.solid)
        return self._room

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


def distance_transform(seen: npt.NDArray[np.bool_]) -> npt.NDArray[np.float32]:
    """For each cell, the Euclidean distance in cells from its centre to the centre of the
    nearest ``seen`` cell; rows + columns + 1 where nothing is seen.

    Exact, in two passes (Felzenszwalb and Huttenlocher's separable transform): the distance
    along each column to the nearest seen cell of that column (two running extrema), then, along
    each row, the lower envelope of the parabolas ``(x - x')² + vertical(x')²``, built for every
    row at once (`_lower_envelope`). About 24 bytes a cell at the most.
    """
    rows, cols = seen.shape
    big = np.float32(rows + cols + 1)
    if not seen.any():
        return np.full(seen.shape, big, dtype=np.float32)
    # Whole numbers below 2**24: exact in float32, at half float64's memory.
    index = np.arange(rows, dtype=np.float32)[:, None]
    nearest = np.maximum.accumulate(np.where(seen, index, -big), axis=0)
    vertical = index - nearest
    nearest = np.minimum.accumulate(np.where(seen, index, 2 * big)[::-1], axis=0)[::-1]
    np.minimum(vertical, nearest - index, out=vertical)
    del nearest
    np.minimum(vertical, big, out=vertical)
    squared = vertical.astype(np.float64)
    del vertical
    squared *= squared
    return _lower_envelope(squared, big)


def _lower_envelope(lifted: npt.NDArray[np.float64], cap: np.float32) -> npt.NDArray[np.float32]:
    """The square root of min over x' of ``(x - x')² + f[r, x']``, for every row r and column
    x, at most ``cap``; ``lifted`` holds f and is overwritten.

    Each row's envelope is built left to right as in the sequential algorithm: its j-th
    parabola has its vertex at column ``vertex[r, j]`` and is the lowest over
    ``[bound[r, j], bound[r, j + 1])``; a new parabola pops those it hides. The rows advance
    together, one column per iteration, and only the rows that pop loop again (the arrays are
    flat so that each row's entry is one gather). The envelope is then read at every column,
    a block of rows at a time, with one search over their bounds laid end to end.
    """
    rows, cols = lifted.shape
    every = np.arange(rows)
    lifted += np.arange(cols, dtype=np.float64) ** 2  # f(q) + q², each parabola's offset
    # Column-major, so that a column is contiguous: flat[q * rows + r].
    flat = np.ascontiguousarray(lifted.T).ravel()
    del lifted
    vertex = np.zeros(rows * cols, dtype=np.int32)  # [r * cols + j]
    bound = np.full(rows * (cols + 1), np.inf)  # [r * (cols + 1) + j]
    bound[:: cols + 1] = -np.inf
    vertex_row, bound_row = every * cols, every * (cols + 1)
    top = np.zeros(rows, dtype=np.intp)  # each row's last parabola
    for q in range(1, cols):
        column = flat[q * rows : (q + 1) * rows]
        last = vertex[vertex_row + top]
        cross = (column - flat[last * rows + every]) / (2.0 * (q - last))
        hidden = np.flatnonzero(cross <= bound[bound_row + top])
        while hidden.size:
            top[hidden] -= 1
            last = vertex[vertex_row[hidden] + top[hidden]]
            cross[hidden] = (column[hidden] - flat[last * rows + hidden]) / (2.0 * (q - last))
            hidden = hidden[cross[hidden] <= bound[bound_row[hidden] + top[hidden]]]
        top += 1
        vertex[vertex_row + top] = q
        bound[bound_row + top] = cross
        bound[bound_row + top + 1] = np.inf
    vertices = vertex.reshape(rows, cols)
    bounds = bound.reshape(rows, cols + 1)
    result = np.empty((rows, cols), dtype=np.float32)
    block = max(1, _ENVELOPE_CELLS // cols)
    columns = np.arange(cols)
    for start in range(0, rows, block):
        part = slice(start, min(rows, start + block))
        count = part.stop - start
        local = np.arange(count)
        # Bounds past each row's last are stale: end every row with `cols` (above every column).
        past = np.arange(cols + 1)[None, :] > top[part, None]
        stride = float(cols + 2)  # each row's bounds shifted by its row: sorted end to end
        shifted = np.where(past, float(cols), np.maximum(bounds[part], -1.0))
        shifted += local[:, None] * stride
        query = columns[None, :] + local[:, None] * stride
        found = np.searchsorted(shifted.ravel(), query.ravel(), side="right").reshape(count, cols)
        found -= 1 + local[:, None] * (cols + 1)
        nearest = vertices[part][local[:, None], found]
        # f at the vertex is its lifted value less its column squared.
        offset = (columns[None, :] - nearest).astype(np.float64)
        height = flat[nearest * rows + every[part, None]] - nearest.astype(np.float64) ** 2
        np.sqrt(offset * offset + height, out=offset)
        np.minimum(offset, cap, out=offset)
        result[part] = offset
    return result


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
    "distance_transform",
    "grid_shape",
    "rasterise",
]
