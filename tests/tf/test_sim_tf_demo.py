"""``rosx sim --tf-demo``: turtle_tf2's demo in the sim's one process, seen from outside."""

from __future__ import annotations

import math
import time

from rosx.client.timing import Time
from rosx.node import Node
from rosx.tf import Buffer, TransformListener
from rosx_turtle.env import ProcessEnv
from rosx_turtle.sim.host import SimHost
from rosx_turtle.sim.run import _parse
from tests.support.procs import free_port, wait_for
from tests.support.turtle_poses import Poses


def test_the_option_is_parsed() -> None:
    assert _parse(["--tf-demo"], ProcessEnv()).tf_demo
    assert not _parse([], ProcessEnv()).tf_demo


def test_turtle2_follows_turtle1_in_the_sim() -> None:
    host = SimHost(free_port(), {"ROS_IP": "127.0.0.1"}, seed=3, watch=False, tf_demo=True).start()
    try:
        node = Node("observer", environ={"ROS_MASTER_URI": host.master_uri}).start()
        try:
            poses = Poses(node, ("turtle1", "turtle2"))
            buffer = Buffer(node=node, debug=False)
            TransformListener(buffer, node=node)
            wait_for(lambda: buffer.can_transform("turtle2", "turtle1", Time()), what="the frames")
            frames = buffer.all_frames_as_yaml()
            assert (
                "turtle1: \n  parent: 'world'\n  broadcaster: '/turtle1_tf2_broadcaster'" in frames
            )
            assert (
                "turtle2: \n  parent: 'world'\n  broadcaster: '/turtle2_tf2_broadcaster'" in frames
            )
            start = poses.latest.get("turtle1", (5.5, 5.5))
            deadline = time.monotonic() + 30
            while poses.moved(start) < 2.0 and time.monotonic() < deadline:
                host.drive(2.0, 0.0)
                time.sleep(0.1)
            wait_for(lambda: poses.distance() < 0.5, what="turtle2 near turtle1", timeout=60)
            assert math.isfinite(poses.distance())
        finally:
            node.shutdown("test over")
    finally:
        host.stop()
