"""rosx rqt_graph's live view, driven by pilot on static graphs (no network, no timer)."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from textual.pilot import Pilot
from textual.widgets import Static

from rosx.graph.options import GraphOptions, Mode
from rosx.graph.state import GraphState
from rosx.graph.view import Vertex
from rosx_commands.rqt_graph.app import GraphApp, make_graph_app
from tests.graph.states import lab1
from tests.tui.conftest import SNAPSHOT_SIZE, run

SnapCompare = Callable[..., bool]


class StaticSource:
    """A graph that changes only when a test says so."""

    def __init__(self, state: GraphState) -> None:
        self.state = state
        self.closed = False

    def snapshot(self) -> GraphState:
        return self.state

    def describe(self, vertex: Vertex) -> str:
        return f"Node [{vertex.label}]" if vertex.kind == "node" else f"Type: x ({vertex.label})"

    def rate(self, topic: str) -> str:
        return "average rate: 10.000 Hz"

    def close(self) -> None:
        self.closed = True


def status(app: GraphApp) -> str:
    return str(app.query_one("#status", Static).render())


async def settle(pilot: Pilot[Any]) -> None:
    await pilot.app.workers.wait_for_complete()
    await pilot.pause()


def test_refresh_marks_what_vanished_and_selection_shows_details() -> None:
    source = StaticSource(lab1())
    app = make_graph_app(source, GraphOptions(mode=Mode.ACTIVE))

    async def drive() -> None:
        async with app.run_test(size=SNAPSHOT_SIZE) as pilot:
            await settle(pilot)
            assert "t:/turtle1/cmd_vel" in app.drawing.boxes
            assert "Nodes/Topics (active) │ 2 nodes, 1 topics" in status(app)
            source.state = lab1(teleop_connected=False)
            await pilot.press("r")
            await settle(pilot)
            assert "changed: - /turtle1/cmd_vel" in status(app)
            await pilot.press("tab")
            await settle(pilot)
            assert app.selected == "n:/teleop_turtle"
            assert "Node [/teleop_turtle]" in str(app.query_one("#info", Static).render())
            await pilot.press("m")
            await settle(pilot)
            assert app.options.mode is Mode.ALL
        assert source.closed

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
