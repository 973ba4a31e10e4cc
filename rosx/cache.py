"""rosx's folder in the user's cache (``$XDG_CACHE_HOME/rosx``, else ``~/.cache/rosx``), and
ROS's own folder (``ROS_HOME``, else ``~/.ros``).

The XDG Base Directory rules: a relative ``XDG_CACHE_HOME`` is ignored. The standard message
types' texts (`rosx.msg.standard`) and the programs of ``rosx shell-init``
(`rosx.workspace.path_commands`) are kept there. ``ROS_HOME`` holds what ROS 1 keeps there:
the logs (`rosx.workspace.logdir`) and, as rospack's, the package index's cache
(`rosx.packages.cache`).
"""

from __future__ import annotations

import os

TYPE_CHECKING = False  # not typing's: a short command here must not import it
if TYPE_CHECKING:
    from collections.abc import Mapping
    from pathlib import Path


def cache_folder(environ: Mapping[str, str]) -> Path | None:
    """rosx's cache folder for the environment ``environ``; None when it names no absolute one."""
    cache = environ.get("XDG_CACHE_HOME", "")
    if not os.path.isabs(cache):  # noqa: PTH117 - no Path made for a value thrown away
        home = environ.get("HOME") or os.path.expanduser("~")  # noqa: PTH111 - HOME may be unset
        if not os.path.isabs(home):  # noqa: PTH117
            return None
        cache = os.path.join(home, ".cache")  # noqa: PTH118
    from pathlib import Path  # noqa: PLC0415 - a <TAB> imports this module and not pathlib

    return Path(cache, "rosx")


def ros_home(environ: Mapping[str, str]) -> Path:
    """``ROS_HOME``, or ``~/.ros``: where ROS keeps its files and where nodes run by default."""
    from pathlib import Path  # noqa: PLC0415 - a <TAB> imports this module and not pathlib

    return Path(ros_home_text(environ))


def ros_home_text(environ: Mapping[str, str]) -> str:
    """`ros_home` as a string, without pathlib (a <TAB> reads the package index's cache there)."""
    if "ROS_HOME" in environ:
        return environ["ROS_HOME"]
    home = environ.get("HOME") or os.path.expanduser("~")  # noqa: PTH111 - HOME may be unset
    return os.path.join(home, ".ros")  # noqa: PTH118 - strings, no pathlib


__all__ = ["cache_folder", "ros_home", "ros_home_text"]
