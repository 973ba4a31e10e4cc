"""The demo the tf tutorials start from: ``roslaunch turtle_tf2 turtle_tf2_demo.launch``.

turtlesim (headless), the teleop, a broadcaster per turtle and the listener that spawns turtle2
and steers it towards turtle1. The test drives turtle1 as the keyboard would (``cmd_vel``),
stops it, and waits until turtle2 has caught up: within 0.5 m. The same for tf's older API
(``turtle_tf_demo.launch``), and the launch's parameters: the teleop's scales.
"""

from __future__ import annotations

import math
import sys
import time
from collections.abc import Iterator
from pathlib import Path

import pytest

from rosx.msg.codec.classes import get_message_class
from rosx.node import Node
from tests.support.cli import clean_environ
from tests.support.procs import free_port, port_open, running, wait_for
from tests.support.turtle_poses import Poses

Twist = get_message_class("geometry_msgs/Twist")


@pytest.fixture
def launched(request: pytest.FixtureRequest, tmp_path: Path) -> Iterator[Node]:
    package, launch_file = request.param
    port = free_port()
    env = {
        **clean_environ(),
        "ROS_MASTER_URI": f"http://localhost:{port}",
        "ROS_HOME": str(tmp_path),
        "HOME": str(tmp_path),
    }
    command = [sys.executable, "-m", "rosx_commands", "roslaunch", "-p", str(port)]
    with running([*command, package, launch_file], env):
        wait_for(lambda: port_open(port), what="the launch's master")
        node = Node("demo_driver", environ=env).start()
        try:
            yield node
        finally:
            node.shutdown("test over")


DEMOS = [("turtle_tf2", "turtle_tf2_demo.launch"), ("turtle_tf", "turtle_tf_demo.launch")]


@pytest.mark.parametrize("launched", DEMOS, indirect=True, ids=["tf2", "tf"])
def test_turtle2_catches_turtle1_once_it_stops(launched: Node) -> None:
    node = launched
    poses = Poses(node, ("turtle1", "turtle2"))
    wait_for(lambda: poses.distance() < math.inf, what="both turtles", timeout=60)
    assert node.params.get("/scale_linear") == 2.0
    assert node.params.get("/scale_angular") == 2.0
    start = poses.latest["turtle1"]
    drive = node.advertise("/turtle1/cmd_vel", Twist, queue_size=1)
    # As the keyboard's Up and Left (scale 2), until turtle1 has moved well away.
    deadline = time.monotonic() + 30
    while poses.moved(start) < 2.0 and time.monotonic() < deadline:
        drive.publish(Twist(linear=get_message_class("geometry_msgs/Vector3")(2.0, 0, 0)))
        time.sleep(0.1)
    assert poses.moved(start) >= 2.0
    wait_for(lambda: poses.distance() < 0.5, what="turtle2 within 0.5 m of turtle1", timeout=60)
