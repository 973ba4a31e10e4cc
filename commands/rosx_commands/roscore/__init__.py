"""``rosx roscore``: master, parameter server and ``/rosout`` node, as ROS 1's roscore.

This module parses roscore's options; `run` runs the core (`rosx.core.Core`) and prints what
roscore prints.
"""

from __future__ import annotations

from collections.abc import Sequence

from rosx.master.defaults import DEFAULT_MASTER_PORT
from rosx_commands.cli import ToolParser, run_command
from rosx_commands.context import Environment

_DESCRIPTION = (
    "roscore will start up a ROS Master, a ROS Parameter Server and a rosout logging node"
)


def _roscore(argv: list[str], env: Environment) -> int:
    parser = ToolParser(env, "roscore", "usage: %prog [options]")
    parser.description = _DESCRIPTION
    parser.epilog = "See http://wiki.ros.org/roscore"
    parser.add_option(
        "-p",
        "--port",
        dest="port",
        default=None,
        help="master port. Only valid if master is launched",
    )
    parser.add_option(
        "-v", action="store_true", dest="verbose", default=False, help="verbose printing"
    )
    parser.add_option(
        "-w",
        "--numworkers",
        dest="num_workers",
        default=None,
        help="override number of worker threads",
    )
    parser.add_option(
        "-t",
        "--timeout",
        dest="timeout",
        help="override the socket connection timeout (in seconds).",
        default=None,
    )
    parser.add_option(
        "--master-logger-level",
        dest="master_logger_level",
        default=False,
        type=str,
        help="set rosmaster.master logger level ('debug', 'info', 'warn', 'error', 'fatal')",
    )
    parser.add_option(
        "--sigint-timeout",
        dest="sigint_timeout",
        type="float",
        default=15.0,
        help="the SIGINT timeout used when killing the core (in seconds).",
    )
    parser.add_option(
        "--sigterm-timeout",
        dest="sigterm_timeout",
        type="float",
        default=2.0,
        help="the SIGTERM timeout used when killing core if SIGINT does not stop the core "
        "(in seconds).",
    )
    options, args = parser.parse(argv)
    if args:
        parser.error("roscore does not take arguments")
    try:
        port = int(options.port) if options.port is not None else DEFAULT_MASTER_PORT
    except ValueError:
        parser.error(f"invalid port: {options.port}")
    if not 0 < port < 65536:
        parser.error(f"invalid port: {options.port}")

    from rosx_commands.roscore.run import run_roscore  # noqa: PLC0415 - not for -h, usage errors

    return run_roscore(port, env.environ, env.stdout, env.stderr)


def roscore(argv: Sequence[str], env: Environment) -> int:
    """Run ``roscore ARGV…``."""
    return run_command(_roscore, list(argv), env)
