"""teleop_twist_keyboard: drive any robot on ``cmd_vel`` from the keyboard.

The keys are teleop_twist_keyboard's: ``u i o / j k l / m , .`` move and turn (``k`` and any
other key stop), the same keys with Shift (``U I O / J K L / M < >``) strafe for holonomic
robots, ``t``/``b`` go up and down; ``q``/``z`` scale both speeds by 1.1 or 0.9, ``w``/``x`` the
linear one, ``e``/``c`` the angular one. Parameters: ``~speed`` (0.5), ``~turn`` (1.0),
``~speed_limit`` and ``~turn_limit`` (1000), ``~repeat_rate`` (0: publish on key presses only),
``~key_timeout`` (0.5 s without a key stops a moving robot), ``~stamped`` and ``~frame_id``
(TwistStamped). It waits for a subscriber to ``cmd_vel`` before it prints its help.

`TwistKeys` is the key logic as data (a key in, the command out); `run_teleop_twist` the
program.
"""

from __future__ import annotations

import select
import threading
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, Any

from rosx.msg.codec.classes import get_message_class
from rosx_turtle.console import Console
from rosx_turtle.env import ProcessEnv
from rosx_turtle.keyboard import RawKeys
from rosx_turtle.program import master_address, start_when_master_is_up
from rosx_turtle.roscpp import NodeArgs

if TYPE_CHECKING:
    from collections.abc import Sequence

    from rosx.node import Node
    from rosx_turtle.env import Env

HELP = """
Keyboard teleop: each key sets the Twist published on cmd_vel
---------------------------
Drive and turn:
   u    i    o
   j    k    l
   m    ,    .
Strafe (holonomic robots): the same keys with Shift
---------------------------
   U    I    O
   J    K    L
   M    <    >
t / b : up / down (z)
k, or any other key : stop
q / z : both speeds up / down by 10%
w / x : linear speed up / down by 10%
e / c : angular speed up / down by 10%
Ctrl-C : quit
"""

#: Key → (x, y, z, turn) directions.
MOVES: dict[str, tuple[int, int, int, int]] = {
    "i": (1, 0, 0, 0), "o": (1, 0, 0, -1), "j": (0, 0, 0, 1), "l": (0, 0, 0, -1),
    "u": (1, 0, 0, 1), ",": (-1, 0, 0, 0), ".": (-1, 0, 0, 1), "m": (-1, 0, 0, -1),
    "O": (1, -1, 0, 0), "I": (1, 0, 0, 0), "J": (0, 1, 0, 0), "L": (0, -1, 0, 0),
    "U": (1, 1, 0, 0), "<": (-1, 0, 0, 0), ">": (-1, -1, 0, 0), "M": (-1, 1, 0, 0),
    "t": (0, 0, 1, 0), "b": (0, 0, -1, 0),
}  # fmt: skip
#: Key → (linear, angular) speed factors.
SPEEDS: dict[str, tuple[float, float]] = {
    "q": (1.1, 1.1), "z": (0.9, 0.9), "w": (1.1, 1.0), "x": (0.9, 1.0),
    "e": (1.0, 1.1), "c": (1.0, 0.9),
}  # fmt: skip
CTRL_C = "\x03"


def speeds_line(speed: float, turn: float) -> str:
    """The line printed after each speed change."""
    return f"currently:\tspeed {speed}\tturn {turn} "


@dataclass(frozen=True)
class TwistKeys:
    """The teleop's state: the directions held, the speeds, and how to react to a key."""

    speed: float = 0.5
    turn: float = 1.0
    speed_limit: float = 1000.0
    turn_limit: float = 1000.0
    direction: tuple[int, int, int, int] = (0, 0, 0, 0)
    changes: int = 0

    def command(self) -> tuple[float, float, float, float]:
        """(linear x, linear y, linear z, angular z) to publish."""
        x, y, z, th = self.direction
        return (x * self.speed, y * self.speed, z * self.speed, th * self.turn)

    def press(self, key: str) -> tuple[TwistKeys, list[str], bool]:
        """The state after ``key`` ("" when the key timeout passed), the lines to print, and
        whether to publish."""
        if key in MOVES:
            return replace(self, direction=MOVES[key]), [], True
        if key in SPEEDS:
            linear, angular = SPEEDS[key]
            speed = min(self.speed_limit, self.speed * linear)
            turn = min(self.turn_limit, self.turn * angular)
            lines = []
            if speed == self.speed_limit:
                lines.append("Linear speed limit reached!")
            if turn == self.turn_limit:
                lines.append("Angular speed limit reached!")
            lines.append(speeds_line(speed, turn))
            if self.changes == 14:  # the help again every fifteen changes
                lines.append(HELP)
            state = replace(self, speed=speed, turn=turn, changes=(self.changes + 1) % 15)
            return state, lines, True
        if key == "" and self.direction == (0, 0, 0, 0):
            return self, [], False
        return replace(self, direction=(0, 0, 0, 0)), [], True


