"""``rosx roslaunch`` end to end: the tutorials' turtlemimic file, respawn, required, Ctrl-C.

Each test writes a package into a temporary ``ROS_PACKAGE_PATH`` (the turtlemimic file of the
wiki's rqt_console/roslaunch tutorial, and small rospy scripts that exit), with CI's package
path after it (ROS 1's message-only ``turtlesim`` shadows none of rosx's turtlesim), runs
``rosx roslaunch`` as a user does (its own process, no master at ``ROS_MASTER_URI``, a free
port), watches what it prints and the graph it makes, then sends SIGINT as Ctrl-C does and
checks that no process is left and the port is free. Where the ROS 1 reference is installed,
Debian's ``rosnode`` and ``rostopic`` look at the launched graph too.
"""

from __future__ import annotations

import contextlib
import os
import re
import shutil
import signal
import subprocess
import sys
import threading
from collections.abc import Iterator
from functools import partial
from pathlib import Path
from typing import Any

import pytest

from rosx.msg.codec.classes import get_message_class
from rosx.node import Node
from rosx.packages.index import bundled_packages
from rosx.transport.client import call as xmlrpc_call
from rosx.workspace.environment import ROS_ETC_DIR
from tests.support.cli import clean_environ, rosx
from tests.support.launchfiles import TURTLEMIMIC
from tests.support.procs import free_port, port_open, running, stop, wait_for
from tests.support.ros1 import OVERLAY, needs_ros1, run_ros1

START_X = 5.544444561004639

#: A node that says it is up, then exits with ``~code`` (after ``~delay`` seconds).
QUITTER = """\
#!/usr/bin/env python
import sys
import time

import rospy

rospy.init_node("quitter")
print("quitter up", flush=True)
time.sleep(rospy.get_param("~delay", 0.0))
sys.exit(rospy.get_param("~code", 3))
"""

#: A node that runs until it is stopped.
SPINNER = """\
#!/usr/bin/env python
import rospy

rospy.init_node("spinner")
rospy.spin()
"""

#: A node that ignores SIGINT.
STUBBORN = """\
#!/usr/bin/env python
import signal

import rospy

rospy.init_node("stubborn")
signal.signal(signal.SIGINT, signal.SIG_IGN)
print("stubborn up", flush=True)
rospy.spin()
"""

STUB = """\
<launch>
  <node name="stub" pkg="labl" type="stubborn.py" output="screen"/>
</launch>
"""

MISSING = """\
<launch>
  <node name="nowhere" pkg="labl" type="nowhere.py"/>
  <node name="spin" pkg="labl" type="spinner.py"/>
</launch>
"""

NOPKG = """\
<launch>
  <node pkg="nopkg" type="foo" name="foo"/>
  <node name="spin" pkg="labl" type="spinner.py"/>
</launch>
"""

BROKEN = """\
<launch>
  <node name="spin" pkg="labl" type="spinner.py"/>
  <param name="x" value="$(arg undefined)"/>
</launch>
"""

#: A node that draws a random number.
DICE = """\
#!/usr/bin/env python
import random

import rospy

rospy.init_node("dice")
print("drew", random.random(), flush=True)
rospy.spin()
"""

TWO_DICE = """\
<launch>
  <node name="d1" pkg="labl" type="dice.py" output="screen"/>
  <node name="d2" pkg="labl" type="dice.py" output="screen"/>
</launch>
"""

RESPAWN = """\
<launch>
  <node name="resp" pkg="labl" type="quitter.py" respawn="true" respawn_delay="0.2">
    <param name="code" value="4"/>
  </node>
</launch>
"""

REQUIRED = """\
<launch>
  <node name="spin" pkg="labl" type="spinner.py"/>
  <node name="req" pkg="labl" type="quitter.py" required="true" output="screen">
    <param name="delay" value="0.5"/>
  </node>
</launch>
"""

CLEAN = """\
<launch>
  <param name="answer" value="42"/>
  <node name="once" pkg="labl" type="quitter.py" output="screen">
    <param name="code" value="0"/>
  </node>
</launch>
"""

