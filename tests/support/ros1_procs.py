"""Processes for interop tests: free ports, ROS 1's rosmaster, ROS 1 tools and rospy nodes
(Debian's /usr/bin/python3), each stopped by PID when the test ends."""

from __future__ import annotations

import os
import signal
import socket
import subprocess
import time
import xmlrpc.client
from collections.abc import Iterator, Mapping
from contextlib import contextmanager
from pathlib import Path

from tests.support.ros1 import ros1_python_imports

ROS1_PYTHON = Path("/usr/bin/python3")
ROSMASTER = Path("/usr/bin/rosmaster")
ROSCORE = Path("/usr/bin/roscore")


def ros1_available() -> bool:
    """Whether ROS 1's master, tools and rospy are installed."""
    if not (ROSMASTER.exists() and ROSCORE.exists()):
        return False
    return ros1_python_imports("rospy", "rosmaster", "std_msgs.msg")


def free_port() -> int:
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        return int(sock.getsockname()[1])


def ros_env(master_uri: str, home: Path) -> dict[str, str]:
    """The environment for ROS 1 tools and nodes talking to `master_uri`."""
    env = {
        key: value
        for key, value in os.environ.items()
        if not key.startswith("ROS_") and key not in ("PYTHONPATH", "VIRTUAL_ENV")
    }
    env.update(
        ROS_MASTER_URI=master_uri,
        ROS_HOSTNAME="localhost",
        ROS_HOME=str(home),
        ROS_LOG_DIR=str(home / "log"),
        ROS_PACKAGE_PATH="/usr/share",
        PYTHONUNBUFFERED="1",
    )
    return env


def stop(proc: subprocess.Popen[bytes] | subprocess.Popen[str], grace: float = 5.0) -> None:
    """SIGINT, then SIGTERM, then SIGKILL, by PID, until the process is gone."""
    for sig, wait in ((signal.SIGINT, grace), (signal.SIGTERM, 2.0), (signal.SIGKILL, 2.0)):
        if proc.poll() is not None:
            return
        try:
            os.kill(proc.pid, sig)
        except ProcessLookupError:
            return
        try:
            proc.wait(wait)
        except subprocess.TimeoutExpired:
            continue


def wait_for_master(uri: str, timeout: float = 15.0) -> None:
    deadline = time.monotonic() + timeout
    while True:
        try:
            xmlrpc.client.ServerProxy(uri).getPid("/test")
            return
        except OSError:
            if time.monotonic() > deadline:
                raise
            time.sleep(0.05)


@contextmanager
def rosmaster(home: Path) -> Iterator[str]:
    """ROS 1's rosmaster (as roscore starts it) on a free port; yields its URI."""
    port = free_port()
    uri = f"http://127.0.0.1:{port}/"
    proc = subprocess.Popen(
        [str(ROS1_PYTHON), str(ROSMASTER), "--core", "-p", str(port)],
        env=ros_env(uri, home),
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    try:
        wait_for_master(uri)
        yield uri
    finally:
        stop(proc)


def run_tool(args: list[str], env: Mapping[str, str], timeout: float = 30.0) -> tuple[int, str]:
    """Run a ROS 1 command-line tool; its exit code and its stdout and stderr together."""
    done = subprocess.run(
        [str(ROS1_PYTHON), *args],
        env=dict(env),
        capture_output=True,
        text=True,
        timeout=timeout,
        check=False,
    )
    return done.returncode, done.stdout + done.stderr
