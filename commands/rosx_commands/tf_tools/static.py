"""``static_transform_publisher``: tf2_ros's (latched, once) and tf's (again every period).

tf2_ros's takes ``x y z qx qy qz qw frame child``, ``x y z yaw pitch roll frame child`` or
``/param_name`` (a TransformStamped on the parameter server), publishes the transform once on
the latched ``/tf_static`` and spins. tf's takes the same numbers and frames followed by a
period in milliseconds and publishes on ``/tf`` every period, stamped one period ahead. Both
print ROS 1's usage text and error lines for a wrong command line; unlike ROS 1's, they print
it without waiting for a master first.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from rosx.names.anonymous import roscpp_anonymous_name

if TYPE_CHECKING:
    from collections.abc import Sequence

    from rosx.node import Node
    from rosx_commands.context import Environment
    from rosx_turtle.console import Console

TF2_USAGE = (
    "A command line utility for manually sending a transform.\n"
    "Usage: static_transform_publisher x y z qx qy qz qw frame_id child_frame_id \n"
    "OR \n"
    "Usage: static_transform_publisher x y z yaw pitch roll frame_id child_frame_id \n"
    "OR \n"
    "Usage: static_transform_publisher /param_name \n"
    "\nThis transform is the transform of the coordinate frame from frame_id into the "
    "coordinate frame \n"
    "of the child_frame_id.  \n"
)
TF_USAGE = (
    "A command line utility for manually sending a transform.\n"
    "It will periodicaly republish the given transform. \n"
    "Usage: static_transform_publisher x y z yaw pitch roll frame_id child_frame_id  "
    "period(milliseconds) \n"
    "OR \n"
    "Usage: static_transform_publisher x y z qx qy qz qw frame_id child_frame_id  "
    "period(milliseconds) \n"
    "\nThis transform is the transform of the coordinate frame from frame_id into the "
    "coordinate frame \n"
    "of the child_frame_id.  \n"
)
_WRONG_COUNT = "static_transform_publisher exited due to not having the right number of arguments"
_MEMBERS = (
    ("child_frame_id",),
    ("header", "frame_id"),
    ("transform", "translation", "x"),
    ("transform", "translation", "y"),
    ("transform", "translation", "z"),
    ("transform", "rotation", "x"),
    ("transform", "rotation", "y"),
    ("transform", "rotation", "z"),
    ("transform", "rotation", "w"),
)


def _console(env: Environment) -> Console:
    from rosx_turtle.console import Console  # noqa: PLC0415 - turtlesim's parts load only when used

    return Console(env.stdout, env.stderr, env.environ)


def _numbers(words: Sequence[str]) -> tuple[float, ...]:
    """Translation and rotation from ``x y z qx qy qz qw`` or ``x y z yaw pitch roll``."""
    from rosx.tf.linear import from_rpy  # noqa: PLC0415 - tf code loads only when used
    from rosx_turtle.roscpp import atof  # noqa: PLC0415 - roscpp's habits

    values = [atof(w) for w in words]
    if len(values) == 7:
        return tuple(values)
    yaw, pitch, roll = values[3:]
    return (*values[:3], *from_rpy(roll, pitch, yaw))


def _member(data: Any, path: tuple[str, ...]) -> Any:
    for key in path:
        if not isinstance(data, dict) or key not in data:
            raise KeyError(key)
        data = data[key]
    return data


def _from_parameter(node: Node, name: str) -> tuple[str, str, tuple[float, ...]] | None:
    try:
        data = node.params.get(name)
    except KeyError:
        return None
    try:
        child, parent, *values = (_member(data, path) for path in _MEMBERS)
        return str(parent), str(child), tuple(float(v) for v in values)
    except (KeyError, TypeError, ValueError):
        raise ValueError(data) from None


def static_transform_publisher(argv: Sequence[str], env: Environment) -> int:
    """tf2_ros's ``static_transform_publisher ARGV…``; its exit status."""
    from rosx.node import ERROR, FATAL, INFO  # noqa: PLC0415 - the node runtime loads with the first node
    from rosx_turtle.roscpp import NodeArgs  # noqa: PLC0415 - turtlesim's parts load only when used

    args = NodeArgs.parse(argv, roscpp_anonymous_name("static_transform_publisher"))
    words = list(args.argv)
    console = _console(env)
    if len(words) not in (1, 8, 9):
        env.stdout.write(TF2_USAGE)
        env.stdout.flush()
        console.print(ERROR, _WRONG_COUNT)
        return 255
    transform: list[Any] = []
    if len(words) != 1:
        values = _numbers(words[:-2])
        transform[:] = [words[-2], words[-1], values]
        if words[-2] == words[-1]:
            console.print(
                FATAL,
                f"target_frame and source frame are the same ({words[-2]}, {words[-1]}) "
                "this cannot work",
            )
            return 1

    def body(node: Node) -> None:
        from rosx.tf import StaticTransformBroadcaster  # noqa: PLC0415 - tf code loads only when used

        if not transform:
            name = words[0]
            console.print(INFO, f"Looking for TF in parameter: {name}")
            try:
                found = _from_parameter(node, name)
            except ValueError as bad:
                console.print(FATAL, f"Could not validate XmlRpcC for TF data: {bad.args[0]}")
                node.shutdown("bad parameter")
                return
            if found is None:
                console.print(FATAL, f"Could not read TF from parameter server: {name}")
                node.shutdown("no parameter")
                return
            if found[0] == found[1]:
                console.print(
                    FATAL,
                    f"target_frame and source frame are the same ({found[0]}, {found[1]}) "
                    "this cannot work",
                )
                node.shutdown("same frames")
                return
            transform[:] = found
        parent, child, values = transform
        StaticTransformBroadcaster(node=node).sendTransform(
            _message(parent, child, node.clock.now().to_nsec(), values)
        )
        console.print(INFO, f"Spinning until killed publishing {parent} to {child}")
        node.wait_for_shutdown()

    from rosx_commands.tf_tools.running import run_node  # noqa: PLC0415 - this tool's parts load only when used

    return run_node(args, env, body)


