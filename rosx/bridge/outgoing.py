"""One message of a topic on its way to clients, encoded once per encoding for all of them.

A topic's message arrives at the bridge as its serialized bytes. A client subscribed with
``cbor-raw`` gets those bytes as they came (rosbridge's ``{"secs", "nsecs", "bytes"}``, the
time the bridge received them); the others get JSON or CBOR values, for which the bytes are
decoded once, whatever the number of clients. What a frame looks like is rosbridge v2's
``publish`` op (ROSBRIDGE_PROTOCOL.md, 3.1.3 to 3.1.4 and 3.4.4).
"""

from __future__ import annotations

import json
from typing import TYPE_CHECKING, Any

from rosx.bridge.convert import cbor_values, json_values

if TYPE_CHECKING:
    from rosx.msg.codec.message import Message
    from rosx.msg.codec.rostime import Time


class Outgoing:
    """``raw`` (a message of ``msg_class`` as serialized) published on ``topic``, received at
    ``stamp``; ``msg_class`` None when the type is unknown here (then only cbor-raw works)."""

    __slots__ = ("_cbor", "_cbor_raw", "_json", "_message", "msg_class", "raw", "stamp", "topic")

    def __init__(
        self, topic: str, raw: bytes, msg_class: type[Message] | None, stamp: Time
    ) -> None:
        self.topic = topic
        self.raw = raw
        self.msg_class = msg_class
        self.stamp = stamp
        self._message: Message | None = None
        self._json: str | None = None
        self._cbor: bytes | None = None
        self._cbor_raw: bytes | None = None

    @classmethod
    def of(cls, topic: str, message: Message, stamp: Time) -> Outgoing:
        """An outgoing message from a message object (serialized only if cbor-raw asks)."""
        out = cls(topic, b"", type(message), stamp)
        out._message = message
        return out

    def message(self) -> Message:
        """The decoded message. Raises the codec's errors, or LookupError for an unknown type."""
        if self._message is None:
            if self.msg_class is None:
                raise LookupError("its type is unknown to the bridge")
            self._message = self.msg_class().deserialize(self.raw)
        return self._message

    def publish_json(self) -> str:
        """The ``publish`` op's JSON text."""
        if self._json is None:
            frame = {"op": "publish", "topic": self.topic, "msg": json_values(self.message())}
            self._json = json.dumps(frame, separators=(",", ":"), allow_nan=False)
        return self._json

    def publish_cbor(self) -> bytes:
        """The ``publish`` op as CBOR, numeric arrays as typed arrays."""
        if self._cbor is None:
            import cbor2  # noqa: PLC0415 - only CBOR subscriptions pay for it

            msg = cbor_values(self.message())
            self._cbor = cbor2.dumps({"op": "publish", "topic": self.topic, "msg": msg})
        return self._cbor

    def publish_cbor_raw(self) -> bytes:
        """The ``publish`` op as CBOR with the serialized message (cbor-raw)."""
        if self._cbor_raw is None:
            import cbor2  # noqa: PLC0415 - only CBOR subscriptions pay for it

            if not self.raw and self._message is not None:
                self.raw = serialize(self._message)
            msg: dict[str, Any] = {
                "secs": self.stamp.secs,
                "nsecs": self.stamp.nsecs,
                "bytes": self.raw,
            }
            self._cbor_raw = cbor2.dumps({"op": "publish", "topic": self.topic, "msg": msg})
        return self._cbor_raw


def serialize(message: Message) -> bytes:
    """``message`` in the ROS 1 wire format."""
    import io  # noqa: PLC0415 - rarely needed: topics arrive serialized

    buff = io.BytesIO()
    message.serialize(buff)
    return buff.getvalue()


__all__ = ["Outgoing", "serialize"]