def _number(node: Node, name: str, default: float) -> float:
    value = node.params.get(name, default)
    return (
        float(value) if isinstance(value, (int, float)) and not isinstance(value, bool) else default
    )


def run_teleop_twist(argv: Sequence[str], env: Env | None = None) -> int:
    """Run teleop_twist_keyboard on ``env``'s terminal until Ctrl-C; the exit status."""
    env = env or ProcessEnv()
    args = NodeArgs.parse(argv, "teleop_twist_keyboard")
    console = Console(env.stdout, env.stderr, env.environ)

    def start() -> Node:
        node = args.make_node(env.environ).start()
        args.set_private_params(node)
        return node

    stop = threading.Event()
    node = start_when_master_is_up(
        start, console, master_address(args.master_uri, env.environ), stop
    )
    if node is None:
        return 0
    try:
        return _drive(node, env)
    except KeyboardInterrupt:
        return 0
    finally:
        node.shutdown("teleop ended")


def _drive(node: Node, env: Env) -> int:
    stamped = bool(node.params.get("~stamped", False))
    kind = get_message_class("geometry_msgs/TwistStamped" if stamped else "geometry_msgs/Twist")
    frame = node.params.get("~frame_id", "")
    publisher = node.advertise("cmd_vel", kind, queue_size=1)
    state = TwistKeys(
        speed=_number(node, "~speed", 0.5),
        turn=_number(node, "~turn", 1.0),
        speed_limit=_number(node, "~speed_limit", 1000),
        turn_limit=_number(node, "~turn_limit", 1000),
    )
    repeat = _number(node, "~repeat_rate", 0.0)
    key_timeout = _number(node, "~key_timeout", 0.5)
    waited = 0
    while publisher.get_num_connections() == 0:
        if node.wait_for_shutdown(0.5):
            return 0
        waited += 1
        if waited % 5 == 4:
            env.stdout.write(f"Waiting for subscriber to connect to {node.resolve('cmd_vel')}\n")
            env.stdout.flush()

    def publish(command: tuple[float, float, float, float]) -> None:
        message = kind()
        twist: Any = message.twist if stamped else message
        if stamped:
            message.header.frame_id = frame if isinstance(frame, str) else ""
        twist.linear.x, twist.linear.y, twist.linear.z, twist.angular.z = command
        publisher.publish(message)

    env.stdout.write(HELP + "\n" + speeds_line(state.speed, state.turn) + "\n")
    env.stdout.flush()
    fd = _fileno(env.stdin)
    try:
        with RawKeys(fd) as keys:
            while not node.is_shutdown():
                wait = key_timeout if key_timeout > 0 else None
                if repeat > 0:
                    wait = min(wait or 1 / repeat, 1 / repeat)
                ready, _, _ = select.select([fd], [], [], wait)
                key = keys.read().decode("latin-1") if ready else ""
                if ready and key == "":
                    break  # end of input
                if key == CTRL_C:
                    break
                state, lines, send = state.press(key if ready else "")
                for line in lines:
                    env.stdout.write(line + "\n")
                env.stdout.flush()
                if send or (repeat > 0 and state.direction != (0, 0, 0, 0)):
                    publish(state.command())
    finally:
        publish((0.0, 0.0, 0.0, 0.0))
    return 0


def _fileno(stream: Any) -> int:
    try:
        return int(stream.fileno())
    except (AttributeError, OSError, ValueError):
        return 0
