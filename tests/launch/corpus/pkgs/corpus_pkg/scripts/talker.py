#!/usr/bin/env python3
"""Publishes a greeting on chatter once a second."""

import rospy
from std_msgs.msg import String

rospy.init_node("talker")
pub = rospy.Publisher("chatter", String, queue_size=10)
rate = rospy.Rate(1)
while not rospy.is_shutdown():
    pub.publish(String(data="hello"))
    rate.sleep()
