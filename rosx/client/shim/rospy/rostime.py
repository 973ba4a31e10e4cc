"""``rospy.rostime`` for scripts that rosx runs (see the ``rospy`` package)."""

from rosx.client.timing import (
    Duration,
    Time,
    get_rostime,
    get_time,
)

__all__ = ["Duration", "Time", "get_rostime", "get_time"]
