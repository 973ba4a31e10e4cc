"""``rospy.rostime`` for scripts that rosx runs (see the ``rospy`` package)."""

from rosx.client.timing import (
    Duration,
    Time,
    get_rostime,
    get_time,
    is_wallclock,
    wallsleep,
)

__all__ = ["Duration", "Time", "get_rostime", "get_time", "is_wallclock", "wallsleep"]
