"""``rosx rosbag``: ROS 1's rosbag, sub-command by sub-command, over `rosx.bag`.

``info`` and the file tools (``filter``, ``check``, ``compress``, ``decompress``, ``reindex``,
``fix``) read and write files; ``record`` and ``play`` run a node. Each sub-command's module is
imported only when it runs; options are parsed with optparse, as ROS 1's rosbag parses them,
for the same ``-h`` texts and usage errors.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable, Sequence

from rosx_commands.cli import run_command
from rosx_commands.context import Environment, ExitStatus

#: Sub-command → (module:function, ROS 1's one-line description).
COMMANDS: dict[str, tuple[str, str]] = {
    "check": (
        "tools:check",
        "Determine whether a bag is playable in the current system, or if it can be migrated.",
    ),
    "compress": ("tools:compress", "Compress one or more bag files."),
    "decompress": ("tools:decompress", "Decompress one or more bag files."),
    "decrypt": ("tools:decrypt", "Decrypt one or more bag files."),
    "encrypt": ("tools:encrypt", "Encrypt one or more bag files."),
    "filter": ("tools:filter_bag", "Filter the contents of the bag."),
    "fix": (
        "tools:fix",
        "Repair the messages in a bag file so that it can be played in the current system.",
    ),
    "info": ("info:info", "Summarize the contents of one or more bag files."),
    "play": (
        "play:play",
        "Play back the contents of one or more bag files in a time-synchronized fashion.",
    ),
    "record": ("record:record", "Record a bag file with the contents of specified topics."),
    "reindex": ("tools:reindex", "Reindexes one or more bag files."),
}


def valid_commands() -> str:
    """ROS 1's list of sub-commands (``help`` among them, without a description)."""
    lines = ["Available subcommands:"]
    for name in sorted([*COMMANDS, "help"]):
        line = f"   {name}  "
        if name in COMMANDS:
            line += f"\t{COMMANDS[name][1]}"
        lines.append(line)
    return "\n".join(lines) + "\n"


def _handler(name: str) -> Callable[[list[str], Environment], int]:
    module, _, function = COMMANDS[name][0].partition(":")
    handler: Callable[[list[str], Environment], int] = getattr(
        importlib.import_module(f"rosx_commands.rosbag.{module}"), function
    )
    return handler


def _help(argv: list[str], env: Environment) -> int:
    if not argv:
        env.out("Usage: rosbag <subcommand> [options] [args]")
        env.out()
        env.out(
            "A bag is a file format in ROS for storing ROS message data. "
            "The rosbag command can record, replay and manipulate bags."
        )
        env.out()
        env.out(valid_commands())
        env.out("For additional information, see http://wiki.ros.org/rosbag")
        env.out()
        return ExitStatus.OK
    if argv[0] in COMMANDS:
        return run_command(_handler(argv[0]), ["-h"], env)
    if argv[0] == "help":
        return _help([], env)
    env.err(f"Unknown command: '{argv[0]}'")
    env.err(valid_commands())
    return ExitStatus.OK


def rosbag(argv: Sequence[str], env: Environment) -> int:
    """Run ``rosbag ARGV…``."""
    args = list(argv)
    if "-h" in args or "--help" in args:
        args = ["help", *[a for a in args if a not in ("-h", "--help")]]
    if not args or args[0] == "help":
        return _help(args[1:], env)
    if args[0] not in COMMANDS:
        return _help(args[:1], env)
    return run_command(_handler(args[0]), args[1:], env)
