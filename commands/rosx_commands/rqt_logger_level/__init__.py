"""``rosx rqt_logger_level``: the logger levels of every running node, shown and set.

On a terminal, three lists (nodes → loggers → levels, `rosx_commands.rqt_logger_level.app`);
when stdout is not a terminal (or with ``--text``), each node and its loggers with their
levels, printed once. Levels are read with each node's ``~get_loggers`` and set with its
``~set_logger_level``, which rosx, rospy and roscpp nodes serve alike.
"""

from __future__ import annotations

from collections.abc import Sequence

from rosx_commands.cli import ToolParser, run_command
from rosx_commands.context import CommandError, Environment, ExitStatus

USAGE = """usage: %prog [options]

Show and set the logger levels of running nodes: pick a node, a logger, then a level
(enter sets it). r reads the nodes again, tab moves between the lists, q or Ctrl-C quits."""


def _parser(env: Environment) -> ToolParser:
    parser = ToolParser(env, "rqt_logger_level", USAGE)
    parser.add_option(
        "--text",
        dest="text",
        default=False,
        action="store_true",
        help="print every node's loggers and levels once and exit",
    )
    return parser


def rqt_logger_level(argv: Sequence[str], env: Environment) -> int:
    """Run ``rosx rqt_logger_level ARGV…``."""
    return run_command(_rqt_logger_level, list(argv), env)


def _rqt_logger_level(argv: list[str], env: Environment) -> int:
    from rosx_commands.rqt_logger_level.source import LiveSource  # noqa: PLC0415 - this tool's parts load only when used

    options, rest = _parser(env).parse(argv)
    if rest:
        raise CommandError(
            f"rqt_logger_level: error: unexpected argument {rest[0]!r}", ExitStatus.USAGE
        )
    source = LiveSource(env.master_uri)
    if not options.text and env.stdout_isatty:
        from rosx_commands.rqt_logger_level.app import make_level_app  # noqa: PLC0415 - this tool's parts load only when used

        make_level_app(source).run()
        return ExitStatus.OK
    try:
        for node in source.nodes():
            env.out(node)
            for logger, level in source.loggers(node):
                env.out(f"  {logger}: {level}")
    finally:
        source.close()
    return ExitStatus.OK
