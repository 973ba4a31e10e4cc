#!/usr/bin/env python3
"""actionlib_tools' axserver.py, where rosrun finds it (catkin's libexec folder):
``rosx axserver``."""

import sys

from rosx_commands.main import run_tool

sys.exit(run_tool(["axserver", *sys.argv[1:]]))
