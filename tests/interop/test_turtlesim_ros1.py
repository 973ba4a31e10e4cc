"""rosx's turtlesim_node driven by ROS 1's own tools: rosservice, rostopic, rosparam, rosnode.

The simulator runs as a subprocess (``python -m rosx_turtle turtlesim_node``) on a roscore
(ROS 1's, then rosx's) on a free port; both are stopped when the module ends. Each test starts
from ``rosservice call /reset``. Skipped where the ROS 1 reference is absent.
"""

from __future__ import annotations

import subprocess
import sys
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

import pytest

from tests.support.cli import clean_environ
from tests.support.procs import free_port, port_open, running, stop, wait_for
from tests.support.ros1 import needs_ros1, run_ros1

pytestmark = needs_ros1

START_POSE = """\
x: 5.544444561004639
y: 5.544444561004639
theta: 0.0
linear_velocity: 0.0
angular_velocity: 0.0
---
"""


@dataclass
class Pond:
    uri: str
    log: Path

    def ros1(self, *args: str) -> subprocess.CompletedProcess[str]:
        """A ROS 1 command line against this pond's master."""
        return run_ros1(list(args), ROS_MASTER_URI=self.uri)

    def lines(self) -> list[str]:
        return self.log.read_text().splitlines()


@pytest.fixture(scope="module", params=["ros1-roscore", "rosx-roscore"])
def pond(
    request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory
) -> Iterator[Pond]:
    port = free_port()
    uri = f"http://localhost:{port}"
    home = tmp_path_factory.mktemp("ros_home")
    env = {**clean_environ(), "ROS_MASTER_URI": uri, "ROS_HOME": str(home)}
    if request.param == "ros1-roscore":
        core = ["/usr/bin/roscore", "-p", str(port)]
    else:
        core = [sys.executable, "-m", "rosx_commands", "roscore", "-p", str(port)]
    log = home / "turtlesim.log"
    with running(core, env):
        wait_for(lambda: port_open(port), what="roscore")
        with log.open("w") as out:
            sim = subprocess.Popen(
                [sys.executable, "-m", "rosx_turtle", "turtlesim_node"],
                env=env,
                stdin=subprocess.DEVNULL,
                stdout=out,
                stderr=subprocess.STDOUT,
                start_new_session=True,
            )
            try:
                found = Pond(uri, log)
                wait_for(
                    lambda: "/turtle1/pose" in found.ros1("rostopic", "list").stdout,
                    what="turtlesim",
                )
                yield found
            finally:
                stop(sim)


@pytest.fixture
def fresh(pond: Pond) -> Pond:
    assert pond.ros1("rosservice", "call", "/reset").returncode == 0
    return pond


def test_spawn_answers_the_new_name(fresh: Pond) -> None:
    done = fresh.ros1("rosservice", "call", "/spawn", "2", "3", "0.5", '""')
    assert (done.returncode, done.stdout) == (0, 'name: "turtle2"\n')
    assert "/turtle2/teleport_absolute" in fresh.ros1("rosservice", "list").stdout
    assert fresh.lines()[-1].endswith(
        "]: Spawning turtle [turtle2] at x=[2.000000], y=[3.000000], theta=[0.500000]"
    )


def test_killing_nobody_fails_as_with_roscpp(fresh: Pond) -> None:
    done = fresh.ros1("rosservice", "call", "/kill", "nobody")
    assert done.returncode == 2
    assert done.stderr == "ERROR: service [/kill] responded with an error: b''\n"
    assert fresh.lines()[-1].endswith("]: Tried to kill turtle [nobody], which does not exist")


def test_an_invalid_name_returns_roscpp_text(fresh: Pond) -> None:
    done = fresh.ros1("rosservice", "call", "/spawn", "1", "1", "0", "my turtle")
    assert done.returncode == 2
    assert done.stderr == (
        "ERROR: service [/spawn] responded with an error: b'Character [ ] at element [2] is not "
        "valid in Graph Resource Name [my turtle].  Valid characters are a-z, A-Z, 0-9, / and _.'\n"
    )


def test_echo_shows_the_start_pose(fresh: Pond) -> None:
    done = fresh.ros1("rostopic", "echo", "-n", "1", "/turtle1/pose")
    assert (done.returncode, done.stdout) == (0, START_POSE)


def test_rostopic_pub_moves_the_turtle_about_two_metres(fresh: Pond) -> None:
    done = fresh.ros1(
        "rostopic", "pub", "-1", "/turtle1/cmd_vel", "geometry_msgs/Twist", "{linear: {x: 2.0}}"
    )
    assert done.returncode == 0
    pose: dict[str, float] = {}

    def stopped() -> bool:
        # Moved (however few ticks a loaded machine ran) and stopped: the one Twist is over.
        text = fresh.ros1("rostopic", "echo", "-n", "1", "/turtle1/pose").stdout
        fields = dict(line.split(": ") for line in text.splitlines()[:5] if ": " in line)
        pose.update({k: float(v) for k, v in fields.items()})
        return pose.get("linear_velocity") == 0.0 and pose["x"] > 5.544444561004639

    wait_for(stopped, timeout=60, what="the turtle to move and stop")
    # One Twist moves the turtle 2 m/s x 16 ms per tick for 1 s: a loaded machine runs fewer ticks.
    ticks = (pose["x"] - 5.544444561004639) / (2.0 * 0.016)
    assert abs(ticks - round(ticks)) < 1e-3 and 1 <= round(ticks) <= 65, pose["x"]
    assert pose["y"] == 5.544444561004639


def test_graph_as_ros1_sees_it(fresh: Pond) -> None:
    assert fresh.ros1("rosparam", "get", "/turtlesim/background_r").stdout == "69\n"
    assert "/turtlesim\n" in fresh.ros1("rosnode", "list").stdout
    topics = fresh.ros1("rostopic", "list").stdout.split()
    assert {"/turtle1/cmd_vel", "/turtle1/color_sensor", "/turtle1/pose", "/rosout"} <= set(topics)
    info = fresh.ros1("rostopic", "info", "/turtle1/cmd_vel").stdout
    assert "Type: geometry_msgs/Twist" in info
    assert " * /turtlesim (http://" in info
