#!/usr/bin/env python3
"""turtle_tf2's fixed frame: ``carrot1``, 2 m to the left of turtle1, sent ten times a second."""

import rospy
import tf2_ros
from geometry_msgs.msg import TransformStamped

if __name__ == "__main__":
    rospy.init_node("fixed_tf2_broadcaster")
    broadcaster = tf2_ros.TransformBroadcaster()
    t = TransformStamped()
    t.header.frame_id = "turtle1"
    t.child_frame_id = "carrot1"
    t.transform.translation.y = 2.0
    t.transform.rotation.w = 1.0
    rate = rospy.Rate(10.0)
    while not rospy.is_shutdown():
        t.header.stamp = rospy.Time.now()
        broadcaster.sendTransform(t)
        rate.sleep()
