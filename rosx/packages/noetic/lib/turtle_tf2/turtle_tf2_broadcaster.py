#!/usr/bin/env python3
"""turtle_tf2's broadcaster: the pose of the turtle named by ``~turtle``, as the transform
``world`` -> ``<turtle>`` on /tf, at every pose turtlesim publishes (about 62 a second)."""

import math

import rospy
import tf2_ros
from geometry_msgs.msg import TransformStamped
from turtlesim.msg import Pose


def broadcast(pose: Pose, args: tuple[str, tf2_ros.TransformBroadcaster]) -> None:
    turtle, broadcaster = args
    t = TransformStamped()
    t.header.stamp = rospy.Time.now()
    t.header.frame_id = "world"
    t.child_frame_id = turtle
    t.transform.translation.x = pose.x
    t.transform.translation.y = pose.y
    t.transform.translation.z = 0.0
    # a rotation about z by theta (quaternion_from_euler(0, 0, theta))
    t.transform.rotation.z = math.sin(pose.theta / 2.0)
    t.transform.rotation.w = math.cos(pose.theta / 2.0)
    broadcaster.sendTransform(t)


if __name__ == "__main__":
    rospy.init_node("turtle_tf2_broadcaster")
    turtle = rospy.get_param("~turtle")
    rospy.Subscriber(f"/{turtle}/pose", Pose, broadcast, (turtle, tf2_ros.TransformBroadcaster()))
    rospy.spin()
