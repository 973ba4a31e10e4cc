"""The base classes of generated message and service classes, as rospy scripts see them.

A message class (built by `rosx.msg.codec.classes`) behaves as a class genpy generates: class
attributes ``_type``, ``_md5sum``, ``_full_text``, ``_has_header``, ``__slots__`` (the field
names in order, Python keywords suffixed with ``_``) and ``_slot_types`` (the resolved field
types), the type's constants, construction from all fields in order or from keywords, defaults
for what is not given, ``serialize(buff)`` / ``deserialize(data)`` in the ROS 1 wire format,
equality over type and fields, pickling and copying. ``str()`` gives the text ``rostopic echo``
prints. A service class carries ``_type``, ``_md5sum``, ``_request_class`` and
``_response_class``.
"""

from __future__ import annotations

import copy
import io
import struct
from typing import TYPE_CHECKING, Any, ClassVar, Protocol, TypeVar

if TYPE_CHECKING:
    from collections.abc import Callable
    from types import ModuleType

    from rosx.msg.spec import MsgSpec

_M = TypeVar("_M", bound="Message")

_U32 = struct.Struct("<I")
_PREFIX = b"\0\0\0\0"


class Writable(Protocol):
    """Where `Message.serialize` writes: anything with ``write(bytes)``, e.g. ``io.BytesIO``."""

    def write(self, data: bytes, /) -> object:
        """Write ``data``; the return value is ignored."""


class MessageException(Exception):  # noqa: N818 - genpy's name, which rospy code catches
    """A message could not be built, filled, written or read."""


class SerializationError(MessageException):
    """A field holds a value that cannot be written in the field's wire type."""


class DeserializationError(MessageException):
    """Bytes that do not hold a message of the expected type (most often: too few of them)."""


class Message:
    """Base of every generated message class; the generated subclass supplies the codec."""

    # Set by rospy on received messages; not a field, so not part of __getstate__ or equality.
    # A list, as genpy's: generated classes list their field names in the same form.
    __slots__ = ["_connection_header"]

    _type: ClassVar[str] = ""
    _md5sum: ClassVar[str] = ""
    _full_text: ClassVar[str] = ""
    _has_header: ClassVar[bool] = False
    _slot_types: ClassVar[list[str]] = []
    _spec: ClassVar[MsgSpec | None] = None

    def __init__(self, *args: Any, **kwds: Any) -> None:
        assign_fields(self, args, kwds)

    if TYPE_CHECKING:  # fields are generated per type: to a type checker they are Any

        def __getattr__(self, name: str) -> Any: ...

        def __setattr__(self, name: str, value: Any) -> None: ...

    # -- the codec (generated per type) -----------------------------------------------------

    def serialize(self, buff: Writable) -> None:
        """Write this message in the ROS 1 wire format to ``buff``.

        A message without fields (``rospy.Message()`` itself) writes nothing, as genpy's.
        """
        if self._slot_types:
            raise NotImplementedError(f"{type(self).__name__} has no generated serializer")

    def deserialize(self: _M, data: bytes) -> _M:
        """Read this message's fields from ``data`` (bytes-like) and return ``self``.

        A message without fields reads nothing.
        """
        if self._slot_types:
            raise NotImplementedError(f"{type(self).__name__} has no generated deserializer")
        return self

    def _frame(self) -> bytes:
        """This message as one TCPROS frame: its size (uint32), then what `serialize` writes.

        Types whose values all have a fixed size get a generated one, a single ``pack``.
        """
        buff = io.BytesIO()
        buff.write(_PREFIX)
        self.serialize(buff)
        size = buff.tell() - 4
        buff.seek(0)
        buff.write(_U32.pack(size))
        return buff.getvalue()

    def serialize_numpy(self, buff: Writable, numpy: ModuleType) -> None:
        """As `serialize`, taking numeric arrays as numpy arrays (generated per type)."""
        self.serialize(buff)

    def deserialize_numpy(self: _M, data: bytes, numpy: ModuleType) -> _M:
        """As `deserialize`, giving numeric arrays (not ``uint8[]``) as numpy arrays
        (generated per type)."""
        return self.deserialize(data)

    def _get_types(self) -> list[str]:
        return self._slot_types

    def _check_types(self, exc: BaseException | None = None) -> None:
        """Raise `SerializationError` naming the first field that cannot be written (each
        generated type checks its fields; a message without fields has none to check)."""
        if exc is not None:
            raise SerializationError(str(exc))

    # -- value behaviour --------------------------------------------------------------------

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, type(self)):
            return False
        for name in self.__slots__:
            try:
                mine = getattr(self, name)
                theirs = getattr(other, name)
            except AttributeError:
                return False
            if not _same_value(mine, theirs):
                return False
        return True

    def __ne__(self, other: object) -> bool:
        return not self == other

    # Messages are mutable and compare by value: unhashable, as in genpy.
    __hash__ = None  # type: ignore[assignment]

    def __str__(self) -> str:
        return _format(self)

    def __repr__(self) -> str:
        return _format(self)

    def __getstate__(self) -> list[Any]:
        return [getattr(self, name) for name in self.__slots__]

    def __setstate__(self, state: list[Any]) -> None:
        for name, value in zip(self.__slots__, state, strict=False):
            setattr(self, name, value)

    def __copy__(self: _M) -> _M:
        clone = object.__new__(type(self))
        clone.__setstate__(self.__getstate__())
        return clone

    def __deepcopy__(self: _M, memo: dict[int, Any]) -> _M:
        clone = object.__new__(type(self))
        memo[id(self)] = clone
        clone.__setstate__(copy.deepcopy(self.__getstate__(), memo))
        return clone


