"""rosx rqt_graph's live view, driven by pilot on static graphs (no network, no timer)."""

from __future__ import annotations

import asyncio
import dataclasses
import time
from collections.abc import Callable
from typing import Any

import pytest
from textual.pilot import Pilot
from textual.widgets import Input

from rosx.graph.options import GraphOptions, Mode
from rosx.graph.state import GraphState
from rosx.graph.view import ViewGraph
from rosx_commands.rqt_graph.app import GHOST_SECONDS, History, make_graph_app
from rosx_commands.rqt_graph.view import GraphView
from tests.support.graph_pilot import WIDE, info, mark_at, settle, status
from tests.support.graph_states import lab1
from tests.support.pilot import run
from tests.support.rqt_sources import StaticSource
from tests.support.tui import SNAPSHOT_SIZE, running_after_key

SnapCompare = Callable[..., bool]


def test_refresh_marks_what_vanished_and_selection_shows_details() -> None:
    source = StaticSource(lab1())
    app = make_graph_app(source, GraphOptions(mode=Mode.ACTIVE))

    async def drive() -> None:
        async with app.run_test(size=WIDE) as pilot:
            await settle(pilot)
            assert "t:/turtle1/cmd_vel" in app.drawing.boxes
            assert "Nodes/Topics (active) │ 2 nodes, 1 topics" in status(app)
            assert mark_at(app, "/turtle1/cmd_vel") is None
            source.state = lab1(teleop_connected=False)
            await pilot.press("r")
            await settle(pilot)
            assert "2 nodes, 0 topics │ changed: - /turtle1/cmd_vel" in status(app)
            # what vanished is still drawn, faded, with its edges
            assert "t:/turtle1/cmd_vel" in app.drawing.boxes
            assert mark_at(app, "/turtle1/cmd_vel") == "vanished"
            assert mark_at(app, "▶") == "vanished"
            await pilot.press("r")  # the same graph again: the marks stay
            await settle(pilot)
            assert mark_at(app, "/turtle1/cmd_vel") == "vanished"
            await pilot.press("tab")
            await settle(pilot)
            assert app.selected == "n:/teleop_turtle"
            assert "Node [/teleop_turtle]" in info(app)
            await pilot.press("tab")
            await settle(pilot)
            assert app.selected == "t:/turtle1/cmd_vel"
            assert info(app) == "/turtle1/cmd_vel: gone"
            source.state = lab1()
            await pilot.press("r")
            await settle(pilot)
            assert "changed: + /turtle1/cmd_vel" in status(app)
            assert mark_at(app, "/turtle1/cmd_vel") == "selected"
            await pilot.press("m")
            await settle(pilot)
            assert app.options.mode is Mode.ALL
            assert "changed" not in status(app)  # a new view, not a change
        assert source.closed

    run(drive())


def test_what_appears_is_marked_and_a_selection_lights_its_edges() -> None:
    source = StaticSource(lab1(teleop_connected=False))
    app = make_graph_app(source, GraphOptions(mode=Mode.ACTIVE, group_depth=0))

    async def drive() -> None:
        async with app.run_test(size=WIDE) as pilot:
            await settle(pilot)
            source.state = lab1()
            await pilot.press("r")
            await settle(pilot)
            assert "changed: + /turtle1/cmd_vel" in status(app)
            assert mark_at(app, "/turtle1/cmd_vel") == "appeared"
            assert mark_at(app, "─────▶") == "appeared"
            assert mark_at(app, "/turtlesim") == "node"
            await pilot.press("shift+tab")  # backwards from nothing: the last one
            await settle(pilot)
            assert app.selected == "n:/turtlesim"
            assert mark_at(app, "/turtlesim") == "selected"
            assert mark_at(app, "─────▶", 0) == "appeared"
            assert mark_at(app, "─────▶", 1) == "linked"
            assert "Node [/turtlesim]" in info(app)

    run(drive())


