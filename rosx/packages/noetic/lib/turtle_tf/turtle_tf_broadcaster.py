#!/usr/bin/env python3
"""turtle_tf's broadcaster (tf's API): the pose of the turtle named by ``~turtle`` as the
transform ``world`` -> ``<turtle>``, at every pose turtlesim publishes."""

import rospy
import tf
from turtlesim.msg import Pose


def broadcast(pose: Pose, turtle: str) -> None:
    tf.TransformBroadcaster().sendTransform(
        (pose.x, pose.y, 0),
        tf.transformations.quaternion_from_euler(0, 0, pose.theta),
        rospy.Time.now(),
        turtle,
        "world",
    )


if __name__ == "__main__":
    rospy.init_node("turtle_tf_broadcaster")
    turtle = rospy.get_param("~turtle")
    rospy.Subscriber(f"/{turtle}/pose", Pose, broadcast, turtle)
    rospy.spin()
