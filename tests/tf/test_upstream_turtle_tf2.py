"""The real turtle_tf2 and turtle_tf (github:ros/geometry_tutorials, kinetic-devel, as Noetic
releases them), fetched beside the checkout: ``rosx catkin_make`` builds them in a workspace,
and ``roslaunch turtle_tf2 turtle_tf2_demo.launch`` runs the workspace's own launch file and
scripts, unchanged (``#!/usr/bin/env python``, a broadcaster made per pose). Skipped where the
repository has not been fetched, as on CI.
"""

from __future__ import annotations

import math
import subprocess
import sys
import time
from pathlib import Path

from rosx.msg.codec.classes import get_message_class
from rosx.node import Node
from tests.support.cli import clean_environ
from tests.support.fetched import fetched_tree
from tests.support.procs import free_port, port_open, running, wait_for
from tests.support.turtle_poses import Poses

Twist = get_message_class("geometry_msgs/Twist")
Vector3 = get_message_class("geometry_msgs/Vector3")


def test_the_upstream_demo_builds_and_runs_unchanged(tmp_path: Path) -> None:
    source = tmp_path / "ws" / "src"
    source.mkdir(parents=True)
    for package in ("turtle_tf2", "turtle_tf"):
        fetched_tree("ros/geometry_tutorials", package, source)
    broadcaster = source / "turtle_tf2" / "nodes" / "turtle_tf2_broadcaster.py"
    assert broadcaster.read_text().startswith("#!/usr/bin/env python\n")
    env = {**clean_environ(), "ROS_HOME": str(tmp_path), "HOME": str(tmp_path)}
    rosx = [sys.executable, "-m", "rosx_commands"]
    built = subprocess.run(
        [*rosx, "catkin_make"], cwd=tmp_path / "ws", env=env, capture_output=True, text=True,
        timeout=300, check=False,
    )  # fmt: skip
    assert built.returncode == 0, built.stdout + built.stderr
    # roslaunch resolves the workspace's own script (the overlay), not rosx's bundled one.
    resolved = subprocess.run(
        ["bash", "-c", f". devel/setup.sh && exec {' '.join(rosx)} roslaunch --args "
         "turtle1_tf2_broadcaster turtle_tf2 turtle_tf2_demo.launch"],
        cwd=tmp_path / "ws", env=env, capture_output=True, text=True, timeout=60, check=True,
    )  # fmt: skip
    assert resolved.stdout == f"{broadcaster} __name:=turtle1_tf2_broadcaster\n"
    port = free_port()
    env["ROS_MASTER_URI"] = f"http://localhost:{port}"
    launch = " ".join([*rosx, "roslaunch", "-p", str(port), "turtle_tf2", "turtle_tf2_demo.launch"])
    command = ["bash", "-c", f". devel/setup.sh && exec {launch}"]
    with running(command, env, cwd=tmp_path / "ws"):
        wait_for(lambda: port_open(port), what="the launch's master")
        node = Node("upstream_driver", environ=env).start()
        try:
            poses = Poses(node, ("turtle1", "turtle2"))
            wait_for(lambda: poses.distance() < math.inf, what="both turtles", timeout=60)
            start = poses.latest["turtle1"]
            drive = node.advertise("/turtle1/cmd_vel", Twist, queue_size=1)
            deadline = time.monotonic() + 30
            while poses.moved(start) < 2.0 and time.monotonic() < deadline:
                drive.publish(Twist(linear=Vector3(2.0, 0, 0)))
                time.sleep(0.1)
            wait_for(lambda: poses.distance() < 0.5, what="turtle2 near turtle1", timeout=60)
        finally:
            node.shutdown("test over")
