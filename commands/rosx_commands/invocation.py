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
