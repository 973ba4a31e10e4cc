"""``python -m rosx_turtle EXECUTABLE [ARGS...]``: run one of turtlesim's programs."""

from __future__ import annotations

import sys

from rosx_turtle.executables import main

sys.exit(main())
