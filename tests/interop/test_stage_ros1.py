"""rosx's stageros as ROS 1's tools see it, on ROS 1's roscore: rostopic lists, types and echoes
stage_ros's topics, a rospy node (Debian's) on simulated time follows ``/clock``, looks the laser
up through a tf2_ros listener and drives the robot on ``cmd_vel``, and ROS 1's rosbag records
odometry, scans and tf with the types and frames stage_ros gives them."""

from __future__ import annotations

import json
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest

from rosx.bag.api import Bag
from tests.support.cli import clean_environ
from tests.support.procs import free_port, port_open, running, wait_for
from tests.support.ros1 import ROS1_PYTHON, needs_ros1, ros1_environ, ros1_python_imports
from tests.support.stage_worlds import room

pytestmark = [
    needs_ros1,
    pytest.mark.skipif(not ros1_python_imports("tf2_ros"), reason="no python3-tf2-ros"),
]

ROSX = [sys.executable, "-m", "rosx_commands"]
#: stage_ros's topics for one robot (rosx adds cmd_pose and cmd_pose_stamped).
STAGE_TOPICS = {"/base_pose_ground_truth", "/base_scan", "/clock", "/cmd_vel", "/odom", "/tf"}

#: A rospy node on simulated time: the laser's frame through tf2, a scan, then a drive.
DRIVER = r"""
import json, rospy, tf2_ros
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from sensor_msgs.msg import LaserScan
rospy.init_node("ros1_driver")
out = {"sim_time": rospy.get_param("/use_sim_time")}
buffer = tf2_ros.Buffer()
tf2_ros.TransformListener(buffer)
t = buffer.lookup_transform("odom", "base_laser_link", rospy.Time(), rospy.Duration(30))
out["tf"] = [t.header.frame_id, t.child_frame_id, t.transform.translation.x]
scan = rospy.wait_for_message("/base_scan", LaserScan, timeout=30)
out["scan"] = [scan.header.frame_id, len(scan.ranges), round(scan.ranges[90], 2)]
start = rospy.wait_for_message("/odom", Odometry, timeout=30)
out["clock_follows"] = abs(rospy.Time.now().to_sec() - start.header.stamp.to_sec()) < 5
pub = rospy.Publisher("/cmd_vel", Twist, queue_size=1)
twist = Twist()
twist.linear.x = 0.5
rate = rospy.Rate(10)  # simulated time: ten a simulated second
began = rospy.Time.now()
while rospy.Time.now() - began < rospy.Duration(2):
    pub.publish(twist)
    rate.sleep()
end = rospy.wait_for_message("/odom", Odometry, timeout=30)
out["moved"] = end.pose.pose.position.x - start.pose.pose.position.x
out["odom"] = [end.header.frame_id, end.child_frame_id]
print(json.dumps(out))
"""


@pytest.fixture(scope="module")
def stage(tmp_path_factory: pytest.TempPathFactory) -> Iterator[dict[str, str]]:
    """ROS 1's roscore and rosx's stageros (``rosrun stage_ros stageros -g``) in the test room;
    the environment of ROS 1's programs that use them."""
    folder = tmp_path_factory.mktemp("stage")
    world = folder / "room.world"
    world.write_text(room())
    port = free_port()
    env = {**clean_environ(), **ros1_environ(), "ROS_MASTER_URI": f"http://localhost:{port}"}
    with running(["/usr/bin/roscore", "-p", str(port)], env):
        wait_for(lambda: port_open(port), what="roscore")
        rosx_env = {**clean_environ(), "ROS_MASTER_URI": env["ROS_MASTER_URI"]}
        with running([*ROSX, "rosrun", "stage_ros", "stageros", "-g", str(world)], rosx_env):
            wait_for(lambda: set(rostopic(env, "list").split()) >= STAGE_TOPICS, what="topics")
            yield env


def rostopic(env: dict[str, str], *args: str) -> str:
    """ROS 1's ``rostopic ARGS``' output."""
    done = subprocess.run(
        ["/usr/bin/rostopic", *args],
        env=env,
        capture_output=True,
        text=True,
        timeout=60,
        check=False,
    )
    assert done.returncode == 0, done.stderr
    return done.stdout


def test_ros1_rostopic_sees_stage_ros_topics(stage: dict[str, str]) -> None:
    topics = set(rostopic(stage, "list").split())
    assert STAGE_TOPICS | {"/rosout", "/rosout_agg"} <= topics
    assert rostopic(stage, "type", "/base_scan") == "sensor_msgs/LaserScan\n"
    assert rostopic(stage, "type", "/odom") == "nav_msgs/Odometry\n"
    odom = rostopic(stage, "echo", "-n", "1", "/odom")
    assert '  frame_id: "odom"\nchild_frame_id: "base_footprint"\n' in odom
    scan = rostopic(stage, "echo", "-n", "1", "--noarr", "/base_scan")
    assert '  frame_id: "base_laser_link"\n' in scan
    assert "angle_min: -1.57079" in scan and "range_max: 8.0" in scan


def test_a_rospy_node_on_sim_time_reads_tf_and_drives_the_robot(stage: dict[str, str]) -> None:
    done = subprocess.run(
        [ROS1_PYTHON, "-c", DRIVER],
        env=stage,
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
    )
    assert done.returncode == 0, done.stderr
    out = json.loads(done.stdout)
    assert out["sim_time"] is True and out["clock_follows"] is True
    assert out["tf"] == ["odom", "base_laser_link", 0.0]
    assert out["scan"] == ["base_laser_link", 181, 4.9]  # the east wall, straight ahead
    assert out["odom"] == ["odom", "base_footprint"]
    assert out["moved"] > 0.5  # two simulated seconds at 0.5 m/s, less the first steps


def test_ros1_rosbag_records_the_simulators_topics(stage: dict[str, str], tmp_path: Path) -> None:
    bag = tmp_path / "stage.bag"
    done = subprocess.run(
        ["/usr/bin/rosbag", "record", "-O", str(bag), "-l", "3", "/odom", "/base_scan", "/tf"],
        env=stage,
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
    )
    assert done.returncode == 0, done.stderr
    with Bag(str(bag)) as reader:
        info = reader.get_type_and_topic_info().topics
        assert {topic: info[topic].msg_type for topic in info} == {
            "/odom": "nav_msgs/Odometry",
            "/base_scan": "sensor_msgs/LaserScan",
            "/tf": "tf2_msgs/TFMessage",
        }
        assert all(info[topic].message_count == 3 for topic in info)
        frames = {
            (t.header.frame_id, t.child_frame_id)
            for _, message, _ in reader.read_messages(topics=["/tf"])
            for t in message.transforms
        }
    assert frames == {
        ("odom", "base_footprint"),
        ("base_footprint", "base_link"),
        ("base_link", "base_laser_link"),
    }
