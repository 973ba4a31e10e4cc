"""``stageros`` as a program: `run_stageros(argv, env)` returns its exit status.

``stageros [-g] [-u] [--headless] [--speed N] WORLD`` plus remapping arguments: ``-g`` (no
window, as stage_ros) and ``--headless`` run with log lines only; ``-u`` names robots'
topics after their models; ``--speed N`` runs the simulated clock N times faster than real
time. On a terminal, without those, the world is drawn (`rosx_turtle.stage.view`).
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import TYPE_CHECKING, NamedTuple

from rosx.node import FATAL
from rosx.signals import stop_on_signals
from rosx.terminal import is_terminal
from rosx_turtle.console import Console
from rosx_turtle.env import ProcessEnv
from rosx_turtle.program import (
    master_address,
    run_until_stopped,
    start_when_master_is_up,
)
from rosx_turtle.roscpp import NodeArgs

if TYPE_CHECKING:
    from collections.abc import Sequence

    from rosx_turtle.env import Env
    from rosx_turtle.stage.node.stageros import StageNode
    from rosx_turtle.tui.log import LogRecord

#: Asks for log lines even on a terminal, as for turtlesim_node (``rosx roslaunch`` sets it for
#: the nodes that share its terminal).
HEADLESS_VARIABLE = "ROSX_HEADLESS"
#: The node's name unless ``__name:=`` says otherwise.
DEFAULT_NAME = "stageros"
USAGE = "stageros <worldfile>"


class Options(NamedTuple):
    """stageros's command line."""

    world: Path
    headless: bool
    use_model_names: bool
    speed: float
    node: NodeArgs


class UsageError(ValueError):
    """A command line stageros cannot run."""


def parse_options(argv: Sequence[str]) -> Options:
    """Read stageros's command line (without the program name).

    Raises:
        UsageError: no world file, or a bad ``--speed``.
    """
    node = NodeArgs.parse(argv, DEFAULT_NAME)
    rest = list(node.argv)
    headless = use_model_names = False
    speed = 1.0
    words: list[str] = []
    while rest:
        word = rest.pop(0)
        if word in ("-g", "--headless"):
            headless = True
        elif word == "-u":
            use_model_names = True
        elif word == "--speed" or word.startswith("--speed="):
            text = word.partition("=")[2] if "=" in word else (rest.pop(0) if rest else "")
            try:
                speed = float(text)
            except ValueError:
                raise UsageError(f"--speed needs a number, not '{text}'") from None
            if not math.isfinite(speed) or speed <= 0:
                raise UsageError(f"--speed needs a number above 0, not '{text}'")
        else:
            words.append(word)
    if not words:
        raise UsageError(USAGE)
    return Options(Path(words[-1]), headless, use_model_names, speed, node)


def run_stageros(argv: Sequence[str], env: Env | None = None) -> int:
    """Run stageros until SIGINT, SIGTERM or a shutdown; the exit status."""
    env = env or ProcessEnv()
    console = Console(env.stdout, env.stderr, env.environ)
    try:
        options = parse_options(argv)
    except UsageError as exc:
        print(exc, file=env.stdout if str(exc) == USAGE else env.stderr)
        return 255 if str(exc) == USAGE else 2
    from rosx_turtle.stage.world.load import load_world  # noqa: PLC0415 - numpy
    from rosx_turtle.stage.world.worldfile import WorldFileError  # noqa: PLC0415 - turtlesim's parts load only when used

    if not options.world.is_file():
        console.print(FATAL, f"The world file {options.world} does not exist.")
        return 1
    try:
        world, grid = load_world(options.world)
    except WorldFileError as exc:
        console.print(FATAL, str(exc))
        return 1
    from rosx_turtle.stage.node.stageros import StageNode  # noqa: PLC0415 - turtlesim's parts load only when used

    def start() -> StageNode:
        return StageNode(
            options.node,
            world,
            grid,
            environ=env.environ,
            console=console,
            use_model_names=options.use_model_names,
            speed=options.speed,
        ).start()

    address = master_address(options.node.master_uri, env.environ)
    headless = env.environ.get(HEADLESS_VARIABLE, "") not in ("", "0")
    if options.headless or headless or not is_terminal(env.stdout):
        return run_until_stopped(start, console, address)
    from rosx_turtle.stage.view.run import show_world  # noqa: PLC0415 - textual to draw
    from rosx_turtle.tui.feed import Feed  # noqa: PLC0415 - turtlesim's parts load only when used
    from rosx_turtle.tui.log import ScreenConsole  # noqa: PLC0415 - turtlesim's parts load only when used

    logs: Feed[LogRecord] = Feed()
    screen = ScreenConsole(logs.offer, env.environ)

    def start_drawn() -> StageNode:
        return StageNode(
            options.node,
            world,
            grid,
            environ=env.environ,
            console=screen,
            use_model_names=options.use_model_names,
            speed=options.speed,
        ).start()

    with stop_on_signals() as stop:
        node = start_when_master_is_up(start_drawn, console, address, stop)
    if node is None:
        return 0
    try:
        show_world(node, logs)
    finally:
        node.shutdown("user request")
    return 0


__all__ = ["DEFAULT_NAME", "USAGE", "Options", "UsageError", "parse_options", "run_stageros"]
