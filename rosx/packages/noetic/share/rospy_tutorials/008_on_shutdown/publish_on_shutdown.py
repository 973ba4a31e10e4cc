#!/usr/bin/env python3
"""rospy_tutorials' publish_on_shutdown: node ``talker`` (anonymous) waits; when it is shut
down (Ctrl-C), its ``rospy.on_shutdown`` hook prints and publishes "I'm dead!" on ``chatter``."""

import rospy
from std_msgs.msg import String


def talk() -> None:
    chatter = rospy.Publisher("chatter", String, queue_size=10)
    rospy.init_node("talker", anonymous=True)

    def last_words() -> None:
        print("I'm dead!")
        chatter.publish("I'm dead!")

    rospy.on_shutdown(last_words)
    print("Hit ctrl-C to see on_shutdown example")
    rospy.spin()


if __name__ == "__main__":
    talk()
