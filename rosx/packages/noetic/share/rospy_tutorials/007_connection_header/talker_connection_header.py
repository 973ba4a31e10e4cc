#!/usr/bin/env python3
"""rospy_tutorials' talker_connection_header: the talker, with ``cookies: oreo`` added to the
connection header it sends each subscriber."""

import contextlib

import rospy
from std_msgs.msg import String


def talk() -> None:
    chatter = rospy.Publisher("chatter", String, headers={"cookies": "oreo"}, queue_size=10)
    rospy.init_node("talker", anonymous=True)
    rate = rospy.Rate(10)
    while not rospy.is_shutdown():
        text = f"hello world {rospy.get_time()}"
        rospy.loginfo(text)
        chatter.publish(text)
        rate.sleep()


if __name__ == "__main__":
    with contextlib.suppress(rospy.ROSInterruptException):
        talk()
