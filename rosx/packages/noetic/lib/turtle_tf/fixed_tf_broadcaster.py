#!/usr/bin/env python3
"""turtle_tf's fixed frame: ``carrot1``, 2 m to the left of turtle1, published about ten times
a second as a tf/tfMessage straight on /tf."""

import rospy
import tf.msg
from geometry_msgs.msg import TransformStamped

if __name__ == "__main__":
    rospy.init_node("fixed_tf_broadcaster")
    publisher = rospy.Publisher("/tf", tf.msg.tfMessage, queue_size=1)
    while not rospy.is_shutdown():
        rospy.sleep(0.1)
        t = TransformStamped()
        t.header.frame_id = "turtle1"
        t.header.stamp = rospy.Time.now()
        t.child_frame_id = "carrot1"
        t.transform.translation.y = 2.0
        t.transform.rotation.w = 1.0
        publisher.publish(tf.msg.tfMessage([t]))
