#!/usr/bin/env python3
"""rospy_tutorials' listener_connection_header: node ``listener_connection_header``
(anonymous) reads each message's connection header (``_connection_header``): who sent it,
and the cookies it offers, if any."""

import contextlib

import rospy
from std_msgs.msg import String


def heard(message: String) -> None:
    header = message._connection_header
    who = header.get("callerid", "unknown")
    if "cookies" in header:
        print(f"{who} just offered me {header['cookies']} cookies")
    else:
        print(f"I just heard {message.data} from {who}")


def listen() -> None:
    rospy.Subscriber("chatter", String, heard)
    rospy.init_node("listener_connection_header", anonymous=True)
    rospy.spin()


if __name__ == "__main__":
    with contextlib.suppress(KeyboardInterrupt):
        listen()
    print("exiting")
