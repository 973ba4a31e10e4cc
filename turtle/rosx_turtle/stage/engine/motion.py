"""Moving the robots one step: kinematics, Stage's speed limits, collisions and stalls.

`advance` takes every robot's pose and command and gives the poses after ``dt`` seconds,
all robots at once. Commands are clipped to Stage's default velocity bounds (±1 m/s, ±π/2
rad/s); a ``diff`` robot ignores the sideways speed, an ``omni`` robot moves in its own x and
y. Poses integrate as Stage's do (one Euler step in the heading at the start of the step).

A robot whose body would overlap a solid cell or another robot's body at its new pose stays
where it was and is stalled; it moves again as soon as its command leads somewhere free.
Bodies are boxes, tested by points spread over them (one every half cell, edges included).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np  # noqa: TID253 - the engine is numpy through and through

if TYPE_CHECKING:
    import numpy.typing as npt

    from rosx_turtle.stage.engine.grid import Grid

    Floats = npt.NDArray[np.float64]

#: Stage's default velocity bounds of a position model: x and y (m/s), then yaw (rad/s).
MAX_SPEED = 1.0
MAX_TURN = math.pi / 2


@dataclass(frozen=True, eq=False)
class Bodies:
    """The robots' boxes: ``offset`` (x, y) of each box's centre in the robot's frame (Stage's
    ``origin``), ``half`` sizes, and ``points`` (robots, n, 2) spread over each box, in the box's
    frame (robots with fewer points repeat their last one)."""

    offset: Floats
    half: Floats
    points: Floats

    @classmethod
    def boxes(cls, sizes: Floats, offsets: Floats, spacing: float) -> Bodies:
        """Bodies of ``sizes`` (robots, 2) centred at ``offsets`` (robots, 2)."""
        clouds: list[Floats] = []
        for sx, sy in sizes:
            nx = max(2, math.ceil(sx / spacing) + 1)
            ny = max(2, math.ceil(sy / spacing) + 1)
            gx, gy = np.meshgrid(np.linspace(-sx / 2, sx / 2, nx), np.linspace(-sy / 2, sy / 2, ny))
            clouds.append(np.stack([gx.ravel(), gy.ravel()], axis=1))
        most = max((len(c) for c in clouds), default=1)
        points = np.zeros((len(clouds), most, 2))
        for k, cloud in enumerate(clouds):
            points[k, : len(cloud)] = cloud
            points[k, len(cloud) :] = cloud[-1]
        return cls(np.asarray(offsets, dtype=np.float64), np.asarray(sizes) / 2, points)

    def centres(self, x: Floats, y: Floats, yaw: Floats) -> Floats:
        """The boxes' centres (robots, 2) for robots at (x, y, yaw)."""
        cos, sin = np.cos(yaw), np.sin(yaw)
        ox, oy = self.offset[:, 0], self.offset[:, 1]
        return np.stack([x + ox * cos - oy * sin, y + ox * sin + oy * cos], axis=1)


def clip_command(
    vx: Floats, vy: Floats, w: Floats, omni: npt.NDArray[np.bool_]
) -> tuple[Floats, Floats, Floats]:
    """The commands a robot follows: Stage's bounds applied, no sideways speed unless omni."""
    return (
        np.clip(vx, -MAX_SPEED, MAX_SPEED),
        np.where(omni, np.clip(vy, -MAX_SPEED, MAX_SPEED), 0.0),
        np.clip(w, -MAX_TURN, MAX_TURN),
    )


