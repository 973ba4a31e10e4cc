"""rosx rqt_logger_level's screen, driven by pilot over a fixed source (no network)."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import pytest
from textual.pilot import Pilot
from textual.widgets import OptionList, Static

from rosx.node.errors import ServiceError
from rosx_commands.rqt_logger_level.app import LevelApp, make_level_app
from rosx_commands.rqt_logger_level.source import level_nodes
from tests.support.pilot import run
from tests.support.tui import running_after_key

SnapCompare = Callable[..., bool]
NARROW = (80, 24)


class FixedSource:
    """Lab 1's nodes and their loggers; records what is set."""

    def __init__(self) -> None:
        self.levels = {
            "/rosout": {"rosout": "INFO", "rospy": "INFO"},
            "/teleop_turtle": {"ros": "INFO", "ros.roscpp": "INFO"},
            "/turtlesim": {"ros": "INFO", "ros.roscpp": "INFO", "ros.turtlesim": "INFO"},
        }
        self.set_calls: list[tuple[str, str, str]] = []
        self.refuse = False
        self.closed = False

    def nodes(self) -> list[str]:
        return sorted(self.levels)

    def loggers(self, node: str) -> list[tuple[str, str]]:
        return sorted(self.levels[node].items())

    def set_level(self, node: str, logger: str, level: str) -> None:
        if self.refuse:
            raise ServiceError(f"service [{node}/set_logger_level] unavailable")
        self.set_calls.append((node, logger, level))
        self.levels[node][logger] = level.upper()

    def close(self) -> None:
        self.closed = True


async def settle(pilot: Pilot[Any]) -> None:
    app = pilot.app
    for _ in range(3):
        await app.workers.wait_for_complete()
        await pilot.pause()


def status(app: LevelApp) -> str:
    return str(app.query_one("#status", Static).render())


def options(app: LevelApp, which: str) -> list[str]:
    listing = app.query_one(f"#{which}", OptionList)
    return [str(listing.get_option_at_index(i).prompt) for i in range(listing.option_count)]


def test_nodes_that_serve_both_logger_services() -> None:
    services = [
        ("/turtlesim/set_logger_level", ["/turtlesim"]),
        ("/turtlesim/get_loggers", ["/turtlesim"]),
        ("/half/set_logger_level", ["/half"]),
        ("/clear", ["/turtlesim"]),
    ]
    assert level_nodes(services) == ["/turtlesim"]


def test_node_then_logger_then_level_sets_it_through_the_service() -> None:
    source = FixedSource()
    app = make_level_app(source)

    async def drive() -> None:
        async with app.run_test(size=NARROW) as pilot:
            await settle(pilot)
            assert options(app, "nodes") == ["/rosout", "/teleop_turtle", "/turtlesim"]
            await pilot.press("end", "enter")
            await settle(pilot)
            assert options(app, "loggers") == ["ros INFO", "ros.roscpp INFO", "ros.turtlesim INFO"]
            await pilot.press("end", "enter")
            await settle(pilot)
            assert options(app, "levels") == ["  Debug", "● Info", "  Warn", "  Error", "  Fatal"]
            await pilot.press("home", "enter")
            await settle(pilot)
            assert source.set_calls == [("/turtlesim", "ros.turtlesim", "Debug")]
            assert "ros.turtlesim DEBUG" in options(app, "loggers")
            assert options(app, "levels")[0] == "● Debug"
            assert status(app) == (
                " 3 nodes │ /turtlesim ros.turtlesim │ /turtlesim ros.turtlesim set to Debug"
            )

    run(drive())


def test_a_failed_call_shows_in_full_on_the_status_line() -> None:
    source = FixedSource()
    source.refuse = True
    app = make_level_app(source)

    async def drive() -> None:
        async with app.run_test(size=NARROW) as pilot:
            await settle(pilot)
            await pilot.press("enter", "enter", "enter")
            await settle(pilot)
            assert status(app).endswith("ERROR: service [/rosout/set_logger_level] unavailable")

    run(drive())


@pytest.mark.parametrize("key", ["q", "ctrl+c"])
def test_q_and_ctrl_c_quit(key: str) -> None:
    source = FixedSource()
    app = make_level_app(source)

    running = running_after_key(app, key, settle)
    assert not running
    assert source.closed


def test_snapshot_turtlesim_loggers(snap_compare: SnapCompare) -> None:
    app = make_level_app(FixedSource())

    async def select(pilot: Pilot[Any]) -> None:
        await settle(pilot)
        await pilot.press("end", "enter", "end")
        await settle(pilot)

    assert snap_compare(app, terminal_size=NARROW, run_before=select)
