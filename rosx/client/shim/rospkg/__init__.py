"""``rospkg`` for scripts that rosx runs: ``RosPack`` (``get_path``, ``list``,
``get_depends``…) over rosx's package index, and ``ResourceNotFound``, served by
`rosx.client.rospkg`. A Python that cannot import rosx gets the next ``rospkg`` on its path
instead (see ``rospy``).
"""

from __future__ import annotations

try:
    from rosx.client.rospkg import (
        ResourceNotFound,
        RosPack,
        get_ros_package_path,
        get_ros_paths,
        get_ros_root,
    )
except ImportError:
    from _rosx_shim import load_next  # type: ignore[import-not-found]

    load_next("rospkg")
else:
    from rosx.client.ros1_names import use_ros1_names as _use_ros1_names

    from . import common, environment, rospack

    _use_ros1_names("rosx.client.rospkg")

    __all__ = [
        "ResourceNotFound",
        "RosPack",
        "common",
        "environment",
        "get_ros_package_path",
        "get_ros_paths",
        "get_ros_root",
        "rospack",
    ]
