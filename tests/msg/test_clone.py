"""`rosx.msg.codec.clone`: a copy equal to the message that shares nothing mutable with it."""

from __future__ import annotations

from typing import Any

from rosx.msg.codec.classes import get_message_class
from rosx.msg.codec.clone import clone
from rosx.msg.codec.rostime import Time

PoseStamped = get_message_class("geometry_msgs/PoseStamped")
PoseArray = get_message_class("geometry_msgs/PoseArray")
Pose = get_message_class("geometry_msgs/Pose")
LaserScan = get_message_class("sensor_msgs/LaserScan")
Image = get_message_class("sensor_msgs/Image")
Vector3 = get_message_class("geometry_msgs/Vector3")


def test_nested_messages_and_times_are_copied() -> None:
    msg: Any = PoseStamped()
    msg.header.frame_id = "map"
    msg.header.stamp = Time(5, 6)
    msg.pose.position.x = 1.5
    copy: Any = clone(msg)
    assert copy == msg
    assert copy.header is not msg.header
    assert copy.header.stamp is not msg.header.stamp
    msg.header.stamp.secs = 9
    msg.pose.position.x = 2.5
    assert (copy.header.stamp.secs, copy.pose.position.x) == (5, 1.5)


def test_lists_of_messages_and_numbers_are_copied() -> None:
    poses: Any = PoseArray(poses=[Pose(), Pose()])
    copy: Any = clone(poses)
    poses.poses[0].position.x = 3.0
    poses.poses.append(Pose())
    assert len(copy.poses) == 2
    assert copy.poses[0].position.x == 0.0
    scan: Any = LaserScan(ranges=[1.0, 2.0])
    copied: Any = clone(scan)
    scan.ranges[0] = 7.0
    assert copied.ranges == [1.0, 2.0]


def test_immutable_data_is_shared_and_arrays_copied() -> None:
    import numpy as np

    image: Any = Image(data=bytes(1024))
    assert clone(image).data is image.data  # bytes cannot change: no copy
    scan: Any = LaserScan(ranges=np.arange(4, dtype=np.float32))
    copy: Any = clone(scan)
    scan.ranges[0] = 9.0
    assert copy.ranges.tolist() == [0.0, 1.0, 2.0, 3.0]


def test_a_field_holding_another_class_is_copied_generically() -> None:
    msg: Any = PoseStamped()
    msg.pose = [1, [2]]  # not a Pose: copied whatever it is
    copy: Any = clone(msg)
    msg.pose[1].append(3)
    assert copy.pose == [1, [2]]
    vector: Any = Vector3(x=1.0)
    assert clone(vector) == vector
