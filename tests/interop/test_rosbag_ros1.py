"""rosx's bags and ROS 1's rosbag (Debian's) on one graph: each records, reads and plays the
other's files.

A rosx master runs in this process. A rospy talker publishes ``/chatter`` (String) and a
latched ``/cmd`` (Twist) once every recorder is connected; rosx's recorder and ROS 1's record
the same messages, plain, bz2 and lz4. ROS 1's ``rosbag info``/``check`` accept rosx's bags;
``rosx rosbag info`` prints ROS 1's text for every bag; ROS 1's ``rosbag play`` of a rosx bag
reaches a rosx subscriber, and ``rosx rosbag play`` of a ROS 1 bag reaches a rospy one.
"""

from __future__ import annotations

import subprocess
import sys
import threading
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from rosx.master.server import MasterThread
from rosx.msg.codec.classes import get_message_class
from rosx.node import Node
from tests.support.procs import wait_for
from tests.support.ros1_procs import ROS1_PYTHON, ros1_available, ros_env, stop

pytestmark = pytest.mark.skipif(not ros1_available(), reason="the ROS 1 reference is absent")

ROSBAG = "/usr/bin/rosbag"
RECORD = "/usr/lib/rosbag/record"
COUNT = 100

TALKER = """
import sys, rospy
from std_msgs.msg import String
from geometry_msgs.msg import Twist
rospy.init_node('talker')
chatter = rospy.Publisher('/chatter', String, queue_size=1000)
cmd = rospy.Publisher('/cmd', Twist, queue_size=1000, latch=True)
wanted = int(sys.argv[1])
while not rospy.is_shutdown() and min(chatter.get_num_connections(), cmd.get_num_connections()) < wanted:
    rospy.sleep(0.05)
rate = rospy.Rate(100)
for i in range(COUNT):
    chatter.publish(String('hello %d' % i))
    t = Twist(); t.linear.x = i; cmd.publish(t)
    rate.sleep()
rospy.sleep(1.0)
""".replace("COUNT", str(COUNT))

LISTENER = """
import sys, rospy
from std_msgs.msg import String
got = []
rospy.init_node('listener')
rospy.Subscriber('/chatter', String, lambda m: got.append(m.data))
print('ready', flush=True)
deadline = rospy.get_time() + 30
while not rospy.is_shutdown() and len(got) < COUNT and rospy.get_time() < deadline:
    rospy.sleep(0.05)
print('\\n'.join(got), flush=True)
""".replace("COUNT", str(COUNT))


class Graph:
    def __init__(self, uri: str, home: Path) -> None:
        self.uri = uri
        self.home = home
        self.env = ros_env(uri, home)
        self.rosx_env = {**self.env, "PATH": f"{Path(sys.executable).parent}:/usr/bin:/bin"}

    def rosx(self, *args: str, **kwargs: Any) -> subprocess.Popen[str]:
        return subprocess.Popen(
            [sys.executable, "-m", "rosx_commands", *args],
            env=self.rosx_env,
            cwd=self.home,
            text=True,
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            **kwargs,
        )

    def ros1(self, *args: str) -> subprocess.Popen[str]:
        return subprocess.Popen(
            [str(ROS1_PYTHON), *args],
            env=self.env,
            cwd=self.home,
            text=True,
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
        )

    def ros1_record(self, *args: str) -> subprocess.Popen[str]:
        """ROS 1's C++ recorder itself: Debian's ``rosbag record`` is a Python wrapper that
        dies of SIGINT with a traceback and may leave its recorder child running."""
        return subprocess.Popen(
            [RECORD, *args],
            env=self.env,
            cwd=self.home,
            text=True,
            stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL,
        )

    def run(self, args: list[str], rosx: bool = False) -> subprocess.CompletedProcess[str]:
        command = (
            [sys.executable, "-m", "rosx_commands", *args] if rosx else [str(ROS1_PYTHON), *args]
        )
        return subprocess.run(
            command,
            env=self.rosx_env if rosx else self.env,
            cwd=self.home,
            capture_output=True,
            text=True,
            timeout=60,
            check=False,
        )


@pytest.fixture(scope="module")
def graph(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Graph]:
    home = tmp_path_factory.mktemp("bags")
    with MasterThread(port=0, host="127.0.0.1", advertised_host="127.0.0.1") as master:
        yield Graph(master.uri, home)