_STARTED = re.compile(r"process\[([^\]]+)\]: started with pid \[(\d+)\]")


class Launch:
    """``rosx roslaunch ARGS`` in its own process; its output, read as it comes."""

    def __init__(self, args: list[str], env: dict[str, str]) -> None:
        self.process = subprocess.Popen(
            [sys.executable, "-m", "rosx_commands", "roslaunch", *args],
            env=env,
            stdin=subprocess.DEVNULL,
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
            start_new_session=True,
        )
        self.out = ""
        self.err = ""
        self._lock = threading.Lock()
        assert self.process.stdout is not None and self.process.stderr is not None
        self._readers = [
            threading.Thread(target=self._read, args=(self.process.stdout, "out"), daemon=True),
            threading.Thread(target=self._read, args=(self.process.stderr, "err"), daemon=True),
        ]
        for reader in self._readers:
            reader.start()

    def _read(self, stream: Any, which: str) -> None:
        for line in stream:
            with self._lock:
                setattr(self, which, getattr(self, which) + line)

    def wait_for_text(self, text: str, timeout: float = 60.0, *, stream: str = "out") -> None:
        def seen() -> bool:
            if self.process.poll() is not None and not any(r.is_alive() for r in self._readers):
                raise AssertionError(f"roslaunch ended:\n{self.out}\n{self.err}")
            return text in getattr(self, stream)

        wait_for(seen, timeout=timeout, what=f"{text!r} from roslaunch")

    def pids(self) -> dict[str, list[int]]:
        """Process name -> the pids it was started with, in order."""
        found: dict[str, list[int]] = {}
        for name, pid in _STARTED.findall(self.out):
            found.setdefault(name, []).append(int(pid))
        return found

    def interrupt(self, timeout: float = 60.0) -> int:
        """Ctrl-C: SIGINT to roslaunch alone (its nodes run in their own sessions)."""
        os.kill(self.process.pid, signal.SIGINT)
        return self.finish(timeout)

    def finish(self, timeout: float = 60.0) -> int:
        code = self.process.wait(timeout)
        for reader in self._readers:
            reader.join(10)
        return code

    def close(self) -> None:
        stop(self.process)
        for reader in self._readers:
            reader.join(10)


def _alive(pid: int) -> bool:
    """Whether ``pid`` is a live process (a zombie does not count)."""
    try:
        status = Path(f"/proc/{pid}/stat").read_text()
    except OSError:
        return False
    return status.rsplit(")", 1)[1].split()[0] != "Z"


def _overlay(tmp_path: Path) -> list[str]:
    """CI's package path after the test's own (ROS 1's message-only ``turtlesim`` and the
    message packages first); without the ROS 1 reference, a message-only ``turtlesim`` like
    it: either way rosx's turtlesim programs and launch files must still be found."""
    if (OVERLAY / "turtlesim").is_dir():
        return [str(OVERLAY), "/usr/share"]
    package = tmp_path / "overlay" / "turtlesim"
    shipped = bundled_packages()["turtlesim"]
    for folder in ("msg", "srv"):
        shutil.copytree(shipped / folder, package / folder)
    shutil.copy(shipped / "package.xml", package / "package.xml")
    return [str(tmp_path / "overlay")]


