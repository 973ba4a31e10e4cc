"""turtlesim's executables, as ``rosrun turtlesim <name>`` finds them.

`EXECUTABLES` maps each name to ``module:function``; the function takes the arguments after
the program name and an `Env`, and returns the exit status. Each module is imported only when
its program runs (the teleop does not pay for numpy). `main` runs one by name:
``python -m rosx_turtle turtlesim_node __name:=sim``.
"""

from __future__ import annotations

import importlib
import sys
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from collections.abc import Callable, Sequence

    from rosx_turtle.env import Env

    Program = Callable[[Sequence[str], Env | None], int]

EXECUTABLES: dict[str, str] = {
    "turtlesim_node": "rosx_turtle.tui.pond_run:run_turtlesim_node",
    "turtle_teleop_key": "rosx_turtle.teleop:run_teleop",
    "draw_square": "rosx_turtle.tutorials.draw_square:run_draw_square",
    "mimic": "rosx_turtle.tutorials.mimic:run_mimic",
    "turtlesim_view": "rosx_turtle.viewer:run_turtlesim_view",
}


def load(name: str) -> Program:
    """The program called ``name``; `KeyError` if turtlesim has none."""
    module, _, function = EXECUTABLES[name].partition(":")
    program: Program = getattr(importlib.import_module(module), function)
    return program


def main(argv: Sequence[str] | None = None, env: Env | None = None) -> int:
    """Run ``argv[0]`` with the rest of ``argv``; 2 with a usage line when there is none."""
    argv = list(sys.argv[1:] if argv is None else argv)
    if not argv or argv[0] not in EXECUTABLES:
        names = ", ".join(sorted(EXECUTABLES))
        print(
            f"usage: python -m rosx_turtle EXECUTABLE [ARGS...]  (one of: {names})", file=sys.stderr
        )
        return 2
    return load(argv[0])(argv[1:], env)
