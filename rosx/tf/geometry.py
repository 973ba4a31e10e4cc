"""``tf2_geometry_msgs``: transforming geometry_msgs' stamped types with a TransformStamped.

``do_transform_point``, ``do_transform_vector3`` (rotation only), ``do_transform_pose`` and
``do_transform_wrench`` return a new message in the transform's frame, stamped with the
transform's header, as ROS 1's do (with KDL's arithmetic, `rosx.tf.kdl`). `register` adds them
to the buffers' ``transform()`` (`rosx.tf.interface`), which importing ``tf2_geometry_msgs``
does in a script.
"""

from __future__ import annotations

import copy
from typing import Any

from rosx.tf import kdl
from rosx.tf.ros import message_class


def to_msg_msg(msg: Any) -> Any:
    """A message is its own message form."""
    return msg


def from_msg_msg(msg: Any) -> Any:
    """A message is made from its own message form."""
    return msg


def _frame(t: Any) -> tuple[kdl.Rotation, kdl.Vector]:
    r = t.transform.rotation
    v = t.transform.translation
    return kdl.rotation(r.x, r.y, r.z, r.w), (v.x, v.y, v.z)


def transform_to_kdl(t: Any) -> tuple[kdl.Rotation, kdl.Vector]:
    """The transform as KDL's frame: (rotation matrix, translation)."""
    return _frame(t)


def do_transform_point(point: Any, transform: Any) -> Any:
    """A ``PointStamped`` moved by ``transform``."""
    m, p = _frame(transform)
    q = point.point
    x, y, z = kdl.apply(m, p, (q.x, q.y, q.z))
    res = message_class("geometry_msgs/PointStamped")()
    res.point.x, res.point.y, res.point.z = x, y, z
    res.header = transform.header
    return res


def do_transform_vector3(vector3: Any, transform: Any) -> Any:
    """A ``Vector3Stamped`` rotated by ``transform`` (its translation does not apply)."""
    transform = copy.deepcopy(transform)
    transform.transform.translation.x = 0
    transform.transform.translation.y = 0
    transform.transform.translation.z = 0
    m, p = _frame(transform)
    v = vector3.vector
    x, y, z = kdl.apply(m, p, (v.x, v.y, v.z))
    res = message_class("geometry_msgs/Vector3Stamped")()
    res.vector.x, res.vector.y, res.vector.z = x, y, z
    res.header = transform.header
    return res


def do_transform_pose(pose: Any, transform: Any) -> Any:
    """A ``PoseStamped`` moved by ``transform``."""
    m, p = _frame(transform)
    o = pose.pose.orientation
    q = pose.pose.position
    pose_m = kdl.rotation(o.x, o.y, o.z, o.w)
    x, y, z = kdl.apply(m, p, (q.x, q.y, q.z))
    res = message_class("geometry_msgs/PoseStamped")()
    res.pose.position.x, res.pose.position.y, res.pose.position.z = x, y, z
    r = res.pose.orientation
    r.x, r.y, r.z, r.w = kdl.quaternion(kdl.multiply(m, pose_m))
    res.header = transform.header
    return res


def do_transform_wrench(wrench: Any, transform: Any) -> Any:
    """A ``WrenchStamped`` whose force and torque are rotated by ``transform``."""
    vector3_stamped = message_class("geometry_msgs/Vector3Stamped")
    force = vector3_stamped()
    torque = vector3_stamped()
    force.vector = wrench.wrench.force
    torque.vector = wrench.wrench.torque
    res = message_class("geometry_msgs/WrenchStamped")()
    res.wrench.force = do_transform_vector3(force, transform).vector
    res.wrench.torque = do_transform_vector3(torque, transform).vector
    res.header = transform.header
    return res


def register() -> None:
    """Make these the buffers' ``transform()`` of the four stamped types."""
    from rosx.tf.interface import ConvertRegistration, TransformRegistration  # noqa: PLC0415 - tf code loads only when used

    converts = ConvertRegistration()
    transforms = TransformRegistration()
    for name in ("Vector3Stamped", "PoseStamped", "PointStamped"):
        cls = message_class(f"geometry_msgs/{name}")
        converts.add_to_msg(cls, to_msg_msg)
        converts.add_from_msg(cls, from_msg_msg)
    for name, function in (
        ("PointStamped", do_transform_point),
        ("Vector3Stamped", do_transform_vector3),
        ("PoseStamped", do_transform_pose),
        ("WrenchStamped", do_transform_wrench),
    ):
        transforms.add(message_class(f"geometry_msgs/{name}"), function)


__all__ = [
    "do_transform_point",
    "do_transform_pose",
    "do_transform_vector3",
    "do_transform_wrench",
    "from_msg_msg",
    "register",
    "to_msg_msg",
    "transform_to_kdl",
]
