"""``rosx rosparam``: set, get, load, dump, delete, list, as ROS 1's rosparam."""

from collections.abc import Callable, Sequence

from rosx_commands.cli import commands_overview, run_command
from rosx_commands.context import Environment, ExitStatus
from rosx_commands.rosparam import reading, writing

COMMANDS = [
    ("set", "set parameter"),
    ("get", "get parameter"),
    ("load", "load parameters from file"),
    ("dump", "dump parameters to file"),
    ("delete", "delete parameter"),
    ("list", "list parameter names"),
]


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
    handlers: dict[str, Callable[[list[str], Environment], int]] = {
        "set": writing.set_param,
        "get": reading.get,
        "load": writing.load,
        "dump": reading.dump,
        "delete": writing.delete,
        "list": reading.list_params,
    }
    if not args or args[0] not in handlers:
        env.out(overview())
        return ExitStatus.OK
    return run_command(handlers[args[0]], args[1:], env)
