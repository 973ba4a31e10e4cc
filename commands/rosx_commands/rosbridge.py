"""``rosx rosbridge``: the rosbridge v2 and Foxglove WebSocket servers for browser tools.

Also the programs of the bundled ``rosbridge_server`` and ``rosapi`` packages, which
``rosrun`` and ``roslaunch rosbridge_server rosbridge_websocket.launch`` start:
``rosbridge_websocket`` (rosbridge alone, its settings from ``~port``, ``~address``… or
``--port``/``--address`` as rosbridge_suite reads them) and ``rosapi_node``.
The bridge itself is `rosx.bridge.app.Bridge`; this module parses and waits.
"""

from __future__ import annotations

import os
import threading
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

from rosx_commands.cli import ToolParser, run_command
from rosx_commands.context import Environment

if TYPE_CHECKING:
    from rosx.bridge.app import BridgeOptions

_USAGE = "usage: %prog [options]"
_DESCRIPTION = (
    "Serve the ROS graph to browser tools: the rosbridge v2 protocol (roslibjs, roslibpy, "
    "webviz, Lichtblick) and, with --foxglove-port, the Foxglove WebSocket protocol."
)


def _size(text: str) -> int:
    if not text.isdigit() or int(text) <= 0:
        raise ValueError(f"--max-message-size: {text!r} is not a number of bytes")
    return int(text)


def _rosbridge(argv: list[str], env: Environment) -> int:
    parser = ToolParser(env, "rosx rosbridge", _USAGE)
    parser.description = _DESCRIPTION
    parser.add_option("--port", dest="port", default="9090", help="rosbridge's port (9090)")
    parser.add_option(
        "--address",
        dest="address",
        default="127.0.0.1",
        help="the address to listen on (127.0.0.1: this machine only; 0.0.0.0: every network)",
    )
    parser.add_option(
        "--allow-origin",
        dest="origins",
        action="append",
        default=[],
        help="let pages of this origin connect (repeatable; * wildcards; 'null' for pages "
        "opened from files); pages served from this machine always may",
    )
    parser.add_option(
        "--token", dest="token", default=None, help="clients must send this token (auth op)"
    )
    parser.add_option(
        "--foxglove-port",
        dest="foxglove_port",
        default=None,
        help="also serve the Foxglove WebSocket protocol on this port",
    )
    parser.add_option(
        "--max-message-size",
        dest="max_message",
        default=None,
        help="the largest message a client may send, in bytes (32 MiB)",
    )
    parser.add_option(
        "--no-rosapi", dest="rosapi", action="store_false", default=True, help="no rosapi node"
    )
    options, args = parser.parse(argv)
    if args:
        parser.error("rosx rosbridge takes no arguments")
    from rosx.bridge.app import BridgeOptions  # noqa: PLC0415 - not for -h or usage errors

    settings = BridgeOptions(
        address=options.address,
        allow_origins=tuple(options.origins),
        token=options.token,
        rosapi=options.rosapi,
        environ=env.environ,
    )
    try:
        settings.port = _port(options.port)
        if options.foxglove_port is not None:
            settings.foxglove_port = _port(options.foxglove_port)
        if options.max_message is not None:
            settings.max_message = _size(options.max_message)
    except ValueError as exc:
        parser.error(str(exc))
    return _serve(settings, env)


def _port(text: str) -> int:
    if not text.isdigit() or int(text) > 65535:
        raise ValueError(f"{text!r} is not a port number (0 to 65535)")
    return int(text)


