"""``rosservice list``, ``type``, ``uri``, ``node``, ``info``, ``args`` and ``find``."""

from __future__ import annotations

from rosx_commands.cli import ToolParser
from rosx_commands.context import CommandError, Environment, ExitStatus
from rosx_commands.rosservice.services import Services, request_args


def _service_only(env: Environment, command: str, argv: list[str]) -> str:
    """The one service name of ``rosservice COMMAND /service``, resolved."""
    parser = ToolParser(env, "rosservice", f"usage: %prog {command} /service")
    _, args = parser.parse(argv)
    if not args:
        parser.error("service must be specified")
    if len(args) > 1:
        parser.error("you may only specify one input service")
    return Services(env).resolve(args[0])


def list_services(argv: list[str], env: Environment) -> int:
    """``rosservice list [NS]``: the services, with their nodes (``-n``)."""
    parser = ToolParser(env, "rosservice", "usage: %prog list [/namespace]")
    parser.add_option(
        "-n",
        "--nodes",
        dest="print_nodes",
        default=False,
        action="store_true",
        help="print nodes that provide service(s)",
    )
    options, args = parser.parse(argv)
    if len(args) > 1:
        parser.error("you may only specify one input namespace")
    services = Services(env)
    namespace = services.resolve(args[0]) if args else None
    rows = services.services(namespace)
    if options.print_nodes:
        for name, nodes in sorted(rows, key=lambda row: row[0]):
            env.out(name + " " + ",".join(nodes))
    else:
        for name in sorted(name for name, _ in rows):
            env.out(name)
    return ExitStatus.OK


def service_type(argv: list[str], env: Environment) -> int:
    """``rosservice type SERVICE``: its type."""
    name = _service_only(env, "type", argv)
    found = Services(env).type_of(name)
    if found is None:
        raise CommandError(f"Unknown service [{name}]")
    env.out(found)
    return ExitStatus.OK


def service_uri(argv: list[str], env: Environment) -> int:
    """``rosservice uri SERVICE``: its ``rosrpc://`` URI."""
    name = _service_only(env, "uri", argv)
    uri = Services(env).uri_of(name)
    if not uri:
        raise CommandError(f"Unknown service: {name}")
    env.out(uri)
    return ExitStatus.OK


def service_node(argv: list[str], env: Environment) -> int:
    """``rosservice node SERVICE``: the node that provides it."""
    name = _service_only(env, "node", argv)
    node = Services(env).node_of(name)
    if not node:
        raise CommandError(f"Unknown service: {name}")
    env.out(node)
    return ExitStatus.OK


def service_args(argv: list[str], env: Environment) -> int:
    """``rosservice args SERVICE``: the names of its request's fields."""
    name = _service_only(env, "args", argv)
    env.out(request_args(Services(env).service_class(name)))
    return ExitStatus.OK


def info(argv: list[str], env: Environment) -> int:
    """``rosservice info SERVICE``: its node, URI, type and arguments."""
    parser = ToolParser(env, "rosservice", "usage: %prog info /service")
    _, args = parser.parse(argv)
    if len(args) > 1:
        parser.error("you may only specify one service")
    if not args:
        parser.error("you must specify a service name")
    services = Services(env)
    name = services.resolve(args[0])
    node = services.node_of(name)
    if not node:
        raise CommandError("ERROR: unknown service")
    env.out(f"Node: {node}")
    uri = services.uri_of(name)
    if not uri:
        env.err("ERROR: service is no longer available")
        return ExitStatus.OK
    env.out(f"URI: {uri}")
    found = services.type_of(name)
    if not found:
        env.err("ERROR: service is no longer available")
        return ExitStatus.OK
    env.out(f"Type: {found}")
    env.out(f"Args: {request_args(services.service_class(name))}")
    return ExitStatus.OK


def find(argv: list[str], env: Environment) -> int:
    """``rosservice find TYPE``: the services of a type."""
    parser = ToolParser(env, "rosservice", "usage: %prog find msg-type")
    _, args = parser.parse(argv)
    if not args:
        parser.error("please specify a message type")
    if len(args) > 1:
        parser.error("you may only specify one message type")
    from rosx.node.errors import ServiceError  # noqa: PLC0415 - find only
    from rosx.node.service_client import probe_service  # noqa: PLC0415 - the node runtime loads with the first node

    services = Services(env)
    matches = []
    for name, _ in services.services():
        uri = services.uri_of(name)
        if uri is None:
            continue
        try:
            found = probe_service(services.master, name, uri=uri).get("type")
        except ServiceError:
            continue
        if found == args[0]:
            matches.append(name)
    env.out("\n".join(matches))
    return ExitStatus.OK
