"""rosx rqt_topic's view: pilot and snapshots on a fixed source, then a live turtlesim."""

from __future__ import annotations

import time
from collections.abc import Callable
from typing import Any

import pytest
from textual.pilot import Pilot
from textual.widgets import Static

from rosx.msg.codec.classes import get_message_class
from rosx_commands.context import Environment
from rosx_commands.rqt_topic.app import TopicApp, TopicTree, make_topic_app
from rosx_commands.rqt_topic.monitor import (
    MAX_ITEMS,
    Field,
    LiveTopicSource,
    Reading,
    bytes_per_second,
    fields,
)
from rosx_turtle.sim.host import SimHost
from tests.support.pilot import run
from tests.support.rqt_topics import LAB1_TOPICS, StaticSource
from tests.support.tui import SNAPSHOT_SIZE

SnapCompare = Callable[..., bool]


def rows(app: TopicApp) -> list[str]:
    tree = app.query_one(TopicTree)
    return [str(tree.get_node_at_line(i).label) for i in range(tree.last_line + 1)]  # type: ignore[union-attr]


async def settle(pilot: Pilot[Any]) -> None:
    await pilot.app.workers.wait_for_complete()
    await pilot.pause()


def test_fields_of_a_message_nest_and_cap_arrays() -> None:
    scan = get_message_class("sensor_msgs/LaserScan")(ranges=[0.5] * (MAX_ITEMS + 3))
    scan.header.stamp.secs = 7
    tree = {field.name: field for field in fields(scan)}
    header = tree["header"]
    assert header.value == "" and [f.name for f in header.children] == ["seq", "stamp", "frame_id"]
    assert header.children[1].children == (Field("secs", "7"), Field("nsecs", "0"))
    assert header.children[2] == Field("frame_id", "''")
    ranges = tree["ranges"]
    assert ranges.value == f"[{MAX_ITEMS + 3} items]"
    assert ranges.children[0] == Field("[0]", "0.5")
    assert ranges.children[-1] == Field("… 3 more")
    assert tree["intensities"] == Field("intensities", "[]")
    assert [bytes_per_second(v) for v in (None, 12.0, 1250.0, 2.5e6)] == [
        "",
        "12.00B/s",
        "1.25KB/s",
        "2.50MB/s",
    ]


def test_monitoring_a_topic_shows_its_figures_and_latest_message() -> None:
    source = StaticSource()
    app = make_topic_app(source, periodic=False)

    async def drive() -> None:
        async with app.run_test(size=SNAPSHOT_SIZE) as pilot:
            await settle(pilot)
            assert [r.split()[1] for r in rows(app)] == [t for t, _ in LAB1_TOPICS]
            await pilot.press("end", "space")
            await settle(pilot)
            assert source.watching == ["/turtle1/pose"]
            app.pane.update_readings()
            await pilot.pause()
            assert rows(app)[-1].split() == [
                "☑",
                "/turtle1/pose",
                "turtlesim/Pose",
                "1.25KB/s",
                "62.50",
            ]
            await pilot.press("enter")
            await pilot.pause()
            assert rows(app)[-5:] == [
                "x: 5.54444",
                "y: 5.54444",
                "theta: 0",
                "linear_velocity: 2",
                "angular_velocity: 0",
            ]
            status = str(app.query_one("#topic-status", Static).render())
            assert status.startswith(" 5 topics, 1 monitored")
            source.list.remove(("/turtle1/pose", "turtlesim/Pose"))  # the topic goes away
            app.pane.refresh_topics()
            await settle(pilot)
            assert len(rows(app)) == 4 and source.watching == []
            await pilot.press("q")
        assert source.closed

    run(drive())


def test_ctrl_c_quits() -> None:
    app = make_topic_app(StaticSource(), periodic=False)

    async def drive() -> None:
        async with app.run_test(size=(80, 24)) as pilot:
            await settle(pilot)
            await pilot.press("ctrl+c")
            await pilot.pause()

    run(drive())
    assert app.return_code == 0


def test_snapshot_a_monitored_topic_expanded(snap_compare: SnapCompare) -> None:
    app = make_topic_app(StaticSource(), periodic=False)

    async def expand(pilot: Pilot[Any]) -> None:
        await settle(pilot)
        await pilot.press("end", "space")
        await settle(pilot)
        app.pane.update_readings()
        await pilot.press("enter")
        await pilot.pause()

    assert snap_compare(app, terminal_size=SNAPSHOT_SIZE, run_before=expand)


def test_live_turtlesim_pose_rate_and_value(host: SimHost) -> None:
    source = LiveTopicSource(Environment(environ={"ROS_MASTER_URI": host.master_uri}))
    app = make_topic_app(source, periodic=False)

    async def drive() -> None:
        async with app.run_test(size=(120, 40)) as pilot:
            # Generous deadlines: a loaded machine starts, connects and ticks slowly.
            deadline = time.monotonic() + 60
            while "/turtle1/pose" not in app.pane.types:
                assert time.monotonic() < deadline
                app.pane.refresh_topics()
                await settle(pilot)
            app.pane.toggle("/turtle1/pose")
            await settle(pilot)
            reading = Reading()
            deadline = time.monotonic() + 60
            while reading.rate is None or reading.bandwidth is None or reading.count < 60:
                assert time.monotonic() < deadline, reading
                await pilot.pause(0.2)
                app.pane.update_readings()
                reading = app.pane.readings["/turtle1/pose"]
            # How fast poses come depends on the machine's load (turtlesim ticks fewer times a
            # second when busy); the figures are measured in bench/, here they only show.
            assert reading.rate > 0 and reading.bandwidth > 0
            assert reading.message.x == pytest.approx(5.544445)  # type: ignore[attr-defined]

    run(drive())
    assert source._node is None
