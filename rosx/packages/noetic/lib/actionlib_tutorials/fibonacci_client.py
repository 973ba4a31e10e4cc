#!/usr/bin/env python3
"""actionlib_tutorials' Python Fibonacci client: asks ``fibonacci`` for order 20, prints the
result."""

import sys

import actionlib
import rospy
from actionlib_tutorials.msg import FibonacciAction, FibonacciGoal


def fibonacci_client():
    """Send the goal, wait for the server's answer, return the ``FibonacciResult``."""
    client = actionlib.SimpleActionClient("fibonacci", FibonacciAction)
    client.wait_for_server()
    client.send_goal(FibonacciGoal(order=20))
    client.wait_for_result()
    return client.get_result()


if __name__ == "__main__":
    try:
        rospy.init_node("fibonacci_client_py")
        result = fibonacci_client()
        print("Result:", ", ".join(str(number) for number in result.sequence))
    except rospy.ROSInterruptException:
        print("program interrupted before completion", file=sys.stderr)