def _message(parent: str, child: str, stamp: int, values: tuple[float, ...]) -> Any:
    from rosx.msg.codec.classes import get_message_class  # noqa: PLC0415 - message classes load on first use

    t = get_message_class("geometry_msgs/TransformStamped")()
    t.header.frame_id = parent
    t.header.stamp.secs, t.header.stamp.nsecs = divmod(stamp, 1_000_000_000)
    t.child_frame_id = child
    v = t.transform.translation
    v.x, v.y, v.z = values[0], values[1], values[2]
    q = t.transform.rotation
    q.x, q.y, q.z, q.w = values[3], values[4], values[5], values[6]
    return t


def tf_static_transform_publisher(argv: Sequence[str], env: Environment) -> int:
    """tf's ``static_transform_publisher ARGV… PERIOD_MS``; its exit status."""
    from rosx.node import ERROR, FATAL  # noqa: PLC0415 - the node runtime loads with the first node
    from rosx.tf import linear  # noqa: PLC0415 - tf code loads only when used
    from rosx_turtle.roscpp import NodeArgs, atof  # noqa: PLC0415 - turtlesim's parts load only when used

    args = NodeArgs.parse(argv, roscpp_anonymous_name("static_transform_publisher"))
    words = list(args.argv)
    console = _console(env)
    if len(words) not in (9, 10):
        env.stdout.write(TF_USAGE)
        env.stdout.flush()
        console.print(ERROR, _WRONG_COUNT)
        return 255
    period = atof(words[-1]) / 1000.0
    parent, child = words[-3], words[-2]
    if parent == child:  # tf's says so and publishes anyway
        console.print(
            FATAL,
            f"target_frame and source frame are the same ({parent}, {child}) this cannot work",
        )
    values = _numbers(words[:-3])
    # tf sends the rotation matrix's quaternion: a given quaternion comes out normalized.
    rotation = linear.rotation(linear.matrix(*values[3:]))
    values = (*values[:3], *rotation)
    ahead = round(period * 1e9)

    def body(node: Node) -> None:
        from rosx.node.errors import NodeShutdownError, TimeMovedBackwardsError  # noqa: PLC0415 - with the node runtime
        from rosx.tf import TransformBroadcaster  # noqa: PLC0415 - tf code loads only when used

        broadcaster = TransformBroadcaster(node=node)
        # stamped ahead in ROS time and paced by it, as roscpp's: under simulated time it
        # follows /clock, so lookups in the simulator's time work; nothing is stamped before
        # the first /clock (roscpp's would stamp 0.1 s)
        try:
            node.clock.sleep(0.0, shutdown=node.shutdown_event)
        except NodeShutdownError:
            return
        while not node.is_shutdown():
            stamp = node.clock.now().to_nsec() + ahead
            broadcaster.sendTransform(_message(parent, child, stamp, values))
            try:
                node.clock.sleep(max(period, 0.0), shutdown=node.shutdown_event)
            except NodeShutdownError:
                break
            except TimeMovedBackwardsError:
                continue

    from rosx_commands.tf_tools.running import run_node  # noqa: PLC0415 - this tool's parts load only when used

    return run_node(args, env, body)


__all__ = ["TF2_USAGE", "TF_USAGE", "static_transform_publisher", "tf_static_transform_publisher"]
