"""``rosx rosnode``: list, info, ping, kill, machine, cleanup, as ROS 1's rosnode."""

from __future__ import annotations

import socket
import time

from rosx.graph.nodes import (
    PING_TIMEOUT,
    kill_node,
    node_names,
    purge_node,
    unreachable_nodes,
    unreachable_reasons,
)
from rosx.graph.state import registrations
from rosx.master.client import MasterError
from rosx.names.script import ros_namespace, script_resolve_name
from rosx.transport.errors import (
    CallTimeoutError,
    ConnectError,
    FaultError,
    InvalidUriError,
    TransportError,
)
from rosx_commands.cli import ToolParser, commands_overview, run_command
from rosx_commands.context import CommandError, Environment, ExitStatus

TYPE_CHECKING = False
if TYPE_CHECKING:
    from collections.abc import Sequence
    from typing import NoReturn

    from rosx.master.client import MasterClient

CALLER_ID = "/rosnode"

COMMANDS = [
    ("ping", "test connectivity to node"),
    ("list", "list active nodes"),
    ("info", "print information about node"),
    ("machine", "list nodes running on a particular machine or list machines"),
    ("kill", "kill a running node"),
    ("cleanup", "purge registration information of unreachable nodes"),
]


def overview() -> str:
    """rosnode's list of commands, printed without one or with ``--help``."""
    return commands_overview(
        "rosnode",
        COMMANDS,
        intro="rosnode is a command-line tool for printing information about ROS Nodes.",
        footer="Type rosnode <command> -h for more detailed usage, e.g. 'rosnode ping -h'",
    )


def _resolve(env: Environment, name: str) -> str:
    return script_resolve_name("rosnode", name, ros_namespace(env.environ))


def list_nodes(argv: list[str], env: Environment) -> int:
    """``rosnode list``: the nodes, in a namespace, with URIs (``-u``, ``-a``) or the dead only."""
    parser = ToolParser(env, "rosnode", "usage: %prog list")
    parser.add_option(
        "-u", dest="list_uri", default=False, action="store_true", help="list XML-RPC URIs"
    )
    parser.add_option(
        "-a",
        "--all",
        dest="list_all",
        default=False,
        action="store_true",
        help="list all information",
    )
    parser.add_option(
        "--dead",
        dest="dead",
        default=False,
        action="store_true",
        help="list only the nodes that do not answer (rosx)",
    )
    options, names = parser.parse(argv)
    list_uri, list_all = options.list_uri, options.list_all
    if len(names) > 1:
        parser.error("invalid args: you may only specify one namespace")
    ns = script_resolve_name("rostopic", names[0], ros_namespace(env.environ)) if names else None
    master = env.master(CALLER_ID)
    nodes = node_names(master, ns)
    if options.dead:
        nodes = unreachable_nodes(master, nodes)
    if list_all:
        env.out("\n".join(f"{master.lookup_node(n) or 'unknown address'} \t{n}" for n in nodes))
    elif list_uri:
        env.out("\n".join(master.lookup_node(n) or "unknown address" for n in nodes))
    else:
        env.out("\n".join(nodes))
    return ExitStatus.OK


def info(argv: list[str], env: Environment) -> int:
    """``rosnode info NODE…``: publications, subscriptions, services and connections."""
    parser = ToolParser(env, "rosnode", "usage: %prog info [options] node1 [node2...]")
    parser.add_option(
        "-q",
        "--quiet",
        dest="quiet",
        default=False,
        action="store_true",
        help="Prints only basic information such as pubs/subs and does not contact nodes for more"
        " information",
    )
    options, nodes = parser.parse(argv)
    quiet = options.quiet
    if not nodes:
        parser.error("You must specify at least one node name")
    from rosx.graph.describe import (  # noqa: PLC0415 - graph code loads only when asked for
        InvalidNodeUriError,
        node_connections,
        node_description,
    )

    master = env.master(CALLER_ID)
    for raw in nodes:
        node = _resolve(env, raw)
        env.out("-" * 80)
        env.out(node_description(master, node))
        uri = master.lookup_node(node)
        if uri is None:
            env.err(f"cannot contact [{node}]: unknown node")
            continue
        if not quiet:
            env.out(f"\ncontacting node {uri} ...")
            try:
                env.out(node_connections(master, uri))
            except InvalidNodeUriError:
                raise CommandError(invalid_uri(node, uri)) from None
    return ExitStatus.OK


def invalid_uri(node: str, uri: str) -> str:
    """The error for a node registered with a URI that cannot be called (rosservice's words)."""
    return f"ERROR: node [{node}] has an invalid RPC URI [{uri}]"


