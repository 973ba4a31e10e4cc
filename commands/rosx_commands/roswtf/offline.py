"""roswtf's static checks: the environment (``ROS_ROOT``, ``ROS_PACKAGE_PATH``,
``ROS_MASTER_URI``, ``PYTHONPATH``, ``ROS_HOME``…) and the network variables, in roswtf's words.

roswtf's checks of rosdep's database, of pip/Debian installs of its own Python modules, of
rosbuild manifests and stacks concern a ROS installation rosx does not have, and are not run.
"""

from __future__ import annotations

import os
import socket
from pathlib import Path
from typing import TYPE_CHECKING
from urllib.parse import urlsplit

if TYPE_CHECKING:
    from collections.abc import Callable, Mapping


def _paths(value: str | None) -> list[str]:
    return value.split(os.pathsep) if value else []


def invalid_url(url: str) -> str | None:
    """What is wrong with a master URI, as roswtf says it (None when nothing is, or it is
    empty: another check reports that)."""
    if not url:
        return None
    parts = urlsplit(url)
    if parts.scheme != "http":
        return "protocol is not 'http'"
    if not parts.netloc:
        return "address is missing"
    if ":" not in parts.netloc:
        return "port number is missing"
    pieces = parts.netloc.split(":")
    if len(pieces) != 2:
        return f"invalid address string [{parts.netloc}]"
    if not pieces[1].strip().lstrip("+-").isdigit():
        return f"port number [{pieces[1]}] is invalid"
    return None


def _unresolvable_master_host(url: str) -> str | None:
    netloc = urlsplit(url).netloc
    pieces = netloc.split(":")
    if not netloc or len(pieces) != 2:
        return None
    try:
        socket.getaddrinfo(pieces[0], 0, 0, 0, socket.SOL_TCP)
    except (socket.gaierror, UnicodeError):
        return f"Unknown host {pieces[0]}"
    return None


def _writable_dir(environ: Mapping[str, str], name: str) -> str | None:
    path = environ.get(name)
    if path is None:
        return None
    if Path(path).is_file():
        return f"{name} [{path}] must point to a directory, not a file"
    if not os.access(path, os.W_OK):
        return f"{name} [{path}] is not writable"
    return None


def _ros_hostname(environ: Mapping[str, str]) -> str | None:
    hostname = environ.get("ROS_HOSTNAME")
    if hostname is None:
        return None
    try:
        socket.getaddrinfo(hostname, 0, 0, 0, socket.SOL_TCP)
    except (socket.gaierror, UnicodeError):
        return f"ROS_HOSTNAME [{hostname}] cannot be resolved to an IP address"
    return None


def _ros_ip(environ: Mapping[str, str]) -> str | None:
    address = environ.get("ROS_IP")
    if address is not None and " " in address:
        return f"ROS_IP [{address}] contains whitespace. This is not a valid IP."
    return None


def rules(
    environ: Mapping[str, str], ros_root: str, master_uri: str
) -> list[tuple[str, Callable[[], object], str]]:
    """roswtf's environment and network rules, ``(level, check, message)``, in its order."""
    package_path = environ.get("ROS_PACKAGE_PATH")
    pythonpath = environ.get("PYTHONPATH", "")

    def package_path_files() -> list[str]:
        return [d for d in _paths(package_path) if d and Path(d).is_file()]

    def package_path_missing() -> list[str]:
        return [d for d in _paths(package_path) if d and not Path(d).is_dir()]

    def roslib_count() -> str | None:
        found = {p for p in _paths(pythonpath) if "roslib" in Path(p).parts}
        return (
            "Multiple roslib directories in PYTHONPATH (there should only be one)"
            if len(found) > 1
            else None
        )

    def root_name() -> str | None:
        if Path(os.path.normpath(ros_root)).name not in ("ros", "rosbuild"):
            return f"ROS_ROOT [{ros_root}] must end in directory named 'ros'"
        return None

    console = environ.get("ROSCONSOLE_CONFIG_FILE")
    return [
        (
            "warning",
            lambda: package_path is None,
            "ROS_PACKAGE_PATH is not set. This is not required, but is unusual",
        ),
        (
            "warning",
            lambda: not _paths(package_path),
            "ROS_PACKAGE_PATH is empty. This is not required, but is unusual",
        ),
        (
            "warning",
            lambda: not master_uri,
            "ROS_MASTER_URI is empty. This is not required, but is unusual",
        ),
        (
            "warning",
            lambda: _unresolvable_master_host(master_uri),
            f"Cannot resolve hostname in ROS_MASTER_URI [{master_uri}]",
        ),
        (
            "warning",
            lambda: console is not None and not Path(console).is_file(),
            "ROS_CONSOLE_CONFIG_FILE does not point to an existing file",
        ),
        (
            "error",
            lambda: not Path(ros_root).is_dir(),
            f"ROS_ROOT [{ros_root}] does not point to a directory",
        ),
        ("error", root_name, "ROS_ROOT is invalid: "),
        (
            "error",
            package_path_files,
            f"Path(s) in ROS_PACKAGE_PATH [{package_path}] points to a file instead of a "
            "directory: ",
        ),
        (
            "error",
            package_path_missing,
            f"Not all paths in ROS_PACKAGE_PATH [{package_path}] point to an existing directory: ",
        ),
        (
            "error",
            lambda: [d for d in _paths(pythonpath) if d and not Path(d).is_dir()],
            f"Not all paths in PYTHONPATH [{pythonpath}] point to a directory: ",
        ),
        ("error", roslib_count, f"PYTHONPATH [{pythonpath}] is invalid: "),
        ("error", lambda: _writable_dir(environ, "ROS_HOME"), "ROS_HOME is invalid: "),
        ("error", lambda: _writable_dir(environ, "ROS_LOG_DIR"), "ROS_LOG_DIR is invalid: "),
        (
            "error",
            lambda: _writable_dir(environ, "ROS_TEST_RESULTS_DIR"),
            "ROS_TEST_RESULTS_DIR is invalid: ",
        ),
        (
            "error",
            lambda: invalid_url(master_uri),
            f"ROS_MASTER_URI [{master_uri}] is not a valid URL: ",
        ),
        ("warning", lambda: _ros_hostname(environ), "ROS_HOSTNAME may be incorrect: "),
        ("warning", lambda: _ros_ip(environ), "ROS_IP may be incorrect: "),
    ]


__all__ = ["invalid_url", "rules"]
