"""``rosx roscore`` as a user runs it: summary, refusal of a busy port, Ctrl-C, ``/rosout_agg``."""

from __future__ import annotations

import signal
import subprocess
import sys

from tests.support.cli import clean_environ, rosx
from tests.support.procs import free_port, port_open, running, stop, wait_for
from tests.support.ros1 import ROS1_PYTHON, needs_ros1, ros1_environ, run_ros1


def _core(port: int) -> subprocess.Popen[str]:
    return subprocess.Popen(
        [sys.executable, "-m", "rosx_commands", "roscore", "-p", str(port)],
        env=clean_environ(ROS_MASTER_URI=f"http://localhost:{port}"),
        stdin=subprocess.DEVNULL,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        start_new_session=True,
    )


def test_summary_refusal_and_ctrl_c() -> None:
    port = free_port()
    core = _core(port)
    try:
        wait_for(lambda: port_open(port), what="rosx roscore")
        wait_for(
            lambda: (
                "/rosout_agg"
                in rosx(
                    "rostopic",
                    "list",
                    environ=clean_environ(ROS_MASTER_URI=f"http://localhost:{port}"),
                ).out
            ),
            what="/rosout",
        )
        second = subprocess.run(
            [sys.executable, "-m", "rosx_commands", "roscore", "-p", str(port)],
            env=clean_environ(),
            capture_output=True,
            text=True,
            timeout=30,
            check=False,
        )
        assert second.returncode == 1
        assert "roscore cannot run as another roscore/master is already running." in second.stderr
        assert "Traceback" not in second.stderr
        core.send_signal(signal.SIGINT)
        out, _ = core.communicate(timeout=15)
    finally:
        stop(core)
    assert core.returncode == 0
    lines = out.splitlines()
    assert "SUMMARY" in lines and "PARAMETERS" in lines
    assert " * /rosdistro: noetic" in lines and " * /rosversion: 1.16.0" in lines
    assert f"ROS_MASTER_URI=http://localhost:{port}/" in lines
    assert "started core service [/rosout]" in lines


def test_usage_errors() -> None:
    result = rosx("roscore", "extra")
    assert (result.status, result.err) == (
        2,
        "Usage: roscore [options]\n\nroscore: error: roscore does not take arguments\n",
    )


@needs_ros1
def test_ros1_tools_and_rospy_logging_against_rosx_roscore() -> None:
    port = free_port()
    uri = f"http://localhost:{port}"
    env = ros1_environ(ROS_MASTER_URI=uri)
    core = _core(port)
    try:
        wait_for(lambda: port_open(port), what="rosx roscore")
        wait_for(
            lambda: "/rosout" in run_ros1(["rosnode", "list"], ROS_MASTER_URI=uri).stdout,
            what="/rosout",
        )
        assert (
            run_ros1(["rosparam", "get", "/rosdistro"], ROS_MASTER_URI=uri).stdout
            == "'noetic\n\n  '\n\n"
        )
        assert "Pid:" in run_ros1(["rosnode", "info", "/rosout"], ROS_MASTER_URI=uri).stdout
        assert run_ros1(
            ["rosnode", "ping", "-c", "1", "/rosout"], ROS_MASTER_URI=uri
        ).stdout.startswith("rosnode: node is [/rosout]\n")
        talker = (
            "import rospy\nrospy.init_node('chatty')\n"
            "while not rospy.is_shutdown():\n    rospy.loginfo('hello from rospy')\n    rospy.sleep(0.2)\n"
        )
        with running([ROS1_PYTHON, "-c", talker], env):
            echo = subprocess.run(
                ["rostopic", "echo", "-n", "1", "/rosout_agg/msg"],
                env=env,
                capture_output=True,
                text=True,
                timeout=30,
                check=False,
            )
        assert echo.stdout == '"hello from rospy"\n---\n'
    finally:
        stop(core)  # SIGINT, waited for; escalated only if roscore ignores it
