"""mimic: make one turtle copy another's motion (node ``turtle_mimic``, as in Noetic).

It subscribes to ``input/pose`` and, for every pose, publishes on ``output/cmd_vel`` a Twist
with linear.x = ``linear_velocity`` and angular.z = ``angular_velocity`` (queue 1 each). The
names live under ``ros::NodeHandle("input")`` and ``("output")``, so
``input:=turtlesim1/turtle1 output:=turtlesim2/turtle1`` wires two simulators together. As in
ROS 1, a leader driving backwards makes the follower drive forwards (the pose's linear
velocity is never negative).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from rosx.msg.codec.classes import get_message_class
from rosx_turtle.console import Console
from rosx_turtle.env import ProcessEnv
from rosx_turtle.program import master_address, run_until_stopped
from rosx_turtle.roscpp import NodeArgs, sub_name

if TYPE_CHECKING:
    from collections.abc import Sequence

    from rosx.node import Node
    from rosx_turtle.env import Env

DEFAULT_NAME = "turtle_mimic"


def start_mimic(args: NodeArgs, environ: Any) -> Node:
    """Start the mimic node; it runs until shut down."""
    node = args.make_node(environ).start()
    try:
        args.set_private_params(node)
        twist_class = get_message_class("geometry_msgs/Twist")
        publisher = node.advertise(sub_name(node, "output", "cmd_vel"), twist_class, queue_size=1)

        def on_pose(pose: Any) -> None:
            twist = twist_class()
            twist.angular.z = pose.angular_velocity
            twist.linear.x = pose.linear_velocity
            publisher.publish(twist)

        node.subscribe(
            sub_name(node, "input", "pose"),
            get_message_class("turtlesim/Pose"),
            on_pose,
            queue_size=1,
        )
    except BaseException:
        node.shutdown("start-up failed")
        raise
    return node


def run_mimic(argv: Sequence[str], env: Env | None = None) -> int:
    """Run mimic until SIGINT, SIGTERM or a shutdown; exit status."""
    env = env or ProcessEnv()
    args = NodeArgs.parse(argv, DEFAULT_NAME)
    console = Console(env.stdout, env.stderr, env.environ)
    return run_until_stopped(
        lambda: start_mimic(args, env.environ),
        console,
        master_address(args.master_uri, env.environ),
    )
