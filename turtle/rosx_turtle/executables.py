"""The programs of turtlesim and roscpp_tutorials, as ``rosrun <package> <name>`` finds them.

`PROGRAMS` maps each package's program names to ``module:function`` (`EXECUTABLES`:
turtlesim's); the function takes the arguments after the program name and an `Env`, and
returns the exit status. Each module is imported only when its program runs (the teleop does
not pay for numpy). `main` runs one by name, turtlesim's by default:
``python -m rosx_turtle turtlesim_node __name:=sim``,
``python -m rosx_turtle roscpp_tutorials/talker``.
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

ROSCPP_TUTORIALS: dict[str, str] = {
    "talker": "rosx_turtle.roscpp_tutorials.chatter:run_talker",
    "listener": "rosx_turtle.roscpp_tutorials.chatter:run_listener",
    "add_two_ints_server": "rosx_turtle.roscpp_tutorials.add_two_ints:run_server",
    "add_two_ints_client": "rosx_turtle.roscpp_tutorials.add_two_ints:run_client",
}

PROGRAMS: dict[str, dict[str, str]] = {
    "turtlesim": EXECUTABLES,
    "roscpp_tutorials": ROSCPP_TUTORIALS,
}


def load(name: str, package: str = "turtlesim") -> Program:
    """The program ``name`` of ``package``; `KeyError` if it has none."""
    module, _, function = PROGRAMS[package][name].partition(":")
    program: Program = getattr(importlib.import_module(module), function)
    return program


def main(argv: Sequence[str] | None = None, env: Env | None = None) -> int:
    """Run ``argv[0]`` with the rest of ``argv``; 2 with a usage line when there is none."""
    argv = list(sys.argv[1:] if argv is None else argv)
    package, _, name = argv[0].rpartition("/") if argv else ("", "", "")
    package = package or "turtlesim"
    if name not in PROGRAMS.get(package, {}):
        names = ", ".join(sorted(EXECUTABLES) + [f"roscpp_tutorials/{n}" for n in ROSCPP_TUTORIALS])
        print(
            f"usage: python -m rosx_turtle EXECUTABLE [ARGS...]  (one of: {names})", file=sys.stderr
        )
        return 2
    return load(name, package)(argv[1:], env)
