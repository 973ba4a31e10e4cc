#!/usr/bin/env python3
"""turtle_tf2's listener: spawns ``turtle2`` (or the turtle named by parameter ``turtle``) at
(4, 2) and, ten times a second, steers it towards turtle1 from the transform turtle1 ->
turtle2 (turning by 4 x the bearing, driving at 0.5 x the distance)."""

import math

import rospy
import tf2_ros
from geometry_msgs.msg import Twist
from turtlesim.srv import Spawn

if __name__ == "__main__":
    rospy.init_node("turtle_tf2_listener")
    buffer = tf2_ros.Buffer()
    listener = tf2_ros.TransformListener(buffer)

    rospy.wait_for_service("spawn")
    turtle = rospy.get_param("turtle", "turtle2")
    rospy.ServiceProxy("spawn", Spawn)(4, 2, 0, turtle)
    cmd_vel = rospy.Publisher(f"{turtle}/cmd_vel", Twist, queue_size=1)

    rate = rospy.Rate(10.0)
    while not rospy.is_shutdown():
        try:
            t = buffer.lookup_transform(turtle, "turtle1", rospy.Time())
        except (
            tf2_ros.LookupException,
            tf2_ros.ConnectivityException,
            tf2_ros.ExtrapolationException,
        ):
            rate.sleep()
            continue
        x, y = t.transform.translation.x, t.transform.translation.y
        msg = Twist()
        msg.angular.z = 4 * math.atan2(y, x)
        msg.linear.x = 0.5 * math.sqrt(x**2 + y**2)
        cmd_vel.publish(msg)
        rate.sleep()
