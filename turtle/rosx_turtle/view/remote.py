"""`RemotePond`: a turtlesim's pond rebuilt from what it publishes, for a viewer elsewhere.

A turtlesim node publishes, for every turtle and every tick, ``<turtle>/pose`` and
``<turtle>/color_sensor`` (the canvas colour under the turtle, read after the tick's trail is
drawn). That is enough to draw the pond again without being the simulator:

* each turtle is where its last pose says;
* a trail runs from one pose to the next in the colour the sensor reports there, 3 px wide
  (turtlesim's default pen); when the sensor shows the background, the pen is off (or nothing
  was drawn) and no trail is added;
* a jump farther than a turtle can move in a tick (a teleport, ``/reset``) draws nothing.

What the topics do not carry is not shown: a pen's width, trails drawn before the viewer
started, and ``/clear`` (the trails stay until the view restarts). The background is the
node's ``background_r/g/b`` parameters, read by whoever builds the pond.

Thread-safe: poses and colours arrive on subscription threads, `scene` is read from another.
"""

from __future__ import annotations

import math
import threading
from typing import TYPE_CHECKING

import numpy as np  # noqa: TID253 - the view is array work; only the viewer imports it

from rosx_turtle.engine.canvas import Canvas
from rosx_turtle.engine.constants import DEFAULT_BACKGROUND, DEFAULT_PEN_WIDTH, METER_PX
from rosx_turtle.engine.segments import Segments
from rosx_turtle.view.scene import WORLD_SIZE, Scene, TurtlePose

if TYPE_CHECKING:
    from collections.abc import Sequence

#: Farther than this between two poses (metres) is a jump, not a move: turtlesim moves a turtle
#: at most a few centimetres a tick at the speeds teleop and mimic use.
JUMP = 1.0


class RemotePond:
    """One turtlesim's pond as its topics show it (see the module docstring)."""

    def __init__(self, background: Sequence[int] = DEFAULT_BACKGROUND) -> None:
        self.background: tuple[int, int, int] = (
            int(background[0]),
            int(background[1]),
            int(background[2]),
        )
        self._canvas = Canvas(self.background)
        self._poses: dict[str, TurtlePose] = {}
        self._colours: dict[str, tuple[int, int, int]] = {}
        self._lock = threading.Lock()
        self._scene: Scene | None = None
        self._dirty = True

    @property
    def dirty(self) -> bool:
        """Whether something changed since the last `scene`."""
        return self._dirty

    def set_colour(self, turtle: str, rgb: tuple[int, int, int]) -> None:
        """The colour sensor of ``turtle`` read ``rgb``."""
        with self._lock:
            self._colours[turtle] = rgb

    def set_pose(self, turtle: str, pose: TurtlePose) -> None:
        """``turtle`` is at ``pose``; a trail joins it to the last pose when its pen drew."""
        with self._lock:
            last = self._poses.get(turtle)
            self._poses[turtle] = pose
            self._dirty = True
            colour = self._colours.get(turtle)
            if last is None or colour is None or colour == self.background:
                return
            if math.hypot(pose.x - last.x, pose.y - last.y) > JUMP:
                return
            if (pose.x, pose.y) == (last.x, last.y):
                return
            stroke = Segments(
                np.array([pose.x * METER_PX]),
                np.array([(WORLD_SIZE - pose.y) * METER_PX]),
                np.array([last.x * METER_PX]),
                np.array([(WORLD_SIZE - last.y) * METER_PX]),
                np.array([colour], np.uint8),
                np.array([DEFAULT_PEN_WIDTH], np.int32),
            )
            self._canvas.draw(stroke)

    def forget(self, turtle: str) -> None:
        """``turtle`` is gone (killed): stop drawing it; its trails stay."""
        with self._lock:
            self._poses.pop(turtle, None)
            self._colours.pop(turtle, None)
            self._dirty = True

    @property
    def turtles(self) -> list[str]:
        """The turtles seen, by name."""
        with self._lock:
            return sorted(self._poses)

    def scene(self) -> Scene:
        """The pond now (the same object again while nothing changed)."""
        with self._lock:
            if self._scene is None or self._dirty:
                turtles = tuple(self._poses[name] for name in sorted(self._poses))
                self._scene = Scene(
                    self._canvas.snapshot(), self._canvas.version, self.background, turtles
                )
                self._dirty = False
            return self._scene


__all__ = ["JUMP", "RemotePond"]
