"""rosx rviz on a master: each tool's message as ``rostopic echo`` shows it, in the fixed frame;
scans and tf from other nodes drawn, with rviz's statuses."""

from __future__ import annotations

import asyncio
import math
import threading
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

from rosx.node import Node
from rosx.tf.broadcaster import StaticTransformBroadcaster
from rosx_commands.context import Environment
from rosx_commands.rviz.app import RvizApp
from rosx_commands.rviz.run import live_app
from tests.support.cli import Result, clean_environ, rosx
from tests.support.pilot import run
from tests.support.rviz import config, message, scan

DEADLINE = 30.0


def echo_in_thread(topic: str, environ: dict[str, str]) -> Callable[[], Result | None]:
    """``rostopic echo -n 1 TOPIC`` on a thread; the function gives its result once done."""
    results: list[Result] = []
    thread = threading.Thread(
        target=lambda: results.append(rosx("rostopic", "echo", "-n", "1", topic, environ=environ)),
        daemon=True,
    )
    thread.start()
    return lambda: results[0] if results else None


async def until(predicate: Callable[[], object], what: str) -> None:
    deadline = time.monotonic() + DEADLINE
    while not predicate():
        if time.monotonic() > deadline:
            raise TimeoutError(f"timed out waiting for {what}")
        await asyncio.sleep(0.05)


def a_live_app(master: str, tmp_path: Path, *displays: str, fixed: str = "odom") -> RvizApp:
    env = Environment(environ=clean_environ(ROS_MASTER_URI=master, HOME=str(tmp_path)))
    return live_app(env, config(*displays, fixed=fixed), None, tmp_path / "saved.rviz")


def test_each_tool_is_heard_by_rostopic_echo_in_the_fixed_frame(
    master: str, tmp_path: Path
) -> None:
    environ = clean_environ(ROS_MASTER_URI=master)
    app = a_live_app(master, tmp_path, "{Class: rviz/Grid, Name: Grid}")
    keys = {"/move_base_simple/goal": "g", "/initialpose": "p", "/clicked_point": "c"}
    heard: dict[str, Result | None] = {}

    async def drive() -> None:
        async with app.run_test(size=(100, 30)) as pilot:
            await pilot.press("left_square_bracket", "left_square_bracket")  # 30° left
            for topic, key in keys.items():  # one echo at a time, as a user would
                echo = echo_in_thread(topic, environ)
                deadline = time.monotonic() + DEADLINE
                # rostopic connects when it connects: place the tool until it has heard one.
                while echo() is None and time.monotonic() < deadline:
                    await pilot.press(key, "enter")
                    await until(lambda: not app.pane.workers, "the publishing worker")
                    await asyncio.sleep(0.1)
                heard[topic] = echo()

    run(drive())
    goal, pose, point = (heard[topic] for topic in keys)
    assert goal is not None and pose is not None and point is not None
    z, w = math.sin(math.radians(15)), math.cos(math.radians(15))
    assert goal.status == 0
    assert (
        'frame_id: "odom"\npose: \n  position: \n    x: 0.0\n    y: 0.0\n    z: 0.0\n' in goal.out
    )
    assert f"    z: {z}\n    w: {w}\n---\n" in goal.out
    assert 'frame_id: "odom"\npose: \n  pose: \n    position: \n      x: 0.0' in pose.out
    assert "covariance: [0.25, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.25, " in pose.out
    assert ", 0.06853891945200942]\n---\n" in pose.out
    assert 'frame_id: "odom"\npoint: \n  x: 0.0\n  y: 0.0\n  z: 0.0\n---\n' in point.out


def test_a_scan_and_tf_from_other_nodes_are_drawn(
    master: str, tmp_path: Path, make_node: Callable[..., Node]
) -> None:
    app = a_live_app(
        master,
        tmp_path,
        "{Class: rviz/LaserScan, Name: Scan, Topic: /scan}",
        "{Class: rviz/TF, Name: TF}",
        "{Class: rviz/Map, Name: Map, Topic: /map}",
    )
    node = make_node("/robot")
    statics = StaticTransformBroadcaster(node=node)
    link: Any = message("geometry_msgs/TransformStamped", "odom", child_frame_id="laser")
    link.transform.rotation.w = 1.0
    statics.sendTransform(link)
    publisher = node.advertise("/scan", type(scan()), queue_size=1)

    def panel() -> list[str]:
        return [line for line, _ in app.panel.lines]

    async def drive() -> None:
        async with app.run_test(size=(100, 30)) as pilot:
            await until(lambda: "  ✓ OK (2 frames)" in panel(), "tf's frames")
            await until(lambda: publisher.get_num_connections() > 0, "rviz's subscription")
            publisher.publish(scan())
            await until(
                lambda: (
                    "Showing [179] points from [1] messages"
                    in " ".join(line.strip(" ✓") for line in panel())
                ),
                "the scan drawn",
            )
            await pilot.pause()
            assert "  ⚠ No messages received" in panel()  # the map: nobody publishes it

    run(drive())


def test_under_simulated_time_a_goal_is_stamped_with_the_clock(tmp_path: Path) -> None:
    from rosx.core import Core
    from rosx.msg.codec.classes import get_message_class

    with Core(0, {"ROS_IP": "127.0.0.1"}) as core:
        clock_node = Node("/simulator", master_uri=core.uri, environ={}).start()
        try:
            clock_node.params.set("/use_sim_time", True)
            clock_class = get_message_class("rosgraph_msgs/Clock")
            clock = clock_node.advertise("/clock", clock_class, queue_size=1, latch=True)
            tick: Any = clock_class()
            tick.clock.secs, tick.clock.nsecs = 4242, 500
            clock.publish(tick)
            environ = clean_environ(ROS_MASTER_URI=core.uri)
            app = a_live_app(core.uri, tmp_path, "{Class: rviz/Grid, Name: Grid}")
            heard: list[Result | None] = []

            async def drive() -> None:
                async with app.run_test(size=(100, 30)) as pilot:
                    source: Any = app.pane.source
                    await until(
                        lambda: source.manager is not None and source.stamp().secs == 4242,
                        "rviz's ROS time to be the simulator's",
                    )
                    echo = echo_in_thread("/move_base_simple/goal", environ)
                    deadline = time.monotonic() + DEADLINE
                    while echo() is None and time.monotonic() < deadline:
                        await pilot.press("g", "enter")
                        await until(lambda: not app.pane.workers, "the publishing worker")
                        await asyncio.sleep(0.1)
                    heard.append(echo())

            run(drive())
        finally:
            clock_node.shutdown("test over")
    goal = heard[0]
    assert goal is not None and goal.status == 0
    assert "  stamp: \n    secs: 4242\n    nsecs:       500\n" in goal.out
