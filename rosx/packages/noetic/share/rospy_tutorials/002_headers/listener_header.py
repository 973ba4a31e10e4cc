#!/usr/bin/env python3
"""rospy_tutorials' listener_header: node ``listener_header`` (anonymous) prints each
HeaderString on ``chatter_header`` with its header's number and stamp."""

import contextlib

import rospy
from rospy_tutorials.msg import HeaderString


def heard(message: HeaderString) -> None:
    stamp = message.header.stamp.to_sec()
    print(
        rospy.get_caller_id(),
        message.header.seq,
        "I just heard that %s at %12f" % (message.data, stamp),  # noqa: UP031 - its format
    )


def listen() -> None:
    rospy.Subscriber("chatter_header", HeaderString, heard)
    rospy.init_node("listener_header", anonymous=True)
    rospy.spin()


if __name__ == "__main__":
    with contextlib.suppress(KeyboardInterrupt):
        listen()
    print("exiting")