@pytest.fixture
def world(tmp_path: Path) -> Iterator[dict[str, Any]]:
    """A package ``labl`` (launch files, scripts), a ROS_HOME, a free port without a master;
    a message-only ``turtlesim`` on the package path after it, as in CI (`_overlay`)."""
    package = tmp_path / "src" / "labl"
    (package / "launch").mkdir(parents=True)
    (package / "scripts").mkdir()
    (package / "package.xml").write_text(
        '<?xml version="1.0"?>\n<package format="2"><name>labl</name><version>0.0.1</version>'
        "<description>launch tests</description>"
        '<maintainer email="a@b.c">a</maintainer><license>BSD</license></package>\n'
    )
    for name, text in {
        "turtlemimic.launch": TURTLEMIMIC,
        "respawn.launch": RESPAWN,
        "required.launch": REQUIRED,
        "clean.launch": CLEAN,
        "stub.launch": STUB,
        "missing.launch": MISSING,
        "nopkg.launch": NOPKG,
        "broken.launch": BROKEN,
        "dice.launch": TWO_DICE,
    }.items():
        (package / "launch" / name).write_text(text)
    scripts = {
        "quitter.py": QUITTER,
        "spinner.py": SPINNER,
        "stubborn.py": STUBBORN,
        "dice.py": DICE,
    }
    for name, text in scripts.items():
        script = package / "scripts" / name
        script.write_text(text)
        script.chmod(0o755)
    port = free_port()
    env = clean_environ(
        ROS_MASTER_URI=f"http://localhost:{port}",
        ROS_PACKAGE_PATH=os.pathsep.join([str(tmp_path / "src"), *_overlay(tmp_path)]),
        ROS_HOME=str(tmp_path / "ros_home"),
    )
    env["PYTHONPATH"] = os.pathsep.join(
        str(Path(__file__).resolve().parents[2] / p) for p in (".", "commands", "turtle")
    )
    yield {"env": env, "port": port, "uri": f"http://localhost:{port}", "home": tmp_path}
    assert not port_open(port), "the launch left its master running"


@contextlib.contextmanager
def launched(args: list[str], env: dict[str, str]) -> Iterator[Launch]:
    launch = Launch(args, env)
    try:
        yield launch
    except BaseException:
        launch.close()
        print(f"roslaunch's output:\n{launch.out}\nroslaunch's errors:\n{launch.err}")
        raise
    finally:
        launch.close()


def _node_names(node: Node) -> set[str]:
    state = node.master.call("getSystemState")
    return {n for group in state for _, names in group for n in names}


def _wait_registered(uri: str, *names: str) -> None:
    """Wait until the master knows every one of ``names`` (a node Ctrl-C'd while Python is
    still starting up cannot end cleanly, with ROS 1 either)."""

    def known() -> bool:
        with contextlib.suppress(Exception):
            code, _, state = xmlrpc_call(uri, "getSystemState", "/test")
            if code == 1:
                found = {n for group in state for _, members in group for n in members}
                return set(names) <= found
        return False

    wait_for(known, timeout=60, what=f"{names} registered")


def test_turtlemimic_starts_a_core_two_turtlesims_and_mimic_and_ctrl_c_ends_all(
    world: dict[str, Any],
) -> None:
    env, uri = world["env"], world["uri"]
    with launched(["labl", "turtlemimic.launch"], env) as launch:
        launch.wait_for_text("process[mimic-4]: started with pid")
        watcher = Node("/launch_watcher", master_uri=uri, environ={}).start()
        try:
            wait_for(
                lambda: (
                    {"/turtlesim1/sim", "/turtlesim2/sim", "/mimic", "/rosout"}
                    <= _node_names(watcher)
                ),
                timeout=60,
                what="the launched nodes",
            )
            poses: dict[str, Any] = {}
            pose_type = get_message_class("turtlesim/Pose")
            for ns in ("turtlesim1", "turtlesim2"):
                watcher.subscribe(f"/{ns}/turtle1/pose", pose_type, partial(poses.__setitem__, ns))
            twist_type = get_message_class("geometry_msgs/Twist")
            cmd = watcher.advertise("/turtlesim1/turtle1/cmd_vel", twist_type, queue_size=1)
            twist = twist_type()
            twist.linear.x = 2.0

            def both_moved() -> bool:
                cmd.publish(twist)
                return all(
                    ns in poses and poses[ns].x > START_X + 0.5
                    for ns in ("turtlesim1", "turtlesim2")
                )

            wait_for(both_moved, timeout=60, what="both turtles moving")
        finally:
            watcher.shutdown("test over")
        pids = launch.pids()
        assert launch.interrupt() == 0, launch.err
    node_pids = [pid for name, found in pids.items() if name != "master" for pid in found]
    assert sorted(pids) == ["master", "mimic-4", "rosout-1", "turtlesim1/sim-2", "turtlesim2/sim-3"]
    assert not [pid for pid in node_pids if pid != launch.process.pid and _alive(pid)]
    assert not port_open(world["port"])
    assert launch.out.endswith(
        "[mimic-4] killing on exit\n"
        "[turtlesim2/sim-3] killing on exit\n"
        "[turtlesim1/sim-2] killing on exit\n"
        "[rosout-1] killing on exit\n"
        "[master] killing on exit\n"
        "shutting down processing monitor...\n"
        "... shutting down processing monitor complete\n"
        "done\n"
    )
    assert launch.err == ""


