#!/usr/bin/env python3
"""actionlib_tutorials' random numbers for the averaging server: ``random_number``
(std_msgs/Float32), normally distributed around 5 (deviation 1), 20 a second."""

import random

import rospy
from std_msgs.msg import Float32


def gen_number():
    rospy.init_node("random_number_generator")
    publisher = rospy.Publisher("random_number", Float32)
    rospy.loginfo("Generating random numbers")
    rate = rospy.Rate(20)
    while not rospy.is_shutdown():
        publisher.publish(Float32(random.normalvariate(5, 1)))
        rate.sleep()


if __name__ == "__main__":
    try:
        gen_number()
    except KeyboardInterrupt:
        print("done")
