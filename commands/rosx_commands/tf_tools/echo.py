"""``tf_echo SOURCE TARGET [RATE]``: the transform between two frames, once a second.

As ROS 1's (tf's C++ program): it waits up to a second for the transform, then at each tick
prints ``At time …``, the translation, the rotation as a quaternion and as roll, pitch, yaw
(radians and degrees) with three decimals (``_precision:=N`` for more), or, when the lookup
fails, ``Failure at …``, tf2's reason and the frames it knows. The numbers are tf's: the
quaternion is read back from the rotation matrix and the angles from tf's ``getRPY``, so
signs such as ``-0.000`` come out where ROS 1 prints them. ``_rate:=`` sets the rate when the
command line gives none.
"""

from __future__ import annotations

import math
import time
from typing import TYPE_CHECKING

from rosx.names.anonymous import roscpp_anonymous_name

if TYPE_CHECKING:
    from collections.abc import Sequence

    from rosx.node import Node
    from rosx.tf import Buffer
    from rosx_commands.context import Environment

USAGE = (
    "Usage: tf_echo source_frame target_frame [echo_rate]\n\n"
    "This will echo the transform from the coordinate frame of the source_frame\n"
    "to the coordinate frame of the target_frame. \n"
    "Note: This is the transform to get data from target_frame into the source_frame.\n"
    "Default echo rate is 1 if echo_rate is not given.\n"
)


def transform_text(stamp: int, values: tuple[float, ...], precision: int) -> str:
    """The lines tf_echo prints for one transform (``values``: x, y, z, qx, qy, qz, qw)."""
    from rosx.tf import linear, stamps  # noqa: PLC0415 - tf code loads only when used

    basis = linear.matrix(*values[3:])
    qx, qy, qz, qw = linear.rotation(basis)
    roll, pitch, yaw = linear.rpy(basis, tf1=True)

    def fmt(*numbers: float) -> str:
        return ", ".join(f"{n:.{precision}f}" for n in numbers)

    return (
        f"At time {stamps.to_sec(stamp):.{precision}f}\n"
        f"- Translation: [{fmt(*values[:3])}]\n"
        f"- Rotation: in Quaternion [{fmt(qx, qy, qz, qw)}]\n"
        f"            in RPY (radian) [{fmt(roll, pitch, yaw)}]\n"
        f"            in RPY (degree) [{fmt(*(a * 180.0 / math.pi for a in (roll, pitch, yaw)))}]\n"
    )


def failure_text(error: Exception, frames: str, now_ns: int) -> str:
    """The lines tf_echo prints when the lookup fails."""
    return (
        f"Failure at {now_ns // 1_000_000_000}.{now_ns % 1_000_000_000:09d}\n"
        f"Exception thrown:{error}\n"
        "The current list of frames is:\n"
        f"{frames}\n"
    )


def _strip(frame: str) -> str:
    return frame[1:] if frame.startswith("/") else frame


def echo_loop(
    node: Node,
    buffer: Buffer,
    source: str,
    target: str,
    period: float,
    precision: int,
    env: Environment,
) -> None:
    """Print the transform every ``period`` seconds until the node shuts down."""
    from rosx.client.timing import Time  # noqa: PLC0415 - the rospy API loads only when used
    from rosx.tf import TransformException  # noqa: PLC0415 - tf code loads only when used

    source, target = _strip(source), _strip(target)
    deadline = time.monotonic() + period
    buffer.can_transform(source, target, Time(), 1.0)
    while not node.is_shutdown():
        try:
            stamp, values = buffer.lookup(source, target, 0)
            text = transform_text(stamp, values, precision)
        except TransformException as error:
            text = failure_text(error, buffer.all_frames_as_string(), node.clock.now().to_nsec())
        env.stdout.write(text)
        env.stdout.flush()
        # ros::Rate: each tick one period after the last; a late loop starts afresh.
        now = time.monotonic()
        if deadline < now - period:
            deadline = now
        if node.wait_for_shutdown(max(0.0, deadline - now)):
            break
        deadline += period


def tf_echo(argv: Sequence[str], env: Environment) -> int:
    """Run ``tf_echo ARGV…``; its exit status (255 for a wrong command line, as ROS 1's)."""
    from rosx_turtle.roscpp import NodeArgs, atof  # noqa: PLC0415 - roscpp's command line

    args = NodeArgs.parse(argv, roscpp_anonymous_name("tf_echo"))
    if len(args.argv) not in (2, 3):
        env.stdout.write(USAGE)
        env.stdout.flush()
        return 255
    if len(args.argv) == 3:
        rate = atof(args.argv[2])
    else:
        given = args.params.get("rate", 1.0)
        rate = float(given) if isinstance(given, (int, float)) else 1.0
    if rate <= 0.0:
        env.stderr.write("Echo rate must be > 0.0\n")
        return 255
    precision = 3
    if "precision" in args.params:
        precision = int(args.params["precision"])
        if precision < 1:
            env.stderr.write("Precision must be > 0\n")
            return 255
        env.stdout.write(f"Precision default value was overriden, new value: {precision}\n")
    source, target = args.argv[0], args.argv[1]

    from rosx_commands.tf_tools.running import run_node  # noqa: PLC0415 - this tool's parts load only when used

    def body(node: Node) -> None:
        from rosx.tf import Buffer, TransformListener  # noqa: PLC0415 - tf code loads only when used

        buffer = Buffer(node=node, debug=False)
        TransformListener(buffer, node=node)
        echo_loop(node, buffer, source, target, 1.0 / rate, precision, env)

    return run_node(args, env, body)


__all__ = ["USAGE", "echo_loop", "failure_text", "tf_echo", "transform_text"]
