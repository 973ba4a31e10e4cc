"""The ROS log folder: where roscore, roslaunch and their nodes write, as ROS 1 lays it out.

ROS 1 (rospkg, rosgraph.roslogging) keeps logs under ``ROS_LOG_DIR`` if set, else
``ROS_HOME/log``, else ``~/.ros/log``; each run of a core gets a folder named by its run id
(``/run_id``), and a ``latest`` symbolic link in the log folder points at the newest one.
roslaunch (and roscore, which is a roslaunch) writes ``roslaunch-<host>-<pid>.log`` there, a
node launched with its output logged writes ``<name>-<n>-stdout.log``, and every node gets
``__log:=<run folder>/<name>-<n>.log``. ``roscd log`` goes to the current run's folder
(`current_log_dir`), as rosbash's does through ``roslaunch-logs``.

Everything takes the environment as a mapping; nothing here reads `os.environ`.
"""

from __future__ import annotations

import os
import socket
from pathlib import Path
from typing import TYPE_CHECKING

from rosx.cache import ros_home

if TYPE_CHECKING:
    from collections.abc import Callable, Mapping

#: Above this many bytes in the log folder, roslaunch suggests ``rosclean``.
DISK_USAGE_WARNING = 1 << 30


def log_dir(environ: Mapping[str, str]) -> Path:
    """``ROS_LOG_DIR``, or ``ROS_HOME/log``: the folder holding one folder per run."""
    if "ROS_LOG_DIR" in environ:
        return Path(environ["ROS_LOG_DIR"])
    return ros_home(environ) / "log"


def run_log_dir(environ: Mapping[str, str], run_id: str) -> Path:
    """The folder of one run: ``<log folder>/<run_id>``."""
    return log_dir(environ) / run_id


def prepare_run_log_dir(environ: Mapping[str, str], run_id: str) -> Path:
    """Create the run's folder and point ``latest`` at it; the folder.

    A ``latest`` that is not a symbolic link is left alone, as ROS 1 leaves it.

    Raises:
        OSError: the folder cannot be created.
    """
    folder = run_log_dir(environ, run_id)
    folder.mkdir(parents=True, exist_ok=True)
    latest = folder.parent / "latest"
    try:
        if latest.is_symlink():
            latest.unlink()
        if not latest.exists():
            latest.symlink_to(folder)
    except OSError:
        pass  # another launcher renewed it at the same moment, or the folder is read-only
    return folder


def current_run_id(environ: Mapping[str, str], timeout: float = 2.0) -> str | None:
    """The ``/run_id`` of the master at ``ROS_MASTER_URI``, or None when none answers."""
    from rosx.master.client import (  # noqa: PLC0415 - the network only for roscd log
        MasterClient,
        MasterError,
        MasterUnreachable,
    )
    from rosx.master.defaults import master_uri  # noqa: PLC0415 - as the client

    master = MasterClient(master_uri(environ), "/roslaunch", timeout=timeout)
    try:
        run_id = master.call("getParam", "/run_id")
    except (MasterError, MasterUnreachable, ValueError):
        return None
    finally:
        master.close()
    return str(run_id) if run_id else None


def current_log_dir(environ: Mapping[str, str]) -> tuple[Path, bool]:
    """Where ``roscd log`` goes, as ``roslaunch-logs`` says: the running core's run folder, or
    the log folder itself when no master answers; and whether a master answered."""
    run_id = current_run_id(environ)
    if run_id is None:
        return log_dir(environ), False
    return run_log_dir(environ, run_id), True


def launcher_log_name(pid: int | None = None) -> str:
    """``roslaunch-<host>-<pid>.log``: the log file of roslaunch (and roscore)."""
    return f"roslaunch-{socket.gethostname()}-{os.getpid() if pid is None else pid}.log"


def announce_run_log(
    environ: Mapping[str, str],
    run_id: str,
    *,
    out: Callable[[str], object],
    err: Callable[[str], object],
    check_disk: bool = True,
) -> Path | None:
    """What roslaunch and roscore do and print first: the run's log folder (with ``latest``),
    ``... logging to <folder>/roslaunch-<host>-<pid>.log``, then the disk-usage check.

    Returns:
        The launcher's log file (created empty), or None when the folder cannot be made
        (rosgraph's warnings are printed then, and nothing is logged).
    """
    try:
        folder = prepare_run_log_dir(environ, run_id)
        path = folder / launcher_log_name()
        path.touch()
    except OSError:
        err(
            f"WARNING: cannot create log directory [{run_log_dir(environ, run_id)}]. "
            "Please set ROS_LOG_DIR to a writable location."
        )
        err("WARNING: unable to configure logging. No log files will be generated")
        return None
    out(f"... logging to {path}")
    if check_disk:
        out("Checking log directory for disk usage. This may take a while.")
        out("Press Ctrl-C to interrupt")
        logs = log_dir(environ)
        if disk_usage(logs) > DISK_USAGE_WARNING:
            err(
                f"WARNING: disk usage in log directory [{logs}] is over 1GB.\n"
                "It's recommended that you use the 'rosclean' command."
            )
        else:
            out("Done checking log file disk usage. Usage is <1GB.")
    return path


def disk_usage(folder: Path) -> int:
    """The bytes of the files below ``folder`` (0 if it does not exist)."""
    total = 0
    for directory, _, files in os.walk(folder):
        for name in files:
            try:
                total += (Path(directory) / name).lstat().st_size
            except OSError:
                continue
    return total


__all__ = [
    "DISK_USAGE_WARNING",
    "announce_run_log",
    "current_log_dir",
    "current_run_id",
    "disk_usage",
    "launcher_log_name",
    "log_dir",
    "prepare_run_log_dir",
    "ros_home",
    "run_log_dir",
]
