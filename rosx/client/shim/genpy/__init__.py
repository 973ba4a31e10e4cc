"""``genpy`` for scripts that rosx runs: ``Message``, ``Time``, ``Duration`` and the
(de)serialization errors, which are rosx's message classes' own (`rosx.msg.codec`). A Python
that cannot import rosx gets the next ``genpy`` on its path instead (see ``rospy``).
"""

from __future__ import annotations

try:
    from rosx.msg.codec.message import (
        DeserializationError,
        Message,
        MessageException,
        SerializationError,
    )
    from rosx.msg.codec.rostime import Duration, Time, TVal
except ImportError:
    from _rosx_shim import load_next  # type: ignore[import-not-found]

    load_next("genpy")
else:
    from rosx.client.ros1_names import use_ros1_names as _use_ros1_names

    from . import message, rostime

    _use_ros1_names("rosx.msg.codec.message", "rosx.msg.codec.rostime")

    __all__ = [
        "DeserializationError",
        "Duration",
        "Message",
        "MessageException",
        "SerializationError",
        "TVal",
        "Time",
        "message",
        "rostime",
    ]
