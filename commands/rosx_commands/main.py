"""The ``rosx`` entry point: one sub-command per ROS tool (`rosx_commands.tools`), each loaded
only when used.

``rosx rostopic list`` imports the rostopic module and nothing else of the CLI (not even typer),
so short commands stay fast; ``rosx --help`` builds the typer menu (`rosx_commands.menu`).
"""

from __future__ import annotations

import sys
from collections.abc import Sequence

from rosx.signals import interrupt_on_sigint
from rosx_commands.context import Environment
from rosx_commands.tools import TOOLS, load_tool


def run_tool(argv: Sequence[str], env: Environment | None = None) -> int:
    """Run ``rosx ARGV…`` and return its exit status (the tests' way in)."""
    env = env or Environment()
    if argv and argv[0] in TOOLS:
        status = load_tool(argv[0])(argv[1:], env)
        if status and env.stderr_isatty:
            _hint(argv[0], argv[1:], env)
        return status
    from rosx_commands.menu import run_menu  # noqa: PLC0415 - typer only for the menu

    return run_menu(argv, env)


def _hint(tool: str, args: Sequence[str], env: Environment) -> None:
    """After a tool's error, on a terminal: the command meant, when words typed with spaces
    for underscores make a name that exists, or what rosx has instead of a package it lacks
    (`rosx_commands.hints.after_error`)."""
    from rosx_commands.hints import after_error  # noqa: PLC0415 - only after an error

    line = after_error(tool, args, env)
    if line is not None:
        env.err(line)


def run() -> None:
    """Console-script entry point."""
    interrupt_on_sigint()
    sys.exit(run_tool(sys.argv[1:]))


__all__ = ["TOOLS", "load_tool", "run", "run_tool"]
