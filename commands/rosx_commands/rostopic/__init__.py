"""``rosx rostopic``: list, info, type, find (and the streaming commands), as ROS 1's rostopic."""

from collections.abc import Callable, Sequence

from rosx.names.remap_args import strip_remap_args
from rosx_commands.cli import run_command
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
    lines = [
        "rostopic is a command-line tool for printing information about ROS Topics.",
        "",
        "Commands:",
    ]
    lines += [f"\trostopic {name}\t{text}" for name, text in COMMANDS]
    lines += ["", "Type rostopic <command> -h for more detailed usage, e.g. 'rostopic echo -h'", ""]
    return "\n".join(lines)


def rostopic(argv: Sequence[str], env: Environment) -> int:
    """Run ``rostopic ARGV…``."""
    args = strip_remap_args(list(argv))
    handlers: dict[str, Callable[[list[str], Environment], int]] = {
        "list": listing.list_topics,
        "info": listing.info,
        "type": listing.topic_type,
        "find": listing.find,
    }
    if not args or args[0] not in handlers:
        env.out(overview())
        return ExitStatus.EX_USAGE
    return run_command(handlers[args[0]], args[1:], env)
