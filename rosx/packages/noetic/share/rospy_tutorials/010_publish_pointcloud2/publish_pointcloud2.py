#!/usr/bin/env python3
"""rospy_tutorials' publish_pointcloud2: node ``pc2_publisher`` publishes, ten times a second,
a 100 x 100 grid of points (x, y, a rippling z, and z again as intensity) in frame ``map`` as
a ``sensor_msgs/PointCloud2`` on ``points2``, built with ``sensor_msgs.point_cloud2``."""

import numpy as np  # noqa: TID253 - a script of its own, as the original
import rospy
from sensor_msgs import point_cloud2
from sensor_msgs.msg import PointCloud2, PointField
from std_msgs.msg import Header

WIDTH = 100
HEIGHT = 100


def cloud(count: int) -> PointCloud2:
    fields = [
        PointField("x", 0, PointField.FLOAT32, 1),
        PointField("y", 4, PointField.FLOAT32, 1),
        PointField("z", 8, PointField.FLOAT32, 1),
        PointField("intensity", 12, PointField.FLOAT32, 1),
    ]
    header = Header()
    header.frame_id = "map"
    header.stamp = rospy.Time.now()
    x, y = np.meshgrid(np.linspace(-2, 2, WIDTH), np.linspace(-2, 2, HEIGHT))
    z = 0.5 * np.sin(2 * x - count / 10.0) * np.sin(2 * y)
    points = np.array([x, y, z, z]).reshape(4, -1).T
    return point_cloud2.create_cloud(header, fields, points)


def publish() -> None:
    rospy.init_node("pc2_publisher")
    points2 = rospy.Publisher("points2", PointCloud2, queue_size=100)
    rate = rospy.Rate(10)
    count = 0
    while not rospy.is_shutdown():
        points2.publish(cloud(count))
        count += 1
        rate.sleep()


if __name__ == "__main__":
    publish()
