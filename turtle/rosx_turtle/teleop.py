"""turtle_teleop_key: drive turtle1 with the arrow keys, as ROS 1's (Noetic) does.

Node ``teleop_turtle`` publishes ``geometry_msgs/Twist`` on ``turtle1/cmd_vel`` (queue 1,
remappable). ``scale_linear`` and ``scale_angular`` (default 2.0) are read once at start-up
through the node's *public* namespace (``/scale_linear``, not ``~scale_linear``).

It prints three lines, then reads fd 0 one byte at a time in raw mode (`RawKeys`). Each byte:
``A`` (the last byte of the Up arrow's ``ESC [ A``) publishes linear.x = +scale_linear, ``B``
(Down) -scale_linear, ``D`` (Left) angular.z = +scale_angular, ``C`` (Right) -scale_angular,
every other field 0, one message per byte, so capital A/B/C/D drive too; lowercase ``q``
quits; anything else is ignored. Nothing else is printed.

It ends with the terminal restored and status 0 on ``q``, Ctrl-C (SIGINT) and SIGTERM, and at
the end of input (where ROS 1's would spin forever). A failed read prints
``read():: <strerror>`` (``perror("read():")``) and ends with status 255, as ROS 1's
``return -1`` from main does.
"""

from __future__ import annotations

import threading
from typing import TYPE_CHECKING, Any

from rosx.msg.codec.classes import get_message_class
from rosx.signals import STOP_SIGNALS, handling
from rosx_turtle.console import Console
from rosx_turtle.env import ProcessEnv
from rosx_turtle.keyboard import RawKeys
from rosx_turtle.program import master_address, start_when_master_is_up
from rosx_turtle.roscpp import NodeArgs

if TYPE_CHECKING:
    from collections.abc import Sequence

    from rosx.node import Node, Publisher
    from rosx_turtle.env import Env

DEFAULT_NAME = "teleop_turtle"
HELP = (
    "Reading from keyboard\n"
    "---------------------------\n"
    "Use arrow keys to move the turtle. 'q' to quit.\n"
)
#: Key byte → (linear, angular) before scaling.
KEYS = {b"A": (1.0, 0.0), b"B": (-1.0, 0.0), b"D": (0.0, 1.0), b"C": (0.0, -1.0)}
QUIT = b"q"
READ_FAILED = 255


class _Quit(BaseException):
    """A signal asked the key loop to end."""


def _quit(signum: int) -> None:
    raise _Quit


def param_double(node: Node, name: str, default: float) -> float:
    """``NodeHandle::param<double>``: a number on the server, else ``default``."""
    value = node.params.get(name, default)
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return default
    return float(value)


def run_teleop(argv: Sequence[str], env: Env | None = None) -> int:
    """Run turtle_teleop_key on ``env``'s terminal (fd 0 when stdin has none); exit status."""
    env = env or ProcessEnv()
    args = NodeArgs.parse(argv, DEFAULT_NAME)
    console = Console(env.stdout, env.stderr, env.environ)
    node: Node | None = None
    try:
        with RawKeys(_fileno(env.stdin)) as keys, handling(STOP_SIGNALS, _quit):
            node = start_when_master_is_up(
                lambda: _start(args, env),
                console,
                master_address(args.master_uri, env.environ),
                threading.Event(),
            )
            assert node is not None
            a_scale = param_double(node, "scale_angular", 2.0)
            l_scale = param_double(node, "scale_linear", 2.0)
            twist_class = get_message_class("geometry_msgs/Twist")
            publisher = node.advertise("turtle1/cmd_vel", twist_class, queue_size=1)
            env.stdout.write(HELP)
            env.stdout.flush()
            return _key_loop(keys, publisher, twist_class, l_scale, a_scale, env)
    except _Quit:
        return 0
    finally:
        if node is not None:
            node.shutdown("teleop ended")


def _start(args: NodeArgs, env: Env) -> Node:
    node = args.make_node(env.environ).start()
    args.set_private_params(node)
    return node


def _key_loop(
    keys: RawKeys,
    publisher: Publisher,
    twist_class: type[Any],
    l_scale: float,
    a_scale: float,
    env: Env,
) -> int:
    while True:
        try:
            byte = keys.read()
        except OSError as exc:
            env.stderr.write(f"read():: {exc.strerror}\n")
            env.stderr.flush()
            return READ_FAILED
        if not byte or byte == QUIT:
            return 0
        motion = KEYS.get(byte)
        if motion is None:
            continue
        linear, angular = motion
        twist = twist_class()
        twist.angular.z = a_scale * angular
        twist.linear.x = l_scale * linear
        publisher.publish(twist)


def _fileno(stream: Any) -> int:
    try:
        return int(stream.fileno())
    except (AttributeError, OSError, ValueError):
        return 0
