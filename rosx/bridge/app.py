"""A running bridge: the graph node, rosapi's node and the WebSocket servers, in one process.

`Bridge` is what ``rosx rosbridge`` and the bundled ``rosbridge_websocket`` program run, and
what the tests start in-process: ``Bridge(options).start()`` … ``shutdown()``.
"""

from __future__ import annotations

import contextlib
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from rosx.bridge.graph_side import GraphSide
from rosx.bridge.protocol import DEFAULT_MAX_MESSAGE
from rosx.bridge.rosapi import RosApi
from rosx.bridge.server import BridgeServer
from rosx.node import Node

if TYPE_CHECKING:
    from collections.abc import Callable, Mapping

    from rosx.bridge.foxglove_server import FoxgloveServer


@dataclass
class BridgeOptions:
    """What the command line and the launch file's parameters say."""

    port: int = 9090
    address: str = "127.0.0.1"
    allow_origins: tuple[str, ...] = ()
    token: str | None = None
    max_message: int = DEFAULT_MAX_MESSAGE
    rosapi: bool = True
    foxglove_port: int | None = None
    node_name: str = "rosbridge_websocket"
    master_uri: str | None = None
    environ: Mapping[str, str] | None = None
    private_params: dict[str, str] = field(default_factory=dict)
    remappings: dict[str, str] = field(default_factory=dict)
    #: Read the node's private parameters (``~port``, ``~address``, ``~max_message_size``,
    #: ``~allow_origin``, ``~token``) as rosbridge_websocket does; names in ``fixed`` were
    #: given on the command line and win.
    read_params: bool = False
    fixed: frozenset[str] = frozenset()


class Bridge:
    """The bridge's nodes and servers. ``log`` gets the lines ROS 1's prints."""

    def __init__(self, options: BridgeOptions, log: Callable[[str], object] = print) -> None:
        self.options = options
        self.log = log
        self.node = Node(
            options.node_name,
            master_uri=options.master_uri,
            environ=options.environ,
            private_params=options.private_params,
            remappings=options.remappings,
        )
        self.rosapi_node: Node | None = None
        self.graph: GraphSide | None = None
        self.server: BridgeServer | None = None
        self.foxglove: FoxgloveServer | None = None

    def start(self) -> Bridge:
        """Start the nodes and bind the servers; returns self.

        Raises:
            MasterUnreachable: no master answers.
            BadParameterError: a private parameter (``~port``…) is not what it names.
            OSError: a port cannot be bound.
        """
        options = self.options
        try:
            self.node.start()
            if options.read_params:
                self._read_params()
            if options.rosapi:
                self.rosapi_node = Node(
                    "rosapi", master_uri=options.master_uri, environ=options.environ
                ).start()
                RosApi(self.rosapi_node).advertise()
            self.graph = GraphSide(self.node, log=self.log)
            self.server = BridgeServer(
                self.graph,
                host=options.address,
                port=options.port,
                allow_origins=options.allow_origins,
                token=options.token,
                max_message=options.max_message,
                log=self.log,
            )
            self.node.io.run(self.server.start())
            self.log(
                f"Rosbridge WebSocket server started at ws://{_url_host(options.address)}:{self.server.port}"
            )
            if options.foxglove_port is not None:
                self._start_foxglove(options.foxglove_port)
        except BaseException:
            self.shutdown("start-up failed")
            raise
        return self

    def _start_foxglove(self, port: int) -> None:
        from rosx.bridge.foxglove_server import FoxgloveServer  # noqa: PLC0415 - when asked for

        options = self.options
        self.foxglove = FoxgloveServer(
            self.node,
            host=options.address,
            port=port,
            allow_origins=options.allow_origins,
            token=options.token,
            max_message=options.max_message,
            log=self.log,
        )
        self.node.io.run(self.foxglove.start())
        where = f"ws://{_url_host(options.address)}:{self.foxglove.port}"
        self.log(f"Foxglove WebSocket server started at {where}")

    def _read_params(self) -> None:
        options, params = self.options, self.node.params

        def param(name: str) -> str | None:
            if name in options.fixed or not params.has("~" + name):
                return None
            value = params.get("~" + name)
            return None if value is None or str(value) in ("", "None") else str(value)

        port = param("port")
        if port is not None:
            options.port = _whole("~port", port, "a port number (0 to 65535)", 0, 65535)
        address = param("address")
        if address is not None:
            options.address = address
        size = param("max_message_size")
        if size is not None:
            options.max_message = _whole("~max_message_size", size, "a number of bytes", 1, None)
        origins = param("allow_origin")
        if origins is not None:
            options.allow_origins = tuple(origins.replace(",", " ").split())
        token = param("token")
        if token is not None:
            options.token = token

    @property
    def port(self) -> int:
        """The rosbridge server's bound port."""
        assert self.server is not None
        return self.server.port

    def shutdown(self, reason: str = "") -> None:
        """Close the servers and shut the nodes down."""
        for server in (self.foxglove, self.server):
            if server is not None:
                # the nodes must go down whatever the servers do
                with contextlib.suppress(Exception):
                    self.node.io.run(server.close(), timeout=5.0)
        if self.graph is not None:
            self.graph.close()
        if self.rosapi_node is not None:
            self.rosapi_node.shutdown(reason)
        self.node.shutdown(reason)

    def __enter__(self) -> Bridge:
        return self.start()

    def __exit__(self, *exc: object) -> None:
        self.shutdown("bridge closed")


class BadParameterError(ValueError):
    """A private parameter of the bridge that cannot be what it names (the message says so)."""


def _whole(name: str, text: str, what: str, low: int, high: int | None) -> int:
    try:
        value = int(text)
    except ValueError:
        value = low - 1
    if value < low or (high is not None and value > high):
        raise BadParameterError(f"{name}: {text!r} is not {what}")
    return value


def _url_host(address: str) -> str:
    return f"[{address}]" if ":" in address else address


__all__ = ["BadParameterError", "Bridge", "BridgeOptions"]
