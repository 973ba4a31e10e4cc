#!/usr/bin/env python3
"""actionlib_tools' axclient.py, where rosrun finds it (catkin's libexec folder):
``rosx axclient``."""

import sys

from rosx_commands.main import run_tool

sys.exit(run_tool(["axclient", *sys.argv[1:]]))
