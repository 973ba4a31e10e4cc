#!/usr/bin/env python3
"""turtle_tf2's moving frame: ``carrot1`` circling turtle1 at 10 m, once every two seconds."""

import math

import rospy
import tf2_ros
from geometry_msgs.msg import TransformStamped

if __name__ == "__main__":
    rospy.init_node("dynamic_tf2_broadcaster")
    broadcaster = tf2_ros.TransformBroadcaster()
    t = TransformStamped()
    t.header.frame_id = "turtle1"
    t.child_frame_id = "carrot1"
    t.transform.rotation.w = 1.0
    rate = rospy.Rate(10.0)
    while not rospy.is_shutdown():
        angle = rospy.Time.now().to_sec() * math.pi
        t.header.stamp = rospy.Time.now()
        t.transform.translation.x = 10 * math.sin(angle)
        t.transform.translation.y = 10 * math.cos(angle)
        broadcaster.sendTransform(t)
        rate.sleep()