class ServiceDefinition:
    """Base of every generated service class: the type and its two message classes."""

    _type: ClassVar[str] = ""
    _md5sum: ClassVar[str] = ""
    _request_class: ClassVar[type[Message]]
    _response_class: ClassVar[type[Message]]


def serialize_frame(msg: Any) -> bytes:
    """``msg`` in the ROS 1 wire format as one TCPROS frame (uint32 length prefix first): a
    class of this codec through its generated ``_frame``, another library's through its
    ``serialize``."""
    if isinstance(msg, Message):
        return msg._frame()
    return Message._frame(msg)


def assign_fields(msg: Message, args: tuple[Any, ...], kwds: dict[str, Any]) -> None:
    """Set ``msg``'s fields from constructor arguments, as genpy does; unset fields get None.

    The generated ``__init__`` then replaces every None with the field's default.
    """
    names = type(msg).__slots__
    if args and kwds:
        raise TypeError("Message constructor may only use args OR keywords, not both")
    if args:
        if len(args) != len(names):
            raise TypeError(f"Invalid number of arguments, args should be {names} args are{args}")
        for name, value in zip(names, args, strict=True):
            setattr(msg, name, value)
        return
    for key in kwds:
        if key not in names:
            raise AttributeError(f"{key} is not an attribute of {type(msg).__name__}")
    for name in names:
        setattr(msg, name, kwds.get(name))


def _same_value(mine: Any, theirs: Any) -> bool:
    # Lists and tuples are interchangeable: deserialised arrays are tuples, built ones lists.
    if isinstance(mine, list | tuple) and isinstance(theirs, list | tuple):
        return tuple(mine) == tuple(theirs)
    result = mine == theirs
    if isinstance(result, bool):
        return result
    try:  # numpy arrays compare element-wise
        return bool(result.all())
    except (AttributeError, ValueError):
        return False


_formatter: Callable[[Message], str] | None = None


def _format(msg: Message) -> str:
    global _formatter  # noqa: PLW0603 - found once, on first use
    if _formatter is None:
        try:
            from rosx.msg.text.echo import format_message  # noqa: PLC0415 - heavy, only for printing
        except ImportError:
            return _plain_format(msg)
        _formatter = format_message
    return _formatter(msg)


def _plain_format(msg: Message) -> str:
    fields = ", ".join(f"{name}={getattr(msg, name, None)!r}" for name in msg.__slots__)
    return f"{msg._type}({fields})"


__all__ = [
    "DeserializationError",
    "Message",
    "MessageException",
    "SerializationError",
    "ServiceDefinition",
    "Writable",
    "assign_fields",
    "serialize_frame",
]
