"""Teleports: requests queued by the services, applied at the start of the next tick.

turtlesim's rules (Noetic ``Turtle::update``, first step), applied in arrival order per turtle:

* **relative** (``linear``, ``angular``): theta += angular first (not normalised here; the
  tick's integration does that), then move ``linear`` metres along the new heading;
* **absolute** (``x``, ``y``, ``theta``): x and theta are set; internal y becomes
  ``max(0, WORLD_SIZE - y)``, so a y above the world lands on the top edge silently, whereas
  x < 0, x > WORLD_SIZE or y < 0 are left to the tick's wall check (which warns);
* with the pen on, each teleport strokes a line from the new position back to the old one.

Velocities and the command time are not touched. Request values are float32, as in the
service messages.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np  # noqa: TID253 - the engine is numpy through and through

from rosx_turtle.engine.constants import WORLD_SIZE, f32
from rosx_turtle.engine.segments import Segments, pen_strokes

if TYPE_CHECKING:
    from collections.abc import Sequence

    from rosx_turtle.engine.state import Turtles


@dataclass(frozen=True)
class Teleport:
    """One queued teleport of turtle ``name``.

    Absolute: ``x``, ``y`` (world frame) and ``theta``. Relative: ``linear`` metres after
    turning by ``theta`` (the request's ``angular``).
    """

    name: str
    relative: bool
    x: float = 0.0
    y: float = 0.0
    theta: float = 0.0
    linear: float = 0.0

    @classmethod
    def absolute(cls, name: str, x: float, y: float, theta: float) -> Teleport:
        """A ``teleport_absolute`` request."""
        return cls(name, False, x=f32(x), y=f32(y), theta=f32(theta))

    @classmethod
    def by(cls, name: str, linear: float, angular: float) -> Teleport:
        """A ``teleport_relative`` request."""
        return cls(name, True, theta=f32(angular), linear=f32(linear))


def apply_teleports(turtles: Turtles, requests: Sequence[Teleport]) -> tuple[Turtles, Segments]:
    """Apply ``requests`` in order; the new state and the pen strokes they drew.

    Requests naming no turtle (killed meanwhile) are skipped. The k-th requests of all turtles
    are applied together, so a burst for many turtles costs a few array operations.
    """
    known = [r for r in requests if r.name in turtles]
    if not known:
        return turtles, Segments.empty()
    rounds: list[list[Teleport]] = []
    seen: dict[str, int] = {}
    for request in known:
        k = seen.get(request.name, 0)
        seen[request.name] = k + 1
        if k == len(rounds):
            rounds.append([])
        rounds[k].append(request)
    strokes = Segments.empty()
    for batch in rounds:
        turtles, drawn = _apply_round(turtles, batch)
        strokes = strokes + drawn
    return turtles, strokes


def _apply_round(turtles: Turtles, batch: Sequence[Teleport]) -> tuple[Turtles, Segments]:
    rows = turtles.rows([r.name for r in batch])
    relative = np.array([r.relative for r in batch])
    x_req = np.array([r.x for r in batch])
    y_req = np.array([r.y for r in batch])
    theta_req = np.array([r.theta for r in batch])
    linear = np.array([r.linear for r in batch])

    old_x, old_y = turtles.x.copy(), turtles.y.copy()
    theta = np.where(relative, turtles.theta[rows] + theta_req, theta_req)
    x = np.where(relative, turtles.x[rows] + np.cos(theta) * linear, x_req)
    y = np.where(
        relative, turtles.y[rows] + -np.sin(theta) * linear, np.maximum(0.0, WORLD_SIZE - y_req)
    )

    new_x, new_y, new_theta = turtles.x.copy(), turtles.y.copy(), turtles.theta.copy()
    new_x[rows], new_y[rows], new_theta[rows] = x, y, theta
    moved = turtles.evolve(x=new_x, y=new_y, theta=new_theta)
    draw = np.zeros(len(turtles), np.bool_)
    draw[rows] = moved.pen_on[rows]
    return moved, pen_strokes(moved, old_x, old_y, draw)
