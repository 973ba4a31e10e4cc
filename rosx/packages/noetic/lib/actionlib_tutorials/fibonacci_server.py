#!/usr/bin/env python3
"""actionlib_tutorials' Python Fibonacci server: the action named after the node (``fibonacci``).

For a goal of order N it sends the sequence grown by one number a second as feedback, starting
from the seeds 0 and 1, and answers the N + 1 numbers; a cancel stops it between numbers.
"""

import actionlib
import rospy
from actionlib_tutorials.msg import FibonacciAction, FibonacciFeedback, FibonacciResult


class FibonacciServer:
    """The sequence, one number a second, with feedback and preemption."""

    def __init__(self, name):
        self.name = name
        self.server = actionlib.SimpleActionServer(
            name, FibonacciAction, execute_cb=self.execute, auto_start=False
        )
        self.server.start()

    def execute(self, goal):
        rate = rospy.Rate(1)
        numbers = [0, 1]
        rospy.loginfo(
            "%s: Executing, creating fibonacci sequence of order %i with seeds %i, %i",
            self.name,
            goal.order,
            numbers[0],
            numbers[1],
        )
        for _ in range(1, goal.order):
            if self.server.is_preempt_requested():
                rospy.loginfo("%s: Preempted", self.name)
                self.server.set_preempted()
                return
            numbers.append(numbers[-1] + numbers[-2])
            self.server.publish_feedback(FibonacciFeedback(sequence=numbers))
            rate.sleep()
        rospy.loginfo("%s: Succeeded", self.name)
        self.server.set_succeeded(FibonacciResult(sequence=numbers))


if __name__ == "__main__":
    rospy.init_node("fibonacci")
    FibonacciServer(rospy.get_name())
    rospy.spin()
