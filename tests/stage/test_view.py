"""The world drawn: pictures (pure) and stageros's terminal window (pilot)."""

from __future__ import annotations

import asyncio

import numpy as np

from rosx_turtle.stage.engine.grid import rasterise
from rosx_turtle.stage.engine.simulation import StageSim, StepReport
from rosx_turtle.stage.view.app import make_stage_app
from rosx_turtle.stage.view.picture import FLOOR, HIT, NOSE, WALL, WorldPainter, colour, laser_hits
from rosx_turtle.stage.view.widget import WorldView
from rosx_turtle.stage.world.model import build
from rosx_turtle.stage.world.worldfile import parse
from rosx_turtle.tui.feed import Feed
from tests.support.stage_worlds import room


def test_the_picture_shows_walls_floor_the_robot_its_nose_and_the_hits() -> None:
    world = build(parse(room('pose [ 0 0 0 0 ] name "r" color "green"'), "t.world"))
    grid = rasterise(world)
    sim = StageSim(world, grid)
    report = sim.step(scan_all=True)
    painter = WorldPainter(world, grid)
    painter.resize(60, 60)  # 12.4 m over 60 pixels: about 0.21 m a pixel
    image = painter.paint(report, laser_hits(report))
    colours = {tuple(int(v) for v in pixel) for pixel in image.reshape(-1, 3)}
    assert {FLOOR, WALL, HIT, NOSE, colour("green")} <= colours
    row, col, _ = painter.pixel(np.array([0.0]), np.array([0.0]))
    assert tuple(image[row[0], col[0]]) == colour("green")
    row, col, _ = painter.pixel(np.array([5.0]), np.array([0.0]))
    assert tuple(image[row[0], col[0]]) in (WALL, HIT)
    assert colour("gray30") == (76, 76, 76)


def test_the_window_draws_steps_and_poses() -> None:
    world = build(parse(room('pose [ 1 -2 0 90 ] name "era"'), "t.world"))
    grid = rasterise(world)
    sim = StageSim(world, grid)
    steps: Feed[StepReport] = Feed()

    async def drive() -> None:
        app = make_stage_app(world, grid, ("era",), steps)
        async with app.run_test(size=(80, 24)) as pilot:
            steps.offer(sim.step(scan_all=True))
            view = app.query_one(WorldView)
            for _ in range(50):
                await pilot.pause(0.05)
                if view.report is not None and str(app.query_one("#robots").render()).strip():
                    break
            assert view.frames >= 1
            assert (
                str(app.query_one("#robots").render()).strip() == "t=0.1s  era x=1.00 y=-2.00 θ=90°"
            )
            await pilot.press("q")

    asyncio.run(drive())
