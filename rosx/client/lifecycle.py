"""Starting, running and stopping the process's node: rospy's ``init_node``, ``spin``, shutdown.

`init_node` follows rospy's rules: the name is a base name (``namespaces are not allowed in
node names``), ``__name:=`` overrides it (and cancels ``anonymous``), ``__ns:=`` or
``ROS_NAMESPACE`` give the namespace, ``from:=to`` remap names, ``_param:=value`` set private
parameters, and a second call is allowed only with the same arguments. While the master cannot
be reached it logs rospy's ``Unable to immediately register with master node [...]`` once and
keeps trying, until the master answers or the process is told to stop.

Unless ``disable_rostime`` is given, a true ``/use_sim_time`` parameter makes the node's time
follow ``/clock`` (`rosx.node.simtime`, `rosx.client.timing`).

Unless ``disable_signals`` is given, SIGINT (Ctrl-C) and SIGTERM shut the node down as rospy's
handlers do: no `KeyboardInterrupt` reaches the program; instead `is_shutdown` becomes true and
sleeps end with `ROSInterruptException`. The teardown runs on a thread of its own, because a
signal handler may interrupt code that holds a lock the teardown needs.
"""

from __future__ import annotations

import atexit
import os
import sys
import threading
import warnings
from typing import TYPE_CHECKING

from rosx.client import state
from rosx.client.exceptions import ROSException, ROSInitException
from rosx.client.logs import LoggerLevels
from rosx.names import (
    anonymous_node_name,
    is_legal_base_name,
    strip_remap_args,
)
from rosx.node.rosout import console_line, print_console

if TYPE_CHECKING:
    from collections.abc import Callable, Mapping

    from rosx.client.logfile import LogFile
    from rosx.node import Node

DEBUG = 1
INFO = 2
WARN = 4
ERROR = 8
FATAL = 16

_RETRY_PERIOD = 0.2
_SPIN_PERIOD = 0.5
_exit_registered = False


def myargv(argv: list[str] | None = None) -> list[str]:
    """``argv`` (default ``sys.argv``) without its remapping arguments."""
    return strip_remap_args(sys.argv if argv is None else argv)


def init_node(
    name: str,
    argv: list[str] | None = None,
    anonymous: bool = False,
    log_level: int | None = None,
    disable_rostime: bool = False,
    disable_rosout: bool = False,
    disable_signals: bool = False,
    xmlrpc_port: int = 0,
    tcpros_port: int = 0,
) -> None:
    """Register this process with the master as node ``name`` (see the module docstring).

    Raises:
        ValueError: ``name`` is empty or holds a namespace.
        ROSException: called before with different arguments.
        ROSInitException: the start was interrupted, or a ``_param:=`` value is invalid.
    """
    if argv is not None:
        state.CLIENT.reload(argv)
    if not name:
        raise ValueError("name must not be empty")
    if "/" in name:
        raise ValueError("namespaces are not allowed in node names")
    arguments = (name, argv, anonymous, log_level, disable_rostime, disable_signals)
    with state.CLIENT.lock:
        if state.CLIENT.init_args is not None:
            if state.CLIENT.init_args != arguments:
                raise ROSException(
                    "rospy.init_node() has already been called with different arguments: "
                    + str(state.CLIENT.init_args)
                )
            return
        state.CLIENT.init_args = arguments
    if not disable_signals and threading.current_thread() is threading.main_thread():
        _register_signals()
    _register_exit()
    args = state.CLIENT.args
    if args.name:
        name, anonymous = args.name, False
    if anonymous:
        name = anonymous_node_name(name)
    if not is_legal_base_name(name):
        warnings.warn(
            f"'{name}' is not a legal ROS base name. This may cause problems with other ROS tools.",
            stacklevel=2,
        )
    log_file = _open_log_file(name)
    node = _start_node(name, log_level or INFO, xmlrpc_port, tcpros_port, disable_rosout)
    node.on_shutdown(state.CLIENT.signal_shutdown)
    if not disable_rostime:
        _init_time(node)
    if log_file is not None:
        node.log_sink.record = log_file.write
        node.on_shutdown(
            lambda reason: log_file.write("rospy.core", INFO, f"signal_shutdown [{reason}]")
        )
    if not state.CLIENT.started(node):
        raise ROSInitException("init_node interrupted before it could complete")


