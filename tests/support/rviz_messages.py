"""Messages for rviz's displays: point clouds, poses, markers, images, a robot's URDF."""

from __future__ import annotations

import math
import struct
from typing import Any

import numpy as np

from rosx.msg.codec.classes import get_message_class
from rosx_commands.rviz.displays.markers import ADD
from tests.support.rviz import message


def cloud(points: list[tuple[float, float, float, int]], frame: str = "base_link") -> object:
    fields = []
    field_class = get_message_class("sensor_msgs/PointField")
    for offset, name in enumerate(("x", "y", "z")):
        fields.append(field_class(name=name, offset=4 * offset, datatype=7, count=1))
    fields.append(field_class(name="rgb", offset=16, datatype=7, count=1))
    data = b"".join(
        struct.pack("<fffxxxxI", x, y, z, rgb) for x, y, z, rgb in points
    )  # padded to 20 bytes a point
    return message(
        "sensor_msgs/PointCloud2",
        frame,
        height=1,
        width=len(points),
        fields=fields,
        is_bigendian=False,
        point_step=20,
        row_step=20 * len(points),
        data=data,
        is_dense=False,
    )


def pose_msg(x: float, y: float, yaw: float, frame: str = "odom") -> Any:
    msg = message("geometry_msgs/PoseStamped", frame)
    msg.pose.position.x, msg.pose.position.y = x, y
    msg.pose.orientation.z, msg.pose.orientation.w = math.sin(yaw / 2), math.cos(yaw / 2)
    return msg


def marker(kind: int, marker_id: int = 0, action: int = ADD, **fields: Any) -> Any:
    msg = message("visualization_msgs/Marker", "map", ns="shapes", id=marker_id, type=kind)
    msg.action = action
    msg.pose.orientation.w = 1.0
    msg.scale.x = msg.scale.y = msg.scale.z = 1.0
    msg.color.r, msg.color.a = 1.0, 1.0
    for name, value in fields.items():
        setattr(msg, name, value)
    return msg


URDF = """<robot name="burger">
  <material name="dark"><color rgba="0.2 0.2 0.2 1"/></material>
  <link name="base_footprint"/>
  <link name="base_link">
    <visual><origin xyz="-0.032 0 0.07"/><geometry><box size="0.14 0.14 0.14"/></geometry>
      <material name="dark"/></visual>
  </link>
  <link name="wheel"><visual><geometry><cylinder radius="0.033" length="0.018"/></geometry></visual></link>
  <link name="mesh"><visual><geometry><mesh filename="package://x/y.stl"/></geometry></visual></link>
</robot>"""


def image(encoding: str, pixels: np.ndarray[Any, Any]) -> Any:
    height, width = pixels.shape[:2]
    data = pixels.tobytes()
    return message(
        "sensor_msgs/Image", "camera", height=height, width=width, encoding=encoding,
        is_bigendian=0, step=len(data) // height, data=data,
    )  # fmt: skip
