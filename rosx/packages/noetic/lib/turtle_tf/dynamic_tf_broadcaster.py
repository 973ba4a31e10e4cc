#!/usr/bin/env python3
"""turtle_tf's moving frame: ``carrot1`` circling turtle1 at 10 m, once every two seconds."""

import math

import rospy
import tf

if __name__ == "__main__":
    rospy.init_node("dynamic_tf_broadcaster")
    broadcaster = tf.TransformBroadcaster()
    rate = rospy.Rate(10.0)
    while not rospy.is_shutdown():
        angle = rospy.Time.now().to_sec() * math.pi
        broadcaster.sendTransform(
            (10 * math.sin(angle), 10 * math.cos(angle), 0.0),
            (0.0, 0.0, 0.0, 1.0),
            rospy.Time.now(),
            "carrot1",
            "turtle1",
        )
        rate.sleep()
