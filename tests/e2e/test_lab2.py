"""Lab 2 of the lab sheet, end to end, in bash, in a temporary HOME.

A rosx roscore and a headless rosx turtlesim run on a free port for the whole module. bash
runs the sheet's steps (with ``rosx`` in front, then as typed after ``rosx shell-init``):
``catkin_create_pkg``, ``catkin_make``, ``source ~/catkin_ws/devel/setup.bash``,
``roscd lab2``, ``mkdir scripts``, ``chmod +x``, ``rosrun lab2 pub.py``. A node in this process
watches ``/turtle1/pose``. The same scripts then run under ROS 1's rospy (Debian's Python)
where the ROS 1 reference is installed.
"""

from __future__ import annotations

import subprocess
import sys
import threading
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from rosx.msg.codec.classes import get_message_class, get_service_class
from rosx.node import Node
from tests.support.cli import clean_environ
from tests.support.lab2_scripts import PUB, STOP_AT_TEN
from tests.support.procs import free_port, port_open, running, stop, wait_for
from tests.support.ros1 import ROS1_PYTHON, needs_ros1, ros1_environ

START_X = 5.544444561004639


class Lab:
    """The running pond, the HOME holding the workspace, and a node watching the turtle."""

    def __init__(self, home: Path, uri: str, env: dict[str, str], watcher: Node) -> None:
        self.home = home
        self.uri = uri
        self.env = env
        self.watcher = watcher
        self.latest: Any = None
        self._arrived = threading.Event()
        watcher.subscribe("/turtle1/pose", get_message_class("turtlesim/Pose"), self._pose)
        empty = get_service_class("std_srvs/Empty")
        self._reset = watcher.service_client("/reset", empty)
        self._empty = empty._request_class

    def _pose(self, msg: Any) -> None:
        self.latest = msg
        self._arrived.set()

    def pose(self) -> Any:
        assert self._arrived.wait(15), "no pose from turtlesim"
        return self.latest

    def reset(self) -> None:
        self._reset.call(self._empty())
        wait_for(lambda: abs(self.pose().x - START_X) < 1e-3, what="the reset turtle")

    def bash(self, script: str) -> subprocess.CompletedProcess[str]:
        return subprocess.run(
            ["bash", "-c", script],
            env=self.env,
            cwd=self.home,
            capture_output=True,
            text=True,
            timeout=120,
            check=False,
        )

    def nodes(self) -> list[str]:
        state = self.watcher.master.call("getSystemState")
        return sorted({n for group in state for _, names in group for n in names})


@pytest.fixture(scope="module")
def lab(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Lab]:
    home = tmp_path_factory.mktemp("home")
    bin_dir = home / ".local" / "bin"
    bin_dir.mkdir(parents=True)
    wrapper = bin_dir / "rosx"
    wrapper.write_text(f'#!/bin/sh\nexec "{sys.executable}" -m rosx_commands "$@"\n')
    wrapper.chmod(0o755)
    port = free_port()
    uri = f"http://127.0.0.1:{port}/"
    env = clean_environ(HOME=str(home), ROS_MASTER_URI=uri, ROS_HOME=str(home / ".ros"))
    env["PATH"] = f"{bin_dir}:{env.get('PATH', '/usr/bin:/bin')}"
    env.pop("PYTHONPATH", None)
    env.pop("PWD", None)
    env.pop("XDG_CACHE_HOME", None)  # shell-init's programs go to this HOME's cache folder
    core = [sys.executable, "-m", "rosx_commands", "roscore", "-p", str(port)]
    sim = [sys.executable, "-m", "rosx_turtle", "turtlesim_node", "--headless"]
    with running(core, env):
        wait_for(lambda: port_open(port), what="roscore")
        with running(sim, env):
            watcher = Node("lab_watcher", master_uri=uri, environ={}).start()
            try:
                found = Lab(home, uri, env, watcher)
                found.pose()
                yield found
            finally:
                watcher.shutdown("test over")


SHEET_STEPS = """\
set -e
mkdir -p ~/catkin_ws/src
cd ~/catkin_ws/src
rosx catkin_create_pkg lab2 std_msgs rospy roscpp
cd ~/catkin_ws
rosx catkin_make
source ~/catkin_ws/devel/setup.bash
rosx roscd lab2
echo "now in $(pwd)"
mkdir scripts
cd scripts
touch pub.py
chmod +x pub.py
cat > pub.py <<'EOF'
{pub}EOF
cat > stop.py <<'EOF'
{stop}EOF
chmod +x stop.py
"""


@pytest.fixture(scope="module")
def workspace(lab: Lab) -> subprocess.CompletedProcess[str]:
    """The sheet's steps, with ``rosx`` in front of each ROS command."""
    return lab.bash(SHEET_STEPS.format(pub=PUB, stop=STOP_AT_TEN))


