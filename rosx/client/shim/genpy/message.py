"""``genpy.message`` for scripts that rosx runs (see the ``genpy`` package)."""

from rosx.client.roslib import get_message_class, get_service_class, strify_message
from rosx.msg.codec.message import (
    DeserializationError,
    Message,
    MessageException,
    SerializationError,
)
from rosx.msg.codec.rostime import Duration, Time, TVal

__all__ = [
    "DeserializationError",
    "Duration",
    "Message",
    "MessageException",
    "SerializationError",
    "TVal",
    "Time",
    "get_message_class",
    "get_service_class",
    "strify_message",
]
