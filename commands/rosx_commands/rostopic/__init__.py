"""``rosx rostopic``: list, info, type, find (and the streaming commands), as ROS 1's rostopic."""

from collections.abc import Sequence

from rosx.names.remap_args import strip_remap_args
from rosx_commands.cli import run_app, tool_app
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
USAGES = {
    "list": "rostopic list [/namespace]",
    "info": "rostopic info /topic",
    "type": "rostopic type [-h] topic_or_field",
    "find": "rostopic find msg-type",
    "echo": "rostopic echo [options] /topic",
    "pub": "rostopic pub /topic type [args...]",
    "hz": "rostopic hz [options] /topic_0 [/topic_1 [topic_2 [..]]]",
    "bw": "rostopic bw [options] /topic",
    "delay": "rostopic delay [options] /topic",
}


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

    argv = strip_remap_args(list(argv))
    known = {name for name, _ in COMMANDS}
    if not argv or (argv[0] not in known and argv[0] not in ("-h", "--help")):
        env.out(overview())
        return ExitStatus.EX_USAGE
    app = tool_app("Prints information about ROS topics.")
    listing.register(app)
    return run_app(app, argv, env, tool="rostopic", usages=USAGES)