def blocked(grid: Grid, bodies: Bodies, x: Floats, y: Floats, yaw: Floats) -> npt.NDArray[np.bool_]:
    """Which robots at (x, y, yaw) overlap a solid cell or another robot's body.

    Only the robots whose bounding circle may reach a solid cell (the grid's `Grid.room` at
    the centre tells) and the pairs whose circles overlap are tested point by point.
    """
    count = x.shape[0]
    hit = np.zeros(count, dtype=np.bool_)
    centres = bodies.centres(x, y, yaw)
    radius = np.hypot(bodies.half[:, 0], bodies.half[:, 1])
    row, col, inside = grid.cells(centres[:, 0], centres[:, 1])
    # A solid cell's point is at least the distance between the cells' centres less √2 cells.
    room = np.where(inside, grid.room[row, col] - math.sqrt(2.0), 0.0) * grid.resolution
    near = np.flatnonzero(room <= radius)
    if near.size:
        px, py = _points(bodies, centres, yaw, near)
        hit[near] = grid.solid_at(px, py).any(axis=1)
    if count > 1:
        apart = np.hypot(
            centres[:, None, 0] - centres[None, :, 0], centres[:, None, 1] - centres[None, :, 1]
        )
        close = np.triu(apart < radius[:, None] + radius[None, :], k=1)
        for a, b in zip(*np.nonzero(close), strict=True):
            if _touch(bodies, centres, yaw, int(a), int(b)):
                hit[a] = hit[b] = True
    return hit


def _points(
    bodies: Bodies, centres: Floats, yaw: Floats, which: npt.NDArray[np.intp]
) -> tuple[Floats, Floats]:
    """The world points of the bodies of robots ``which``: (robots, points) x and y."""
    cos, sin = np.cos(yaw[which])[:, None], np.sin(yaw[which])[:, None]
    local = bodies.points[which]
    px = centres[which, 0:1] + local[:, :, 0] * cos - local[:, :, 1] * sin
    py = centres[which, 1:2] + local[:, :, 0] * sin + local[:, :, 1] * cos
    return px, py


def _touch(bodies: Bodies, centres: Floats, yaw: Floats, a: int, b: int) -> bool:
    """Whether the bodies of robots ``a`` and ``b`` overlap (either's points in the other)."""
    pair = np.array([a, b])
    px, py = _points(bodies, centres, yaw, pair)
    for mine, other in ((0, 1), (1, 0)):
        k = int(pair[other])
        rx, ry = px[mine] - centres[k, 0], py[mine] - centres[k, 1]
        c, s = math.cos(yaw[k]), math.sin(yaw[k])
        u, v = rx * c + ry * s, -rx * s + ry * c
        if np.any((np.abs(u) < bodies.half[k, 0]) & (np.abs(v) < bodies.half[k, 1])):
            return True
    return False


def advance(
    grid: Grid,
    bodies: Bodies,
    pose: tuple[Floats, Floats, Floats],
    command: tuple[Floats, Floats, Floats],
    dt: float,
) -> tuple[Floats, Floats, Floats, npt.NDArray[np.bool_]]:
    """The poses after ``dt`` (robots that would collide stay put) and who is stalled."""
    x, y, yaw = pose
    vx, vy, w = command
    cos, sin = np.cos(yaw), np.sin(yaw)
    nx = x + (vx * cos - vy * sin) * dt
    ny = y + (vx * sin + vy * cos) * dt
    nyaw = np.arctan2(np.sin(yaw + w * dt), np.cos(yaw + w * dt))
    moving = (vx != 0) | (vy != 0) | (w != 0)
    stalled = blocked(grid, bodies, nx, ny, nyaw) & moving
    # A robot stopped by another frees the other's path only next step: test again once.
    if stalled.any():
        nx, ny, nyaw = (np.where(stalled, old, new) for old, new in ((x, nx), (y, ny), (yaw, nyaw)))
        again = blocked(grid, bodies, nx, ny, nyaw) & moving & ~stalled
        stalled = stalled | again
        nx, ny, nyaw = (np.where(stalled, old, new) for old, new in ((x, nx), (y, ny), (yaw, nyaw)))
    return nx, ny, nyaw, stalled


__all__ = ["MAX_SPEED", "MAX_TURN", "Bodies", "advance", "blocked", "clip_command"]
