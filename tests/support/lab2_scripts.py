"""The lab sheet's Lab 2 scripts, typos corrected and nothing else changed.

The sheet's ``rospy.init node``, ``rospy Rate``, ``/turtle1/cmd vel``, ``queue size``,
``rospy.is shutdown``, ``geometry msgs`` and the broken ``if name == ' main ':`` block are
corrected; the subscriber script gains the ``rospy.init_node`` and ``rate`` it uses without
defining. `STOP_AT_TEN` is the answer to Assignment 3: the subscriber with an if-else on
``pos.x``.
"""

from __future__ import annotations

PUB = """\
#!/usr/bin/python3
import rospy
from geometry_msgs.msg import Twist
vel = Twist()
def main():
    rospy.init_node("lab2")
    rate = rospy.Rate(100)
    # Code to publish
    pub = rospy.Publisher('/turtle1/cmd_vel', Twist,queue_size=10)
    while not rospy.is_shutdown():
        # TODO
        vel.linear.x = 1
        pub.publish(vel)
        rate.sleep()
if __name__ == '__main__':
    try:
        main()
    except rospy.ROSInterruptException:
        pass
"""

_SUB = """\
#!/usr/bin/python3
import rospy
from geometry_msgs.msg import Twist
from turtlesim.msg import Pose
vel = Twist()
pos = Pose()
def callback(data):
   \"\"\"Active when recevie info from topic\"\"\"
   # using global keyword to
   # edit variable outside function
   global pos
   pos = data
def main():
   rospy.init_node("lab2")
   rate = rospy.Rate(100)
   #_Code to publish
   pub = rospy.Publisher('/turtle1/cmd_vel', Twist,queue_size=10)
   sub = rospy.Subscriber('/turtle1/pose', Pose, callback)
   while not rospy.is_shutdown():
       print("Turtle is running at", pos.x, pos.y)
{move}
       pub.publish(vel)
       rate.sleep()
if __name__ == '__main__':
   try:
       main()
   except rospy.ROSInterruptException:
       pass
"""

SUB = _SUB.format(move="       vel.linear.x = 1")

STOP_AT_TEN = _SUB.format(
    move="""\
       if pos.x >= 10:
           vel.linear.x = 0
       else:
           vel.linear.x = 1"""
)
