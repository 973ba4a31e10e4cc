"""Motion for one tick, over all turtles at once: command timeout, integration, walls.

turtlesim's per-turtle update (``Turtle::update`` in Noetic), vectorised; the order is theirs:

1. a command older than `COMMAND_TIMEOUT` seconds of wall time (strictly) is dropped: vx, vy and
   w become 0 (a turtle that was never commanded has ``last_command`` 0, so it rests);
2. semi-implicit Euler with the fixed step: theta first, normalised into [-PI, PI) with
   turtlesim's ``PI``, then the position moves along the **new** heading, ``vy`` sideways
   (Noetic applies ``linear.y`` always); internal y points down, so it decreases;
3. a turtle outside [0, WORLD_SIZE] on either axis (strictly) is reported in a `WallHits`
   with its internal coordinates before clamping (the warning's quirk: y from the top), then
   clamped onto the edge. Velocities stay, so a turtle pushing on a wall hits it every tick.

Pure functions: `Turtles` in, `Turtles` out, no clock (the caller passes ``now``).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np  # noqa: TID253 - the engine is numpy through and through

from rosx_turtle.engine.constants import COMMAND_TIMEOUT, DT, PI, WORLD_SIZE

if TYPE_CHECKING:
    import numpy.typing as npt

    from rosx_turtle.engine.state import Turtles

    F64 = npt.NDArray[np.float64]


def wall_warning(x: float, y: float) -> str:
    """turtlesim's warning for a turtle at internal (``x``, ``y``) outside the world."""
    return f"Oh no! I hit the wall! (Clamping from [x={x:f}, y={y:f}])"


@dataclass(frozen=True, eq=False)
class WallHits:
    """The turtles that ended a tick outside the world, before they were clamped.

    ``rows`` index the tick's `Turtles`; ``x`` and ``y`` are internal coordinates (y from the
    top), exactly what turtlesim's warning prints.
    """

    rows: npt.NDArray[np.intp]
    x: F64
    y: F64

    def __len__(self) -> int:
        return len(self.rows)

    def messages(self) -> list[str]:
        """One warning text per hit, in row (name) order."""
        return [wall_warning(float(x), float(y)) for x, y in zip(self.x, self.y, strict=True)]


def expire_commands(turtles: Turtles, now: float) -> Turtles:
    """Stop the turtles whose last command is more than `COMMAND_TIMEOUT` s older than ``now``."""
    stale = (now - turtles.last_command) > COMMAND_TIMEOUT
    if not stale.any():
        return turtles
    return turtles.evolve(
        vx=np.where(stale, 0.0, turtles.vx),
        vy=np.where(stale, 0.0, turtles.vy),
        w=np.where(stale, 0.0, turtles.w),
    )


def normalize_angle(theta: F64) -> F64:
    """``theta`` wrapped into [-PI, PI) the way turtlesim does it."""
    result: F64 = theta - 2 * PI * np.floor((theta + PI) / (2 * PI))
    return result


def integrate(turtles: Turtles, dt: float = DT) -> Turtles:
    """One semi-implicit Euler step: heading first, then position along the new heading."""
    theta = normalize_angle(turtles.theta + turtles.w * dt)
    cos, sin = np.cos(theta), np.sin(theta)
    vx, vy = turtles.vx, turtles.vy
    x = turtles.x + (cos * vx * dt - sin * vy * dt)
    y = turtles.y - (cos * vy * dt + sin * vx * dt)
    return turtles.evolve(theta=theta, x=x, y=y)


def clamp_to_walls(turtles: Turtles) -> tuple[Turtles, WallHits]:
    """Clamp every turtle into the world; the ones that were outside, as `WallHits`."""
    x, y = turtles.x, turtles.y
    outside = (x < 0) | (x > WORLD_SIZE) | (y < 0) | (y > WORLD_SIZE)
    rows = np.flatnonzero(outside)
    hits = WallHits(rows, x[rows], y[rows])
    if not len(rows):
        return turtles, hits
    clamped = turtles.evolve(x=np.clip(x, 0.0, WORLD_SIZE), y=np.clip(y, 0.0, WORLD_SIZE))
    return clamped, hits


def advance(turtles: Turtles, now: float, dt: float = DT) -> tuple[Turtles, WallHits]:
    """Timeout, integration and walls for one tick (steps 2 to 4 of turtlesim's update)."""
    return clamp_to_walls(integrate(expire_commands(turtles, now), dt))
