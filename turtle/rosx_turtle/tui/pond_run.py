"""turtlesim_node on a terminal: the pond full-screen instead of log lines.

`run_turtlesim_node` is the program: with stdout a terminal (and no ``--headless``, and no
``ROSX_HEADLESS`` in the environment: ``rosx roslaunch`` sets it for the nodes that share its
terminal) it starts the node as `rosx_turtle.node.run.run_turtlesim` does, then draws the pond
until ``q``, Ctrl-C,
SIGTERM or a shutdown from outside (``rosnode kill``), and leaves the graph. Otherwise it is
`run_turtlesim` itself, log lines only. The log lines still reach ``/rosout`` while the pond is
drawn; messages from before the pond opens (waiting for the master) are printed as usual.
`show_pond` draws the pond of a node that is already running.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from rosx.signals import stop_on_signals
from rosx.terminal import is_terminal
from rosx_turtle.console import Console
from rosx_turtle.env import ProcessEnv
from rosx_turtle.node.run import DEFAULT_NAME, run_turtlesim
from rosx_turtle.program import master_address, start_when_master_is_up
from rosx_turtle.roscpp import NodeArgs
from rosx_turtle.tui.log import ScreenConsole
from rosx_turtle.tui.running import run_app

if TYPE_CHECKING:
    from collections.abc import Sequence

    from rosx_turtle.env import Env
    from rosx_turtle.node.turtlesim import TurtlesimNode
    from rosx_turtle.tui.feed import Feed
    from rosx_turtle.tui.log import LogRecord
    from rosx_turtle.view.scene import Scene

#: The option that asks for log lines even on a terminal.
HEADLESS = "--headless"
#: The environment variable that asks for them too (any value but "" and "0").
HEADLESS_VARIABLE = "ROSX_HEADLESS"


def run_turtlesim_node(
    argv: Sequence[str], env: Env | None = None, *, seed: int | None = None
) -> int:
    """Run turtlesim_node: the pond on a terminal, log lines otherwise; the exit status."""
    env = env or ProcessEnv()
    args = [arg for arg in argv if arg != HEADLESS]
    headless = env.environ.get(HEADLESS_VARIABLE, "") not in ("", "0")
    if len(args) != len(argv) or headless or not is_terminal(env.stdout):
        return run_turtlesim(args, env, seed=seed)
    from rosx_turtle.node.turtlesim import TurtlesimNode  # noqa: PLC0415 - loads numpy
    from rosx_turtle.tui.feed import Feed  # noqa: PLC0415 - textual to draw

    node_args = NodeArgs.parse(args, DEFAULT_NAME)
    console = Console(env.stdout, env.stderr, env.environ)
    logs: Feed[LogRecord] = Feed()
    screen = ScreenConsole(logs.offer, env.environ)

    def start() -> TurtlesimNode:
        return TurtlesimNode(node_args, environ=env.environ, console=screen, seed=seed).start()

    address = master_address(node_args.master_uri, env.environ)
    with stop_on_signals() as stop:
        node = start_when_master_is_up(start, console, address, stop)
    if node is None:
        return 0
    try:
        show_pond(node, logs)
    finally:
        node.shutdown("user request")
    return 0


def show_pond(node: TurtlesimNode, logs: Feed[LogRecord] | None = None) -> None:
    """Draw ``node``'s pond full-screen until the user quits or the node shuts down; the
    latest record offered to ``logs`` (see `ScreenConsole`) shows under it."""
    from rosx_turtle.tui.factory import make_pond_app  # noqa: PLC0415 - textual to draw
    from rosx_turtle.tui.feed import Feed  # noqa: PLC0415 - turtlesim's parts load only when used
    from rosx_turtle.view.adapt import follow  # noqa: PLC0415 - turtlesim's parts load only when used

    scenes: Feed[Scene] = Feed()
    unfollow = follow(node, scenes.offer)
    try:
        run_app(make_pond_app(scenes, logs), gone=node.wait_for_shutdown)
    finally:
        unfollow()
