#!/usr/bin/env python3
"""turtle_tf2's waiting listener: as turtle_tf2_listener.py, but each lookup is of the transform
at the present time, waiting up to a second for it to arrive."""

import math

import rospy
import tf2_ros
from geometry_msgs.msg import Twist
from turtlesim.srv import Spawn

if __name__ == "__main__":
    rospy.init_node("turtle_tf2_listener_wait")
    buffer = tf2_ros.Buffer()
    listener = tf2_ros.TransformListener(buffer)

    rospy.wait_for_service("spawn")
    rospy.ServiceProxy("spawn", Spawn)(4, 2, 0, "turtle2")
    cmd_vel = rospy.Publisher("turtle2/cmd_vel", Twist, queue_size=1)

    rate = rospy.Rate(10.0)
    while not rospy.is_shutdown():
        try:
            t = buffer.lookup_transform("turtle2", "turtle1", rospy.Time.now(), rospy.Duration(1.0))
        except tf2_ros.TransformException:
            continue
        x, y = t.transform.translation.x, t.transform.translation.y
        msg = Twist()
        msg.angular.z = 4 * math.atan2(y, x)
        msg.linear.x = 0.5 * math.sqrt(x**2 + y**2)
        cmd_vel.publish(msg)
        rate.sleep()
