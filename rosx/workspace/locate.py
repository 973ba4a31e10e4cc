"""Where ``roscd`` and ``rosls`` go: ``package[/sub/dir]``, or the workspace with no argument.

``log`` is the log folder of the running core (what ``roslaunch-logs`` answers, see
`rosx.workspace.logdir`). With no argument, rosbash's roscd goes to ``ROS_WORKSPACE`` if set,
else to the first entry of ``CMAKE_PREFIX_PATH`` that is a catkin workspace (holds a
``.catkin`` file: a ``devel`` directory), and otherwise explains that neither is set.
``package/sub/dir`` goes below the package's directory.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import TYPE_CHECKING

from rosx.packages.index import PackageIndex, PackageNotFoundError

if TYPE_CHECKING:
    from collections.abc import Mapping

NO_WORKSPACE = (
    "Neither ROS_WORKSPACE is set nor a catkin workspace is listed in CMAKE_PREFIX_PATH.  "
    "Please set ROS_WORKSPACE or source a catkin workspace to use roscd with no arguments."
)


class LocateError(LookupError):
    """Nowhere to go; ``str()`` is rosbash's text."""


def workspace_dir(environ: Mapping[str, str]) -> Path:
    """Where ``roscd`` with no argument goes."""
    if environ.get("ROS_WORKSPACE"):
        return Path(environ["ROS_WORKSPACE"])
    for entry in environ.get("CMAKE_PREFIX_PATH", "").split(os.pathsep):
        if entry and (Path(entry) / ".catkin").is_file():
            return Path(entry)
    raise LocateError(NO_WORKSPACE)


def locate(target: str, environ: Mapping[str, str], notes: list[str] | None = None) -> Path:
    """The directory ``roscd TARGET`` goes to (``TARGET`` is ``package[/sub/dir]``, or
    ``log[/sub/dir]``: the running core's log folder). What rosbash prints on the way (``No
    active roscore`` for ``log`` without a master) is added to ``notes``."""
    if not target:
        return workspace_dir(environ)
    package, _, rest = target.partition("/")
    if package == "log":
        from rosx.workspace.logdir import current_log_dir  # noqa: PLC0415 - workspace code loads only when used

        directory, running = current_log_dir(environ)
        if not running and notes is not None:
            notes.append("No active roscore")
        return directory / rest if rest else directory
    try:
        directory = PackageIndex.from_environ(environ).find(package)
    except PackageNotFoundError:
        raise LocateError(f"roscd: No such package/stack '{target}'") from None
    return directory / rest if rest else directory


__all__ = ["NO_WORKSPACE", "LocateError", "locate", "workspace_dir"]