def test_filters_and_namespace_groups_are_keys() -> None:
    source = StaticSource(lab1())
    app = make_graph_app(source, GraphOptions(mode=Mode.ACTIVE))

    async def drive() -> None:
        async with app.run_test(size=WIDE) as pilot:
            await settle(pilot)
            assert [f.namespace for f in app.drawing.frames] == ["/turtle1"]
            await pilot.press("g")  # 2 -> 3 -> 0
            await settle(pilot)
            await pilot.press("g")
            await settle(pilot)
            assert app.options.group_depth == 0
            assert app.drawing.frames == ()
            await pilot.press("n")
            line = app.query_one("#filter", Input)
            assert line.has_focus and line.value == "/"
            await pilot.press("backspace", *"-/teleop_turtle", "enter")
            await settle(pilot)
            assert app.options.namespace_filter == "-/teleop_turtle"
            assert set(app.drawing.boxes) == {"n:/turtlesim", "t:/turtle1/cmd_vel"}
            assert "Nodes/Topics (active) │ 1 nodes, 1 topics" in status(app)
            await pilot.press("t")
            await pilot.press("backspace", *"(", "enter")
            await settle(pilot)
            assert "ERROR: bad filter '('" in status(app)
            assert line.has_focus and app.options.topic_filter == "/"
            await pilot.press("escape")
            assert app.query_one(GraphView).has_focus
            await pilot.press("n", "ctrl+u", "enter")  # empty: everything, as rqt_graph's "/"
            await settle(pilot)
            assert app.options.namespace_filter == "/"
            assert "t:/turtle1/cmd_vel" in app.drawing.boxes
            assert "ERROR" not in status(app)

    run(drive())


def chain(nodes: int) -> GraphState:
    """``/n0 -> /t0 -> /n1 -> /t1 -> ...``, each topic with a second, parallel subscriber."""
    pubs = {f"/t{i}": (f"/n{i}",) for i in range(nodes - 1)}
    subs = {f"/t{i}": (f"/n{i + 1}", f"/side{i}") for i in range(nodes - 1)}
    return GraphState(pubs, subs)


def test_the_view_pans_over_a_drawing_larger_than_the_screen() -> None:
    app = make_graph_app(StaticSource(chain(40)), GraphOptions(mode=Mode.ALL))

    async def drive() -> None:
        async with app.run_test(size=SNAPSHOT_SIZE) as pilot:
            await settle(pilot)
            view = app.query_one(GraphView)
            lines = app.drawing.lines
            width = max(map(len, lines))
            assert width > 1000
            assert (view.virtual_size.width, view.virtual_size.height) == (width, len(lines))
            for keys in ([], ["end"], ["right"] * 30, ["pagedown"], ["home"]):
                await pilot.press(*keys)
                await pilot.pause()
                x, y = view.scroll_offset
                seen = view.visible_text()
                w = view.scrollable_content_region.width
                expected = [line[x : x + w].ljust(w) for line in lines[y : y + len(seen)]]
                expected += [" " * w] * (len(seen) - len(expected))
                assert seen == expected, keys
            assert view.scroll_offset == (0, 0)

    run(drive())


def test_snapshot_active_mode_with_a_topic_selected(snap_compare: SnapCompare) -> None:
    app = make_graph_app(StaticSource(lab1()), GraphOptions(mode=Mode.ACTIVE))

    async def select(pilot: Pilot[Any]) -> None:
        await settle(pilot)
        await pilot.press("tab", "tab")
        await settle(pilot)

    assert snap_compare(app, terminal_size=SNAPSHOT_SIZE, run_before=select)


def test_snapshot_nodes_only(snap_compare: SnapCompare) -> None:
    app = make_graph_app(StaticSource(lab1()))
    assert snap_compare(app, terminal_size=SNAPSHOT_SIZE, run_before=settle)


def test_snapshot_a_vanished_topic_drawn_faded(snap_compare: SnapCompare) -> None:
    source = StaticSource(lab1())
    app = make_graph_app(source, GraphOptions(mode=Mode.ACTIVE))

    async def vanish(pilot: Pilot[Any]) -> None:
        await settle(pilot)
        source.state = lab1(teleop_connected=False)
        await pilot.press("r")
        await settle(pilot)

    assert snap_compare(app, terminal_size=SNAPSHOT_SIZE, run_before=vanish)


