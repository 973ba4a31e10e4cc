"""Lasers: every beam of every robot cast at once through the grid, then against the robots.

`cast` marches all rays together by sphere tracing: each ray advances by the grid's clearance
at its tip (a distance that cannot skip a wall), at least one cell, until its tip is in a
cell a laser sees, leaves the grid or passes its range; rays that hit are then refined by a
few bisection steps between the last free point and the hit. Rays that finish drop out of the
working set, so the few that graze walls cost little. `cast_bodies` intersects the rays with
oriented boxes (the robots' bodies) in one broadcast slab test.

A beam that hits nothing reads its ``range_max`` and intensity 0, as in Stage.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np  # noqa: TID253 - the engine is numpy through and through

if TYPE_CHECKING:
    import numpy.typing as npt

    from rosx_turtle.stage.engine.grid import Grid

    Floats = npt.NDArray[np.float64]

#: Sphere-tracing rounds before the last rays are given up as misses (a safety net: far fewer
#: are needed, since every round advances a ray by at least half a cell).
MAX_ROUNDS = 4096
#: Bisection steps that refine a hit (each halves the error left by the last step).
REFINE_STEPS = 5
#: The shortest step a ray takes, in cells: a ray grazing a wall creeps along it at this pace,
#: and at most a corner of a cell can be cut by it (the hit is then refined by bisection).
STEP_MIN_CELLS = 1.0
#: A clearance is measured between cell centres: this many cells are kept as a margin.
_MARGIN_CELLS = 1.5


def cast(
    grid: Grid,
    x: Floats,
    y: Floats,
    angle: Floats,
    range_max: Floats,
) -> tuple[Floats, npt.NDArray[np.float32]]:
    """Distances to the first cell a laser sees along each ray, and its ``ranger_return``.

    Rays start at (x, y) in direction ``angle``; a ray that sees nothing within
    ``range_max`` reads ``range_max`` with return 0.
    """
    count = x.shape[0]
    dx, dy = np.cos(angle), np.sin(angle)
    res = grid.resolution
    clearance = grid.clearance
    returns = grid.returns
    rows, cols = grid.shape
    t_enter, t_exit = _grid_span(grid, x, y, dx, dy)
    ranges = range_max.astype(np.float64, copy=True)
    intensity = np.zeros(count, dtype=np.float32)
    t = t_enter.copy()
    last = t.copy()
    active = np.flatnonzero((t_enter <= t_exit) & (t_enter < range_max))
    step_min = STEP_MIN_CELLS * res
    x0, y0 = grid.origin
    for _ in range(MAX_ROUNDS):
        if active.size == 0:
            break
        ta = t[active]
        px = x[active] + ta * dx[active]
        py = y[active] + ta * dy[active]
        col = np.floor((px - x0) / res).astype(np.intp)
        row = np.floor((py - y0) / res).astype(np.intp)
        inside = (row >= 0) & (row < rows) & (col >= 0) & (col < cols)
        np.clip(row, 0, rows - 1, out=row)
        np.clip(col, 0, cols - 1, out=col)
        seen = returns[row, col]
        hit = inside & (seen > 0)
        gone = ~inside | (ta > range_max[active]) | (ta > t_exit[active])
        if hit.any():
            which = active[hit]
            ranges[which] = ta[hit]
            intensity[which] = seen[hit]
        keep = ~(hit | gone)
        active = active[keep]
        step = np.maximum(clearance[row[keep], col[keep]] - _MARGIN_CELLS * res, step_min)
        last[active] = t[active]
        t[active] = ta[keep] + step
    hits = intensity > 0
    if hits.any():
        ranges[hits] = _refine(grid, x[hits], y[hits], dx[hits], dy[hits], last[hits], ranges[hits])
    np.minimum(ranges, range_max, out=ranges)
    return ranges, intensity


def _refine(
    grid: Grid, x: Floats, y: Floats, dx: Floats, dy: Floats, free: Floats, hit: Floats
) -> Floats:
    """Bisect between a free point and a hit, ``REFINE_STEPS`` times; the hit end."""
    for _ in range(REFINE_STEPS):
        mid = 0.5 * (free + hit)
        row, col, inside = grid.cells(x + mid * dx, y + mid * dy)
        seen = inside & (grid.returns[row, col] > 0)
        hit = np.where(seen, mid, hit)
        free = np.where(seen, free, mid)
    return hit


def _grid_span(grid: Grid, x: Floats, y: Floats, dx: Floats, dy: Floats) -> tuple[Floats, Floats]:
    """Where each ray enters and leaves the grid's rectangle (enter > leave: never inside)."""
    width, height = grid.size
    lo = (grid.origin[0], grid.origin[1])
    hi = (lo[0] + width, lo[1] + height)
    t0 = np.zeros_like(x)
    t1 = np.full_like(x, np.inf)
    for p, d, low, high in ((x, dx, lo[0], hi[0]), (y, dy, lo[1], hi[1])):
        with np.errstate(divide="ignore", invalid="ignore"):
            a = (low - p) / d
            b = (high - p) / d
        parallel = d == 0
        outside = parallel & ((p < low) | (p >= high))
        near = np.where(parallel, -np.inf, np.minimum(a, b))
        far = np.where(parallel, np.inf, np.maximum(a, b))
        t0 = np.maximum(t0, near)
        t1 = np.minimum(t1, far)
        t1 = np.where(outside, -np.inf, t1)
    return t0, t1


def cast_bodies(
    x: Floats,
    y: Floats,
    angle: Floats,
    owner: npt.NDArray[np.intp],
    centre: Floats,
    yaw: Floats,
    half: Floats,
) -> tuple[Floats, npt.NDArray[np.intp]]:
    """Distance along each ray to the nearest box it enters (inf for none) and that box,
    skipping the box of its ``owner`` (an index past the last box: none); box ``k`` has centre
    ``centre[k]`` (x, y), heading ``yaw[k]`` and half sizes ``half[k]``. Rays starting inside a
    box other than their owner's read 0."""
    if centre.shape[0] == 0:
        return np.full(x.shape, np.inf), np.zeros(x.shape, dtype=np.intp)
    cos, sin = np.cos(yaw)[None, :], np.sin(yaw)[None, :]
    # Ray origins and directions in every box's frame: (rays, boxes).
    rx = x[:, None] - centre[None, :, 0]
    ry = y[:, None] - centre[None, :, 1]
    ox = rx * cos + ry * sin
    oy = -rx * sin + ry * cos
    dx, dy = np.cos(angle)[:, None], np.sin(angle)[:, None]
    ux = dx * cos + dy * sin
    uy = -dx * sin + dy * cos
    near = np.zeros_like(ox)
    far = np.full_like(ox, np.inf)
    for o, u, h in ((ox, ux, half[None, :, 0]), (oy, uy, half[None, :, 1])):
        with np.errstate(divide="ignore", invalid="ignore"):
            a = (-h - o) / u
            b = (h - o) / u
        parallel = u == 0
        inside = np.where(np.abs(o) <= h, -np.inf, np.inf)
        near = np.maximum(near, np.where(parallel, inside, np.minimum(a, b)))
        far = np.minimum(far, np.where(parallel, np.inf, np.maximum(a, b)))
    distance = np.where(near <= far, near, np.inf)
    mine = owner[:, None] == np.arange(centre.shape[0])[None, :]
    distance[mine] = np.inf
    nearest = distance.argmin(axis=1)
    result: Floats = distance[np.arange(x.shape[0]), nearest]
    return result, nearest


__all__ = ["MAX_ROUNDS", "REFINE_STEPS", "cast", "cast_bodies"]
