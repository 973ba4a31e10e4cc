"""`Scene`: what the pond view draws, one immutable value per simulation tick.

A scene is the trail canvas (turtlesim's 500x500 RGB image, row 0 at the top of the world) and
each turtle's pose. The view never looks inside the simulator: whoever hosts it turns the
simulator's state into a scene (`rosx_turtle.view.adapt`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    import numpy as np
    import numpy.typing as npt

    Canvas = npt.NDArray[np.uint8]

#: Side of the square world in metres: (500 - 1) / 45, as turtlesim computes it.
WORLD_SIZE = 499 / 45
#: Side of the trail canvas in pixels.
CANVAS_SIZE = 500


@dataclass(frozen=True)
class TurtlePose:
    """One turtle as the view sees it: world metres (origin bottom-left), heading CCW from +x."""

    name: str
    x: float
    y: float
    theta: float
    linear_velocity: float = 0.0
    angular_velocity: float = 0.0
    #: Which sprite the simulator picked for it (-1: let the name decide).
    sprite: int = -1


@dataclass(frozen=True, eq=False)
class Scene:
    """The pond at one tick.

    Attributes:
        canvas: ``(500, 500, 3)`` uint8 RGB trails over the background; never changed after the
            scene is made (a copy of the simulator's canvas).
        canvas_version: Differs between two scenes whose canvases may differ; equal versions
            promise equal canvases, so the view skips comparing them.
        background: The colour the canvas was last cleared with (trails are what differs).
        turtles: The turtles, drawn in this order (turtlesim draws them by name).
    """

    canvas: Canvas
    canvas_version: int
    background: tuple[int, int, int]
    turtles: tuple[TurtlePose, ...]
