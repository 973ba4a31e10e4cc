#!/usr/bin/env python3
"""turtle_tf's waiting listener: steers turtle2 towards ``carrot1`` at the present time,
waiting up to a second for each transform (``waitForTransform``)."""

import math

import rospy
import tf
from geometry_msgs.msg import Twist
from turtlesim.srv import Spawn

if __name__ == "__main__":
    rospy.init_node("turtle_tf_listener_wait")
    listener = tf.TransformListener()
    rospy.wait_for_service("spawn")
    rospy.ServiceProxy("spawn", Spawn)(4, 2, 0, "turtle2")
    cmd_vel = rospy.Publisher("turtle2/cmd_vel", Twist, queue_size=1)
    rate = rospy.Rate(10.0)
    while not rospy.is_shutdown():
        try:
            now = rospy.Time.now()
            listener.waitForTransform("/turtle2", "/carrot1", now, rospy.Duration(1.0))
            (x, y, _), _ = listener.lookupTransform("/turtle2", "/carrot1", now)
        except tf.Exception:
            continue
        msg = Twist()
        msg.angular.z = 4 * math.atan2(y, x)
        msg.linear.x = 0.5 * math.sqrt(x**2 + y**2)
        cmd_vel.publish(msg)
        rate.sleep()