def test_turtlesims_own_multisim_file_starts_two_turtlesims(world: dict[str, Any]) -> None:
    with launched(["turtlesim", "multisim.launch"], world["env"]) as launch:
        _wait_registered(world["uri"], "/turtlesim1/sim", "/turtlesim2/sim")
        assert launch.interrupt() == 0, launch.err
    assert sorted(launch.pids()) == ["master", "rosout-1", "turtlesim1/sim-2", "turtlesim2/sim-3"]
    assert launch.err == ""


def test_the_start_up_text_is_roslaunchs(world: dict[str, Any]) -> None:
    env, port = world["env"], world["port"]
    with launched(["labl", "turtlemimic.launch"], env) as launch:
        launch.wait_for_text("process[mimic-4]: started with pid")
        run_id = re.search(r"setting /run_id to (\S+)", launch.out)
        assert run_id is not None
        log_dir = world["home"] / "ros_home" / "log" / run_id[1]
        sim_log = log_dir / "turtlesim1-sim-2-stdout.log"
        # The nodes' output goes to their log files, the turtlesims' log lines among them.
        wait_for(
            lambda: "Starting turtlesim with node name /turtlesim1/sim" in sim_log.read_text(),
            timeout=60,
            what="turtlesim's first log line",
        )
        _wait_registered(world["uri"], "/turtlesim1/sim", "/turtlesim2/sim", "/mimic")
        # roscd log goes to the running core's log folder.
        where = rosx("roscd", "--where", "log", environ=env)
        assert (where.status, where.out, where.err) == (0, f"{log_dir}\n", "")
        assert launch.interrupt() == 0
    where = rosx("roscd", "--where", "log", environ=env)
    assert (where.status, where.out) == (0, f"{log_dir.parent}\n")
    assert where.err == "No active roscore\n"
    server = re.search(r"started roslaunch server (\S+)", launch.out)
    assert server is not None
    pids = launch.pids()
    launcher = re.search(r"logging to (\S+)", launch.out)
    assert launcher is not None and Path(launcher[1]).parent == log_dir
    expected = (
        f"... logging to {launcher[1]}\n"
        "Checking log directory for disk usage. This may take a while.\n"
        "Press Ctrl-C to interrupt\n"
        "Done checking log file disk usage. Usage is <1GB.\n"
        f"started roslaunch server {server[1]}\n"
        "\n"
        "SUMMARY\n"
        "========\n"
        "\n"
        "PARAMETERS\n"
        " * /rosdistro: noetic\n"
        " * /rosversion: 1.16.0\n"
        "\n"
        "NODES\n"
        "  /\n"
        "    mimic (turtlesim/mimic)\n"
        "  /turtlesim1/\n"
        "    sim (turtlesim/turtlesim_node)\n"
        "  /turtlesim2/\n"
        "    sim (turtlesim/turtlesim_node)\n"
        "\n"
        "auto-starting new master\n"
        f"process[master]: started with pid [{pids['master'][0]}]\n"
        f"ROS_MASTER_URI=http://localhost:{port}\n"
        f"setting /run_id to {run_id[1]}\n"
        f"process[rosout-1]: started with pid [{pids['rosout-1'][0]}]\n"
        "started core service [/rosout]\n"
        f"process[turtlesim1/sim-2]: started with pid [{pids['turtlesim1/sim-2'][0]}]\n"
        f"process[turtlesim2/sim-3]: started with pid [{pids['turtlesim2/sim-3'][0]}]\n"
        f"process[mimic-4]: started with pid [{pids['mimic-4'][0]}]\n"
    )
    assert launch.out.startswith(expected)
    assert (world["home"] / "ros_home" / "log" / "latest").resolve() == log_dir.resolve()
    assert (log_dir / "mimic-4-stdout.log").exists()


