#!/usr/bin/env python3
"""turtle_tf2's sensor: spawns turtle3 at (4, 2), drives it in a circle, and publishes its
position as a geometry_msgs/PointStamped in the ``world`` frame on ``turtle_point_stamped``."""

import rospy
from geometry_msgs.msg import Point, PointStamped, Twist
from std_msgs.msg import Header
from turtlesim.msg import Pose
from turtlesim.srv import Spawn

if __name__ == "__main__":
    rospy.init_node("turtle_tf2_msg_broadcaster")
    rospy.wait_for_service("spawn")
    rospy.ServiceProxy("spawn", Spawn)(4, 2, 0, "turtle3")
    points = rospy.Publisher("turtle_point_stamped", PointStamped, queue_size=1)

    def forward(pose: Pose) -> None:
        header = Header(0, rospy.Time.now(), "world")
        points.publish(PointStamped(header, Point(pose.x, pose.y, 0)))

    rospy.Subscriber("/turtle3/pose", Pose, forward)
    cmd_vel = rospy.Publisher("turtle3/cmd_vel", Twist, queue_size=1)
    while not rospy.is_shutdown():
        msg = Twist()
        msg.linear.x = 1
        msg.angular.z = 1
        cmd_vel.publish(msg)
        rospy.sleep(rospy.Duration(0.1))
