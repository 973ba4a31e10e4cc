"""Scenes from the simulator: `SceneMaker` for a `Simulation`, `follow` for a running node.

Poses are float32, as ``turtlesim/Pose`` carries them. The canvas is copied only when its
version changed. The background (what the last ``/clear`` or ``/reset`` filled the canvas with)
is not part of the simulator's state, so it is read off the canvas: the most common colour on a
sparse grid of pixels, re-read only when the canvas changes and kept unless a clear majority of
the grid disagrees (trails alone never cover most of the pond).

`SceneMaker` runs on the simulator's thread, between ticks (the engine is not thread-safe); the
scenes it returns own their data and may be read on any thread afterwards.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np  # noqa: TID253 - the view is array work; only the TUI imports it

from rosx_turtle.view.scene import Scene, TurtlePose

if TYPE_CHECKING:
    from collections.abc import Callable

    from rosx_turtle.engine import Simulation, TickReport
    from rosx_turtle.node.turtlesim import TurtlesimNode
    from rosx_turtle.view.scene import Canvas

#: Pixels per side of the grid the background is read from.
_GRID = 16
#: Share of the grid a new colour must cover to be taken as the new background.
_MAJORITY = 0.5


def background_of(canvas: Canvas, current: tuple[int, int, int] | None) -> tuple[int, int, int]:
    """The canvas's background: ``current`` unless most of a grid of samples says otherwise."""
    step = max(canvas.shape[0] // _GRID, 1)
    samples = canvas[step // 2 :: step, step // 2 :: step].reshape(-1, 3)
    colours, counts = np.unique(samples, axis=0, return_counts=True)
    best = int(np.argmax(counts))
    if current is not None and counts[best] <= _MAJORITY * len(samples):
        return current
    r, g, b = (int(channel) for channel in colours[best])
    return r, g, b


class SceneMaker:
    """Makes scenes of one simulation; `make` returns the last scene again if nothing changed."""

    def __init__(self) -> None:
        self._version = -1
        self._canvas: Canvas | None = None
        self._background: tuple[int, int, int] | None = None
        self._last: Scene | None = None

    def make(self, simulation: Simulation) -> Scene:
        """The pond as ``simulation`` holds it now."""
        canvas = simulation.canvas
        if self._canvas is None or canvas.version != self._version:
            self._canvas = canvas.snapshot()
            self._version = canvas.version
            self._background = background_of(self._canvas, self._background)
        assert self._background is not None
        turtles = simulation.turtles
        x = turtles.x.astype(np.float32).tolist()
        y = turtles.world_y.astype(np.float32).tolist()
        theta = turtles.theta.astype(np.float32).tolist()
        speed = np.hypot(turtles.vx, turtles.vy).astype(np.float32).tolist()
        turn = turtles.w.astype(np.float32).tolist()
        sprites = turtles.sprite.tolist()
        poses = tuple(
            TurtlePose(name, x[row], y[row], theta[row], speed[row], turn[row], sprites[row])
            for row, name in enumerate(turtles.names)
        )
        last = self._last
        if (
            last is not None
            and last.canvas is self._canvas
            and last.turtles == poses
            and last.background == self._background
        ):
            return last
        self._last = Scene(self._canvas, self._version, self._background, poses)
        return self._last


def follow(node: TurtlesimNode, offer: Callable[[Scene], object]) -> Callable[[], None]:
    """Call ``offer(scene)`` after the next tick of ``node``, then after each that changes it.

    ``offer`` runs on the node's tick thread: it must be quick (hand the scene to a `Feed`).
    Returns a function that stops following.
    """
    maker = SceneMaker()
    offered: list[Scene] = []

    def tick(report: TickReport) -> None:
        scene = maker.make(node.sim)
        if not offered or scene is not offered[0]:
            offered[:] = [scene]
            offer(scene)

    return node.add_tick_listener(tick)