def _serve(settings: BridgeOptions, env: Environment) -> int:
    from rosx.bridge.app import BadParameterError, Bridge  # noqa: PLC0415 - not for -h or usage errors
    from rosx.node import install_signal_handlers  # noqa: PLC0415 - with the bridge
    from rosx.signals import soon, wait  # noqa: PLC0415 - with the bridge

    bridge = Bridge(settings, log=env.out)
    try:
        bridge.start()
    except BadParameterError as exc:
        env.err(str(exc))
        return 1
    except OSError as exc:
        where = f"{settings.address}:{settings.port}"
        if settings.foxglove_port is not None:
            where += f" and :{settings.foxglove_port}"
        # a name that does not resolve is a gaierror, whose errno is no errno of the system's
        why = os.strerror(exc.errno) if exc.errno and exc.errno > 0 else exc.strerror or str(exc)
        env.err(f"Unable to start the bridge on {where}: {why[:1].lower()}{why[1:]}")
        return 1
    stop = threading.Event()
    # The handler neither sets the event nor raises into the wait (see `rosx.signals`).
    install_signal_handlers(lambda reason: soon(stop.set), quiet=True)
    bridge.node.on_shutdown(lambda reason: stop.set())
    try:
        wait(stop)
    except KeyboardInterrupt:
        pass
    finally:
        bridge.shutdown("rosbridge stopped")
    return 0


def rosbridge(argv: Sequence[str], env: Environment) -> int:
    """Run ``rosx rosbridge ARGV…``."""
    return run_command(_rosbridge, list(argv), env)


# -- the bundled programs ----------------------------------------------------------------------


def _program_options(argv: Sequence[str], default_name: str) -> tuple[BridgeOptions, list[str]]:
    from rosx.bridge.app import BridgeOptions  # noqa: PLC0415 - the program's own import
    from rosx.names import parse_remap_args  # noqa: PLC0415 - the program's own import

    args = parse_remap_args(argv)
    options = BridgeOptions(
        node_name=args.name or default_name,
        master_uri=args.master,
        private_params=dict(args.params),
        remappings=dict(args.remappings),
    )
    return options, list(args.argv)


def _flag(argv: list[str], name: str) -> str | None:
    if name in argv:
        at = argv.index(name) + 1
        if at < len(argv):
            return argv[at]
    return None


def rosbridge_websocket(argv: Sequence[str], env: Environment | None = None) -> int:
    """rosbridge_server's ``rosbridge_websocket``: the rosbridge server alone (no rosapi).

    Its settings are private parameters (``~port``, ``~address``, ``~max_message_size``,
    ``~allow_origin``, ``~token``), overridden by ``--port``/``--address`` as in ROS 1.
    """
    env = env or Environment()
    options, rest = _program_options(argv, "rosbridge_websocket")
    options.rosapi = False
    options.environ = env.environ
    options.read_params = True
    # rosbridge_suite listens on every interface unless told; rosx on this machine only
    fixed = set()
    try:
        port = _flag(rest, "--port")
        if port is not None:
            options.port = _port(port)
            fixed.add("port")
    except ValueError as exc:
        env.err(f"--port: invalid value: {exc}")
        return 1
    address = _flag(rest, "--address")
    if address is not None:
        options.address = address
        fixed.add("address")
    options.fixed = frozenset(fixed)
    return run_command(lambda _argv, env: _serve(options, env), [], env)


def rosapi_node(argv: Sequence[str], env: Environment | None = None) -> int:
    """rosapi's ``rosapi_node``: rosapi's services, on a node of their own."""
    env = env or Environment()
    options, _ = _program_options(argv, "rosapi")
    return run_command(lambda _argv, env: _run_rosapi(options, env), [], env)


def _run_rosapi(options: BridgeOptions, env: Environment) -> int:
    from rosx.bridge.rosapi import RosApi  # noqa: PLC0415 - the program's own import
    from rosx.node import Node, install_signal_handlers  # noqa: PLC0415 - the program's own import
    from rosx.signals import soon  # noqa: PLC0415 - the program's own import

    node = Node(
        options.node_name,
        master_uri=options.master_uri,
        environ=env.environ,
        remappings=options.remappings,
    ).start()
    install_signal_handlers(lambda reason: soon(lambda: node.shutdown(reason)), quiet=True)
    RosApi(node).advertise()
    try:
        node.wait_for_shutdown()
    except KeyboardInterrupt:
        pass
    finally:
        node.shutdown("rosapi stopped")
    return 0


__all__: list[Any] = ["rosapi_node", "rosbridge", "rosbridge_websocket"]
