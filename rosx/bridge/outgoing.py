"""One message of a topic on its way to clients, encoded once per encoding for all of them.

A topic's message arrives at the bridge as its serialized bytes. A client subscribed with
``cbor-raw`` gets those bytes as they came (rosbridge's ``{"secs", "nsecs", "bytes"}``, the
time the bridge received them), never copied; the others get JSON or CBOR values, for which
the bytes are decoded once, whatever the number of clients. What a frame looks like is
rosbridge v2's ``publish`` op (ROSBRIDGE_PROTOCOL.md, 3.1.3 to 3.1.4 and 3.4.4).
"""

from __future__ import annotations

import json
import struct
from typing import TYPE_CHECKING, Any

from rosx.bridge.convert import cbor_values, json_values
from rosx.bridge.jsontext import json_text
from rosx.msg.codec.codegen import variant

if TYPE_CHECKING:
    from rosx.msg.codec.message import Message

#: Each topic's JSON text before its message (a topic's name is written once).
_json_heads: dict[str, str] = {}
#: The CBOR head of a byte string of a length (RFC 8949, 3.1: major type 2).
_BYTES_16 = struct.Struct(">BH")
_BYTES_32 = struct.Struct(">BI")
_BYTES_64 = struct.Struct(">BQ")


class Outgoing:
    """``raw`` (a message of ``msg_class`` as serialized) published on ``topic``, received at
    ``stamp_ns`` (nanoseconds since the epoch); ``msg_class`` None when the type is unknown
    here (then only cbor-raw works)."""

    __slots__ = (
        "_cbor",
        "_cbor_raw",
        "_json",
        "_message",
        "msg_class",
        "raw",
        "stamp_ns",
        "topic",
    )

    def __init__(
        self, topic: str, raw: bytes, msg_class: type[Message] | None, stamp_ns: int
    ) -> None:
        self.topic = topic
        self.raw = raw
        self.msg_class = msg_class
        self.stamp_ns = stamp_ns
        self._message: Message | None = None
        self._json: str | None = None
        self._cbor: bytes | None = None
        self._cbor_raw: tuple[bytes, bytes] | None = None

    @classmethod
    def of(cls, topic: str, message: Message, stamp_ns: int) -> Outgoing:
        """An outgoing message from a message object (serialized only if cbor-raw asks)."""
        out = cls(topic, b"", type(message), stamp_ns)
        out._message = message
        return out

    def message(self) -> Message:
        """The decoded message. Raises the codec's errors, or LookupError for an unknown type."""
        if self._message is None:
            cls = self.msg_class
            if cls is None:
                raise LookupError("its type is unknown to the bridge")
            try:  # each value built anew, straight into a bare instance: the quickest read
                self._message = variant(cls, "deserialize_fresh")(object.__new__(cls), self.raw)
            except Exception:  # the codec's own path says what is wrong (or reads it lossily)
                self._message = cls().deserialize(self.raw)
        return self._message

    def publish_json(self) -> str:
        """The ``publish`` op's JSON text."""
        if self._json is None:
            message = self.message()
            head = _json_heads.get(self.topic)
            if head is None:
                head = _json_heads[self.topic] = (
                    f'{{"op":"publish","topic":{json.dumps(self.topic)},"msg":'
                )
            try:
                body = json_text(message)
            except (TypeError, AttributeError):  # a value of an unexpected kind: the long way
                body = json.dumps(json_values(message), separators=(",", ":"), allow_nan=False)
            self._json = f"{head}{body}}}"
        return self._json

    def publish_cbor(self) -> bytes:
        """The ``publish`` op as CBOR, numeric arrays as typed arrays."""
        if self._cbor is None:
            import cbor2  # noqa: PLC0415 - only CBOR subscriptions pay for it

            msg = cbor_values(self.message())
            self._cbor = cbor2.dumps({"op": "publish", "topic": self.topic, "msg": msg})
        return self._cbor

    def publish_cbor_raw(self) -> tuple[bytes, bytes]:
        """The ``publish`` op as CBOR with the serialized message (cbor-raw), in two pieces:
        everything up to the bytes, then the bytes as they came."""
        if self._cbor_raw is None:
            import cbor2  # noqa: PLC0415 - only CBOR subscriptions pay for it

            if not self.raw and self._message is not None:
                self.raw = serialize(self._message)
            secs, nsecs = divmod(self.stamp_ns, 1_000_000_000)
            msg: dict[str, Any] = {"secs": secs, "nsecs": nsecs, "bytes": b""}
            # The bytes come last: the encoding of the empty string's head (one byte, 0x40)
            # gives way to the head of the message's length.
            head = cbor2.dumps({"op": "publish", "topic": self.topic, "msg": msg})
            self._cbor_raw = (head[:-1] + _bytes_head(len(self.raw)), self.raw)
        return self._cbor_raw


def _bytes_head(length: int) -> bytes:
    if length < 24:
        return bytes((0x40 | length,))
    if length < 1 << 8:
        return bytes((0x58, length))
    if length < 1 << 16:
        return _BYTES_16.pack(0x59, length)
    if length < 1 << 32:
        return _BYTES_32.pack(0x5A, length)
    return _BYTES_64.pack(0x5B, length)


def serialize(message: Message) -> bytes:
    """``message`` in the ROS 1 wire format."""
    import io  # noqa: PLC0415 - rarely needed: topics arrive serialized

    buff = io.BytesIO()
    message.serialize(buff)
    return buff.getvalue()


__all__ = ["Outgoing", "serialize"]