@pytest.fixture(scope="module")
def recorded(graph: Graph) -> Graph:
    """Record the talker with three rosx recorders and three ROS 1 ones."""
    recorders = [
        graph.rosx("rosbag", "record", "-O", "rx_plain", "/chatter", "/cmd"),
        graph.rosx("rosbag", "record", "-O", "rx_bz2", "-j", "-a", "-x", "/rosout.*"),
        graph.rosx("rosbag", "record", "-O", "rx_lz4.bag", "--lz4", "/chatter", "/cmd"),
        graph.ros1_record("-O", "r1_plain", "/chatter", "/cmd"),
        graph.ros1_record("-O", "r1_bz2", "-j", "/chatter", "/cmd"),
        graph.ros1_record("-O", "r1_lz4", "--lz4", "/chatter", "/cmd"),
    ]
    talker = graph.ros1("-c", TALKER, str(len(recorders)))
    try:
        talker.wait(60)
    finally:
        stop(talker)
        for process in recorders:
            stop(process)
    for name in ("rx_plain", "rx_bz2", "rx_lz4", "r1_plain", "r1_bz2", "r1_lz4"):
        assert (graph.home / f"{name}.bag").exists(), name
        assert not (graph.home / f"{name}.bag.active").exists(), name
    return graph


@pytest.mark.parametrize("name", ["rx_plain", "rx_bz2", "rx_lz4"])
def test_ros1_accepts_rosx_bags(recorded: Graph, name: str) -> None:
    info = recorded.run([ROSBAG, "info", f"{name}.bag"])
    assert info.returncode == 0, info.stderr
    assert f"/chatter   {COUNT} msgs" in info.stdout
    check = recorded.run([ROSBAG, "check", f"{name}.bag"])
    assert check.stdout == "Bag file does not need any migrations.\n"


@pytest.mark.parametrize("name", ["rx_plain", "rx_bz2", "rx_lz4", "r1_plain", "r1_bz2", "r1_lz4"])
@pytest.mark.parametrize("options", [[], ["--freq"], ["-y"], ["-y", "-k", "topics"]])
def test_rosx_info_prints_ros1s_text(recorded: Graph, name: str, options: list[str]) -> None:
    ros1 = recorded.run([ROSBAG, "info", *options, f"{name}.bag"])
    mine = recorded.run(["rosbag", "info", *options, f"{name}.bag"], rosx=True)
    assert (mine.returncode, mine.stdout, mine.stderr) == (
        ros1.returncode,
        ros1.stdout,
        ros1.stderr,
    )


def test_ros1_play_of_a_rosx_bag_reaches_a_rosx_subscriber(recorded: Graph) -> None:
    got: list[str] = []
    done = threading.Event()

    def heard(msg: Any) -> None:
        got.append(msg.data)
        if len(got) == COUNT:
            done.set()

    string = get_message_class("std_msgs/String")
    with Node("bag_listener", master_uri=recorded.uri, environ={}) as node:
        node.subscribe("/chatter", string, heard)
        player = recorded.ros1(ROSBAG, "play", "-r", "4", "rx_plain.bag")
        try:
            assert done.wait(30), f"{len(got)} of {COUNT} messages"
            player.wait(30)
        finally:
            stop(player)
    assert got == [f"hello {i}" for i in range(COUNT)]


def test_rosx_play_of_a_ros1_bag_reaches_a_rospy_subscriber(recorded: Graph) -> None:
    listener = recorded.ros1("-c", LISTENER)
    try:
        assert listener.stdout is not None
        assert listener.stdout.readline() == "ready\n"
        with Node("probe", master_uri=recorded.uri, environ={}) as probe:
            wait_for(
                lambda: any(t == "/chatter" for t, _ in probe.master.call("getSystemState")[1]),
                what="the rospy subscriber",
            )
        player = recorded.rosx("rosbag", "play", "-q", "-r", "4", "r1_lz4.bag")
        try:
            out, _ = listener.communicate(timeout=60)
            player.wait(30)
        finally:
            stop(player)
    finally:
        stop(listener)
    assert out.split("\n")[:COUNT] == [f"hello {i}" for i in range(COUNT)]
