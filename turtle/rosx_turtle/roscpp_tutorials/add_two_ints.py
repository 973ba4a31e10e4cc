"""roscpp_tutorials' add_two_ints_server and add_two_ints_client (roscpp_tutorials/TwoInts).

The server (node ``add_two_ints_server``) answers ``add_two_ints`` with ``a + b``, logging
``request: x=<a>, y=<b>`` and ``  sending back response: [<sum>]``. The client (node
``add_two_ints_client``) takes exactly two arguments, read as C's ``atoi`` reads them, calls
the service once without waiting for it, and logs ``Sum: <sum>``; otherwise it logs
``usage: add_two_ints_client X Y`` (INFO) or ``Failed to call service add_two_ints`` (ERROR)
and exits with 1.
"""

from __future__ import annotations

import re
from typing import TYPE_CHECKING, Any

from rosx.msg.codec.classes import get_service_class
from rosx.node import ERROR, INFO, NodeError
from rosx.transport.errors import TransportError
from rosx_turtle.console import Console, NodeLog
from rosx_turtle.env import ProcessEnv
from rosx_turtle.program import master_address, run_until_stopped
from rosx_turtle.roscpp import NodeArgs, advertise_service

if TYPE_CHECKING:
    from collections.abc import Mapping, Sequence

    from rosx.node import Node
    from rosx_turtle.env import Env

LOGGER = "ros.roscpp_tutorials"
SERVICE = "add_two_ints"
_LEADING_INT = re.compile(r"\s*([+-]?[0-9]+)")


def atoi(text: str) -> int:
    """C's ``atoi``: the leading decimal integer of ``text`` (after blanks), else 0; as an int."""
    match = _LEADING_INT.match(text)
    if match is None:
        return 0
    value = int(match.group(1)) & 0xFFFFFFFF
    return value - (1 << 32) if value >= 1 << 31 else value


class AddTwoIntsServer:
    """The server node: answers ``add_two_ints`` until `shutdown`."""

    def __init__(self, args: NodeArgs, environ: Mapping[str, str], console: Console | None):
        self.node: Node = args.make_node(environ)
        self.args = args
        self.log = NodeLog(self.node, console, LOGGER)

    def start(self) -> AddTwoIntsServer:
        """Start the node, read its private parameters and advertise ``add_two_ints``; returns
        self."""
        node = self.node.start()
        self.args.set_private_params(node)
        service = get_service_class("roscpp_tutorials/TwoInts")
        advertise_service(node, SERVICE, service, self._add, self.log)
        return self

    def _add(self, request: Any) -> Any:
        total = request.a + request.b
        self.log(INFO, f"request: x={request.a}, y={request.b}")
        self.log(INFO, f"  sending back response: [{total}]")
        return {"sum": total}

    def shutdown(self, reason: str = "") -> None:
        """Shut the node down with ``reason``; the service goes with it."""
        self.node.shutdown(reason)

    def wait_for_shutdown(self, timeout: float | None = None) -> bool:
        """Block until the node shuts down; False if ``timeout`` passed first."""
        return self.node.wait_for_shutdown(timeout)


class _OneCall:
    """The client's node: one call, then it shuts itself down with the exit status kept."""

    def __init__(self, args: NodeArgs, environ: Mapping[str, str], console: Console | None):
        self.node: Node = args.make_node(environ)
        self.args = args
        self.log = NodeLog(self.node, console, LOGGER)
        self.status = 0

    def start(self, a: int, b: int) -> _OneCall:
        node = self.node.start()
        self.args.set_private_params(node)
        service = get_service_class("roscpp_tutorials/TwoInts")
        client = node.service_client(SERVICE, service)
        try:
            response = client.call(service._request_class(a=a, b=b))
        except (NodeError, TransportError, OSError):
            self.log(ERROR, f"Failed to call service {SERVICE}")
            self.status = 1
        else:
            self.log(INFO, f"Sum: {response.sum}")
        self.node.shutdown("done")
        return self

    def shutdown(self, reason: str = "") -> None:
        self.node.shutdown(reason)

    def wait_for_shutdown(self, timeout: float | None = None) -> bool:
        return self.node.wait_for_shutdown(timeout)


def run_server(argv: Sequence[str], env: Env | None = None) -> int:
    """Run add_two_ints_server until SIGINT, SIGTERM or a shutdown; exit status."""
    env = env or ProcessEnv()
    args = NodeArgs.parse(argv, "add_two_ints_server")
    console = Console(env.stdout, env.stderr, env.environ)
    return run_until_stopped(
        lambda: AddTwoIntsServer(args, env.environ, console).start(),
        console,
        master_address(args.master_uri, env.environ),
    )


def run_client(argv: Sequence[str], env: Env | None = None) -> int:
    """Run ``add_two_ints_client X Y``; exit status."""
    env = env or ProcessEnv()
    args = NodeArgs.parse(argv, "add_two_ints_client")
    console = Console(env.stdout, env.stderr, env.environ)
    if len(args.argv) != 2:
        console.print(INFO, "usage: add_two_ints_client X Y")
        return 1
    a, b = atoi(args.argv[0]), atoi(args.argv[1])
    calls: list[_OneCall] = []

    def start() -> _OneCall:
        calls.append(_OneCall(args, env.environ, console))
        return calls[-1].start(a, b)

    run_until_stopped(start, console, master_address(args.master_uri, env.environ))
    return calls[-1].status if calls else 0
