"""``rospy.impl`` for scripts that rosx runs: ``rospy.impl.rosout`` and
``rospy.impl.tcpros_service`` (see the ``rospy`` package)."""

from . import rosout, tcpros_service

__all__ = ["rosout", "tcpros_service"]
