"""rospy scripts of a talker and a listener, for the graph tools' tests against ROS 1."""

from __future__ import annotations

TALKER = """
import rospy
from std_msgs.msg import String
rospy.init_node('talker')
p = rospy.Publisher('chatter', String, queue_size=10)
r = rospy.Rate(10)
while not rospy.is_shutdown():
    p.publish(String('hello'))
    r.sleep()
"""


LISTENER = """
import rospy
from std_msgs.msg import String
rospy.init_node('listener')
rospy.Subscriber('chatter', String, lambda m: None)
rospy.spin()
"""