def test_respawn_restarts_a_node_that_exits(world: dict[str, Any]) -> None:
    with launched(["labl", "respawn.launch"], world["env"]) as launch:
        launch.wait_for_text("[resp-2] restarting process\n", timeout=60)
        wait_for(lambda: len(launch.pids().get("resp-2", [])) >= 3, timeout=60, what="respawns")
        assert launch.interrupt() == 0
    first, second, *_ = launch.pids()["resp-2"]
    assert first != second
    log_dir = Path(re.findall(r"logging to (\S+)", launch.out)[0]).parent
    died = (  # the script's command line, as ROS 1 runs it
        f"[resp-2] process has died [pid {first}, exit code 4, cmd "
        f"{world['home'] / 'src' / 'labl' / 'scripts' / 'quitter.py'} __name:=resp "
        f"__log:={log_dir / 'resp-2.log'}].\n"
        f"log file: {log_dir / 'resp-2'}*.log\n"
    )
    assert died in launch.err
    assert launch.out.count("[resp-2] restarting process\n") >= 2
    # Logged output, appended across restarts.
    assert (log_dir / "resp-2-stdout.log").read_text().count("quitter up\n") >= 2
    assert not [p for p in launch.pids()["resp-2"] if _alive(p)]


def test_a_required_node_that_exits_ends_the_launch(world: dict[str, Any]) -> None:
    with launched(["labl", "required.launch"], world["env"]) as launch:
        code = launch.finish(timeout=90)
    assert code == 0
    pids = launch.pids()
    assert "quitter up\n" in launch.out  # output="screen"
    rule = "=" * 80
    assert (
        f"{rule}REQUIRED process [req-3] has died!\nprocess has died [pid {pids['req-3'][0]}, exit code 3"
        in launch.err
    )
    assert f"Initiating shutdown!\n{rule}\n" in launch.err
    assert launch.out.endswith(
        "[req-3] killing on exit\n"
        "[spin-2] killing on exit\n"
        "[rosout-1] killing on exit\n"
        "[master] killing on exit\n"
        "shutting down processing monitor...\n"
        "... shutting down processing monitor complete\n"
        "done\n"
    )
    assert not _alive(pids["spin-2"][0])


def test_with_a_master_running_the_launch_ends_when_its_nodes_end(
    world: dict[str, Any],
) -> None:
    env, port = world["env"], world["port"]
    core = [sys.executable, "-m", "rosx_commands", "roscore", "-p", str(port)]
    with running(core, env):
        wait_for(lambda: port_open(port), what="roscore")
        with launched(["labl", "clean.launch"], env) as launch:
            assert launch.finish(timeout=90) == 0
        with launched(["-v", "--skip-log-check", "labl", "clean.launch"], env) as verbose:
            assert verbose.finish(timeout=90) == 0
        with Node("/checker", master_uri=world["uri"], environ={}) as checker:
            run_id = checker.master.call("getParam", "/run_id")
            assert checker.master.call("getParam", "/answer") == 42
    assert f"logging to {world['home'] / 'ros_home' / 'log' / run_id}/" in launch.out
    assert "auto-starting new master" not in launch.out
    where = world["home"] / "src" / "labl" / "launch" / "clean.launch"
    etc = env.get("ROS_ETC_DIR") or str(ROS_ETC_DIR)
    assert (
        f"... loading XML file [{Path(etc, 'roscore.xml')}]\n"
        "... executing command param [rosversion roslaunch]\n"
        "Added parameter [/rosversion]\n"
        "... executing command param [rosversion -d]\n"
        "Added parameter [/rosdistro]\n"
        "Added core node of type [rosout/rosout] in namespace [/]\n"
        f"... loading XML file [{where}]\n"
        "Added parameter [/answer]\n"
        "Added parameter [/once/code]\n"
        "Added node of type [labl/quitter.py] in namespace [/]\n"
        "started roslaunch server "
    ) in verbose.out
    assert (
        f"ROS_MASTER_URI=http://localhost:{port}\nprocess[once-1]: started with pid" in launch.out
    )
    assert launch.out.endswith(
        "[once-1] process has finished cleanly\n"
        f"log file: {world['home'] / 'ros_home' / 'log' / run_id / 'once-1'}*.log\n"
        "all processes on machine have died, roslaunch will exit\n"
        "shutting down processing monitor...\n"
        "... shutting down processing monitor complete\n"
        "done\n"
    )


