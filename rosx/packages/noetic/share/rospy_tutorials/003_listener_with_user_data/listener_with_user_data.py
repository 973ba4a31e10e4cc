#!/usr/bin/env python3
"""rospy_tutorials' listener_with_user_data: one callback subscribed four times, each with its
own argument (rospy's ``callback_args``): three times to ``chatter``, once to ``chatter2``."""

import contextlib
from typing import Any

import rospy
from std_msgs.msg import String


def heard(message: String, args: Any) -> None:
    if args in (1, 2):
        print(f"#{args}: I heard [{message.data}]")
    else:
        print(f"I heard [{message.data}] with userdata [{args}]")


def listen() -> None:
    rospy.Subscriber("chatter", String, heard, 1)
    rospy.Subscriber("chatter", String, heard, 2)
    rospy.Subscriber("chatter", String, heard, ("chatter1", 4))
    rospy.Subscriber("chatter2", String, heard, "This is from chatter2")
    rospy.init_node("listener_with_user_data", anonymous=True)
    rospy.spin()


if __name__ == "__main__":
    with contextlib.suppress(KeyboardInterrupt):
        listen()
    print("exiting")