def _open_log_file(name: str) -> LogFile | None:
    """The ``__log:=`` file, opened and begun with rospy's first line; None without one."""
    path = state.CLIENT.args.log
    if not path:
        return None
    from rosx.client.logfile import open_log_file  # noqa: PLC0415 - only under roslaunch

    log_file = open_log_file(path)
    if log_file is not None:
        full = state.CLIENT.namespace() + name
        log_file.write("rospy.client", INFO, f"init_node, name[{full}], pid[{os.getpid()}]")
    return log_file


def _make_node(
    name: str, log_level: int, xmlrpc_port: int, tcpros_port: int, disable_rosout: bool
) -> Node:
    from rosx.node import Node  # noqa: PLC0415 - the runtime loads with the first node

    args = state.CLIENT.args
    node = Node(
        name,
        namespace=state.CLIENT.namespace(),
        master_uri=args.master,
        remappings=dict(args.remappings),
        host=args.hostname or args.ip,
        xmlrpc_port=xmlrpc_port,
        tcpros_port=tcpros_port,
        rosout_enabled=not disable_rosout,
        log_level=log_level,
        console=_console,
        private_params=dict(args.params),
        warn_refusals=True,
    )
    # The rospy API logs through Python's ``rosout`` logger: its level is the node's.
    node.log_sink.levels = LoggerLevels(node.log_sink.levels)
    return node


def _start_node(
    name: str, log_level: int, xmlrpc_port: int, tcpros_port: int, disable_rosout: bool
) -> Node:
    from rosx.node.startup import ParamArgsError  # noqa: PLC0415 - the node runtime loads with the first node
    from rosx.transport.errors import TransportError  # noqa: PLC0415 - the network code loads only to talk

    told = False
    while True:
        if state.CLIENT.requested:
            raise ROSInitException("init_node interrupted before it could complete")
        node = _make_node(name, log_level, xmlrpc_port, tcpros_port, disable_rosout)
        if node.master.answers(timeout=2.0):
            try:
                return node.start()
            except ParamArgsError as error:
                raise ROSInitException(str(error)) from None
            except TransportError:
                pass  # the master went away meanwhile: wait for it again
        if not told:
            _console(
                ERROR,
                _line(
                    ERROR,
                    f"Unable to immediately register with master node [{node.master_uri}]: "
                    "master may not be running yet. Will keep trying.",
                ),
            )
            told = True
        state.CLIENT.shutdown_event.wait(_RETRY_PERIOD)


def _init_time(node: Node) -> None:
    """ROS time from ``/clock`` when ``/use_sim_time`` is set (rospy's ``init_simtime``).

    Raises:
        ROSInitException: the master could not be asked (rospy's words), the node shut down.
    """
    from rosx.master.client import MasterError  # noqa: PLC0415 - the node runtime loads with the first node
    from rosx.node.simtime import follow_sim_time  # noqa: PLC0415 - the node runtime loads with the first node
    from rosx.transport.errors import TransportError  # noqa: PLC0415 - the network code loads only to talk

    try:
        follow_sim_time(node)
    except (MasterError, TransportError) as error:
        _console(ERROR, _line(ERROR, f"Unable to initialize /clock: {error}"))
        node.shutdown("Failed to initialize time")
        raise ROSInitException(
            "Failed to initialize time. Please check logs for additional details"
        ) from None


def _line(level: int, message: str) -> str:
    return console_line(level, message)


def _console(level: int, line: str) -> None:
    print_console(level, line, stdout=sys.stdout, stderr=sys.stderr)


