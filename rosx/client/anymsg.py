"""`AnyMsg`: rospy's message class that subscribes to any type and keeps the bytes as they came.

A subscriber of `AnyMsg` accepts every publisher of the topic whatever its type; each message
holds the serialized bytes (``_buff``) and the publisher's connection header, which names the
type. Publishing an `AnyMsg` sends those bytes unchanged, so a node can relay messages it never
decodes.
"""

from __future__ import annotations

from typing import Any, ClassVar

from rosx.client.exceptions import ROSException
from rosx.msg.codec.message import Message, Writable

ANYTYPE = "*"


class AnyMsg(Message):
    """A message of any type, kept serialized."""

    __slots__ = ["_buff"]

    _type: ClassVar[str] = ANYTYPE
    _md5sum: ClassVar[str] = ANYTYPE
    _full_text: ClassVar[str] = ""
    _has_header: ClassVar[bool] = False
    _slot_types: ClassVar[list[str]] = []

    def __init__(self, *args: Any) -> None:
        if args:
            raise ROSException("AnyMsg does not accept arguments")
        self._buff: Any = None

    @classmethod
    def from_raw(cls, buff: bytes, connection_header: dict[str, str]) -> AnyMsg:
        """A message holding ``buff``, received with ``connection_header``."""
        msg = cls()
        msg._buff = bytes(buff)
        msg._connection_header = connection_header
        return msg

    def buffer(self) -> Any:
        """The serialized bytes (what `deserialize` was given, as it was given).

        Raises:
            ROSException: the message holds none yet.
        """
        if self._buff is None:
            raise ROSException("AnyMsg is not initialized")
        return self._buff

    def serialize(self, buff: Writable) -> None:
        """Write the bytes this message was received with, unchanged (the relay's pass-through).

        Raises:
            ROSException: the message holds no bytes yet.
        """
        buff.write(self.buffer())

    def deserialize(self, data: Any) -> AnyMsg:
        """Keep ``data`` as it is, as rospy does; publishing the message sends it."""
        self._buff = data
        return self


__all__ = ["AnyMsg"]
