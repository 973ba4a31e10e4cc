#!/usr/bin/env python3
"""rospy_tutorials' talker_header: node ``talker_header``, a HeaderString on ``chatter_header``.

Ten times a second it prints "hello world N" and publishes it with an empty header, which
the publisher numbers (``header.seq``) as rospy's does.
"""

import rospy
from rospy_tutorials.msg import HeaderString


def talk() -> None:
    chatter = rospy.Publisher("chatter_header", HeaderString, queue_size=10)
    rospy.init_node("talker_header")
    count = 0
    while not rospy.is_shutdown():
        text = f"hello world {count}"
        print(text)
        chatter.publish(HeaderString(None, text))
        count += 1
        rospy.sleep(0.1)


if __name__ == "__main__":
    talk()
