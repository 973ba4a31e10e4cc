"""Lasers: every beam of every robot cast at once through the grid, then against the robots.

`cast` moves all rays together, in rounds, in the grid's cell units. Each round a ray takes
the longer of two steps, both exact: the sphere-tracing step (the grid's clearance at its tip
less the most a cell's extent can take off it, √2 cells: it can reach a wall's face but never
pass it) and the step to the next cell boundary it crosses (it then stands in the next cell,
which the next round looks at). So far from walls rays leap, and near them they go cell by
cell, never cutting a cell's corner; the distance at which a ray first stands in a cell a
laser sees is where it entered it. Rays that finish drop out of the working set (its arrays
are the rows of one array, compacted in one call), so the few that run along walls, a cell a
round, cost little.

`cast_bodies` intersects the rays with oriented boxes (the robots' bodies) in one broadcast
slab test, over only the rays whose angle can meet each box.

A beam that hits nothing reads its ``range_max`` and intensity 0, as in Stage.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np  # noqa: TID253 - the engine is numpy through and through

if TYPE_CHECKING:
    import numpy.typing as npt

    from rosx_turtle.stage.engine.grid import Grid

    Floats = npt.NDArray[np.float64]
    Indices = npt.NDArray[np.intp]

#: Rounds before the last rays are given up as misses (a safety net: every round moves a ray
#: into the next cell at least).
MAX_ROUNDS = 100_000
#: What a cell's extent can take off a distance between centres, in cells: half a diagonal at
#: each end.
_MARGIN = math.sqrt(2.0)
#: How far past a boundary a ray steps to stand in the next cell (cells; far below any
#: distance a laser reports).
_NUDGE = 1e-6
#: A boundary index no ray reaches, for the axis a ray runs parallel to.
_NEVER = 1e300
# The rows of the working set's array.
_T, _X, _Y, _UX, _UY, _END, _NEXT_X, _NEXT_Y, _INV_X, _INV_Y, _RAY = range(11)


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
    t_enter, t_exit = _grid_span(grid, x, y, dx, dy)
    ranges = range_max.astype(np.float64, copy=True)
    intensity = np.zeros(count, dtype=np.float32)
    live = np.flatnonzero((t_enter <= t_exit) & (t_enter < range_max))
    if live.size == 0:
        return ranges, intensity
    end = np.minimum(range_max, t_exit)
    state = _working_set(grid, x[live], y[live], dx[live], dy[live], t_enter[live], end[live])
    state[_RAY] = live
    returns = grid.returns.ravel()
    clearance = grid.clearance.ravel()
    cols = grid.shape[1]
    for _ in range(MAX_ROUNDS):
        t, px, py = state[_T], state[_X], state[_Y]
        col = px.astype(np.intp)  # px >= 0 inside the grid: truncation is floor
        row = py.astype(np.intp)
        cell = row * cols + col
        seen = returns.take(cell, mode="clip")  # rays past their end are dropped below
        done = (seen > 0) | (t > state[_END])
        if done.any():
            hit = done & (t <= state[_END])
            rays = state[_RAY, hit].astype(np.intp)
            ranges[rays] = t[hit] * res
            intensity[rays] = seen[hit]
            keep = ~done
            state = state[:, keep]
            col, row, cell = col[keep], row[keep], cell[keep]
            t, px, py = state[_T], state[_X], state[_Y]
        if state.shape[1] == 0:
            break
        with np.errstate(over="ignore", invalid="ignore"):
            cross_x = (col + state[_NEXT_X] - px) * state[_INV_X]
            cross_y = (row + state[_NEXT_Y] - py) * state[_INV_Y]
        step = np.maximum(clearance.take(cell, mode="clip") - _MARGIN, np.minimum(cross_x, cross_y))
        step += _NUDGE
        t += step
        px += step * state[_UX]
        py += step * state[_UY]
    np.minimum(ranges, range_max, out=ranges)
    return ranges, intensity


def _working_set(
    grid: Grid, x: Floats, y: Floats, ux: Floats, uy: Floats, start: Floats, end: Floats
) -> Floats:
    """The rows of the working set (in cells) for rays from (x, y) along (ux, uy), their tips
    at ``start`` and their ends at ``end`` (metres); `_RAY` is left to the caller."""
    res = grid.resolution
    state = np.empty((11, x.shape[0]))
    t = state[_T]
    t[:] = start / res
    state[_X] = (x - grid.origin[0]) / res + t * ux
    state[_Y] = (y - grid.origin[1]) / res + t * uy
    state[_UX], state[_UY] = ux, uy
    state[_END] = end / res
    with np.errstate(divide="ignore"):
        # The next boundary is the cell's right (top) edge going up, its left (bottom) going
        # down; none for the axis a ray runs parallel to.
        for u, boundary, inverse in ((ux, _NEXT_X, _INV_X), (uy, _NEXT_Y, _INV_Y)):
            state[boundary] = np.where(u > 0, 1.0, np.where(u < 0, 0.0, _NEVER))
            state[inverse] = np.where(u == 0, _NEVER, 1.0 / np.where(u == 0, 1.0, u))
    return state


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
    origin: Floats,
    first: Floats,
    increment: Floats,
    samples: Indices,
    owner: Indices,
    centre: Floats,
    yaw: Floats,
    half: Floats,
) -> tuple[Floats, Indices]:
    """Where the beams of fans meet oriented boxes: the distance along each beam to the nearest
    box it enters (inf for none) and that box.

    Fan ``f`` is ``samples[f]`` beams from ``origin[f]`` (x, y) at angles ``first[f] + i *
    increment[f]``, skipping the box of its ``owner`` (an index past the last box: none); the
    beams of all fans are returned one fan after another. Box ``k`` has centre ``centre[k]``,
    heading ``yaw[k]`` and half sizes ``half[k]``. A beam starting inside a box reads 0.

    Only the beams whose angle can meet a box's bounding circle are tested (a few per box
    and fan), in one broadcast slab test.
    """
    total = int(samples.sum())
    distance = np.full(total, np.inf)
    nearest = np.zeros(total, dtype=np.intp)
    boxes = centre.shape[0]
    if boxes == 0 or total == 0:
        return distance, nearest
    fan, box, beam = _beams_near_boxes(origin, first, increment, samples, owner, centre, half)
    if fan.size == 0:
        return distance, nearest
    angle = first[fan] + beam * increment[fan]
    cos, sin = np.cos(yaw[box]), np.sin(yaw[box])
    rx = origin[fan, 0] - centre[box, 0]
    ry = origin[fan, 1] - centre[box, 1]
    dx, dy = np.cos(angle), np.sin(angle)
    # The beam's origin and direction in the box's frame, then the slab test on each axis.
    near = np.zeros(fan.shape)
    far = np.full(fan.shape, np.inf)
    for o, u, h in (
        (rx * cos + ry * sin, dx * cos + dy * sin, half[box, 0]),
        (-rx * sin + ry * cos, -dx * sin + dy * cos, half[box, 1]),
    ):
        with np.errstate(divide="ignore", invalid="ignore"):
            a = (-h - o) / u
            b = (h - o) / u
        parallel = u == 0
        inside = np.where(np.abs(o) <= h, -np.inf, np.inf)
        near = np.maximum(near, np.where(parallel, inside, np.minimum(a, b)))
        far = np.minimum(far, np.where(parallel, np.inf, np.maximum(a, b)))
    met = near <= far
    starts = np.cumsum(samples) - samples
    ray, box, near = (starts[fan] + beam)[met], box[met], near[met]
    if ray.size == 0:
        return distance, nearest
    order = np.lexsort((near, ray))  # by beam, then by distance: each beam's nearest first
    ray, box, near = ray[order], box[order], near[order]
    nearest_first = np.concatenate([[True], ray[1:] != ray[:-1]])
    distance[ray[nearest_first]] = near[nearest_first]
    nearest[ray[nearest_first]] = box[nearest_first]
    return distance, nearest


def _beams_near_boxes(
    origin: Floats,
    first: Floats,
    increment: Floats,
    samples: Indices,
    owner: Indices,
    centre: Floats,
    half: Floats,
) -> tuple[Indices, Indices, Indices]:
    """(fan, box, beam) for every beam of every fan whose angle is within the angle a box's
    bounding circle spans from the fan's origin (every beam when the origin is in the circle),
    the owner's box left out."""
    fans, boxes = origin.shape[0], centre.shape[0]
    radius = np.hypot(half[:, 0], half[:, 1])[None, :]
    rx = centre[None, :, 0] - origin[:, None, 0]
    ry = centre[None, :, 1] - origin[:, None, 1]
    reach = np.hypot(rx, ry)
    within = reach <= radius
    spread = np.arcsin(np.clip(radius / np.where(within, 1.0, reach), 0.0, 1.0))
    bearing = np.mod(np.arctan2(ry, rx) - first[:, None], 2 * math.pi)
    step = np.where(increment > 0, increment, 1.0)[:, None]
    last = (samples - 1)[:, None]
    los, his = [], []
    # The circle's span, and the same a turn before and after (a fan may pass 0 or 2π).
    for turn in (-2 * math.pi, 0.0, 2 * math.pi):
        lo = np.ceil((bearing + turn - spread) / step)
        hi = np.floor((bearing + turn + spread) / step)
        if turn == 0.0:
            lo, hi = np.where(within, 0, lo), np.where(within, last, hi)
        else:
            hi = np.where(within, -1, hi)
        los.append(np.maximum(lo, 0))
        his.append(np.minimum(hi, last))
    lo = np.stack(los).astype(np.intp)
    hi = np.stack(his).astype(np.intp)
    mine = owner[:, None] == np.arange(boxes)[None, :]
    counts = np.where(mine[None], 0, np.maximum(hi - lo + 1, 0)).ravel()
    fan = np.broadcast_to(np.arange(fans)[None, :, None], lo.shape).ravel()
    box = np.broadcast_to(np.arange(boxes)[None, None, :], lo.shape).ravel()
    total = int(counts.sum())
    fan, box = np.repeat(fan, counts), np.repeat(box, counts)
    # Beam numbers: each run's low end, then 0, 1, 2... within the run.
    starts = np.cumsum(counts) - counts
    beam = np.repeat(lo.ravel(), counts) + np.arange(total) - np.repeat(starts, counts)
    return fan, box, beam


__all__ = ["MAX_ROUNDS", "cast", "cast_bodies"]
