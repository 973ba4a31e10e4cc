"""`Simulation`: the turtle pond as turtlesim runs it, with no I/O, no clock and no ROS.

It owns the `Turtles`, the trail `Canvas`, the queue of teleports and the name counter, and
offers what turtlesim's callbacks do (spawn, kill, reset, clear, commands, pens, teleports)
plus `tick`, one 16 ms step for every turtle at once:

1. queued teleports are applied (their pen strokes drawn at once);
2. commands older than a second (by the ``now`` the caller passes) are dropped, the turtles
   move one fixed step and are clamped at the walls (`rosx_turtle.engine.motion`);
3. each colour sensor reads the canvas under its turtle, **before** this tick's trails;
4. every turtle that moved with its pen on draws its trail from where it was.

All turtles take each phase together, so where turtlesim updates one turtle after another a
turtle's sensor does not see the trail another turtle drew in the same tick.

Naming follows turtlesim: an empty name takes ``"turtle" + counter`` after incrementing it,
skipping names in use; kill never lowers the counter and only `reset` sets it back to 0. The
caller checks names for ROS validity; the engine accepts any string. Not thread-safe: one
thread calls everything (turtlesim runs its callbacks on its timer thread, between ticks).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np  # noqa: TID253 - the engine is numpy through and through

from rosx_turtle.engine.canvas import Canvas
from rosx_turtle.engine.constants import (
    CENTRE,
    DEFAULT_BACKGROUND,
    FRESH_PEN_WIDTH,
    SPRITE_COUNT,
    WORLD_SIZE,
    f32,
)
from rosx_turtle.engine.motion import WallHits, advance
from rosx_turtle.engine.segments import Segments, pen_strokes
from rosx_turtle.engine.state import Turtles
from rosx_turtle.engine.teleports import Teleport, apply_teleports

if TYPE_CHECKING:
    from collections.abc import Sequence

    import numpy.typing as npt

    F32 = npt.NDArray[np.float32]


class NameTakenError(ValueError):
    """A spawn asked for the name of a turtle that exists."""


@dataclass(frozen=True, eq=False)
class TickReport:
    """What one tick produced, row for row with ``turtles`` (sorted by name).

    The pose arrays are float32, as ``turtlesim/Pose`` carries them: ``x`` and ``y`` in the world
    frame (y up), ``theta``, ``linear_velocity`` (never negative) and ``angular_velocity``.
    ``colours`` (n, 3) are the colour sensors' readings; ``walls`` the turtles that hit a wall;
    ``strokes`` every pen stroke drawn this tick; ``changed`` whether anything moved, turned or
    teleported (turtlesim repaints only then).
    """

    turtles: Turtles
    x: F32
    y: F32
    theta: F32
    linear_velocity: F32
    angular_velocity: F32
    colours: npt.NDArray[np.uint8]
    walls: WallHits
    strokes: Segments
    changed: bool

    def pose(self, row: int) -> tuple[float, float, float, float, float]:
        """The pose of the turtle in ``row``: x, y, theta, linear and angular velocity."""
        return (
            float(self.x[row]),
            float(self.y[row]),
            float(self.theta[row]),
            float(self.linear_velocity[row]),
            float(self.angular_velocity[row]),
        )


class Simulation:
    """turtlesim's state and rules; see the module docstring.

    Args:
        background: The canvas colour to start with.
        seed: Seeds the choice of sprites (None: unpredictable, as turtlesim's ``rand()``).
    """

    def __init__(
        self, background: Sequence[int] = DEFAULT_BACKGROUND, *, seed: int | None = None
    ) -> None:
        self.turtles = Turtles.empty()
        self.canvas = Canvas(background)
        self.counter = 0
        self.teleports: list[Teleport] = []
        self._rng = np.random.default_rng(seed)

    def __contains__(self, name: object) -> bool:
        return name in self.turtles

    # -- the pond's services ---------------------------------------------------------------

    def spawn(self, x: float, y: float, theta: float, name: str = "") -> str:
        """Add a turtle at world (``x``, ``y``) heading ``theta``; its name.

        Values are taken as float32, as the ``Spawn`` request holds them, and not clamped: a
        turtle outside the world hits the wall on its first tick.

        Raises:
            NameTakenError: ``name`` is given and in use.
        """
        if name:
            if name in self.turtles:
                raise NameTakenError(name)
        else:
            while True:
                self.counter += 1
                name = f"turtle{self.counter}"
                if name not in self.turtles:
                    break
        x, y = f32(x), f32(y)
        sprite = int(self._rng.integers(SPRITE_COUNT))
        self.turtles = self.turtles.with_turtle(name, x, f32(WORLD_SIZE - y), f32(theta), sprite)
        return name

    def kill(self, name: str) -> bool:
        """Remove turtle ``name`` and its queued teleports; False if there is none."""
        if name not in self.turtles:
            return False
        self.turtles = self.turtles.without(name)
        self.teleports = [t for t in self.teleports if t.name != name]
        return True

    def clear(self, background: Sequence[int]) -> None:
        """Erase every trail: fill the canvas with ``background`` (each channel taken mod 256)."""
        self.canvas.fill([channel & 0xFF for channel in background])

    def reset(self, background: Sequence[int]) -> str:
        """Remove every turtle, set the counter to 0, spawn turtle1 at the centre, clear."""
        self.turtles = Turtles.empty()
        self.teleports = []
        self.counter = 0
        name = self.spawn(CENTRE, CENTRE, 0.0)
        self.clear(background)
        return name

    # -- per-turtle input ------------------------------------------------------------------

    def command(self, name: str, vx: float, vy: float, w: float, now: float) -> bool:
        """A cmd_vel for ``name`` received at wall time ``now``: it replaces the last one."""
        row = self.turtles.row(name)
        if row is None:
            return False
        t = self.turtles
        vxs, vys, ws, times = t.vx.copy(), t.vy.copy(), t.w.copy(), t.last_command.copy()
        vxs[row], vys[row], ws[row], times[row] = vx, vy, w, now
        self.turtles = t.evolve(vx=vxs, vy=vys, w=ws, last_command=times)
        return True

    def set_pen(self, name: str, r: int, g: int, b: int, width: int, off: int) -> bool:
        """``set_pen``: off keeps colour and width; on takes the colour, width 0 meaning 1 px."""
        row = self.turtles.row(name)
        if row is None:
            return False
        t = self.turtles
        pen_on = t.pen_on.copy()
        pen_on[row] = not off
        if off:
            self.turtles = t.evolve(pen_on=pen_on)
            return True
        rgb, widths = t.pen_rgb.copy(), t.pen_width.copy()
        rgb[row] = (r & 0xFF, g & 0xFF, b & 0xFF)
        widths[row] = width if width else FRESH_PEN_WIDTH
        self.turtles = t.evolve(pen_on=pen_on, pen_rgb=rgb, pen_width=widths)
        return True

    def teleport_absolute(self, name: str, x: float, y: float, theta: float) -> bool:
        """Queue a jump to world (``x``, ``y``) heading ``theta``, for the next tick."""
        if name not in self.turtles:
            return False
        self.teleports.append(Teleport.absolute(name, x, y, theta))
        return True

    def teleport_relative(self, name: str, linear: float, angular: float) -> bool:
        """Queue a turn by ``angular`` then a move of ``linear`` metres, for the next tick."""
        if name not in self.turtles:
            return False
        self.teleports.append(Teleport.by(name, linear, angular))
        return True

    # -- time ------------------------------------------------------------------------------

    def tick(self, now: float) -> TickReport:
        """One step of every turtle; ``now`` is the wall-clock time for the command timeout."""
        start = self.turtles
        jumped = any(request.name in start for request in self.teleports)
        teleported, jumps = apply_teleports(start, self.teleports)
        self.teleports = []
        self.canvas.draw(jumps)
        moved, walls = advance(teleported, now)
        colours = self.canvas.sample(moved.x, moved.y)
        shifted = (moved.x != teleported.x) | (moved.y != teleported.y)
        trails = pen_strokes(moved, teleported.x, teleported.y, shifted & moved.pen_on)
        self.canvas.draw(trails)
        self.turtles = moved
        changed = jumped or bool(shifted.any()) or bool((moved.theta != start.theta).any())
        return TickReport(
            turtles=moved,
            x=moved.x.astype(np.float32),
            y=moved.world_y.astype(np.float32),
            theta=moved.theta.astype(np.float32),
            linear_velocity=np.sqrt(moved.vx * moved.vx + moved.vy * moved.vy).astype(np.float32),
            angular_velocity=moved.w.astype(np.float32),
            colours=colours,
            walls=walls,
            strokes=jumps + trails,
            changed=changed,
        )
