"""``rosx sim``: `run_sim(argv, env)` starts Lab 1's graph in this process and shows it.

On a terminal it draws the pond, the teleop pane and the live graph panels until ``q`` or
Ctrl-C. When stdout is not a terminal, or with ``--headless``, it prints the master's URI and
turtlesim's log lines instead, and runs until SIGINT or SIGTERM. Either way other terminals
attach with ``ROS_MASTER_URI``. Exit status 0, or 1 when the master's port is taken (with
roscore's words for it), or 2 for a bad option.
"""

from __future__ import annotations

import argparse
import sys
from typing import TYPE_CHECKING, NoReturn

from rosx.core import PortInUseError
from rosx_turtle.console import Console
from rosx_turtle.env import ProcessEnv
from rosx_turtle.program import stop_on_signals
from rosx_turtle.sim.host import SimHost
from rosx_turtle.tui.running import is_terminal, run_app

if TYPE_CHECKING:
    from collections.abc import Sequence

    from _typeshed import SupportsWrite

    from rosx_turtle.env import Env

DEFAULT_PORT = 11311
DESCRIPTION = (
    "Run a ROS master, /rosout, turtlesim and a keyboard teleop in one process, and show the "
    "pond with live topic and node panels. Other terminals attach with ROS_MASTER_URI."
)


class _ExitError(Exception):
    def __init__(self, status: int) -> None:
        super().__init__(status)
        self.status = status


class _Parser(argparse.ArgumentParser):
    """argparse writing to the run's streams and returning instead of exiting."""

    def __init__(self, env: Env) -> None:
        super().__init__(prog="rosx sim", description=DESCRIPTION)
        self.env = env

    def _print_message(self, message: str, file: SupportsWrite[str] | None = None) -> None:
        if message:
            stream = self.env.stderr if file is sys.stderr else self.env.stdout
            stream.write(message)

    def exit(self, status: int = 0, message: str | None = None) -> NoReturn:
        if message:
            self.env.stderr.write(message)
        raise _ExitError(status)


def port(text: str) -> int:
    """A port number, 1 to 65535 (argparse names the option's type after this function)."""
    number = int(text)
    if not 0 < number < 65536:
        raise ValueError(text)
    return number


def _parse(argv: Sequence[str], env: Env) -> argparse.Namespace:
    parser = _Parser(env)
    parser.add_argument(
        "-p", "--port", type=port, default=DEFAULT_PORT, help="the master's port (11311)"
    )
    parser.add_argument(
        "--headless", action="store_true", help="no screen: print log lines, run until Ctrl-C"
    )
    return parser.parse_args(list(argv))


def run_sim(argv: Sequence[str], env: Env | None = None, *, seed: int | None = None) -> int:
    """Run ``rosx sim ARGV…``; the exit status (see the module docstring)."""
    env = env or ProcessEnv()
    try:
        options = _parse(argv, env)
    except _ExitError as done:
        return done.status
    headless = options.headless or not is_terminal(env.stdout)
    console = Console(env.stdout, env.stderr, env.environ) if headless else None
    host = SimHost(options.port, env.environ, console=console, seed=seed, watch=not headless)
    try:
        host.start()
    except PortInUseError as busy:
        colour = is_terminal(env.stderr)
        text = busy.message
        env.stderr.write((f"\033[31m{text}\033[0m" if colour else text) + "\n")
        env.stderr.flush()
        return 1
    except KeyboardInterrupt:  # Ctrl-C while starting: what started has been stopped
        return 0
    try:
        if headless:
            _run_headless(host, env)
        else:
            _run_screen(host)
    except KeyboardInterrupt:
        pass
    finally:
        host.stop()
    return 0


def _run_headless(host: SimHost, env: Env) -> None:
    env.stdout.write(f"ROS_MASTER_URI={host.master_uri}\n")
    env.stdout.flush()
    with stop_on_signals() as stop:
        while not stop.wait(0.2):
            pass


def _run_screen(host: SimHost) -> None:
    from rosx_turtle.tui.factory import make_sim_app  # noqa: PLC0415 - textual for the screen

    run_app(make_sim_app(host))
