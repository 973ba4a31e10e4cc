"""roscpp_tutorials' talker and listener: std_msgs/String on ``chatter`` (queues of 1000).

The talker (node ``talker``) publishes ``hello world <count>`` ten times a second, counting
from 0, each logged at INFO first; the listener (node ``listener``) logs
``I heard: [<text>]`` for each message.
"""

from __future__ import annotations

import itertools
from typing import TYPE_CHECKING, Any

from rosx.msg.codec.classes import get_message_class
from rosx.node import INFO
from rosx_turtle.console import Console, NodeLog
from rosx_turtle.env import ProcessEnv
from rosx_turtle.node.ticker import Ticker
from rosx_turtle.program import master_address, run_until_stopped
from rosx_turtle.roscpp import NodeArgs

if TYPE_CHECKING:
    from collections.abc import Mapping, Sequence

    from rosx.node import Node
    from rosx_turtle.env import Env

LOGGER = "ros.roscpp_tutorials"
QUEUE_SIZE = 1000
PERIOD = 0.1


class Talker:
    """The talker node: started, it publishes until `shutdown`."""

    def __init__(self, args: NodeArgs, environ: Mapping[str, str], console: Console | None):
        self.node: Node = args.make_node(environ)
        self.args = args
        self.log = NodeLog(self.node, console, LOGGER)
        self._count = itertools.count()
        self._ticker = Ticker(PERIOD, self._talk, name="rosx-talker")
        self._string = get_message_class("std_msgs/String")
        self._publisher: Any = None

    def start(self) -> Talker:
        """Start the node, advertise ``chatter`` and publish ``hello world 0`` at once, then ten
        a second; returns self."""
        node = self.node.start()
        self.args.set_private_params(node)
        self._publisher = node.advertise("chatter", self._string, queue_size=QUEUE_SIZE)
        self._talk()
        self._ticker.start()
        return self

    def _talk(self) -> None:
        text = f"hello world {next(self._count)}"
        self.log(INFO, text)
        self._publisher.publish(self._string(data=text))

    def shutdown(self, reason: str = "") -> None:
        """Stop talking and shut the node down with ``reason``."""
        self._ticker.stop()
        self.node.shutdown(reason)

    def wait_for_shutdown(self, timeout: float | None = None) -> bool:
        """Block until the node shuts down; False if ``timeout`` passed first."""
        return self.node.wait_for_shutdown(timeout)


class Listener:
    """The listener node: logs what it hears on ``chatter`` until `shutdown`."""

    def __init__(self, args: NodeArgs, environ: Mapping[str, str], console: Console | None):
        self.node: Node = args.make_node(environ)
        self.args = args
        self.log = NodeLog(self.node, console, LOGGER)

    def start(self) -> Listener:
        """Start the node and subscribe to ``chatter``, logging ``I heard: [...]`` for each
        message; returns self."""
        node = self.node.start()
        self.args.set_private_params(node)
        string = get_message_class("std_msgs/String")
        node.subscribe("chatter", string, self._heard, queue_size=QUEUE_SIZE)
        return self

    def _heard(self, message: Any) -> None:
        self.log(INFO, f"I heard: [{message.data}]")

    def shutdown(self, reason: str = "") -> None:
        """Shut the node down with ``reason``."""
        self.node.shutdown(reason)

    def wait_for_shutdown(self, timeout: float | None = None) -> bool:
        """Block until the node shuts down; False if ``timeout`` passed first."""
        return self.node.wait_for_shutdown(timeout)


def run_talker(argv: Sequence[str], env: Env | None = None) -> int:
    """Run the talker until SIGINT, SIGTERM or a shutdown; exit status."""
    env = env or ProcessEnv()
    args = NodeArgs.parse(argv, "talker")
    console = Console(env.stdout, env.stderr, env.environ)
    return run_until_stopped(
        lambda: Talker(args, env.environ, console).start(),
        console,
        master_address(args.master_uri, env.environ),
    )


def run_listener(argv: Sequence[str], env: Env | None = None) -> int:
    """Run the listener until SIGINT, SIGTERM or a shutdown; exit status."""
    env = env or ProcessEnv()
    args = NodeArgs.parse(argv, "listener")
    console = Console(env.stdout, env.stderr, env.environ)
    return run_until_stopped(
        lambda: Listener(args, env.environ, console).start(),
        console,
        master_address(args.master_uri, env.environ),
    )