@needs_ros1
def test_ros1_tools_see_the_launched_graph(world: dict[str, Any]) -> None:
    env, uri = world["env"], world["uri"]
    with launched(["labl", "turtlemimic.launch"], env) as launch:
        launch.wait_for_text("process[mimic-4]: started with pid")

        def listed() -> bool:
            nodes = run_ros1(["rosnode", "list"], ROS_MASTER_URI=uri).stdout
            return nodes == "/mimic\n/rosout\n/turtlesim1/sim\n/turtlesim2/sim\n"

        wait_for(listed, timeout=60, what="rosnode list")
        topics = run_ros1(["rostopic", "list"], ROS_MASTER_URI=uri).stdout.splitlines()
        assert {
            "/turtlesim1/turtle1/cmd_vel",
            "/turtlesim1/turtle1/pose",
            "/turtlesim2/turtle1/cmd_vel",
            "/turtlesim2/turtle1/pose",
            "/rosout",
            "/rosout_agg",
        } <= set(topics)
        info = run_ros1(["rosnode", "info", "/mimic"], ROS_MASTER_URI=uri).stdout
        assert "/turtlesim1/turtle1/pose" in info and "/turtlesim2/turtle1/cmd_vel" in info
        assert launch.interrupt() == 0


def test_a_node_that_ignores_sigint_gets_sigterm_after_the_timeout(world: dict[str, Any]) -> None:
    args = ["--sigint-timeout", "0.5", "labl", "stub.launch"]
    with launched(args, world["env"]) as launch:
        launch.wait_for_text("stubborn up\n")
        _wait_registered(world["uri"], "/stub")
        assert launch.interrupt() == 0
    assert launch.err == "[stub-2] escalating to SIGTERM\n"
    assert "[stub-2] killing on exit\n[rosout-1] killing on exit\n" in launch.out
    assert not _alive(launch.pids()["stub-2"][0])


def test_a_node_that_cannot_be_found_is_reported_and_the_others_start(
    world: dict[str, Any],
) -> None:
    with launched(["labl", "missing.launch"], world["env"]) as launch:
        launch.wait_for_text("process[spin-3]: started with pid")
        _wait_registered(world["uri"], "/spin")
        assert launch.interrupt() == 0
    where = world["home"] / "src" / "labl" / "launch" / "missing.launch"
    assert launch.err == (
        f"ERROR: cannot launch node of type [labl/nowhere.py]: {where}:2: <node>: Cannot locate "
        "node of type [nowhere.py] in package [labl]. Make sure file exists in package path and "
        "permission is set to executable (chmod +x)\n"
    )
    assert "nowhere-2" not in launch.pids()


def test_a_node_of_a_package_not_found_is_reported_as_roslaunch_does(
    world: dict[str, Any],
) -> None:
    with launched(["labl", "nopkg.launch"], world["env"]) as launch:
        launch.wait_for_text("process[spin-3]: started with pid")
        _wait_registered(world["uri"], "/spin")
        assert launch.interrupt() == 0
    where = world["home"] / "src" / "labl" / "launch" / "nopkg.launch"
    searched = world["env"]["ROS_PACKAGE_PATH"].split(os.pathsep)
    paths = "".join(f"ROS path [{n}]={path}\n" for n, path in enumerate(searched))
    assert launch.err == (
        f"ERROR: cannot launch node of type [nopkg/foo]: {where}:2: <node>: nopkg\n{paths}"
    )


