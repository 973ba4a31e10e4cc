"""Where the ROS 1 reference is, and how to run it; tests that need it skip cleanly without it."""

from __future__ import annotations

import contextlib
import functools
import json
import os
import shutil
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

ROS1_PYTHON = os.environ.get("ROS1_PYTHON", "/usr/bin/python3")
OVERLAY = Path(os.environ.get("ROS1_OVERLAY", "/tmp/ros1-overlay"))


@functools.cache
def ros1_python_imports(*modules: str) -> bool:
    """True when ROS 1's Python can import every one of ``modules``."""
    try:
        done = subprocess.run(
            [ROS1_PYTHON, "-c", "import " + ", ".join(modules)],
            capture_output=True,
            timeout=60,
            check=False,
        )
    except (OSError, subprocess.TimeoutExpired):
        return False
    return done.returncode == 0


def ros1_available() -> bool:
    """True when ROS 1's tools and rospy (Debian's Python) are installed with the overlay."""
    if shutil.which("roscore", path="/usr/bin") is None or not (OVERLAY / "turtlesim").is_dir():
        return False
    probe = subprocess.run(
        [ROS1_PYTHON, "-c", "import rospy, rosmsg, genpy"], capture_output=True, check=False
    )
    return probe.returncode == 0


ROS1 = ros1_available()
needs_ros1 = pytest.mark.skipif(not ROS1, reason="the ROS 1 reference is not installed")


#: rosx's package folder: the shim folders (``rospy``, ``tf2_ros``…) are in it.
_ROSX = Path(__file__).resolve().parents[2] / "rosx"


def ros1_environ(**extra: str) -> dict[str, str]:
    """The environment ROS 1's tools need (as ../shared/tools/ros1-reference prints it).

    rosx's shim folders on the run's ``PYTHONPATH`` (a shell that sourced a workspace's
    ``devel/setup.bash``) are left out: run from the checkout, where ROS 1's Python can import
    rosx, they would give it rosx's ``rospy`` instead of its own.
    """
    env = _without_rosx({k: v for k, v in os.environ.items() if not k.startswith("ROS_")})
    env["ROS_PACKAGE_PATH"] = f"{OVERLAY}:/usr/share"
    env.update(extra)
    return env


def _without_rosx(environ: dict[str, str]) -> dict[str, str]:
    """``environ`` without rosx's folders on its ``PYTHONPATH``."""
    env = dict(environ)
    entries = [entry for entry in env.pop("PYTHONPATH", "").split(os.pathsep) if entry]
    kept = [entry for entry in entries if _ROSX not in (p := Path(entry).resolve(), *p.parents)]
    if kept:
        env["PYTHONPATH"] = os.pathsep.join(kept)
    return env


#: What rospkg prints before reading a manifest where ``rosdep update`` never ran, as on the
#: reference machine (offline): a fact about that machine, not part of any tool's answer.
ROSDEP_UNSET = "the rosdep view is empty: call 'sudo rosdep init' and 'rosdep update'\n"


def run_ros1(args: list[str], *, stdin: str = "", **extra: str) -> subprocess.CompletedProcess[str]:
    """Run a ROS 1 command line (``rosmsg show …``) and capture its output."""
    done = subprocess.run(
        args,
        input=stdin,
        capture_output=True,
        text=True,
        env=ros1_environ(**extra),
        timeout=60,
        check=False,
    )
    done.stderr = done.stderr.replace(ROSDEP_UNSET, "")
    return done


def ros1_python(script: str, **extra: str) -> Any:
    """Run ``script`` under ROS 1's Python; it prints one JSON document, which is returned."""
    done = subprocess.run(
        [ROS1_PYTHON, "-c", script],
        capture_output=True,
        text=True,
        env=ros1_environ(**extra),
        timeout=120,
        check=True,
    )
    return json.loads(done.stdout)


#: The two masters interop tests run against.
ROSCORES = ["ros1-roscore", "rosx-roscore"]


def ros1_python_with_path(
    code: str, pythonpath: list[Path], cwd: Path
) -> subprocess.CompletedProcess[str]:
    """Run ``code`` in ROS 1's Python with ``pythonpath`` and no ``ROS_*`` variables."""
    env = {k: v for k, v in os.environ.items() if not k.startswith("ROS_")}
    env["PYTHONPATH"] = os.pathsep.join(str(p) for p in pythonpath)
    return subprocess.run(
        [ROS1_PYTHON, "-c", code], env=env, cwd=cwd, capture_output=True, text=True, check=False
    )


@contextlib.contextmanager
def roscore(kind: str) -> Iterator[str]:
    """ROS 1's roscore (``ros1-roscore``) or rosx's (``rosx-roscore``) on a free port; its URI."""
    from tests.support.procs import free_port, port_open, running, wait_for

    port = free_port()
    uri = f"http://localhost:{port}"
    if kind == "ros1-roscore":
        core = ["/usr/bin/roscore", "-p", str(port)]
    else:
        core = [sys.executable, "-m", "rosx_commands", "roscore", "-p", str(port)]
    environ = {k: v for k, v in os.environ.items() if not k.startswith("ROS_")}
    if kind == "ros1-roscore":
        environ = _without_rosx(environ)
    with running(core, {**environ, "ROS_MASTER_URI": uri}):
        wait_for(lambda: port_open(port), what=kind)
        yield uri