def test_the_sheet_steps_make_a_package_and_a_workspace(
    lab: Lab, workspace: subprocess.CompletedProcess[str]
) -> None:
    assert workspace.returncode == 0, workspace.stderr
    src = lab.home / "catkin_ws" / "src"
    out = workspace.stdout
    assert "Created file lab2/package.xml\nCreated file lab2/CMakeLists.txt\n" in out
    assert f"Successfully created files in {src}/lab2." in out
    assert f"Base path: {lab.home / 'catkin_ws'}\nSource space: {src}\n" in out
    assert "-- ~~  - lab2\n" in out and "-- Configuring done\n" in out
    assert f"now in {src}/lab2\n" in out
    assert (src / "lab2" / "scripts" / "pub.py").read_text() == PUB
    devel = lab.home / "catkin_ws" / "devel"
    assert {"setup.bash", "setup.sh", "setup.zsh"} <= {p.name for p in devel.iterdir()}


def _rosrun(lab: Lab, script: str, log: Path) -> subprocess.Popen[bytes]:
    """``rosrun lab2 SCRIPT`` typed as on the sheet, in a shell set up as a student's."""
    command = (
        'eval "$(rosx shell-init bash)"\n'
        "source ~/catkin_ws/devel/setup.bash\n"
        f"rosrun lab2 {script}\n"
    )
    with log.open("wb") as out:
        return subprocess.Popen(
            ["bash", "-c", command],
            env=lab.env,
            cwd=lab.home,
            stdin=subprocess.DEVNULL,
            stdout=out,
            stderr=subprocess.STDOUT,
            start_new_session=True,
        )


def _stopped_at_ten(lab: Lab, process: subprocess.Popen[bytes], log: Path) -> None:
    try:
        wait_for(lambda: lab.pose().x > 9.5, timeout=30, what="the turtle near x = 10")
        wait_for(lambda: lab.pose().linear_velocity == 0.0, timeout=10, what="a stop")
        time.sleep(1.0)
        pose = lab.pose()
        assert abs(pose.x - 10.0) < 0.1, pose.x
        assert pose.linear_velocity == 0.0
    finally:
        stop(process)
    assert process.poll() is not None
    assert "Turtle is running at" in log.read_text()


def test_rosrun_pub_moves_the_turtle(lab: Lab, workspace: Any, tmp_path: Path) -> None:
    lab.reset()
    process = _rosrun(lab, "pub.py", tmp_path / "pub.log")
    try:
        wait_for(lambda: "/lab2" in lab.nodes(), what="the lab2 node")
        wait_for(lambda: lab.pose().x > START_X + 0.5, timeout=20, what="the turtle moving")
        assert lab.pose().linear_velocity == 1.0
    finally:
        stop(process)
    assert process.returncode == 0, (tmp_path / "pub.log").read_text()
    wait_for(lambda: "/lab2" not in lab.nodes(), what="lab2 to unregister")
    assert "Traceback" not in (tmp_path / "pub.log").read_text()


def test_rosrun_stop_at_ten_stops_the_turtle_at_x_10(
    lab: Lab, workspace: Any, tmp_path: Path
) -> None:
    lab.reset()
    log = tmp_path / "stop.log"
    _stopped_at_ten(lab, _rosrun(lab, "stop.py", log), log)


def _ros1(lab: Lab, script: str, log: Path) -> subprocess.Popen[bytes]:
    env = ros1_environ(ROS_MASTER_URI=lab.uri, ROS_HOME=str(lab.home / ".ros"))
    path = lab.home / "catkin_ws" / "src" / "lab2" / "scripts" / script
    with log.open("wb") as out:
        return subprocess.Popen(
            [ROS1_PYTHON, str(path)],
            env=env,
            stdin=subprocess.DEVNULL,
            stdout=out,
            stderr=subprocess.STDOUT,
            start_new_session=True,
        )


@needs_ros1
def test_the_same_pub_script_runs_under_ros1_rospy(
    lab: Lab, workspace: Any, tmp_path: Path
) -> None:
    lab.reset()
    process = _ros1(lab, "pub.py", tmp_path / "pub.log")
    try:
        wait_for(lambda: lab.pose().x > START_X + 0.5, timeout=30, what="the turtle moving")
    finally:
        stop(process)


@needs_ros1
def test_the_same_stop_script_stops_the_turtle_under_ros1_rospy(
    lab: Lab, workspace: Any, tmp_path: Path
) -> None:
    lab.reset()
    log = tmp_path / "stop.log"
    _stopped_at_ten(lab, _ros1(lab, "stop.py", log), log)
