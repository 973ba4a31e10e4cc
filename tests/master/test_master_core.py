"""``rosx roscore`` (`rosx.core.Core` and what roscore prints around it) in a subprocess: what
it prints compared with ROS 1's roscore, the parameters it sets, how it refuses a taken port,
how it stops."""

from __future__ import annotations

import os
import re
import signal
import socket
import subprocess
import sys
import time
import xmlrpc.client
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from tests.support.ros1_procs import (
    ROS1_PYTHON,
    ROSCORE,
    free_port,
    ros1_available,
    ros_env,
    run_tool,
    stop,
)

ROOT = Path(__file__).resolve().parents[2]


class RosProxy:
    """Python's own XML-RPC client (rospy's), with replies typed for the tests."""

    def __init__(self, uri: str) -> None:
        self.proxy = xmlrpc.client.ServerProxy(uri)

    def call(self, method: str, *params: Any) -> Any:
        return getattr(self.proxy, method)(*params)


needs_ros1 = pytest.mark.skipif(not ros1_available(), reason="ROS 1 (roscore, rospy) is absent")


def _start_core(port: int, env: dict[str, str]) -> subprocess.Popen[str]:
    return subprocess.Popen(
        [sys.executable, "-m", "rosx_commands", "roscore", "-p", str(port)],
        env={**env, "PYTHONPATH": str(ROOT)},
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        cwd=ROOT,
    )


def _read_through(proc: subprocess.Popen[str], marker: str, timeout: float = 30.0) -> list[str]:
    assert proc.stdout is not None
    lines: list[str] = []
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        line = proc.stdout.readline()
        if not line:
            break
        lines.append(line)
        if marker in line:
            return lines
    raise AssertionError(f"{marker!r} never printed; got {''.join(lines)!r}")


def _wait_until_settled(port: int, timeout: float = 30.0) -> None:
    """Wait for ROS 1's roscore to reach its process monitor: a signal before that ends it on
    a different path (``No processes to monitor``). Its parameters are set first, then rosout
    starts and registers with the master."""
    master = RosProxy(f"http://localhost:{port}/")
    deadline = time.monotonic() + timeout
    for method, name in (("getParam", "/rosdistro"), ("lookupNode", "/rosout")):
        while master.call(method, "/test", name)[0] != 1:
            assert time.monotonic() < deadline, f"{method} {name} never answered"
            time.sleep(0.05)


def _finish(proc: subprocess.Popen[str], sig: int = signal.SIGINT) -> tuple[int, str, str]:
    os.kill(proc.pid, sig)
    out, err = proc.communicate(timeout=30)
    return proc.returncode, out, err


@pytest.fixture
def env(tmp_path: Path) -> Iterator[dict[str, str]]:
    yield ros_env("http://localhost:11311", tmp_path)


@pytest.fixture
def core(env: dict[str, str]) -> Iterator[tuple[subprocess.Popen[str], int, list[str]]]:
    port = free_port()
    proc = _start_core(port, {**env, "ROS_MASTER_URI": f"http://localhost:{port}"})
    try:
        lines = _read_through(proc, "started core service [/rosout]")
        yield proc, port, lines
    finally:
        stop(proc)


_DROPPED = ("... logging to", "Checking log directory", "Press Ctrl-C", "Done checking log")


def _normalise(text: str) -> list[str]:
    text = re.sub(r"\x1b\[\d*m|\x1b\]2;[^\x07]*\x07\n?", "", text)
    text = re.sub(r"http://[^/\s]+/", "URI", text)
    text = re.sub(r"\[\d+\]", "[PID]", text)
    text = re.sub(r"[0-9a-f]{8}-[0-9a-f]{4}-[0-9a-f]{4}-[0-9a-f]{4}-[0-9a-f]{12}", "RUN_ID", text)
    text = re.sub(r"(ros_comm version |/rosversion: )[\d.]+", r"\1VERSION", text)
    text = re.sub(r"/rosdistro: \w+", "/rosdistro: DISTRO", text)
    return [line for line in text.split("\n") if not line.startswith(_DROPPED)]


