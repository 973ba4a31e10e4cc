"""tf2's exceptions, as ``tf2_ros`` (and ``tf2_py``, ``tf``) name them.

`TransformException` is the base of the five errors a lookup can raise; ``tf.Exception`` is the
same class. Their ``__module__`` is ``tf2``, as in ROS 1 (whose classes come from the ``_tf2``
extension), so an uncaught one reads ``tf2.LookupException: …`` in a traceback, word for word
as there.
"""

from __future__ import annotations


class TransformException(Exception):  # noqa: N818 - tf2's name
    """Any failure of a transform lookup."""


class ConnectivityException(TransformException):
    """The two frames are in trees that do not connect."""


class LookupException(TransformException):
    """A frame is unknown (or the tree has a loop)."""


class ExtrapolationException(TransformException):
    """The time asked for is outside the data buffered for a frame on the way."""


class InvalidArgumentException(TransformException):
    """A frame name is empty or starts with ``/``, or an argument has the wrong type."""


class TimeoutException(TransformException):
    """A wait for a transform ended without it."""


for _cls in (
    TransformException,
    ConnectivityException,
    LookupException,
    ExtrapolationException,
    InvalidArgumentException,
    TimeoutException,
):
    _cls.__module__ = "tf2"

__all__ = [
    "ConnectivityException",
    "ExtrapolationException",
    "InvalidArgumentException",
    "LookupException",
    "TimeoutException",
    "TransformException",
]