def ping_node(
    env: Environment, master: MasterClient, node: str, count: int | None, verbose: bool
) -> bool:
    """Ping ``node`` through ``getPid`` ``count`` times (forever when None), once a second."""
    uri = master.lookup_node(node)
    if uri is None:
        env.err(f"cannot ping [{node}]: unknown node")
        return False
    if verbose:
        env.out(f"pinging {node} with a timeout of {PING_TIMEOUT}s")
    done, total = 0, 0.0
    try:
        while True:
            start = time.time()
            try:
                master.node_call(uri, "getPid", timeout=PING_TIMEOUT)
            except CallTimeoutError:
                env.err(f"connection to [{node}] timed out")
                return False
            except InvalidUriError:
                env.err(invalid_uri(node, uri))
                return False
            except ConnectError:
                fresh = master.lookup_node(node)
                if fresh is None:
                    env.err(f"cannot ping [{node}]: unknown node")
                    return False
                if fresh != uri:
                    if verbose:
                        env.out(f"node url has changed from [{uri}] to [{fresh}], retrying to ping")
                    uri = fresh
                    continue
                env.err(f"ERROR: connection refused to [{uri}]")
                return False
            except (TransportError, FaultError):
                env.err(f"connection to [{node}] failed")
                return False
            except MasterError as error:
                raise MasterError(error.code, f"remote call failed: {error.status}") from None
            elapsed = (time.time() - start) * 1000.0
            total += elapsed
            done += 1
            if verbose:
                env.out(f"xmlrpc reply from {uri}\ttime={elapsed:f}ms")
            if count and done >= count:
                break
            time.sleep(1.0)
    except KeyboardInterrupt:
        pass
    if verbose and done > 1:
        env.out(f"ping average: {total / done:f}ms")
    return True


def ping(argv: list[str], env: Environment) -> int:
    """``rosnode ping``: call a node's ``getPid`` (``-c`` times, or every node with ``--all``)."""
    parser = ToolParser(env, "rosnode", "usage: %prog ping [options] <node>")
    parser.add_option(
        "--all", "-a", dest="ping_all", default=False, action="store_true", help="ping all nodes"
    )
    parser.add_option(
        "-c",
        dest="ping_count",
        default=None,
        metavar="COUNT",
        type="int",
        help="number of pings to send. Not available with --all",
    )
    options, names = parser.parse(argv)
    ping_all, count = options.ping_all, options.ping_count
    master = env.master(CALLER_ID)
    if ping_all:
        if names:
            parser.error(f"Invalid arguments '{' '.join(names)}' used with --all")
        if count:
            parser.error("-c may not be used with --all")
        every = node_names(master)
        env.out("Will ping the following nodes: \n" + "".join(f" * {n}\n" for n in every))
        answered = [ping_node(env, master, node, 1, True) for node in every]
        # ROS 1 exits 0 even when a node did not answer; a script deserves to know.
        return ExitStatus.OK if all(answered) else ExitStatus.ERROR
    if not names:
        _no_node_to_ping(env, parser, master)
    if len(names) > 1:
        parser.error("you may only specify one input node")
    node = _resolve(env, names[0])
    env.out(f"rosnode: node is [{node}]")
    return ExitStatus.OK if ping_node(env, master, node, count, True) else ExitStatus.ERROR


def _no_node_to_ping(env: Environment, parser: ToolParser, master: MasterClient) -> NoReturn:
    """rosnode's usage error for ``ping`` without a node, as ROS 1 gives it: the list of nodes
    when the master answers, then (its first exit caught by its own bare ``except``) the short
    error, which alone is printed when there is no master."""
    try:
        listing = "\n".join(node_names(master))
    except (TransportError, MasterError):
        listing = None
    if listing is not None:
        try:
            parser.error("Please enter a node to ping. Available nodes are:\n" + listing)
        except CommandError as listed:
            env.err(listed.message)
    parser.error("Please enter a node to ping")


def machine(argv: list[str], env: Environment) -> int:
    """``rosnode machine [HOST]``: the machines of the graph, or the nodes on one."""
    parser = ToolParser(env, "rosnode", "usage: %prog machine [machine-name]")
    _, names = parser.parse(argv)
    if len(names) > 1:
        parser.error("please enter only one machine name")
    from rosx.transport.address import uri_hostname  # noqa: PLC0415 - only machine needs it

    master = env.master(CALLER_ID)
    hosts: dict[str, str] = {}
    for node in node_names(master):
        uri = master.lookup_node(node)
        if uri is not None:
            hosts[node] = uri_hostname(uri)
    if not names:
        env.out("\n".join(sorted(set(hosts.values()))))
        return ExitStatus.OK
    wanted = _addresses(names[0])
    if wanted is None:
        raise CommandError(f"ERROR: cannot resolve machine name [{names[0]}] to address")
    chosen = [n for n, h in hosts.items() if h == names[0] or (_addresses(h) or set()) & wanted]
    env.out("\n".join(sorted(chosen)))
    return ExitStatus.OK