@needs_ros1
def test_output_has_roscore_shape(env: dict[str, str]) -> None:
    port = free_port()
    port_env = {**env, "ROS_MASTER_URI": f"http://localhost:{port}"}
    real = subprocess.Popen(
        [str(ROS1_PYTHON), str(ROSCORE), "-p", str(port)],
        env=port_env,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        head = _read_through(real, "started core service [/rosout]")
        _wait_until_settled(port)
        code, tail, _ = _finish(real)
        theirs = (code, "".join(head) + tail)
    finally:
        stop(real)
    ours_proc = _start_core(port, port_env)
    try:
        head = _read_through(ours_proc, "started core service [/rosout]")
        code, tail, err = _finish(ours_proc)
        ours = (code, "".join(head) + tail)
    finally:
        stop(ours_proc)
    assert ours[0] == theirs[0] == 0
    assert _normalise(ours[1]) == _normalise(theirs[1])
    assert err == ""


def test_plain_output_has_no_escapes(core: tuple[subprocess.Popen[str], int, list[str]]) -> None:
    proc, port, lines = core
    text = "".join(lines)
    assert "\x1b" not in text
    assert f"ROS_MASTER_URI=http://localhost:{port}/\n" in lines
    run_id = next(line for line in lines if line.startswith("setting /run_id to ")).split()[-1]
    logging_to = rf"\.\.\. logging to \S+/log/{run_id}/roslaunch-\S+-{proc.pid}\.log\n"
    assert re.fullmatch(logging_to, lines[0]), lines[0]
    assert lines[1:4] == [
        "Checking log directory for disk usage. This may take a while.\n",
        "Press Ctrl-C to interrupt\n",
        "Done checking log file disk usage. Usage is <1GB.\n",
    ]
    lines = lines[4:]
    assert lines[0] == f"started roslaunch server http://localhost:{port}/\n"
    assert lines[1:13] == [
        "ros_comm version 1.16.0\n",
        "\n",
        "\n",
        "SUMMARY\n",
        "========\n",
        "\n",
        "PARAMETERS\n",
        " * /rosdistro: noetic\n",
        " * /rosversion: 1.16.0\n",
        "\n",
        "NODES\n",
        "\n",
    ]
    code, out, err = _finish(proc)
    assert code == 0
    assert out == (
        "[rosout-1] killing on exit\n[master] killing on exit\n"
        "shutting down processing monitor...\n... shutting down processing monitor complete\n"
        "done\n"
    )
    assert err == ""


def test_core_parameters(core: tuple[subprocess.Popen[str], int, list[str]]) -> None:
    proc, port, lines = core
    uri = f"http://localhost:{port}/"
    master = RosProxy(uri)
    run_id = next(line for line in lines if line.startswith("setting /run_id to ")).split()[-1]
    assert master.call("getParam", "/x", "/run_id") == [1, "Parameter [/run_id]", run_id]
    assert master.call("getParam", "/x", "/rosversion")[2] == "1.16.0\n"
    assert master.call("getParam", "/x", "/rosdistro")[2] == "noetic\n"
    launch = master.call("getParam", "/x", "/roslaunch/uris")[2]
    assert launch == {f"host_localhost__{port}": uri}
    assert master.call("getUri", "/x") == [1, "", uri]
    assert master.call("getPid", "/x") == [1, "", proc.pid]


@needs_ros1
def test_rosparam_reads_core_parameters(
    core: tuple[subprocess.Popen[str], int, list[str]], env: dict[str, str]
) -> None:
    _, port, _ = core
    tool_env = {**env, "ROS_MASTER_URI": f"http://localhost:{port}"}
    # YAML of "noetic\n", the trailing newline kept as roscore keeps it.
    expected = (0, "'noetic\n\n  '\n\n")
    assert run_tool(["/usr/bin/rosparam", "get", "/rosdistro"], tool_env) == expected


def test_second_core_on_the_port_refuses(
    core: tuple[subprocess.Popen[str], int, list[str]], env: dict[str, str]
) -> None:
    _, port, _ = core
    second = _start_core(port, env)
    out, err = second.communicate(timeout=30)
    assert second.returncode == 1
    assert err.endswith(
        "RLException: roscore cannot run as another roscore/master is already running. \n"
        "Please kill other roscore/master processes before relaunching.\n"
        f"The ROS_MASTER_URI is http://localhost:{port}/\n"
        "The traceback for the exception was written to the log file\n"
    )
    assert out.endswith("NODES\n\n")
    _assert_logged_with_its_traceback(out, "roscore cannot run as another roscore/master")


def _assert_logged_with_its_traceback(out: str, error: str) -> None:
    """The launcher's log (``... logging to LOG``) holds ``error`` and the traceback, as
    roslaunch's does."""
    log = Path(re.findall(r"^\.\.\. logging to (.*)$", out, re.MULTILINE)[0])
    logged = log.read_text()
    assert "[roslaunch][ERROR] " in logged and error in logged
    assert "Traceback (most recent call last):" in logged and "PortInUseError" in logged


@needs_ros1
def test_ros1_roscore_sees_rosx_master_running(
    core: tuple[subprocess.Popen[str], int, list[str]], env: dict[str, str]
) -> None:
    _, port, _ = core
    real = subprocess.run(
        [str(ROS1_PYTHON), str(ROSCORE), "-p", str(port)],
        env=env,
        capture_output=True,
        text=True,
        timeout=60,
        check=False,
    )
    assert real.returncode == 1
    assert "roscore cannot run as another roscore/master is already running." in real.stderr


def test_port_taken_by_something_else(env: dict[str, str]) -> None:
    with socket.socket() as squatter:
        squatter.bind(("127.0.0.1", 0))
        squatter.listen()
        port = squatter.getsockname()[1]
        proc = _start_core(port, env)
        out, err = proc.communicate(timeout=30)
    assert proc.returncode == 1
    assert f"ERROR: Unable to start XML-RPC server, port {port} is already in use\n" in out
    assert err.endswith(
        f"RLException: ERROR: could not contact master [http://localhost:{port}/]\n"
        "The traceback for the exception was written to the log file\n"
    )
    _assert_logged_with_its_traceback(out, "could not contact master")


def test_sigterm_and_shutdown_call_stop_it(env: dict[str, str]) -> None:
    port = free_port()
    proc = _start_core(port, env)
    try:
        _read_through(proc, "setting /run_id")
        code, out, _ = _finish(proc, signal.SIGTERM)
        assert code == 0
        assert out.endswith("done\n")
    finally:
        stop(proc)
    proc = _start_core(port, env)
    try:
        _read_through(proc, "started core service [/rosout]")
        master = RosProxy(f"http://localhost:{port}/")
        assert master.call("shutdown", "/tester", "bye") == [1, "shutdown", 0]
        out, _ = proc.communicate(timeout=30)
        assert proc.returncode == 0
        assert out.startswith(
            "shutdown request: bye\n[rosout-1] killing on exit\n[master] killing on exit\n"
        )
    finally:
        stop(proc)


def test_warns_when_ros_master_uri_names_another_port(env: dict[str, str]) -> None:
    port = free_port()
    proc = _start_core(port, {**env, "ROS_MASTER_URI": "http://localhost:1"})
    try:
        _read_through(proc, "setting /run_id")
        _, _, err = _finish(proc)
    finally:
        stop(proc)
    assert err == f"WARNING: ROS_MASTER_URI port [1] does not match this roscore [{port}]\n"
