#!/usr/bin/env python3
"""rospy_tutorials' listener: node ``listener`` (anonymous), logs each String on ``chatter``."""

import rospy
from std_msgs.msg import String


def heard(message: String) -> None:
    rospy.loginfo(rospy.get_caller_id() + "I heard %s", message.data)


def listen() -> None:
    rospy.init_node("listener", anonymous=True)
    rospy.Subscriber("chatter", String, heard)
    rospy.spin()


if __name__ == "__main__":
    listen()
