"""``rosx rosparam``: set, get, load, dump, delete, list, as ROS 1's rosparam."""

import importlib
from collections.abc import Sequence

from rosx_commands.cli import commands_overview, run_command
from rosx_commands.context import Environment, ExitStatus

COMMANDS = [
    ("set", "set parameter"),
    ("get", "get parameter"),
    ("load", "load parameters from file"),
    ("dump", "dump parameters to file"),
    ("delete", "delete parameter"),
    ("list", "list parameter names"),
]

#: Sub-command → (module of this package, function).
_HANDLERS = {
    "set": ("writing", "set_param"),
    "get": ("reading", "get"),
    "load": ("writing", "load"),
    "dump": ("reading", "dump"),
    "delete": ("writing", "delete"),
    "list": ("reading", "list_params"),
}


def overview() -> str:
    """What ROS 1's rosparam prints without a (known) sub-command."""
    return commands_overview(
        "rosparam",
        COMMANDS,
        intro="rosparam is a command-line tool for getting, setting, and deleting parameters"
        " from the ROS Parameter Server.",
    )


def rosparam(argv: Sequence[str], env: Environment) -> int:
    """Run ``rosparam ARGV…`` (rosparam, unlike the other tools, keeps ``a:=b`` words)."""
    args = list(argv)
    if not args or args[0] not in _HANDLERS:
        env.out(overview())
        return ExitStatus.OK
    # Only the sub-command's module is imported: reading needs no YAML loader, writing no dumper.
    module, function = _HANDLERS[args[0]]
    handler = getattr(importlib.import_module(f"rosx_commands.rosparam.{module}"), function)
    return run_command(handler, args[1:], env)
