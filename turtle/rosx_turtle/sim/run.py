"""``rosx sim``: `run_sim(argv, env)` starts Lab 1's graph in this process and shows it.

On a terminal it draws the pond, the teleop pane and the live graph panels until ``q`` or
Ctrl-C. When stdout is not a terminal, or with ``--headless``, it prints the master's URI and
turtlesim's log lines instead, and runs until SIGINT or SIGTERM. Either way other terminals
attach with ``ROS_MASTER_URI``. The first time it runs where ROS 1's command names do not run
rosx's tools, it says how to make every terminal ready (``rosx shell-init --install``).

``--robot [WORLD]`` runs the robot lab instead (`rosx_turtle.stage.lab`): stageros in the
TurtleBot3-shaped arena (or WORLD), its map on ``/map`` (or ``--map MAP.yaml``'s), ``map`` →
``odom``, and teleop_twist_keyboard in a pane, beside the same live panels.

``--tf-demo`` adds turtle_tf2's demo (a broadcaster per turtle, the listener that spawns
turtle2 and makes it follow turtle1), as ``roslaunch turtle_tf2 turtle_tf2_demo.launch`` does.

Its master listens on ``--port``, else on the port of ``ROS_MASTER_URI`` when that names this
machine (as roslaunch starts its core), else on 11311. With ``--join`` it starts no core:
turtlesim and teleop (and the screen) join the master already running at ``ROS_MASTER_URI`` (or,
with ``--port``, the one on that port of this host). When the
port is taken by a master, it says which nodes run there and how to join it or pick another
port. Exit status 0; 1 when the port is taken, the master to join does not answer, or the
robot lab's world or map cannot be read; 2 for a bad option.
"""

from __future__ import annotations

import argparse
import sys
from typing import TYPE_CHECKING, NoReturn

from rosx.core import PortInUseError
from rosx.master.client import MasterError, MasterUnreachable
from rosx.master.defaults import DEFAULT_MASTER_PORT, master_uri
from rosx.signals import stop_on_signals
from rosx.terminal import is_terminal
from rosx.transport.address import advertised_host, http_uri, is_local_host
from rosx.wire.xmlrpc_http import parse_http_uri
from rosx_turtle.console import Console
from rosx_turtle.env import ProcessEnv
from rosx_turtle.sim.host import SimHost
from rosx_turtle.stage.lab.plan import LabError, plan_lab
from rosx_turtle.tui.running import run_app

