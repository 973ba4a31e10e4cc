"""tf both ways between rosx and ROS 1 (Debian's tf2_ros, tf and their C++ tools).

rosx's static_transform_publisher and broadcasters feed ROS 1's tf_echo and rospy's tf2_ros and
tf listeners; ROS 1's static_transform_publisher and a rospy broadcaster feed rosx's listener
and tf_echo. tf_echo's first block must read the same from both programs, character for
character: the gimbal-locked and ``-0.000`` cases included.
"""

from __future__ import annotations

import json
import math
import queue
import subprocess
import sys
import threading
import time
from collections.abc import Iterator
from typing import Any

import pytest

from tests.support.cli import clean_environ
from tests.support.procs import free_port, port_open, running, stop, wait_for
from tests.support.ros1 import ROS1_PYTHON, needs_ros1, ros1_environ, ros1_python_imports

pytestmark = [
    needs_ros1,
    pytest.mark.skipif(not ros1_python_imports("tf2_ros", "tf"), reason="no python3-tf2-ros"),
]

ROSX = [sys.executable, "-m", "rosx_commands"]
TF_ECHO = "/usr/lib/tf/tf_echo"
STATIC = "/usr/lib/tf2_ros/static_transform_publisher"

ROS1_LISTENER = r"""
import json, sys, rospy, tf2_ros, tf
rospy.init_node("ros1_listener", anonymous=True)
buffer = tf2_ros.Buffer()
tf2_ros.TransformListener(buffer)
old = tf.TransformListener()
out = {}
for child in sys.argv[1:]:
    ok = buffer.can_transform("world", child, rospy.Time(), rospy.Duration(20))
    t = buffer.lookup_transform("world", child, rospy.Time())
    tr, r = t.transform.translation, t.transform.rotation
    old.waitForTransform("/world", "/" + child, rospy.Time(), rospy.Duration(20))
    out[child] = {"tf2": [tr.x, tr.y, tr.z, r.x, r.y, r.z, r.w],
                  "tf": old.lookupTransform("/world", "/" + child, rospy.Time())}
print(json.dumps(out))
"""

ROS1_BROADCASTER = r"""
import rospy, tf2_ros
from geometry_msgs.msg import TransformStamped
rospy.init_node("ros1_mover")
br = tf2_ros.TransformBroadcaster()
rate = rospy.Rate(20)
while not rospy.is_shutdown():
    t = TransformStamped()
    t.header.stamp = rospy.Time.now()
    t.header.frame_id = "world"
    t.child_frame_id = "mover"
    t.transform.translation.x = 0.5
    t.transform.rotation.w = 1.0
    br.sendTransform(t)
    rate.sleep()
"""


@pytest.fixture(scope="module")
def master() -> Iterator[dict[str, str]]:
    """ROS 1's roscore on a free port; the environment of programs that use it."""
    port = free_port()
    env = {**clean_environ(), **ros1_environ(), "ROS_MASTER_URI": f"http://localhost:{port}"}
    with running(["/usr/bin/roscore", "-p", str(port)], env):
        wait_for(lambda: port_open(port), what="roscore")
        yield env


def first_block(command: list[str], env: dict[str, str], timeout: float = 30.0) -> str:
    """The first five lines tf_echo prints from ``At time``, once it has printed them."""
    process = subprocess.Popen(
        command, env=env, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True,
        start_new_session=True,
    )  # fmt: skip
    lines: queue.Queue[str] = queue.Queue()
    assert process.stdout is not None
    stream = process.stdout

    def pump() -> None:
        for line in stream:
            lines.put(line)

    threading.Thread(target=pump, daemon=True).start()
    block: list[str] = []
    deadline = time.monotonic() + timeout
    try:
        while len(block) < 5:
            line = lines.get(timeout=max(0.1, deadline - time.monotonic()))
            if line.startswith("At time") or block:
                block.append(line)
    finally:
        stop(process)
    return "".join(block)


def test_ros1_reads_what_rosx_broadcasts(master: dict[str, str]) -> None:
    with (
        running([*ROSX, "static_transform_publisher", "0", "0", "0", "0", "1.5707963267948966", "0", "world", "gimbal"], master),
        running([*ROSX, "static_transform_publisher", "1", "2", "3", "-0.1", "0.2", "-0.3", "world", "tilted"], master),
        running([*ROSX, "rosrun", "tf", "static_transform_publisher", "0", "0", "1", "0", "0", "0", "1", "world", "legacy", "100"], master),
    ):  # fmt: skip
        for child in ("gimbal", "tilted"):
            theirs = first_block([TF_ECHO, "world", child], master)
            ours = first_block([*ROSX, "tf_echo", "world", child], master)
            assert ours == theirs
            assert theirs.startswith("At time 0.000\n")
        # tf's publisher stamps each transform 100 ms ahead: the times differ, the rest not.
        theirs = first_block([TF_ECHO, "world", "legacy"], master)
        ours = first_block([*ROSX, "tf_echo", "world", "legacy"], master)
        assert ours.split("\n", 1)[1] == theirs.split("\n", 1)[1]
        assert float(ours.split()[2]) > time.time() - 60
        done = subprocess.run(
            [ROS1_PYTHON, "-c", ROS1_LISTENER, "tilted", "legacy"],
            env=master, capture_output=True, text=True, timeout=60, check=True,
        )  # fmt: skip
    heard = json.loads(done.stdout)
    half = [a / 2 for a in (-0.3, 0.2, -0.1)]  # roll, pitch, yaw halved
    c = [math.cos(a) for a in half]
    s = [math.sin(a) for a in half]
    quaternion = [
        s[0] * c[1] * c[2] - c[0] * s[1] * s[2],
        c[0] * s[1] * c[2] + s[0] * c[1] * s[2],
        c[0] * c[1] * s[2] - s[0] * s[1] * c[2],
        c[0] * c[1] * c[2] + s[0] * s[1] * s[2],
    ]
    assert heard["tilted"]["tf2"] == pytest.approx([1, 2, 3, *quaternion])
    assert heard["tilted"]["tf"] == [pytest.approx([1, 2, 3]), pytest.approx(quaternion)]
    assert heard["legacy"]["tf2"] == pytest.approx([0, 0, 1, 0, 0, 0, 1])


def test_rosx_reads_what_ros1_broadcasts(master: dict[str, str]) -> None:
    from rosx.client.timing import Time
    from rosx.node import Node
    from rosx.tf import Buffer, TransformListener

    with (
        running([STATIC, "1", "2", "3", "0.1", "-0.2", "0.3", "world", "base"], master),
        running([ROS1_PYTHON, "-c", ROS1_BROADCASTER], master),
    ):
        node = Node("rosx_listener", environ=master).start()
        try:
            buffer = Buffer(node=node, debug=False)
            TransformListener(buffer, node=node)
            wait_for(lambda: buffer.can_transform("base", "mover", Time()), what="both transforms")
            moving = buffer.lookup_transform("world", "mover", Time())
            assert moving.transform.translation.x == 0.5
            frames: Any = buffer.all_frames_as_yaml()
            assert "mover: \n  parent: 'world'\n  broadcaster: '/ros1_mover'\n" in frames
            assert "  most_recent_transform: 0.000\n" in frames.split("base: \n")[1]
        finally:
            node.shutdown("test over")
        theirs = first_block([TF_ECHO, "world", "base"], master)
        ours = first_block([*ROSX, "tf_echo", "/world", "/base"], master)
    assert ours == theirs
    assert theirs.startswith("At time 0.000\n- Translation: [1.000, 2.000, 3.000]\n")
