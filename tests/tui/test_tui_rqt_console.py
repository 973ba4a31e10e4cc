"""rosx rqt_console's screen, driven by pilot over a fixed source (no network, no timer)."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import pytest
from textual.pilot import Pilot
from textual.widgets import Static

from rosx.master.client import MasterUnreachable
from rosx_commands.rqt_console.app import ConsoleApp, make_console_app
from rosx_commands.rqt_console.model import Entry, Kind, Rule, Rules
from rosx_commands.rqt_console.source import Inbox
from tests.support.pilot import run
from tests.support.tui import running_after_key

SnapCompare = Callable[..., bool]
NARROW = (80, 24)
WIDE = (120, 40)
WALL = "Oh no! I hit the wall! (Clamping from [x=11.120889, y=5.544445])"


pytestmark = pytest.mark.usefixtures("utc")  # times shown as UTC


class FixedSource:
    """Entries a test puts in; start fails when told to."""

    def __init__(self, entries: list[Entry] = (), error: BaseException | None = None) -> None:  # type: ignore[assignment]
        self.inbox = Inbox()
        for entry in entries:
            self.inbox.put(entry)
        self.error = error
        self.closed = False

    def start(self) -> str:
        if self.error is not None:
            raise self.error
        return "/rosout_agg at http://localhost:11311/"

    def close(self) -> None:
        self.closed = True


TOPICS = ("/rosout", "/turtle1/pose", "/turtle1/color_sensor", "/turtle1/cmd_vel")


def lab1_log() -> list[Entry]:
    """What Lab 1's turtlesim logs, then a drive into the wall, then a few debug lines."""
    start = 1_700_000_000.25
    entries = [
        Entry(start, 2, "/turtlesim", "Starting turtlesim with node name /turtlesim", TOPICS),
        Entry(
            start + 0.1,
            2,
            "/turtlesim",
            "Spawning turtle [turtle1] at x=[5.544445], y=[5.544445], theta=[0.000000]",
            TOPICS,
            "turtle_frame.cpp:TurtleFrame:99",
        ),
    ]
    for i in range(6):
        entries.append(
            Entry(start + 3 + i * 0.016, 4, "/turtlesim", WALL, TOPICS, "turtle.cpp:update:193")
        )
    for i in range(4):
        entries.append(
            Entry(
                start + 4 + i * 0.016,
                1,
                "/turtlesim",
                f"[turtle1]: pos_x: 11.088889 pos_y: 5.544445 theta: {i}.000000",
                TOPICS,
            )
        )
    entries.append(
        Entry(
            start + 5,
            8,
            "/teleop_turtle",
            "could not read from the keyboard",
            ("/rosout", "/turtle1/cmd_vel"),
        )
    )
    return entries


async def settle(pilot: Pilot[Any]) -> None:
    app = pilot.app
    assert isinstance(app, ConsoleApp)
    await pilot.pause()
    app.pane.ingest()
    await pilot.pause()
    await pilot.pause()


def status(app: ConsoleApp) -> str:
    return str(app.query_one("#status", Static).render())


def rows(app: ConsoleApp) -> list[str]:
    return app.pane.table.visible_text()


def test_records_show_as_rows_and_repeats_fold() -> None:
    app = make_console_app(FixedSource(lab1_log()), period=None)

    async def drive() -> None:
        async with app.run_test(size=NARROW) as pilot:
            await settle(pilot)
            assert status(app).startswith(" 8 of 8 messages │ /rosout_agg at http://")
            shown = rows(app)
            assert shown[0].split() == ["Time", "Severity", "Node", "Message"]
            assert shown[1].startswith("22:13:20.250 Info     /turtlesim       Starting turtl")
            assert shown[3] == (
                "22:13:23.330 Warn     /turtlesim       (6 times) Oh no! I hit the wall! (Clampi…"
            )
            assert len(shown[3]) == 80

    run(drive())


def test_wide_terminals_show_topics_and_location() -> None:
    app = make_console_app(FixedSource(lab1_log()), period=None)

    async def drive() -> None:
        async with app.run_test(size=WIDE) as pilot:
            await settle(pilot)
            header = rows(app)[0].split()
            assert header == ["Time", "Severity", "Node", "Message", "Topics", "Location"]
            assert rows(app)[3].endswith(
                "hit the wall! (Cl… /rosout, /turtle1/p… turtle.cpp:update:193"
            )

    run(drive())


def test_rules_from_keys_include_exclude_highlight_and_undo() -> None:
    app = make_console_app(FixedSource(lab1_log()), period=None)

    async def drive() -> None:
        async with app.run_test(size=NARROW) as pilot:
            await settle(pilot)
            await pilot.press("x", *"severity:debug", "enter")
            await pilot.pause()
            assert status(app).startswith(" 4 of 8 messages │ exclude severity:debug │")
            await pilot.press("i", *"node:turtlesim", "enter")
            await pilot.pause()
            assert " 3 of 8 messages │ exclude severity:debug; include node:turtlesim" in status(
                app
            )
            await pilot.press("h", *"wall", "enter")
            await pilot.pause()
            table = app.pane.table
            assert table.rules.highlights(app.pane.entries.shown(2))
            await pilot.press("u", "u")
            await pilot.pause()
            assert status(app).startswith(" 4 of 8 messages │ exclude severity:debug │")
            await pilot.press("r")
            await pilot.pause()
            assert status(app).startswith(" 8 of 8 messages │ /rosout_agg")

    run(drive())


