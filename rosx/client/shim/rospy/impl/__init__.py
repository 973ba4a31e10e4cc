"""``rospy.impl`` for scripts that rosx runs: ``rospy.impl.rosout`` (see the ``rospy`` package)."""

from . import rosout

__all__ = ["rosout"]
