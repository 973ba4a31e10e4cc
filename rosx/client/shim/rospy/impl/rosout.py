"""``rospy.impl.rosout`` for scripts that rosx runs: `RosOutHandler`, the handler on the
``rosout`` logger that publishes its records on ``/rosout`` (see the ``rospy`` package)."""

from rosx.client.logs import RosoutHandler as RosOutHandler

__all__ = ["RosOutHandler"]