if TYPE_CHECKING:
    from collections.abc import Mapping, Sequence

    from _typeshed import SupportsWrite

    from rosx_turtle.env import Env
    from rosx_turtle.stage.lab.host import LabHost

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
        "-p",
        "--port",
        type=port,
        default=None,
        help=f"the master's port (ROS_MASTER_URI's on this machine, else {DEFAULT_MASTER_PORT})",
    )
    parser.add_argument(
        "--join",
        action="store_true",
        help="start no master: run turtlesim and teleop against the master at ROS_MASTER_URI "
        "(or at --port on this host)",
    )
    parser.add_argument(
        "--headless", action="store_true", help="no screen: print log lines, run until Ctrl-C"
    )
    parser.add_argument(
        "--robot",
        nargs="?",
        const="",
        default=None,
        metavar="WORLD",
        help="the robot lab instead: a simulated robot with a laser (Stage's WORLD, else a "
        "TurtleBot3-shaped arena), its map and keyboard teleop",
    )
    parser.add_argument(
        "--map", metavar="MAP.yaml", help="with --robot: the map map_server serves on /map"
    )
    parser.add_argument(
        "--tf-demo",
        action="store_true",
        help="also run turtle_tf2's demo: turtle2 follows turtle1 through tf",
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
    port_number = _own_port(env.environ) if options.port is None else options.port
    join = _join_uri(options.port, env) if options.join else None
    if options.map and options.robot is None:
        env.stderr.write("rosx sim: error: --map goes with --robot\n")
        return 2
    host: SimHost | LabHost
    if options.robot is None:
        host = SimHost(
            port_number,
            env.environ,
            console=console,
            seed=seed,
            watch=not headless,
            join=join,
            tf_demo=options.tf_demo,
        )
    else:
        from rosx_turtle.stage.lab.host import LabHost  # noqa: PLC0415 - numpy, the engine

        plan = plan_lab(options.robot or None, options.map)
        host = LabHost(
            plan, port_number, env.environ, console=console, watch=not headless, join=join
        )
    try:
        host.start()
    except PortInUseError as busy:
        _error(env, _port_taken(busy, options.port, robot=options.robot is not None))
        return 1
    except (MasterUnreachable, MasterError):
        _error(env, f"ERROR: Unable to communicate with master at {join}")
        _error(env, "Start one (rosx roscore), or run rosx sim without --join for its own.")
        return 1
    except LabError as problem:
        _error(env, str(problem))
        return 1
    except KeyboardInterrupt:  # Ctrl-C while starting: what started has been stopped
        return 0
    try:  # from here on Ctrl-C (or ``kill -INT``) stops what started, whenever it comes
        from rosx.workspace.path_commands import hint_once  # noqa: PLC0415 - once it runs

        notice = hint_once(env.environ)
        if headless:
            if notice:
                env.stderr.write(notice + "\n")
            _run_headless(host, env)
        else:
            _run_screen(host, notice)
    except KeyboardInterrupt:
        pass
    finally:
        host.stop()
    return 0


def _own_port(environ: Mapping[str, str]) -> int:
    """The port of the master ``rosx sim`` starts without ``--port``: that of
    ``ROS_MASTER_URI`` when it names this machine, as roslaunch starts its core there (so
    the other terminals, which follow the variable, find it), else 11311."""
    try:
        host, port, _ = parse_http_uri(master_uri(environ))
    except ValueError:
        return DEFAULT_MASTER_PORT
    return port if is_local_host(host) else DEFAULT_MASTER_PORT


def _join_uri(port_option: int | None, env: Env) -> str:
    """The master ``--join`` joins: at ``--port`` on this host, else ``ROS_MASTER_URI``."""
    if port_option is not None:
        return http_uri(advertised_host(env.environ), port_option)
    return master_uri(env.environ)


def _port_taken(busy: PortInUseError, port_option: int | None, *, robot: bool = False) -> str:
    """What to say when the master's port is taken: by a master (which nodes run there, and
    how to join it or use another port), or by something else (roscore's words, and the
    option); ``robot`` for the robot lab's command."""
    if not busy.another_master:
        return f"{busy.message}\nUse --port PORT for another port."
    command = "rosx sim --robot" if robot else "rosx sim"
    join = f"{command} --join" + (f" --port {busy.port}" if port_option is not None else "")
    what = "the robot lab" if robot else "turtlesim and teleop"
    return (
        f"A ROS master is already running at {busy.uri}\n"
        f"{_running_there(busy.uri)}\n"
        f"Run `{join}` to start {what} against it,\n"
        f"or `{command} --port PORT` for a master of its own on another port."
    )


def _running_there(uri: str) -> str:
    from rosx.graph.fetch import fetch_state  # noqa: PLC0415 - only when the port is taken

    try:
        nodes = fetch_state(uri, "/rosx_sim", bus_info=False).nodes
    except (MasterUnreachable, MasterError):
        return "Its nodes could not be listed."
    return "Nodes there: " + (", ".join(nodes) if nodes else "none")


def _error(env: Env, text: str) -> None:
    colour = is_terminal(env.stderr)
    env.stderr.write((f"\033[31m{text}\033[0m" if colour else text) + "\n")
    env.stderr.flush()


def _run_headless(host: SimHost | LabHost, env: Env) -> None:
    env.stdout.write(f"ROS_MASTER_URI={host.master_uri}\n")
    env.stdout.flush()
    with stop_on_signals() as stop:
        while not stop.wait(0.2):
            pass


def _run_screen(host: SimHost | LabHost, notice: str | None) -> None:
    if isinstance(host, SimHost):
        from rosx_turtle.tui.factory import make_sim_app  # noqa: PLC0415 - textual for the screen

        run_app(make_sim_app(host, notice=notice))
        return
    from rosx_turtle.stage.view.lab_app import make_lab_app  # noqa: PLC0415 - textual

    run_app(make_lab_app(host, notice=notice))
