"""``rospy.msg`` for scripts that rosx runs (see the ``rospy`` package)."""

from rosx.client.anymsg import (
    AnyMsg,
)

__all__ = ["AnyMsg"]
