"""``roslib.message`` for scripts that rosx runs (see the ``roslib`` package): the message
classes by name and genpy's names it re-exports."""

from rosx.client.roslib import get_message_class, get_service_class, strify_message
from rosx.msg.codec.message import DeserializationError, Message, SerializationError
from rosx.msg.codec.rostime import Duration, Time, TVal

__all__ = [
    "DeserializationError",
    "Duration",
    "Message",
    "SerializationError",
    "TVal",
    "Time",
    "get_message_class",
    "get_service_class",
    "strify_message",
]
