"""Times as tf2's core keeps them: integer nanoseconds, made from the caller's time objects.

tf2 prints times as ``toSec()`` with ``%.09f``; `text` does the same arithmetic, so the times
quoted in error texts are ROS 1's to the digit. ROS 1's Python binding also passes every
``rospy.Time`` through a double (``to_sec()``, then ``fromSec``), which loses a few hundred
nanoseconds at today's epoch: a transform looked up at a message's stamp comes back stamped a
little off, and ``t.header.stamp == msg.header.stamp`` fails. `nanos` keeps a time's seconds
and nanoseconds exactly instead; only objects that have nothing but ``to_sec()`` go through
the double, as in ROS 1.
"""

from __future__ import annotations

import math

#: One second, in the nanoseconds stamps are counted in.
SECOND = 1_000_000_000
#: ``ros::TIME_MAX``: the largest time.
TIME_MAX = 0xFFFFFFFF * SECOND + 999_999_999

_TIME_ERROR = "time must have a to_sec method, e.g. rospy.Time or rospy.Duration"


def from_sec(seconds: float) -> int:
    """``ros::Time::fromSec``: ``seconds`` in nanoseconds, rounded half away from zero."""
    whole = math.floor(seconds)
    return whole * SECOND + math.floor((seconds - whole) * 1e9 + 0.5)


def nanos(stamp: object) -> int:
    """A time or duration object in nanoseconds: exactly from ``secs`` and ``nsecs`` (rospy's,
    genpy's and rosx's times), else from ``to_sec()``.

    Raises:
        TypeError: ``stamp`` is neither (tf2's message).
    """
    try:
        return int(stamp.secs * SECOND + stamp.nsecs)  # type: ignore[attr-defined]
    except AttributeError:
        pass
    try:
        seconds = stamp.to_sec()  # type: ignore[attr-defined]
    except AttributeError:
        raise TypeError(_TIME_ERROR) from None
    return from_sec(seconds)


def to_sec(stamp_ns: int) -> float:
    """``ros::Time::toSec()`` of a stamp in ns (seconds plus 1e-9 times nanoseconds)."""
    secs, nsecs = divmod(stamp_ns, SECOND)
    return float(secs) + 1e-9 * float(nsecs)


def text(stamp_ns: int) -> str:
    """A stamp as tf2's error texts print it (``%.09f`` of ``toSec()``)."""
    return f"{to_sec(stamp_ns):.9f}"


__all__ = ["SECOND", "TIME_MAX", "from_sec", "nanos", "text", "to_sec"]
