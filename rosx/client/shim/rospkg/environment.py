"""``rospkg.environment`` for scripts that rosx runs (see the ``rospkg`` package)."""

from rosx.client.rospkg import get_ros_package_path, get_ros_paths, get_ros_root

__all__ = ["get_ros_package_path", "get_ros_paths", "get_ros_root"]