def test_a_broken_launch_file_starts_nothing(world: dict[str, Any]) -> None:
    with launched(["labl", "broken.launch"], world["env"]) as launch:
        assert launch.finish() == 1
    where = world["home"] / "src" / "labl" / "launch" / "broken.launch"
    error = f"RLException: {where}:3: <param>: requires the 'undefined' arg to be set"
    # roslaunch opens its log first, then loads the files, and logs the error's traceback.
    log = next((world["home"] / "ros_home" / "log" / "latest").glob("roslaunch-*.log"))
    assert launch.out == (
        f"... logging to {log.resolve()}\n"
        "Checking log directory for disk usage. This may take a while.\n"
        "Press Ctrl-C to interrupt\n"
        "Done checking log file disk usage. Usage is <1GB.\n"
    )
    assert launch.err == f"{error}\nThe traceback for the exception was written to the log file\n"
    logged = log.read_text()
    assert "[ERROR] " in logged and f": {error}\n" in logged
    assert "Traceback (most recent call last):" in logged


def test_a_port_held_by_something_else_is_roslaunchs_error(world: dict[str, Any]) -> None:
    import socket

    with socket.socket() as holder:
        holder.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        holder.bind(("127.0.0.1", world["port"]))
        holder.listen()
        with launched(["labl", "clean.launch"], world["env"]) as launch:
            assert launch.finish() == 1
    assert (
        f"auto-starting new master\nprocess[master]: started with pid [{launch.process.pid}]\n"
        f"ERROR: Unable to start XML-RPC server, port {world['port']} is already in use\n"
        "shutting down processing monitor...\n"
        "... shutting down processing monitor complete\n"
    ) in launch.out
    assert launch.err == (
        f"RLException: ERROR: could not contact master [{world['uri']}]\n"
        "The traceback for the exception was written to the log file\n"
    )
    assert "process[once" not in launch.out


def test_wait_waits_for_a_master(world: dict[str, Any]) -> None:
    env, port = world["env"], world["port"]
    with launched(["--wait", "labl", "clean.launch"], env) as launch:
        launch.wait_for_text("roscore/master is not yet running, will wait for it to start\n")
        core = [sys.executable, "-m", "rosx_commands", "roscore", "-p", str(port)]
        with running(core, env):
            assert launch.finish(timeout=90) == 0
    assert launch.out.startswith(
        "roscore/master is not yet running, will wait for it to start\n"
        "master has started, initiating launch\n... logging to "
    )
    assert "[once-1] process has finished cleanly\n" in launch.out


def test_python_nodes_do_not_share_their_random_numbers(world: dict[str, Any]) -> None:
    """Python nodes start as forks of one loaded process: each still draws its own numbers
    (Python reseeds ``random`` in a fork), and so its own anonymous names."""
    with launched(["labl", "dice.launch"], world["env"]) as launch:
        wait_for(lambda: launch.out.count("drew ") == 2, timeout=60, what="two draws")
        _wait_registered(world["uri"], "/d1", "/d2")
        assert launch.interrupt() == 0
    draws = re.findall(r"drew (\S+)", launch.out)
    assert len(set(draws)) == 2, draws


def test_core_runs_roscore(world: dict[str, Any]) -> None:
    """``roslaunch --core`` is roscore, log folder included."""
    args = ["--core", "-p", str(world["port"])]
    with launched(args, world["env"]) as launch:
        launch.wait_for_text("started core service [/rosout]\n")
        assert launch.interrupt() == 0
    run_id = re.findall(r"setting /run_id to (\S+)", launch.out)[0]
    log_dir = world["home"] / "ros_home" / "log" / run_id
    assert launch.out.startswith(f"... logging to {log_dir}/roslaunch-")
    assert "ros_comm version 1.16.0\n" in launch.out
    assert launch.out.endswith("... shutting down processing monitor complete\ndone\n")
    assert (world["home"] / "ros_home" / "log" / "latest").resolve() == log_dir.resolve()
