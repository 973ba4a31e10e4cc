"""rosx rqt: the registered tools as tabs, each built when first shown; and its command line."""

from __future__ import annotations

import io
from collections.abc import Callable
from typing import Any

from textual.pilot import Pilot
from textual.widget import Widget

from rosx.graph.options import GraphOptions, Mode
from rosx_commands.context import Environment
from rosx_commands.main import run_tool
from rosx_commands.rqt.app import make_rqt_app
from rosx_commands.rqt.tabs import TABS, Tab
from rosx_commands.rqt_graph.app import GraphPane
from rosx_commands.rqt_plot.app import PlotPane
from rosx_commands.rqt_topic.app import TopicPane
from tests.support.graph_states import lab1
from tests.support.pilot import run
from tests.support.plot import StaticFeed, fill
from tests.support.rqt_sources import StaticSource
from tests.support.rqt_topics import StaticSource as StaticTopics
from tests.support.tui import SNAPSHOT_SIZE

SnapCompare = Callable[..., bool]
ENV = Environment(environ={"ROS_MASTER_URI": "http://127.0.0.1:9/"})


def static_tabs(built: list[str]) -> list[Tab]:
    """The three tools on fixed sources; ``built`` records which factories ran."""

    def graph(env: Environment) -> Widget:
        built.append("graph")
        return GraphPane(StaticSource(lab1()), GraphOptions(mode=Mode.ACTIVE))

    def plot(env: Environment) -> Widget:
        built.append("plot")
        return PlotPane(StaticFeed(), ["/turtle1/pose/x:y"])

    def topic(env: Environment) -> Widget:
        built.append("topic")
        return TopicPane(StaticTopics(), periodic=False)

    return [Tab("graph", "Graph", graph), Tab("plot", "Plot", plot), Tab("topic", "Topics", topic)]


def test_the_registry_names_each_tools_factory() -> None:
    assert [tab.name for tab in TABS][:3] == ["graph", "plot", "topic"]
    for tab in TABS:
        assert callable(tab.load()), tab


def test_tabs_are_built_when_first_shown_and_keep_their_state() -> None:
    built: list[str] = []
    app = make_rqt_app(ENV, static_tabs(built))

    async def drive() -> None:
        async with app.run_test(size=SNAPSHOT_SIZE) as pilot:
            await app.workers.wait_for_complete()
            await pilot.pause()
            assert built == ["graph"] and app.active == "graph"
            assert "t:/turtle1/cmd_vel" in app.query_one(GraphPane).drawing.boxes
            await pilot.press("f2")
            await app.workers.wait_for_complete()
            await pilot.pause()
            assert built == ["graph", "plot"] and app.active == "plot"
            plot = app.query_one(PlotPane)
            assert [s.name for s in plot.series] == ["/turtle1/pose/x", "/turtle1/pose/y"]
            await pilot.press("space")  # the plot's own key, in its tab
            assert plot.settings.paused
            await pilot.press("ctrl+pagedown")
            await pilot.pause()
            assert built == ["graph", "plot", "topic"] and app.active == "topic"
            await pilot.press("ctrl+pagedown", "ctrl+pagedown")
            await pilot.pause()
            assert app.active == "plot" and built == ["graph", "plot", "topic"]
            assert plot.settings.paused
            await pilot.press("ctrl+c")
        assert app.return_code == 0

    run(drive())


def test_snapshot_the_plot_tab(snap_compare: SnapCompare) -> None:
    app = make_rqt_app(ENV, static_tabs([]), first="plot")

    async def draw(pilot: Pilot[Any]) -> None:
        await pilot.app.workers.wait_for_complete()
        await pilot.pause()
        pane = pilot.app.query_one(PlotPane)
        for phase, series in enumerate(pane.series):
            fill(series, phase)
        pane._tick()
        await pilot.pause()

    assert snap_compare(app, terminal_size=SNAPSHOT_SIZE, run_before=draw)


def test_command_line_errors() -> None:
    for argv, error in (
        (["rqt", "-s", "nope"], "rqt: error: unknown tab 'nope' (one of: graph, plot, topic"),
        (["rqt_plot", "/pose:x"], "rqt_plot: error: /pose:x must contain a topic and field name"),
        (["rqt_plot", "--ymin", "1"], "rqt_plot: error: give both --ymin and --ymax"),
        (["rqt_plot", "/a/x"], "rqt_plot: error: the plot needs a terminal"),
        (["rqt_topic", "x"], "rqt_topic: error: unexpected argument 'x'"),
        (["rqt_topic"], "rqt_topic: error: the view needs a terminal"),
    ):
        out, err = io.StringIO(), io.StringIO()
        status = run_tool(argv, Environment(stdout=out, stderr=err, environ={}))
        assert status == 2 and error in err.getvalue(), (argv, err.getvalue())
        assert "Traceback" not in err.getvalue()
