"""Running one of tf's C++ tools as a process: its node, until a signal or a shutdown.

The node starts once the master answers (roscpp's ``Failed to contact master … Retrying...``
until then) and keeps ROS time as roscpp does (``/clock`` when ``/use_sim_time`` is set); the
tool's body runs on a thread of its own while the main thread waits for
SIGINT/SIGTERM or the node's shutdown (``rosnode kill``), after which the node leaves the graph
and the exit status is 0, as with roscpp.
"""

from __future__ import annotations

import os
import sys
import threading
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from collections.abc import Callable

    from rosx.node import Node
    from rosx_commands.context import Environment
    from rosx_turtle.roscpp import NodeArgs


def run_node(args: NodeArgs, env: Environment, body: Callable[[Node], object]) -> int:
    """Start ``args``' node, run ``body(node)`` beside the wait; 0 once stopped."""
    from rosx.node.simtime import follow_sim_time  # noqa: PLC0415 - the node runtime loads with the node
    from rosx_turtle.console import Console  # noqa: PLC0415 - turtlesim's parts load only when used
    from rosx_turtle.program import master_address, run_until_stopped  # noqa: PLC0415 - turtlesim's parts load only when used

    console = Console(env.stdout, env.stderr, env.environ)

    def start() -> Node:
        node = args.make_node(env.environ)
        node.start()
        follow_sim_time(node)
        args.set_private_params(node)
        worker = threading.Thread(target=_guarded, args=(body, node), daemon=True)
        worker.start()
        return node

    return run_until_stopped(start, console, master_address(args.master_uri, env.environ))


def _guarded(body: Callable[[Node], object], node: Node) -> None:
    try:
        body(node)
    except BrokenPipeError:  # the reader went away (``tf_echo a b | head``): stop quietly
        _quiet_stdout()
        node.shutdown("output closed")
    except Exception as error:  # a node shutting down under the body ends it quietly
        if not node.is_shutdown():
            node.shutdown(f"tool failed: {error}")
            raise
    else:
        if not node.is_shutdown():
            node.shutdown("done")


def _quiet_stdout() -> None:
    """Point the process's stdout at /dev/null, so that nothing more fails on exit."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError):
        pass


__all__ = ["run_node"]
