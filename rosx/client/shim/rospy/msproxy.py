"""``rospy.msproxy`` for scripts that rosx runs (see the ``rospy`` package)."""

from rosx.client.masterproxy import (
    MasterProxy,
)

__all__ = ["MasterProxy"]
