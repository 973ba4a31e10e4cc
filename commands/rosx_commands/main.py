"""The ``rosx`` entry point: one sub-command per ROS tool (`rosx_commands.tools`), each loaded
only when used.

``rosx rostopic list`` imports the rostopic module and nothing else of the CLI (not even typer),
so short commands stay fast; ``rosx --help`` builds the typer menu (`rosx_commands.menu`).
"""

from __future__ import annotations

import signal
import sys
from collections.abc import Sequence

from rosx_commands.context import Environment
from rosx_commands.tools import TOOLS, load_tool


def run_tool(argv: Sequence[str], env: Environment | None = None) -> int:
    """Run ``rosx ARGV…`` and return its exit status (the tests' way in)."""
    env = env or Environment()
    if argv and argv[0] in TOOLS:
        return load_tool(argv[0])(argv[1:], env)
    from rosx_commands.menu import run_menu  # noqa: PLC0415 - typer only for the menu

    return run_menu(argv, env)


def take_sigint() -> None:
    """Make SIGINT raise `KeyboardInterrupt` even when this process started with it ignored.

    A POSIX shell starts ``cmd &`` with SIGINT ignored, and Python then installs no handler of
    its own; ROS 1's tools install theirs and stop on ``kill -INT``, so rosx's do too.
    """
    if signal.getsignal(signal.SIGINT) is signal.SIG_IGN:
        signal.signal(signal.SIGINT, signal.default_int_handler)


def run() -> None:
    """Console-script entry point."""
    take_sigint()
    sys.exit(run_tool(sys.argv[1:]))


__all__ = ["TOOLS", "load_tool", "run", "run_tool", "take_sigint"]
