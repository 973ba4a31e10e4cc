"""rosx rqt_plot's view, driven by pilot on a feed with a fixed clock (no network)."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import pytest
from textual.pilot import Pilot
from textual.widgets import OptionList, Static

from rosx_commands.rqt_plot.app import PlotApp, PlotSettings, make_plot_app
from tests.support.pilot import run
from tests.support.plot import StaticFeed, fill
from tests.support.tui import SNAPSHOT_SIZE

SnapCompare = Callable[..., bool]


def status(app: PlotApp) -> str:
    return str(app.query_one("#plot-status", Static).render())


def legend(app: PlotApp) -> list[str]:
    options = app.query_one("#legend", OptionList)
    return [str(options.get_option_at_index(i).prompt) for i in range(options.option_count)]


async def settle(pilot: Pilot[Any]) -> None:
    await pilot.app.workers.wait_for_complete()
    await pilot.pause()
    pane = pilot.app.pane  # type: ignore[attr-defined]
    pane._tick()  # the frame the timer would draw next
    await pilot.pause()


def three_series() -> tuple[StaticFeed, PlotApp]:
    feed = StaticFeed()
    app = make_plot_app(feed, ["/turtle1/pose/x:y", "/scan/ranges[0]"], PlotSettings(fps=1))
    return feed, app


def test_series_from_the_shorthand_are_drawn_with_a_legend() -> None:
    feed, app = three_series()

    async def drive() -> None:
        async with app.run_test(size=SNAPSHOT_SIZE) as pilot:
            await settle(pilot)
            pane = app.pane
            assert feed.attached == ["/turtle1/pose/x", "/turtle1/pose/y", "/scan/ranges[0]"]
            for phase, series in enumerate(pane.series):
                fill(series, phase)
            await settle(pilot)
            assert legend(app) == [
                "━━ /turtle1/pose/x  -0.544021",
                "━━ /turtle1/pose/y  -0.99999",
                "━━ /scan/ranges[0]  -0.536573",
            ]
            assert status(app) == " live │ window 10 s ([ ]) │ y auto"
            datasets = pane.plot._datasets
            assert len(datasets) == 3
            assert datasets[0].x[0] == 0.0 and datasets[0].x[-1] == 10.0
            assert (pane.plot._x_min, pane.plot._x_max) == (0.0, 10.0)
            assert -1.0 <= pane.plot._y_min < -0.99 and 0.99 < pane.plot._y_max <= 1.0

    run(drive())


def test_nothing_is_drawn_while_nothing_arrives_or_while_paused() -> None:
    _, app = three_series()

    async def drive() -> None:
        async with app.run_test(size=SNAPSHOT_SIZE) as pilot:
            await settle(pilot)
            pane = app.pane
            frames = pane.frames
            for _ in range(5):
                pane._tick()
            assert pane.frames == frames  # idle: no redraw
            pane.series[0].append(10.0, 3.0)
            pane._tick()
            assert pane.frames == frames + 1
            await pilot.press("space")
            assert status(app).startswith(" paused")
            pane.series[0].append(10.0, 4.0)
            pane._tick()
            assert pane.frames == frames + 1  # paused: samples kept, not drawn
            assert pane.series[0].latest == 4.0
            await pilot.press("space")
            pane._tick()
            assert pane.frames == frames + 2

    run(drive())


def test_add_remove_clear_axes_and_window_keys() -> None:
    feed, app = three_series()

    async def drive() -> None:
        async with app.run_test(size=SNAPSHOT_SIZE) as pilot:
            await settle(pilot)
            pane = app.pane
            await pilot.press("a", *"/odom/pose/pose/position/x:y", "enter")
            await settle(pilot)
            assert [s.name for s in pane.series][-2:] == [
                "/odom/pose/pose/position/x",
                "/odom/pose/pose/position/y",
            ]
            await pilot.press("a", *"/turtle1/pose", "enter")
            await settle(pilot)
            assert status(app).endswith(
                "│ /turtle1/pose is a topic (turtlesim/Pose): name a numeric field of it"
            )
            assert len(pane.series) == 5
            await pilot.press("down", "x")  # the second series goes
            await settle(pilot)
            assert feed.detached == ["/turtle1/pose/y"]
            assert [s.name for s in pane.series][:2] == ["/turtle1/pose/x", "/scan/ranges[0]"]
            fill(pane.series[0], 0.0)
            await settle(pilot)
            shown = (pane.plot._y_min, pane.plot._y_max)
            await pilot.press("s")  # fixed axes: the range autoscale had
            await settle(pilot)
            assert " │ y -0.9999…1 │" in status(app)
            pane.series[0].append(10.0, 50.0)
            await settle(pilot)
            assert (pane.plot._y_min, pane.plot._y_max) == shown
            await pilot.press("s")
            await settle(pilot)
            assert pane.plot._y_max == 50.0
            await pilot.press("left_square_bracket")
            await settle(pilot)
            assert "window 5 s" in status(app)
            assert pane.plot._x_min == 5.0
            await pilot.press("right_square_bracket", "right_square_bracket")
            assert "window 20 s" in status(app)
            await pilot.press("c")
            assert all(len(s) == 0 for s in pane.series)

    run(drive())


@pytest.mark.parametrize("key", ["q", "ctrl+c"])
def test_q_and_ctrl_c_quit_and_the_feed_is_closed(key: str) -> None:
    feed, app = three_series()

    async def drive() -> None:
        async with app.run_test(size=(80, 24)) as pilot:
            await settle(pilot)
            await pilot.press(key)
            await pilot.pause()

    run(drive())
    assert app.return_code == 0 and feed.closed


def test_snapshot_three_series(snap_compare: SnapCompare) -> None:
    _, app = three_series()

    async def draw(pilot: Pilot[Any]) -> None:
        await settle(pilot)
        for phase, series in enumerate(app.pane.series):
            fill(series, 2 * phase)
        await settle(pilot)

    assert snap_compare(app, terminal_size=SNAPSHOT_SIZE, run_before=draw)


def test_snapshot_fixed_axes_at_80x24(snap_compare: SnapCompare) -> None:
    feed = StaticFeed()
    settings = PlotSettings(window=5.0, ymin=-2.0, ymax=2.0, fps=1)
    app = make_plot_app(feed, ["/turtle1/pose/theta"], settings)

    async def draw(pilot: Pilot[Any]) -> None:
        await settle(pilot)
        fill(app.pane.series[0], 0.0)
        await settle(pilot)

    assert snap_compare(app, terminal_size=(80, 24), run_before=draw)
