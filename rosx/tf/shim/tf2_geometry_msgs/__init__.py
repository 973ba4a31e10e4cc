"""``tf2_geometry_msgs`` for scripts that rosx runs (`rosx.tf.geometry`); importing it makes
``Buffer.transform()`` take geometry_msgs' stamped types, as in ROS 1."""

from __future__ import annotations

try:
    from rosx.tf.geometry import (
        do_transform_point,
        do_transform_pose,
        do_transform_vector3,
        do_transform_wrench,
        from_msg_msg,
        register,
        to_msg_msg,
        transform_to_kdl,
    )
except ImportError:
    from _rosx_shim import load_next  # type: ignore[import-not-found]

    load_next("tf2_geometry_msgs")
else:
    from rosx.client.modules import install as _install

    _install()
    register()
    from geometry_msgs.msg import (  # type: ignore[import-not-found]
        PointStamped,
        PoseStamped,
        Vector3Stamped,
        WrenchStamped,
    )

    __all__ = [
        "PointStamped",
        "PoseStamped",
        "Vector3Stamped",
        "WrenchStamped",
        "do_transform_point",
        "do_transform_pose",
        "do_transform_vector3",
        "do_transform_wrench",
        "from_msg_msg",
        "to_msg_msg",
        "transform_to_kdl",
    ]
