"""``rospy.service`` for scripts that rosx runs (see the ``rospy`` package)."""

from rosx.client.exceptions import (
    ServiceException,
)

__all__ = ["ServiceException"]
