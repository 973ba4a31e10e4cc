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
    """Which robots at (x, y, yaw) overlap a solid cell or another robot's body."""
    centres = bodies.centres(x, y, yaw)
    cos, sin = np.cos(yaw)[:, None], np.sin(yaw)[:, None]
    px = centres[:, 0:1] + bodies.points[:, :, 0] * cos - bodies.points[:, :, 1] * sin
    py = centres[:, 1:2] + bodies.points[:, :, 0] * sin + bodies.points[:, :, 1] * cos
    hit = np.asarray(grid.solid_at(px, py).any(axis=1), dtype=np.bool_)
    count = x.shape[0]
    if count > 1:
        # Every robot's points in every other robot's box frame: (robots, others, points).
        rx = px[:, None, :] - centres[None, :, 0:1]
        ry = py[:, None, :] - centres[None, :, 1:2]
        c, s = np.cos(yaw)[None, :, None], np.sin(yaw)[None, :, None]
        u = rx * c + ry * s
        v = -rx * s + ry * c
        half = bodies.half[None, :, :]
        inside = (np.abs(u) < half[:, :, 0:1]) & (np.abs(v) < half[:, :, 1:2])
        touching = np.asarray(inside.any(axis=2), dtype=np.bool_)
        touching[np.arange(count), np.arange(count)] = False
        hit = hit | touching.any(axis=1) | touching.any(axis=0)
    return hit


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
