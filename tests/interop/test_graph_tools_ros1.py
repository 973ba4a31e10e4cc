"""rosx rostopic / rosnode against a real ROS 1 graph: same words as ROS 1's tools print."""

from __future__ import annotations

import re
from collections.abc import Iterator

import pytest

from tests.support.cli import clean_environ, rosx
from tests.support.procs import free_port, running, wait_for
from tests.support.ros1 import ROS1_PYTHON, ROSCORES, needs_ros1, ros1_environ, roscore, run_ros1

pytestmark = needs_ros1

TALKER = """
import rospy
from std_msgs.msg import String
from geometry_msgs.msg import Twist
rospy.init_node('talker')
p = rospy.Publisher('chatter', String, queue_size=10)
q = rospy.Publisher('/turtle1/cmd_vel', Twist, queue_size=1)
rospy.Subscriber('/turtle1/pose', Twist, lambda m: None)
rospy.Service('/add', __import__('std_srvs.srv').srv.Empty, lambda r: [])
r = rospy.Rate(10)
while not rospy.is_shutdown():
    p.publish(String('hello'))
    r.sleep()
"""
LISTENER = """
import rospy
from std_msgs.msg import String
rospy.init_node('listener')
rospy.Subscriber('chatter', String, lambda m: None)
rospy.spin()
"""


@pytest.fixture(scope="module", params=ROSCORES)
def graph(request: pytest.FixtureRequest) -> Iterator[str]:
    """A roscore (ROS 1's or rosx's) with a rospy talker and listener; yields the master URI."""
    with roscore(request.param) as uri:
        env = ros1_environ(ROS_MASTER_URI=uri)
        with running([ROS1_PYTHON, "-c", TALKER], env), running([ROS1_PYTHON, "-c", LISTENER], env):
            wait_for(
                lambda: (
                    "/listener" in run_ros1(["rosnode", "list"], ROS_MASTER_URI=uri).stdout
                    and "/chatter" in run_ros1(["rostopic", "list"], ROS_MASTER_URI=uri).stdout
                ),
                what="talker and listener",
            )
            # Let the listener's connection to the talker come up before comparing bus info.
            wait_for(
                lambda: (
                    "inbound"
                    in run_ros1(["rosnode", "info", "/listener"], ROS_MASTER_URI=uri).stdout
                ),
                what="the chatter connection",
            )
            yield uri


COMMANDS = [
    ["rostopic", "list"],
    ["rostopic", "list", "-v"],
    ["rostopic", "list", "-p"],
    ["rostopic", "list", "-s"],
    ["rostopic", "list", "-v", "-s"],
    ["rostopic", "list", "/turtle1"],
    ["rostopic", "list", "-v", "/turtle1"],
    ["rostopic", "info", "/chatter"],
    ["rostopic", "info", "/turtle1/pose"],
    ["rostopic", "info", "chatter"],
    ["rostopic", "info", "/nope"],
    ["rostopic", "info"],
    ["rostopic", "type", "/chatter"],
    ["rostopic", "type", "/turtle1/cmd_vel/linear"],
    ["rostopic", "type", "/turtle1/cmd_vel/linear/x"],
    ["rostopic", "type", "/turtle1/cmd_vel/linear/x/y"],
    ["rostopic", "type", "/nope"],
    ["rostopic", "find", "std_msgs/String"],
    ["rostopic", "find", "geometry_msgs/Twist"],
    ["rostopic", "list", "a", "b"],
    ["rosnode", "list"],
    ["rosnode", "list", "-u"],
    ["rosnode", "list", "-a"],
    ["rosnode", "list", "/list"],
    ["rosnode", "info", "-q", "/talker"],
    ["rosnode", "info", "/listener"],
    ["rosnode", "info", "/nope"],
    ["rosnode", "machine"],
    ["rosnode", "kill", "/nope"],
    ["rosnode", "ping"],
    ["rosnode"],
    ["rostopic"],
]


@pytest.mark.parametrize("argv", COMMANDS, ids=" ".join)
def test_same_output_as_ros1(graph: str, argv: list[str]) -> None:
    ros1 = run_ros1(argv, ROS_MASTER_URI=graph)
    ours = rosx(*argv, environ=clean_environ(ROS_MASTER_URI=graph))
    assert (ours.out, ours.err, ours.status) == (ros1.stdout, ros1.stderr, ros1.returncode)


def test_ping_of_an_unknown_node_has_ros1_text_and_fails(graph: str) -> None:
    argv = ["rosnode", "ping", "-c", "1", "/nope"]
    ros1 = run_ros1(argv, ROS_MASTER_URI=graph)
    ours = rosx(*argv, environ=clean_environ(ROS_MASTER_URI=graph))
    assert (ours.out, ours.err) == (ros1.stdout, ros1.stderr)
    assert (ours.status, ros1.returncode) == (1, 0)  # rosx tells a script the ping failed


def test_ping_has_ros1_shape(graph: str) -> None:
    ours = rosx(
        "rosnode", "ping", "-c", "2", "/talker", environ=clean_environ(ROS_MASTER_URI=graph)
    )
    lines = ours.out.splitlines()
    assert lines[:2] == ["rosnode: node is [/talker]", "pinging /talker with a timeout of 3.0s"]
    assert all(
        re.fullmatch(r"xmlrpc reply from http://\S+/\ttime=\d+\.\d{6}ms", line)
        for line in lines[2:4]
    )
    assert re.fullmatch(r"ping average: \d+\.\d{6}ms", lines[4])


NO_MASTER = [
    ["rostopic", "list"],
    ["rostopic", "info", "/x"],
    ["rostopic", "echo", "/x"],
    ["rostopic", "pub", "/x", "std_msgs/Empty"],
    ["rosnode", "list"],
    ["rosnode", "info", "/x"],
    ["rosnode", "ping", "/x"],
    ["rosnode", "ping"],
    ["rosnode", "kill", "/x"],
    ["rosservice", "list"],
    ["rosservice", "call", "/x"],
    ["rosparam", "get", "/"],
    ["rosparam", "set", "/a", "1"],
]


@pytest.mark.parametrize("argv", NO_MASTER, ids=" ".join)
def test_no_master_same_as_ros1(argv: list[str]) -> None:
    uri = f"http://127.0.0.1:{free_port()}"
    ros1 = run_ros1(argv, ROS_MASTER_URI=uri)
    ours = rosx(*argv, environ=clean_environ(ROS_MASTER_URI=uri))
    assert (ours.out, ours.err, ours.status) == (ros1.stdout, ros1.stderr, ros1.returncode)