def test_a_bad_rule_is_said_and_the_line_stays_open() -> None:
    app = make_console_app(FixedSource(lab1_log()), period=None)

    async def drive() -> None:
        async with app.run_test(size=NARROW) as pilot:
            await settle(pilot)
            await pilot.press("i", *"severity:loud", "enter")
            await pilot.pause()
            assert "ERROR: unknown severity 'loud'" in status(app)
            assert app.query_one("#rule").has_class("editing")
            await pilot.press("escape")
            assert not app.query_one("#rule").has_class("editing")

    run(drive())


def test_selection_shows_details_and_escape_follows_again() -> None:
    app = make_console_app(FixedSource(lab1_log()), period=None)

    async def drive() -> None:
        async with app.run_test(size=NARROW) as pilot:
            await settle(pilot)
            await pilot.press("home", "down", "down")
            await pilot.pause()
            text = str(app.query_one("#details", Static).render())
            assert text.splitlines()[:5] == [
                "Node: /turtlesim",
                "Time: 1700000003.330000 (2023-11-14 22:13:23)",
                "Severity: Warn (6 times)",
                "Published Topics: /rosout, /turtle1/pose, /turtle1/color_sensor, /turtle1/cmd_vel",
                "Location: turtle.cpp:update:193",
            ]
            assert not app.pane.table.follow
            await pilot.press("escape")
            await pilot.pause()
            assert app.pane.table.cursor is None and app.pane.table.follow
            assert not app.query_one("#details").has_class("open")

    run(drive())


def test_pause_holds_new_records_and_clear_empties() -> None:
    source = FixedSource(lab1_log())
    app = make_console_app(source, period=None)

    async def drive() -> None:
        async with app.run_test(size=NARROW) as pilot:
            await settle(pilot)
            await pilot.press("p")
            source.inbox.put(Entry(1_700_000_010.0, 2, "/late", "while paused"))
            await settle(pilot)
            assert " 8 of 8 messages │ PAUSED (1 waiting)" in status(app)
            await pilot.press("p")
            await pilot.pause()
            assert status(app).startswith(" 9 of 9 messages")
            assert "while paused" in rows(app)[-1] or any("while paused" in r for r in rows(app))
            await pilot.press("c")
            await pilot.pause()
            assert status(app).startswith(" 0 of 0 messages")

    run(drive())


def test_a_failed_start_shows_the_whole_error_at_80_columns() -> None:
    error = MasterUnreachable("http://localhost:11311/", "[Errno 111] Connection refused")
    app = make_console_app(FixedSource(error=error), period=None)

    async def drive() -> None:
        async with app.run_test(size=NARROW) as pilot:
            await settle(pilot)
            assert status(app) == " 0 of 0 messages │ ERROR: Unable to communicate with master!"

    run(drive())


@pytest.mark.parametrize("key", ["q", "ctrl+c"])
def test_q_and_ctrl_c_quit(key: str) -> None:
    source = FixedSource(lab1_log())
    app = make_console_app(source, period=None)

    running = running_after_key(app, key, settle)
    assert not running
    assert source.closed


def test_100_000_entries_scroll_and_filter() -> None:
    entries = [
        Entry(1_700_000_000 + i / 1000, (1, 2, 4, 8, 16)[i % 5], f"/node{i % 7}", f"record {i}")
        for i in range(100_000)
    ]
    app = make_console_app(FixedSource(entries), period=None)

    async def drive() -> None:
        async with app.run_test(size=NARROW) as pilot:
            await settle(pilot)
            assert status(app).startswith(" 100000 of 100000 messages")
            assert rows(app)[-1].endswith("record 99999")
            app.pane.add_rule(Rule.parse(Kind.INCLUDE, "node:/node3$"))
            await pilot.pause()
            assert status(app).startswith(" 14286 of 100000 messages")
            await pilot.press("home")
            await pilot.pause()
            assert "record 3" in rows(app)[1]

    run(drive())


def test_snapshot_narrow_with_a_highlight_and_a_selection(snap_compare: SnapCompare) -> None:
    rules = Rules().with_rule(Rule.parse(Kind.HIGHLIGHT, "wall"))
    app = make_console_app(FixedSource(lab1_log()), rules, period=None)

    async def select(pilot: Pilot[Any]) -> None:
        await settle(pilot)
        await pilot.press("home", "down")
        await pilot.pause()

    assert snap_compare(app, terminal_size=NARROW, run_before=select)


def test_snapshot_wide(snap_compare: SnapCompare) -> None:
    rules = Rules().with_rule(Rule.parse(Kind.EXCLUDE, "severity:debug"))
    app = make_console_app(FixedSource(lab1_log()), rules, period=None)
    assert snap_compare(app, terminal_size=WIDE, run_before=settle)
