#!/usr/bin/env python3
"""rospy_tutorials' advanced_publish: node ``color_talker`` (anonymous) publishes ColorRGBA
on ``color`` without building messages: ``publish(1, 2, 3, 4)`` fills the fields in order,
``publish(a=1.0)`` by name (the others zero); twice a second, then logs its subscribers."""

import contextlib

import rospy
from std_msgs.msg import ColorRGBA


def talk() -> None:
    topic = "color"
    color = rospy.Publisher(topic, ColorRGBA, queue_size=10)
    rospy.init_node("color_talker", anonymous=True)
    print(
        "\n\nNode running. To see messages, please type\n"
        f"\t'rostopic echo {rospy.resolve_name(topic)}'\nIn another window\n\n"
    )
    while not rospy.is_shutdown():
        color.publish(1, 2, 3, 4)
        rospy.sleep(0.5)
        color.publish(a=1.0)
        rospy.sleep(0.5)
        rospy.loginfo(f"I have {color.get_num_connections()} subscribers")


if __name__ == "__main__":
    with contextlib.suppress(rospy.ROSInterruptException):
        talk()
