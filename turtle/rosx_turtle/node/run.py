"""``turtlesim_node`` as a program: `run_turtlesim(argv, env)` returns its exit status."""

from __future__ import annotations

from typing import TYPE_CHECKING

from rosx_turtle.console import Console
from rosx_turtle.env import ProcessEnv
from rosx_turtle.node.turtlesim import TurtlesimNode
from rosx_turtle.program import master_address, run_until_stopped
from rosx_turtle.roscpp import NodeArgs

if TYPE_CHECKING:
    from collections.abc import Sequence

    from rosx_turtle.env import Env

#: The node's name unless ``__name:=`` says otherwise.
DEFAULT_NAME = "turtlesim"


def run_turtlesim(argv: Sequence[str], env: Env | None = None, *, seed: int | None = None) -> int:
    """Run turtlesim_node (headless: log lines only) until SIGINT, SIGTERM or a shutdown.

    ``argv`` holds the arguments after the program name: remappings (``from:=to``),
    ``__name:=``, ``__ns:=``, ``__master:=``, ``_background_r:=`` and the like; others are
    ignored, as turtlesim ignores them.
    """
    env = env or ProcessEnv()
    args = NodeArgs.parse(argv, DEFAULT_NAME)
    console = Console(env.stdout, env.stderr, env.environ)

    def start() -> TurtlesimNode:
        return TurtlesimNode(args, environ=env.environ, console=console, seed=seed).start()

    return run_until_stopped(start, console, master_address(args.master_uri, env.environ))
