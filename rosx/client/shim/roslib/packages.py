"""``roslib.packages`` for scripts that rosx runs (see the ``roslib`` package)."""

from rosx.client.roslib import (
    InvalidROSPkgException,
    MultipleNodesException,
    ROSPkgException,
    find_node,
    find_resource,
    get_pkg_dir,
)

__all__ = [
    "InvalidROSPkgException",
    "MultipleNodesException",
    "ROSPkgException",
    "find_node",
    "find_resource",
    "get_pkg_dir",
]
