"""rosx rviz with ROS 1 (Debian's roscore, rostopic and tf2_ros): it draws a scan ROS 1's
``rostopic pub`` sends in a frame ROS 1's static_transform_publisher gives, and ROS 1's
``rostopic echo`` hears its 2D Nav Goal in the fixed frame."""

from __future__ import annotations

import asyncio
import subprocess
import time
from collections.abc import Iterator
from pathlib import Path

import pytest

from rosx_commands.context import Environment
from rosx_commands.rviz.config import parse_config
from rosx_commands.rviz.run import live_app
from tests.support.cli import clean_environ
from tests.support.pilot import run
from tests.support.procs import free_port, port_open, running, wait_for
from tests.support.ros1 import needs_ros1, ros1_environ

pytestmark = needs_ros1

STATIC = "/usr/lib/tf2_ros/static_transform_publisher"
SCAN = (
    "{header: {frame_id: laser}, angle_min: -0.1, angle_max: 0.1, angle_increment: 0.1,"
    " range_min: 0.1, range_max: 10.0, ranges: [1.0, 2.0, 3.0]}"
)
CONFIG = """\
Visualization Manager:
  Displays:
    - {Class: rviz/LaserScan, Name: Scan, Topic: /scan}
  Global Options: {Fixed Frame: map}
"""


@pytest.fixture(scope="module")
def ros1() -> Iterator[dict[str, str]]:
    """ROS 1's roscore, a static map -> laser and a scan at 5 Hz from rostopic pub."""
    port = free_port()
    env = {**clean_environ(), **ros1_environ(), "ROS_MASTER_URI": f"http://localhost:{port}"}
    with running(["/usr/bin/roscore", "-p", str(port)], env):
        wait_for(lambda: port_open(port), what="roscore")
        tf = [STATIC, "1", "2", "0", "0", "0", "0", "map", "laser"]
        pub = ["/usr/bin/rostopic", "pub", "-r", "5", "/scan", "sensor_msgs/LaserScan", SCAN]
        with running(tf, env), running(pub, env):
            yield env


def test_rviz_draws_ros1s_scan_and_ros1_hears_its_goal(
    ros1: dict[str, str], tmp_path: Path
) -> None:
    uri = ros1["ROS_MASTER_URI"]
    app = live_app(
        Environment(environ=clean_environ(ROS_MASTER_URI=uri, HOME=str(tmp_path))),
        parse_config(CONFIG, "ros1.rviz"),
        None,
        tmp_path / "saved.rviz",
    )
    echo = subprocess.Popen(
        ["/usr/bin/rostopic", "echo", "-n", "1", "/move_base_simple/goal"],
        env=ros1,
        stdout=subprocess.PIPE,
        stderr=subprocess.DEVNULL,
        text=True,
        start_new_session=True,
    )

    async def drive() -> None:
        async with app.run_test(size=(100, 30)) as pilot:
            deadline = time.monotonic() + 60
            scan = app.manager.displays[0]
            while "Showing [3] points" not in scan.summary and time.monotonic() < deadline:
                await asyncio.sleep(0.1)
            assert scan.summary == "Showing [3] points from [1] messages"
            while echo.poll() is None and time.monotonic() < deadline:
                await pilot.press("g", "enter")
                await asyncio.sleep(0.2)

    try:
        run(drive())
        out, _ = echo.communicate(timeout=30)
    finally:
        if echo.poll() is None:
            echo.kill()
            echo.wait()
    assert 'frame_id: "map"\npose: \n  position: \n    x: 0.0\n    y: 0.0\n' in out
    assert "    w: 1.0\n---\n" in out