class SlowSource(StaticSource):
    """Takes longer to read than the view's period; counts how often it is read."""

    def __init__(self, state: GraphState, delay: float) -> None:
        super().__init__(state)
        self.delay = delay
        self.reads = 0

    def snapshot(self) -> GraphState:
        self.reads += 1
        time.sleep(self.delay)
        return self.state


def test_timer_refreshes_do_not_pile_up_behind_a_slow_one() -> None:
    source = SlowSource(lab1(), delay=0.5)
    app = make_graph_app(source, GraphOptions(mode=Mode.ACTIVE), period=0.05)

    async def drive() -> None:
        started = time.monotonic()  # before the first read, which the app starts as it mounts
        async with app.run_test(size=WIDE) as pilot:
            deadline = started + 60
            while source.reads < 3 and time.monotonic() < deadline:
                await asyncio.sleep(0.05)
            # Piled up, each period (0.05 s) would start a read: the third within 0.1 s of the
            # first. One at a time, each read takes 0.5 s: the third starts 1 s after the first
            # or later (a loaded machine only makes them later).
            assert 3 <= source.reads <= (time.monotonic() - started) / source.delay + 1
            await settle(pilot)
            assert "t:/turtle1/cmd_vel" in app.drawing.boxes

    run(drive())


def test_the_details_panel_opens_with_a_selection_and_escape_closes_it() -> None:
    app = make_graph_app(StaticSource(lab1()), GraphOptions(mode=Mode.ACTIVE))

    async def drive() -> None:
        async with app.run_test(size=SNAPSHOT_SIZE) as pilot:
            await settle(pilot)
            details = app.query_one("#details")
            view = app.query_one(GraphView)
            assert not details.display
            assert view.size.width == SNAPSHOT_SIZE[0]  # the drawing has the whole width
            await pilot.press("tab")
            await settle(pilot)
            assert details.display and view.size.width < SNAPSHOT_SIZE[0] - 30
            assert "Node [/teleop_turtle]" in info(app)
            await pilot.press("escape")
            await pilot.pause()
            assert app.selected is None and not details.display
            assert mark_at(app, "/teleop_turtle") == "node"

    run(drive())


def test_what_vanished_is_labelled_gone_and_dropped_after_a_while() -> None:
    history = History().after(ViewGraph(), now=0.0)
    before = lab1()
    source = StaticSource(before)
    app = make_graph_app(source, GraphOptions(mode=Mode.ACTIVE))

    async def drive() -> None:
        async with app.run_test(size=WIDE) as pilot:
            await settle(pilot)
            source.state = lab1(teleop_connected=False)
            await pilot.press("r")
            await settle(pilot)
            text = "\n".join(app.query_one(GraphView).visible_text())
            assert "/turtle1/cmd_vel (gone)" in text

    run(drive())
    graph = app.graph
    assert graph is not None
    shown = history.after(graph, now=1.0)
    teleop_gone = dataclasses.replace(graph, vertices=graph.vertices[1:], edges=())
    changed = shown.after(teleop_gone, now=2.0)
    assert changed.ghosts.vertices and changed.changes
    assert changed.after(teleop_gone, now=2.0 + GHOST_SECONDS - 0.1).ghosts.vertices
    dropped = changed.after(teleop_gone, now=2.0 + GHOST_SECONDS)
    assert not dropped.ghosts.vertices and not dropped.changes


def test_a_failed_refresh_shows_the_whole_error_at_80_columns() -> None:
    class Unreachable(StaticSource):
        def snapshot(self) -> GraphState:
            raise OSError(
                "cannot connect to http://localhost:11311/: [Errno 111] Connection refused"
            )

    app = make_graph_app(Unreachable(lab1()))

    async def drive() -> None:
        async with app.run_test(size=(80, 24)) as pilot:
            await settle(pilot)
            status_line = app.query_one("#status")
            error = (
                "ERROR: cannot connect to http://localhost:11311/: [Errno 111] Connection refused"
            )
            assert str(status_line.render()).endswith(error)
            assert status_line.size.height == 2  # wrapped, not cut at 80 columns

    run(drive())


@pytest.mark.parametrize("key", ["q", "ctrl+c"])
def test_q_and_ctrl_c_quit(key: str) -> None:
    app = make_graph_app(StaticSource(lab1()))

    running = running_after_key(app, key, settle)
    assert not running
