"""Where the ROS 1 reference is, and how to run it; tests that need it skip cleanly without it.

ROS 1 runs here see nothing that other runs on the machine change under them: the package
overlay is this test run's own copy (`OVERLAY`), ``ROS_HOME`` is a folder of the run's own, and
each `ros1_environ` gives a log folder of its own (`private_ros_home`).
"""

from __future__ import annotations

import atexit
import contextlib
import functools
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any
from xml.etree import ElementTree

import pytest

ROS1_PYTHON = os.environ.get("ROS1_PYTHON", "/usr/bin/python3")
#: The overlay the reference's script keeps (package.xml files for Debian's message packages,
#: turtlesim's definitions). Every ``eval "$(ros1-reference)"`` on the machine rewrites its files
#: in place (emptied, then written), so a ROS 1 crawl of it at that moment reads an empty
#: ``package.xml`` and fails with a ParseError: tests use `OVERLAY`, a copy of it.
SHARED_OVERLAY = Path(os.environ.get("ROS1_OVERLAY", "/tmp/ros1-overlay"))


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
    if (
        shutil.which("roscore", path="/usr/bin") is None
        or not (SHARED_OVERLAY / "turtlesim").is_dir()
    ):
        return False
    probe = subprocess.run(
        [ROS1_PYTHON, "-c", "import rospy, rosmsg, genpy"], capture_output=True, check=False
    )
    return probe.returncode == 0


ROS1 = ros1_available()
needs_ros1 = pytest.mark.skipif(not ROS1, reason="the ROS 1 reference is not installed")


def _private_folder() -> Path:
    """A folder of this process's own under the temporary folder, removed when it exits (by
    this process only: a fork of it that exits leaves it)."""
    folder = Path(tempfile.mkdtemp(prefix="rosx-tests-ros1-"))
    owner = os.getpid()

    def remove() -> None:
        if os.getpid() == owner:
            shutil.rmtree(folder, ignore_errors=True)

    atexit.register(remove)
    return folder


_PRIVATE = _private_folder() if ROS1 else None


def _whole(path: Path) -> bytes:
    """The bytes of a file of the shared overlay once it is whole: not the empty file a rewrite
    leaves for a moment, and for a ``package.xml`` one that parses."""
    deadline = time.monotonic() + 30.0
    while True:
        data = path.read_bytes()
        if data and (path.name != "package.xml" or _parses(data)):
            return data
        if time.monotonic() > deadline:
            raise TimeoutError(f"{path} stayed incomplete for 30 s")
        time.sleep(0.02)


def _parses(xml: bytes) -> bool:
    try:
        ElementTree.fromstring(xml)
    except ElementTree.ParseError:
        return False
    return True


def _copy_overlay(shared: Path, into: Path) -> Path:
    """A copy of the overlay ``shared`` in ``into``: its files whole, its links (to Debian's
    ``/usr/share/<pkg>/msg``) as links."""
    for folder, subfolders, files in os.walk(shared):
        target = into / Path(folder).relative_to(shared)
        target.mkdir(exist_ok=True)
        for name in [*subfolders, *files]:
            source = Path(folder, name)
            if source.is_symlink():
                (target / name).symlink_to(source.readlink())
            elif name in files:
                (target / name).write_bytes(_whole(source))
    return into


#: The overlay ROS 1 runs in tests see: this test run's copy of `SHARED_OVERLAY`.
OVERLAY = (
    SHARED_OVERLAY if _PRIVATE is None else _copy_overlay(SHARED_OVERLAY, _PRIVATE / "overlay")
)


def private_ros_home() -> dict[str, str]:
    """``ROS_HOME`` (rospack's cache, roscore's pid file) in a folder of this test run's own,
    not the user's ``~/.ros`` that every run on the machine shares, and ``ROS_LOG_DIR`` a new
    folder: two ROS 1 programs started at once renew ``log/latest`` at once, and the one that
    loses says so on stderr."""
    root = _PRIVATE or Path(tempfile.gettempdir())
    home = root / "ros_home"
    home.mkdir(exist_ok=True)
    logs = tempfile.mkdtemp(prefix="log-", dir=home)
    return {"ROS_HOME": str(home), "ROS_LOG_DIR": logs}


#: rosx's package folder: the shim folders (``rospy``, ``tf2_ros``…) are in it.
_ROSX = Path(__file__).resolve().parents[2] / "rosx"


def ros1_environ(**extra: str) -> dict[str, str]:
    """The environment ROS 1's tools need (as ../shared/tools/ros1-reference prints it).

    rosx's shim folders on the run's ``PYTHONPATH`` (a shell that sourced a workspace's
    ``devel/setup.bash``) are left out: run from the checkout, where ROS 1's Python can import
    rosx, they would give it rosx's ``rospy`` instead of its own. ``ROS_HOME`` and
    ``ROS_LOG_DIR`` are `private_ros_home`'s unless ``extra`` gives either.
    """
    env = _without_rosx({k: v for k, v in os.environ.items() if not k.startswith("ROS_")})
    env["ROS_PACKAGE_PATH"] = f"{OVERLAY}:/usr/share"
    if "ROS_HOME" not in extra and "ROS_LOG_DIR" not in extra:
        env.update(private_ros_home())
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

#: rospy's own shutdown race: its TCPROS server thread is still in ``accept()`` when the
#: program closes the listening socket, and the thread dies with a traceback after the tool's
#: answer (``rosservice call``, ``rostopic pub``…), now and then, more often on a loaded machine.
#: Exactly that traceback, and nothing else, is ROS 1's noise (`without_ros1_noise`).
ROSPY_ACCEPT_RACE = re.compile(
    r"Exception in thread [^\n]*:\n"
    r"Traceback \(most recent call last\):\n"
    r"(?:  File \"[^\n]*/threading\.py\", line \d+, in \w+\n(?:    [^\n]*\n)+)+"
    r"  File \"[^\n]*/rospy/impl/tcpros_base\.py\", line \d+, in run\n"
    r"    \(client_sock, client_addr\) = self\.server_sock\.accept\(\)\n(?: +\^+\n)?"
    r"  File \"[^\n]*/socket\.py\", line \d+, in accept\n"
    r"    fd, addr = self\._accept\(\)\n(?: +\^+\n)?"
    r"OSError: \[Errno 9\] Bad file descriptor\n"
)


def without_ros1_noise(stderr: str) -> str:
    """ROS 1's stderr without what is a fact of the machine or of ROS 1's own races rather than
    part of the tool's answer: `ROSDEP_UNSET` and `ROSPY_ACCEPT_RACE`. Only ever applied to
    ROS 1's side of a comparison; rosx's is compared as it is."""
    return ROSPY_ACCEPT_RACE.sub("", stderr.replace(ROSDEP_UNSET, ""))


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
    done.stderr = without_ros1_noise(done.stderr)
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
    with running(core, {**environ, **private_ros_home(), "ROS_MASTER_URI": uri}):
        wait_for(lambda: port_open(port), what=kind)
        yield uri
