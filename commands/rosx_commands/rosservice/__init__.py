"""``rosx rosservice``: list, call, type, info, args, find, uri, node, as ROS 1's rosservice."""

from collections.abc import Callable, Sequence

from rosx.names.remap_args import strip_remap_args
from rosx_commands.cli import commands_overview, run_command
from rosx_commands.context import Environment, ExitStatus
from rosx_commands.rosservice import query
from rosx_commands.rosservice.call import call_command
from rosx_commands.rosservice.services import SERVICE_ERROR

COMMANDS = [
    ("args", "print service arguments"),
    ("call", "call the service with the provided args"),
    ("find", "find services by service type"),
    ("info", "print information about service"),
    ("list", "list active services"),
    ("type", "print service type"),
    ("uri", "print service ROSRPC uri"),
]


def overview() -> str:
    """What ROS 1's rosservice prints without a (known) sub-command."""
    return commands_overview(
        "rosservice",
        COMMANDS,
        footer="Type rosservice <command> -h for more detailed usage, e.g. 'rosservice call -h'",
    )


def rosservice(argv: Sequence[str], env: Environment) -> int:
    """Run ``rosservice ARGV…``."""
    args = strip_remap_args(list(argv))
    handlers: dict[str, Callable[[list[str], Environment], int]] = {
        "list": query.list_services,
        "info": query.info,
        "type": query.service_type,
        "uri": query.service_uri,
        "node": query.service_node,
        "call": call_command,
        "args": query.service_args,
        "find": query.find,
    }
    if not args or args[0] not in handlers:
        env.out(overview())
        return ExitStatus.EX_USAGE
    return run_command(handlers[args[0]], args[1:], env, error_status=SERVICE_ERROR)
