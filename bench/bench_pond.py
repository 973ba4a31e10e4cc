"""The pond view's frame rate while a turtle moves: target 30 frames/s or more.

turtlesim draws with Qt, so there is no ROS 1 figure to set against this one; the target is
the one in DESIGN.md. Two figures per terminal size, each over ``--frames`` frames in which
turtle1 drives a circle with its pen on (1.5 m/s, 1 rad/s) and the engine steps
``--ticks-per-frame`` ticks between frames (4 by default, so every frame shows a move):

* **renderer**: the view's own work per frame: scene from the engine, shrinking the trail
  bands that changed, drawing the sprites, repainting the rows that changed and turning them
  into textual strips (what `PondView.render_line` returns); and the same with every row
  redrawn (**full**: as after a resize or a ``/clear``);
* **app**: the whole textual app, headless, fed one scene per frame through its `Feed` and
  waited on until the frame is on its screen (message, render, compositor, headless driver),
  with textual's cap on repaints (``TEXTUAL_FPS``, 60) lifted; a terminal shows
  min(this figure, the cap) frames a second.

    python bench/bench_pond.py [--frames 300] [--ticks-per-frame 4]
"""

from __future__ import annotations

import argparse
import asyncio
import os
import sys
import time
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
sys.path[:0] = [str(ROOT), str(ROOT / "turtle")]
# textual repaints at most TEXTUAL_FPS times a second (60 by default): lift the cap to measure
# what the pond could do; on a real terminal the frame rate is min(this figure, the cap).
os.environ.setdefault("TEXTUAL_FPS", "1000")

TARGET_FPS = 30.0
SIZES = ((80, 24), (120, 40), (200, 60), (320, 90))


class Driver:
    """turtle1 on a circle, the engine stepped by hand with a fixed clock."""

    def __init__(self, ticks_per_frame: int) -> None:
        from rosx_turtle.engine import Simulation
        from rosx_turtle.engine.constants import DEFAULT_BACKGROUND
        from rosx_turtle.view.adapt import SceneMaker

        self.sim = Simulation(seed=1)
        self.sim.reset(DEFAULT_BACKGROUND)
        self.maker = SceneMaker()
        self.ticks = ticks_per_frame
        self.now = 0.0

    def step(self) -> None:
        for _ in range(self.ticks):
            self.now += 0.016
            self.sim.command("turtle1", 1.5, 0.0, 1.0, self.now)
            self.sim.tick(self.now)

    def scene(self) -> Any:
        return self.maker.make(self.sim)

    def next_scene(self) -> Any:
        self.step()
        return self.scene()


def renderer_fps(size: tuple[int, int], frames: int, ticks: int, *, full: bool = False) -> float:
    from textual.strip import Strip

    from rosx_turtle.view.renderer import PondRenderer

    driver = Driver(ticks)
    renderer = PondRenderer()
    renderer.resize(*size)
    renderer.update(driver.next_scene())
    spent = 0.0
    for _ in range(frames):
        driver.step()  # the engine's ticks are not the view's work
        start = time.perf_counter()
        if full:
            renderer.resize(*size)
        rows = renderer.update(driver.scene())
        strips = [Strip(renderer.line(y), size[0]) for y in rows]
        spent += time.perf_counter() - start
        assert len(strips) == len(rows)
    return frames / spent


async def app_fps(size: tuple[int, int], frames: int, ticks: int) -> float:
    from rosx_turtle.tui.factory import make_pond_app
    from rosx_turtle.tui.feed import Feed
    from rosx_turtle.tui.pond import PondView

    driver = Driver(ticks)
    scenes: Feed[Any] = Feed(driver.next_scene())
    app = make_pond_app(scenes)
    async with app.run_test(size=size) as pilot:
        await pilot.pause()
        pond = app.query_one(PondView)
        shown: list[Any] = []
        display = app._display

        def counting_display(screen: Any, update: Any) -> None:
            display(screen, update)
            shown.append(pond.renderer.scene)

        app._display = counting_display  # type: ignore[method-assign, assignment]
        start = time.perf_counter()
        for _ in range(frames):
            scene = driver.next_scene()
            scenes.offer(scene)
            while not shown or shown[-1] is not scene:  # until this frame is on the screen
                await asyncio.sleep(0)
        elapsed = time.perf_counter() - start
    return frames / elapsed


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--frames", type=int, default=300)
    parser.add_argument("--ticks-per-frame", type=int, default=4)
    options = parser.parse_args()
    print(f"pond view, {options.frames} frames, turtle1 moving (target >= {TARGET_FPS:.0f}/s)")
    print(f"{'terminal':>10} {'pond px':>8} {'renderer':>9} {'full':>6} {'app':>6}  (frames/s)")
    from rosx_turtle.view.fit import fit_square

    for width, height in SIZES:
        side = fit_square(width, height).side
        size, frames, ticks = (width, height), options.frames, options.ticks_per_frame
        render = renderer_fps(size, frames, ticks)
        full = renderer_fps(size, frames, ticks, full=True)
        app = asyncio.run(app_fps(size, frames, ticks))
        verdict = "ok" if min(render, full, app) >= TARGET_FPS else "MISSED"
        print(
            f"{width:>5}x{height:<4} {side:>8} {render:>9.0f} {full:>6.0f} {app:>6.0f}  {verdict}"
        )


if __name__ == "__main__":
    main()