# -- signals and exit ---------------------------------------------------------------------------


def _register_signals() -> None:
    from rosx.signals import install_signal_handlers  # noqa: PLC0415 - unless disabled

    def shutdown(reason: str) -> None:
        state.CLIENT.shutdown_in_background(reason)  # the client of the moment

    install_signal_handlers(shutdown, quiet=True)  # rospy keeps Ctrl-C's exception from scripts


def _at_exit() -> None:
    state.CLIENT.at_exit()  # the client of the moment, looked up at exit


def _register_exit() -> None:
    global _exit_registered  # noqa: PLW0603 - one exit hook a process
    if not _exit_registered:
        atexit.register(_at_exit)
        _exit_registered = True


# -- running and stopping -------------------------------------------------------------------------


def is_shutdown() -> bool:
    """Whether the node has been shut down (or is being shut down)."""
    return state.CLIENT.is_shutdown()


def signal_shutdown(reason: str) -> None:
    """Shut the node down: run the ``on_shutdown`` hooks, then leave the ROS graph."""
    state.CLIENT.signal_shutdown(reason)


def on_shutdown(hook: Callable[[], object]) -> None:
    """Call ``hook()`` (no arguments) when the node shuts down, before it leaves the graph."""
    state.CLIENT.add_client_hook(hook)


def spin() -> None:
    """Block until the node shuts down; callbacks run meanwhile on their own threads.

    Raises:
        ROSInitException: `init_node` has not been called.
    """
    if state.CLIENT.node is None:
        raise ROSInitException("client code must call rospy.init_node() first")
    try:
        while not state.CLIENT.shutdown_event.wait(_SPIN_PERIOD):
            pass
    except KeyboardInterrupt:
        state.CLIENT.signal_shutdown("keyboard interrupt")


# -- names ----------------------------------------------------------------------------------------


def get_name() -> str:
    """The node's global name (``/unnamed`` before `init_node`)."""
    return state.CLIENT.caller_id()


get_caller_id = get_name


def get_namespace() -> str:
    """The node's namespace, with a trailing ``/``."""
    return state.CLIENT.namespace()


def resolve_name(name: str, caller_id: str | None = None) -> str:
    """``name`` resolved as the node resolves it: ``~x`` under the node, relative names in its
    namespace, then the command line's remappings (once the node runs)."""
    return state.CLIENT.resolve_name(name, caller_id)


def get_node_uri() -> str | None:
    """The node's Slave API URI, or None before `init_node`."""
    node = state.CLIENT.node
    return node.uri if node is not None else None


def get_ros_root(required: bool = False, env: Mapping[str, str] | None = None) -> str | None:
    """``ROS_ROOT`` (normalised), or None; deprecated in rospy, and warned about as there.

    Raises:
        ROSException: ``required`` and ``ROS_ROOT`` is not set.
    """
    warnings.warn("Call to deprecated function get_ros_root.", DeprecationWarning, stacklevel=2)
    root = (os.environ if env is None else env).get("ROS_ROOT")
    if root:
        return os.path.normpath(root)
    if required:
        raise ROSException("ROS_ROOT is not set")
    return None


def get_published_topics(namespace: str = "/") -> list[list[str]]:
    """``[topic, type]`` of every published topic in ``namespace``."""
    try:
        topics = state.CLIENT.master().call("getPublishedTopics", namespace)
    except Exception as exc:
        raise ROSException(f"unable to get published topics: {exc}") from None
    return [[str(t), str(ty)] for t, ty in topics]


__all__ = [
    "DEBUG",
    "ERROR",
    "FATAL",
    "INFO",
    "WARN",
    "get_caller_id",
    "get_name",
    "get_namespace",
    "get_node_uri",
    "get_published_topics",
    "get_ros_root",
    "init_node",
    "is_shutdown",
    "myargv",
    "on_shutdown",
    "resolve_name",
    "signal_shutdown",
    "spin",
]
