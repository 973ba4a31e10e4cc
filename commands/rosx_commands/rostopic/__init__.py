"""``rosx rostopic``: ROS 1's rostopic, sub-command by sub-command.

``list``, ``info``, ``type`` and ``find`` ask the master (`listing`); ``echo``, ``pub``, ``hz``,
``bw`` and ``delay`` run a node (`echo`, `pub`, `rates`) and are imported only when used.
"""

import importlib
from collections.abc import Callable, Sequence

from rosx.names.remap_args import parse_remap_args
from rosx_commands.cli import commands_overview, run_command
from rosx_commands.context import Environment, ExitStatus
from rosx_commands.rostopic import listing

COMMANDS = [
    ("bw", "display bandwidth used by topic"),
    ("delay", "display delay of topic from timestamp in header"),
    ("echo", "print messages to screen"),
    ("find", "find topics by type"),
    ("hz", "display publishing rate of topic    "),
    ("info", "print information about active topic"),
    ("list", "list active topics"),
    ("pub", "publish data to topic"),
    ("type", "print topic or field type"),
]


def overview() -> str:
    """rostopic's list of commands, printed without one or with ``--help``."""
    return commands_overview(
        "rostopic",
        COMMANDS,
        intro="rostopic is a command-line tool for printing information about ROS Topics.",
        footer="Type rostopic <command> -h for more detailed usage, e.g. 'rostopic echo -h'",
    )


#: The streaming sub-commands, imported only when used (they load the node runtime).
STREAMING = {
    "echo": "rosx_commands.rostopic.echo:echo",
    "pub": "rosx_commands.rostopic.pub:pub",
    "hz": "rosx_commands.rostopic.rates:hz",
    "bw": "rosx_commands.rostopic.rates:bw",
    "delay": "rosx_commands.rostopic.rates:delay",
}


def _streaming(name: str) -> Callable[[list[str], Environment], int]:
    module, _, function = STREAMING[name].partition(":")
    handler: Callable[[list[str], Environment], int] = getattr(
        importlib.import_module(module), function
    )
    return handler


def rostopic(argv: Sequence[str], env: Environment) -> int:
    """Run ``rostopic ARGV…``."""
    env.remap_args = parse_remap_args(list(argv))
    args = list(env.remap_args.argv)
    handlers: dict[str, Callable[[list[str], Environment], int]] = {
        "list": listing.list_topics,
        "info": listing.info,
        "type": listing.topic_type,
        "find": listing.find,
    }
    if args and args[0] in STREAMING:
        return run_command(_streaming(args[0]), args[1:], env)
    if not args or args[0] not in handlers:
        env.out(overview())
        return ExitStatus.EX_USAGE
    return run_command(handlers[args[0]], args[1:], env)
