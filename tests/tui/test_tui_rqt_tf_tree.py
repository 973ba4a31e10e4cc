"""rosx rqt_tf_tree: the tree's rows from a fixed buffer, then the view on a live graph."""

from __future__ import annotations

import io

import pytest
from textual.widgets import Static, Tree

from rosx.tf.core import BufferCore, FrameInfo
from rosx_commands.context import Environment
from rosx_commands.main import run_tool
from rosx_commands.rqt_tf_tree.app import TfTreeApp, TfTreePane
from rosx_commands.rqt_tf_tree.source import Row, tree_rows
from tests.support.cli import clean_environ
from tests.support.pilot import run
from tests.support.tui import SNAPSHOT_SIZE

SECOND = 1_000_000_000


def demo_core() -> BufferCore:
    """turtle_tf2's demo, plus a static laser on turtle1 and a carrot in a second tree."""
    core = BufferCore()
    for k in range(63):  # turtlesim's 62.5 Hz over a second
        stamp = 100 * SECOND + k * 16_000_000
        core.set("world", "turtle1", stamp, (5.5, 5.5, 0, 0, 0, 0, 1), "/turtle1_tf2_broadcaster")
        core.set("world", "turtle2", stamp, (4, 2, 0, 0, 0, 0, 1), "/turtle2_tf2_broadcaster")
    core.set("turtle1", "laser", 0, (0.1, 0, 0.2, 0, 0, 0, 1), "/static_publisher", True)
    core.set("island", "carrot1", 100 * SECOND, (1, 0, 0, 0, 0, 0, 1), "/carrot")
    return core


class FixedSource:
    def __init__(self, core: BufferCore) -> None:
        self.core = core
        self.closed = False

    def frames(self) -> list[FrameInfo]:
        return self.core.frames()

    def now(self) -> float:
        return 101.5

    def close(self) -> None:
        self.closed = True


def test_the_rows_are_the_trees_in_order() -> None:
    rows = tree_rows(demo_core().frames(), now=101.5)
    assert [(r.depth, r.frame) for r in rows] == [
        (0, "island"),
        (1, "carrot1"),
        (0, "world"),
        (1, "turtle1"),
        (2, "laser"),
        (1, "turtle2"),
    ]
    turtle1 = rows[3]
    assert turtle1.broadcaster == "/turtle1_tf2_broadcaster"
    assert turtle1.rate == pytest.approx(63 / 0.992)
    assert turtle1.delay is not None and abs(turtle1.delay - 0.508) < 1e-9
    assert rows[4] == Row(2, "laser", "/static_publisher", 10000.0, None, 0.0, True)


def labels(app: TfTreeApp) -> list[str]:
    tree = app.query_one(Tree)
    return [str(tree.get_node_at_line(i).label) for i in range(tree.last_line + 1)]  # type: ignore[union-attr]


def test_the_pane_draws_the_tree_with_rates_and_delays() -> None:
    core = demo_core()
    source = FixedSource(core)
    app = TfTreeApp(TfTreePane(source, periodic=False))

    async def drive() -> None:
        async with app.run_test(size=SNAPSHOT_SIZE) as pilot:
            await app.workers.wait_for_complete()
            await pilot.pause()
            assert labels(app) == [
                "island",
                "carrot1  /carrot  10000.00 Hz  delay 1.500 s  buffer 0.00 s",
                "world",
                "turtle1  /turtle1_tf2_broadcaster  63.51 Hz  delay 0.508 s  buffer 0.99 s",
                "laser  /static_publisher  static",
                "turtle2  /turtle2_tf2_broadcaster  63.51 Hz  delay 0.508 s  buffer 0.99 s",
            ]
            status = str(app.query_one("#tf-status", Static).render())
            assert status == " 4 frames, 2 trees (not connected)"
            core.set("world", "island", 0, (0, 0, 0, 0, 0, 0, 1), "/joiner", True)
            app.pane.refresh_frames()
            await app.workers.wait_for_complete()
            await pilot.pause()
            assert [label.split()[0] for label in labels(app)] == [
                "world", "island", "carrot1", "turtle1", "laser", "turtle2",
            ]  # fmt: skip
            assert str(app.query_one("#tf-status", Static).render()) == " 5 frames, 1 tree"
            await pilot.press("q")
        assert source.closed

    run(drive())


def test_without_a_terminal_it_says_so() -> None:
    out, err = io.StringIO(), io.StringIO()
    env = Environment(stdout=out, stderr=err, environ=clean_environ())
    assert run_tool(["rqt_tf_tree"], env) == 2
    assert err.getvalue() == "rqt_tf_tree: error: the view needs a terminal\n"


def test_the_live_view_shows_the_sims_tf_demo() -> None:
    from rosx_commands.rqt_tf_tree.source import LiveTfSource
    from rosx_turtle.sim.host import SimHost
    from tests.support.procs import free_port

    host = SimHost(free_port(), {"ROS_IP": "127.0.0.1"}, watch=False, tf_demo=True).start()
    try:
        env = Environment(environ={**clean_environ(), "ROS_MASTER_URI": host.master_uri})
        app = TfTreeApp(TfTreePane(LiveTfSource(env), periodic=False))

        async def drive() -> None:
            async with app.run_test(size=SNAPSHOT_SIZE) as pilot:
                for _ in range(200):  # up to 20 s for the frames to arrive
                    app.pane.refresh_frames()
                    await app.workers.wait_for_complete()
                    await pilot.pause(0.1)
                    if len(labels(app)) == 3:
                        break
                assert [label.split()[:2] for label in labels(app)] == [
                    ["world"],
                    ["turtle1", "/turtle1_tf2_broadcaster"],
                    ["turtle2", "/turtle2_tf2_broadcaster"],
                ]
                await pilot.press("q")

        run(drive())
    finally:
        host.stop()
