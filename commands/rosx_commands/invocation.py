"""Where a command runs: how to run this rosx again, and the user's working directory."""

from __future__ import annotations

import os
import sys
from pathlib import Path

from rosx.workspace.shell import rosx_command
from rosx_commands.context import Environment


def self_command() -> str:
    """The shell words that run rosx, absolute so they work without rosx on ``PATH``."""
    script = Path(sys.argv[0]) if sys.argv and sys.argv[0] else None
    if script is not None and script.name == "rosx" and os.access(script, os.X_OK):
        return rosx_command([str(script.absolute())])
    return rosx_command([sys.executable, "-m", "rosx_commands"])


def complete_command() -> str:
    """The shell words that answer a <TAB> (`rosx_commands.complete.main`): this Python,
    started without ``site`` and isolated from ``PYTHON*`` variables (``-I -S``), given this
    process's module path, so that it finds rosx and its libraries as this one does (pipx's
    and venvs' installs, editable ones) without paying for ``site`` and rosx's command line."""
    import json  # noqa: PLC0415 - shell-init and catkin_make only

    # The first entry is this program's folder (or the working directory), not a library's.
    safe = sys.flags.isolated or getattr(sys.flags, "safe_path", False)  # 3.11's -P
    path = sys.path if safe else sys.path[1:]
    # A JSON list of strings is a Python list: double quotes, which shlex leaves alone.
    code = (
        f"import sys; sys.path[:] = {json.dumps(path)}; "
        "from rosx_commands.complete import main; main()"
    )
    return rosx_command([sys.executable, "-I", "-S", "-c", code])


def script_command() -> list[str]:
    """The words that run a ROS Python script with rosx's ``rospy`` (``rosx run-script``); the
    script's path and arguments follow. ``rosrun`` and ``roslaunch`` start scripts with them."""
    return [sys.executable, "-m", "rosx_commands", "run-script"]


def working_directory(env: Environment) -> Path:
    """The directory the user is in: ``PWD`` (which keeps symbolic links, as shells show it)
    when it names the process's directory, else the process's directory."""
    here = Path.cwd()
    given = env.environ.get("PWD")
    if given and Path(given).is_dir() and Path(given).resolve() == here.resolve():
        return Path(given)
    return here
