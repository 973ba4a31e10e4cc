"""Other terminals attach to ``rosx sim`` through ``ROS_MASTER_URI``: rosx's tools, ROS 1's tools
and rospy scripts see Lab 1's graph and the pose, and drive the turtle."""

from __future__ import annotations

import signal
import subprocess
import sys

from rosx_turtle.sim.host import SimHost
from tests.support.cli import clean_environ, rosx
from tests.support.procs import free_port, port_open, stop, wait_for
from tests.support.pty_terminal import BLUE_BACKGROUND, on_a_terminal
from tests.support.ros1 import needs_ros1, ros1_python, run_ros1

POSE_AT_START = [
    "x: 5.544444561004639",
    "y: 5.544444561004639",
    "theta: 0.0",
    "linear_velocity: 0.0",
    "angular_velocity: 0.0",
    "---",
]


def test_rosx_tools_see_lab1(host: SimHost) -> None:
    environ = clean_environ(ROS_MASTER_URI=host.master_uri)
    echo = rosx("rostopic", "echo", "-n", "1", "/turtle1/pose", environ=environ)
    assert (echo.status, echo.out.splitlines()) == (0, POSE_AT_START)
    nodes = rosx("rosnode", "list", environ=environ)
    assert nodes.out.splitlines() == ["/rosout", "/teleop_turtle", "/turtlesim"]
    info = rosx("rostopic", "info", "/turtle1/cmd_vel", environ=environ).out
    assert "Type: geometry_msgs/Twist" in info
    assert "/teleop_turtle" in info.split("Subscribers:")[0]
    assert "/turtlesim" in info.split("Subscribers:")[1]
    params = rosx("rosparam", "get", "/turtlesim/background_b", environ=environ)
    assert params.out.strip() == "255"


def test_teleop_drives_turtlesim_in_process(host: SimHost) -> None:
    # Teleop and turtlesim share the sim's process: their link has no socket (INTRAPROCESS),
    # and other processes still see it, as they would see roscpp's.
    environ = clean_environ(ROS_MASTER_URI=host.master_uri)
    info = rosx("rosnode", "info", "/turtlesim", environ=environ)
    assert info.status == 0
    link = info.out.split(" * topic: /turtle1/cmd_vel\n", 1)[1].split(" * topic:", 1)[0]
    assert link.splitlines()[0].startswith("    * to: /teleop_turtle (http://")
    assert link.splitlines()[1:3] == ["    * direction: inbound", "    * transport: INTRAPROCESS"]


@needs_ros1
def test_ros1_rostopic_echo_sees_the_pose(host: SimHost) -> None:
    done = run_ros1(
        ["rostopic", "echo", "-n", "1", "/turtle1/pose"], ROS_MASTER_URI=host.master_uri
    )
    assert done.returncode == 0, done.stderr
    assert done.stdout.splitlines() == POSE_AT_START


@needs_ros1
def test_a_rospy_script_drives_the_turtle(host: SimHost) -> None:
    script = """
import json, rospy
from geometry_msgs.msg import Twist
from turtlesim.msg import Pose
rospy.init_node("driver")
pub = rospy.Publisher("/turtle1/cmd_vel", Twist, queue_size=1)
while pub.get_num_connections() < 1:
    rospy.sleep(0.05)
twist = Twist()
twist.linear.x = 2.0
pub.publish(twist)
rospy.sleep(1.5)
pose = rospy.wait_for_message("/turtle1/pose", Pose, timeout=10)
print(json.dumps([pose.x, pose.y]))
"""
    x, y = ros1_python(script, ROS_MASTER_URI=host.master_uri)
    assert 7.0 < x < 7.6 and abs(y - 5.544444561004639) < 1e-6  # about 2 m on


def test_rosx_sim_command_without_a_terminal() -> None:
    port = free_port()
    command = [sys.executable, "-m", "rosx_commands", "sim", "--port", str(port)]
    sim = subprocess.Popen(
        command,
        env=clean_environ(),
        stdin=subprocess.DEVNULL,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        start_new_session=True,
    )
    try:
        wait_for(lambda: port_open(port), what="rosx sim's master")
        uri = f"http://localhost:{port}/"
        environ = clean_environ(ROS_MASTER_URI=uri)
        wait_for(
            lambda: "/turtle1/pose" in rosx("rostopic", "list", environ=environ).out,
            what="turtlesim",
        )
        second = subprocess.run(
            command, env=clean_environ(), capture_output=True, text=True, timeout=30, check=False
        )
        assert second.returncode == 1
        assert second.stderr.splitlines() == [
            f"A ROS master is already running at {uri}",
            "Nodes there: /rosout, /teleop_turtle, /turtlesim",
            f"Run `rosx sim --join --port {port}` to start turtlesim and teleop against it,",
            "or `rosx sim --port PORT` for a master of its own on another port.",
        ]
        sim.send_signal(signal.SIGINT)
        out, err = sim.communicate(timeout=15)
    finally:
        stop(sim)
    assert sim.returncode == 0, err
    assert "Traceback" not in err
    lines = out.splitlines()
    assert f"ROS_MASTER_URI={uri}" in lines
    assert any(line.endswith("Starting turtlesim with node name /turtlesim") for line in lines)
    assert not port_open(port)


def test_rosx_sim_on_a_terminal_draws_drives_and_quits() -> None:
    port = free_port()
    uri = f"http://localhost:{port}/"
    command = [sys.executable, "-m", "rosx_commands", "sim", "--port", str(port)]
    with on_a_terminal(command) as terminal:
        terminal.read(20, until=b"/teleop_turtle")
        environ = clean_environ(ROS_MASTER_URI=uri)
        terminal.type(b"\x1b[A")  # Up, as a terminal sends it
        wait_for(
            lambda: (
                "x: 7." in rosx("rostopic", "echo", "-n", "1", "/turtle1/pose", environ=environ).out
            ),
            what="turtle1 driven forward",
        )
        terminal.type(b"q")
        assert terminal.wait(15) == 0
    assert BLUE_BACKGROUND in terminal.output and "\u2580".encode() in terminal.output
    assert b"ROS_MASTER_URI=" + uri.encode() in terminal.output  # in the header
    assert not port_open(port)
