#!/usr/bin/env python3
"""teleop_twist_keyboard's program, where rosrun and roslaunch look for it (libexec)."""

import sys

from rosx_turtle.teleop_twist import run_teleop_twist

sys.exit(run_teleop_twist(sys.argv[1:]))