def _addresses(host: str) -> set[str] | None:

    try:
        return {str(info[4][0]) for info in socket.getaddrinfo(host, 0, 0, 0, socket.SOL_TCP)}
    except OSError:
        return None


def kill(argv: list[str], env: Environment) -> int:
    """``rosnode kill``: ask nodes to shut down (named, chosen from a list, or ``--all``)."""
    parser = ToolParser(env, "rosnode", "usage: %prog kill [node]...")
    parser.add_option(
        "-a", "--all", dest="kill_all", default=False, action="store_true", help="kill all nodes"
    )
    options, names = parser.parse(argv)
    kill_all = options.kill_all
    master = env.master(CALLER_ID)
    if kill_all:
        if names:
            parser.error("invalid arguments with kill all (-a) option")
        targets = node_names(master)
    elif not names:
        listing = node_names(master)
        if not listing:
            env.err("No nodes running")
            return ExitStatus.OK
        env.stdout.write("\n".join(f"{i + 1}. {n}" for i, n in enumerate(listing)))
        env.stdout.write("\n\nPlease enter the number of the node you wish to kill.\n> ")
        env.stdout.flush()
        targets = [listing[_read_choice(env, len(listing)) - 1]]
    else:
        targets = [_resolve(env, n) for n in names]
        known = node_names(master)
        unknown = [n for n in targets if n not in known]
        if unknown:
            raise CommandError("ERROR: Unknown node(s):\n" + "\n".join(f" * {n}" for n in unknown))
    if len(targets) > 1:
        env.out("killing:\n" + "\n".join(f" * {n}" for n in targets))
    else:
        env.out(f"killing {targets[0]}")
    failed = [node for node in targets if not kill_node(master, node)]
    if failed:
        env.err("ERROR: Failed to kill:\n" + "\n".join(f" * {n}" for n in failed))
        return ExitStatus.ERROR
    env.out("killed")
    return ExitStatus.OK


def _read_choice(env: Environment, limit: int) -> int:
    while True:
        line = env.stdin.readline()
        if not line:
            raise CommandError("ERROR: no selection")
        try:
            choice = int(line.strip())
        except ValueError:
            env.out("ERROR: please enter a number (ctrl-C to cancel)")
            continue
        if 0 < choice <= limit:
            return choice
        env.out("ERROR: invalid selection. Please enter a number (ctrl-C to cancel)")


def cleanup(argv: list[str], env: Environment) -> int:
    """``rosnode cleanup``: unregister the nodes that no longer answer, once confirmed."""
    ToolParser(env, "rosnode", "usage: %prog cleanup").parse(argv)
    master = env.master(CALLER_ID)
    dead = unreachable_reasons(master, node_names(master))
    if not dead:
        return ExitStatus.OK
    for why in dead.values():
        env.err(why)
    env.out("Unable to contact the following nodes:")
    env.out("\n".join(f" * {n}" for n in dead))
    env.out("Warning: these might include alive and functioning nodes, e.g. in unstable networks.")
    env.out("Cleanup will purge all information about these nodes from the master.")
    env.out("Please type y or n to continue:")
    while True:
        answer = env.stdin.readline()
        if not answer:
            env.out("aborting")
            return ExitStatus.OK
        if answer.strip() in ("y", "n"):
            break
    if answer.strip() == "n":
        env.out("aborting")
        return ExitStatus.OK
    state = registrations(master)
    for node in dead:
        env.out(f"Unregistering {node}")
        purge_node(master, node, state)
    env.out("done")
    return ExitStatus.OK


def rosnode(argv: Sequence[str], env: Environment) -> int:
    """Run ``rosnode ARGV…``."""
    args = list(argv)
    handlers = {
        "ping": ping,
        "list": list_nodes,
        "info": info,
        "machine": machine,
        "kill": kill,
        "cleanup": cleanup,
    }
    if not args or args[0] not in handlers:
        env.out(overview())
        return ExitStatus.OK if args and args[0] == "--help" else ExitStatus.EX_USAGE
    return run_command(handlers[args[0]], args[1:], env)
