"""Lab 1 with rqt_console and rqt_logger_level, end to end: a headless turtlesim driven into
the wall with Twist messages, its warning found in rqt_console's table; then its logger set to
debug with rqt_logger_level, and its debug lines found in rqt_console.

Both screens run under pilot against the live graph (``rosx sim``'s world without a screen:
master, ``/rosout``, ``/turtlesim``, ``/teleop_turtle``), through the sources the CLI uses.
"""

from __future__ import annotations

import time
from collections.abc import Iterator

import pytest
from textual.pilot import Pilot
from textual.widgets import OptionList

from rosx_commands.context import Environment
from rosx_commands.rqt_console.app import ConsoleApp, make_console_app
from rosx_commands.rqt_console.source import LiveSource as ConsoleSource
from rosx_commands.rqt_logger_level.app import make_level_app
from rosx_commands.rqt_logger_level.source import LiveSource as LevelSource
from rosx_turtle.sim.host import SimHost
from tests.support.pilot import run
from tests.support.procs import free_port

WALL = "Oh no! I hit the wall!"
DEADLINE = 20.0


@pytest.fixture
def world() -> Iterator[SimHost]:
    host = SimHost(free_port(), {}, seed=4, watch=False).start()
    try:
        yield host
    finally:
        host.stop()


async def drive_until(pilot: Pilot[int], host: SimHost, text: str, severity: str) -> str:
    """Drive the turtle forward until a row of ``severity`` holding ``text`` shows; the row."""
    app = pilot.app
    assert isinstance(app, ConsoleApp)
    deadline = time.monotonic() + DEADLINE
    while time.monotonic() < deadline:
        host.drive(2.0, 0.0)
        await pilot.pause(0.05)
        for row in app.pane.table.visible_text():
            if text in row and f" {severity} " in row:
                return str(row)
    raise AssertionError(f"no {severity} row with {text!r} in {app.pane.table.visible_text()}")


def test_the_wall_warning_then_debug_lines_after_setting_the_level(world: SimHost) -> None:
    env = Environment(environ={"ROS_MASTER_URI": world.master_uri})

    async def wall() -> None:
        app = make_console_app(ConsoleSource(env, world.master_uri))
        async with app.run_test(size=(120, 40)) as pilot:
            row = await drive_until(pilot, world, WALL, "Warn")
            assert "/turtlesim" in row
            assert "/rosout, /turtle1/" in row  # the topics column of a wide terminal
            assert not any(" Debug " in r for r in app.pane.table.visible_text())

    async def set_debug() -> None:
        source = LevelSource(world.master_uri)
        app = make_level_app(source)
        async with app.run_test(size=(80, 24)) as pilot:
            nodes = app.query_one("#nodes", OptionList)
            deadline = time.monotonic() + DEADLINE
            while nodes.option_count < 3 and time.monotonic() < deadline:
                await pilot.pause(0.05)
            names = [str(nodes.get_option_at_index(i).prompt) for i in range(nodes.option_count)]
            assert "/turtlesim" in names
            nodes.highlighted = names.index("/turtlesim")
            await pilot.press("enter")
            loggers = app.query_one("#loggers", OptionList)
            while app.pane.level_of("ros.turtlesim") is None and time.monotonic() < deadline:
                await pilot.pause(0.05)
            assert app.pane.level_of("ros.turtlesim") == "INFO"
            logger_names = [name for name, _ in app.pane.logger_levels]
            loggers.highlighted = logger_names.index("ros.turtlesim")
            await pilot.press("enter", "home", "enter")
            while app.pane.level_of("ros.turtlesim") != "DEBUG" and time.monotonic() < deadline:
                await pilot.pause(0.05)
            assert app.pane.level_of("ros.turtlesim") == "DEBUG"

    async def debug_lines() -> None:
        app = make_console_app(ConsoleSource(env, world.master_uri))
        async with app.run_test(size=(80, 24)) as pilot:
            row = await drive_until(pilot, world, "pos_x:", "Debug")
            assert "/turtlesim" in row

    run(wall())
    run(set_debug())
    run(debug_lines())
