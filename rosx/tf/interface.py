"""``tf2_ros.BufferInterface``: ``transform()`` through the types registered for it.

Libraries register how to transform a stamped type (``tf2_geometry_msgs`` registers
``PointStamped``, ``PoseStamped``…) in `TransformRegistration`, and conversions between types
in `ConvertRegistration`; a buffer's ``transform(obj, target_frame)`` looks up the transform
at ``obj``'s stamp from its frame and applies the registered function. The registries are
shared by every buffer of the process, as in ROS 1. A type is found by its class or, for
messages, by its ROS type name, so a class loaded twice still matches.
"""

from __future__ import annotations

import copy
from typing import Any, ClassVar

from rosx.tf import stamps


class TypeException(Exception):  # noqa: N818 - tf2_ros's name
    """No transform (or conversion) is registered for a type."""

    def __init__(self, errstr: str) -> None:
        super().__init__(errstr)
        self.errstr = errstr


class NotImplementedException(Exception):  # noqa: N818 - tf2_ros's name
    """A `BufferInterface` subclass lacks ``lookup_transform``/``can_transform``."""

    def __init__(self) -> None:
        super().__init__("CanTransform or LookupTransform not implemented")
        self.errstr = "CanTransform or LookupTransform not implemented"


# As ROS 1's, so that a traceback names them alike.
TypeException.__module__ = NotImplementedException.__module__ = "tf2_ros.buffer_interface"


def _keys(key: Any) -> tuple[Any, ...]:
    name = getattr(key, "_type", None)
    return (key, name) if isinstance(name, str) else (key,)


class _Registry:
    """One map of type → function, shared by the instances of a registration class."""

    def __init__(self) -> None:
        self.entries: dict[Any, Any] = {}

    def add(self, key: Any, value: Any) -> None:
        for k in _keys(key):
            self.entries[k] = value

    def get(self, key: Any) -> Any:
        for k in _keys(key):
            if k in self.entries:
                return self.entries[k]
        raise TypeException(f"Type {key!s} if not loaded or supported")


class TransformRegistration:
    """The transform functions of stamped types: ``f(obj, transform_stamped) -> obj``."""

    _map: ClassVar[_Registry] = _Registry()

    def print_me(self) -> None:
        """Print the registered types and their functions (tf2_ros's debugging aid)."""
        print(self._map.entries)

    def add(self, key: Any, callback: Any) -> None:
        """Register ``callback`` as the transform function of type ``key`` (a class or its
        message type name)."""
        self._map.add(key, callback)

    def get(self, key: Any) -> Any:
        """The transform function of ``key``'s type. Raises `TypeException` if none is
        registered."""
        return self._map.get(key)


class ConvertRegistration:
    """Conversions between types: to and from messages, and direct ones."""

    _to_msg: ClassVar[_Registry] = _Registry()
    _from_msg: ClassVar[_Registry] = _Registry()
    _convert: ClassVar[_Registry] = _Registry()

    def add_from_msg(self, key: Any, callback: Any) -> None:
        """Register ``callback`` to build type ``key`` from its message."""
        self._from_msg.add(key, callback)

    def add_to_msg(self, key: Any, callback: Any) -> None:
        """Register ``callback`` to turn type ``key`` into a message."""
        self._to_msg.add(key, callback)

    def add_convert(self, key: Any, callback: Any) -> None:
        """Register ``callback`` for the direct conversion ``key`` (a ``(from, to)`` pair)."""
        self._convert.entries[key] = callback

    def get_from_msg(self, key: Any) -> Any:
        """The from-message function of ``key``. Raises `TypeException` if none is registered."""
        return self._from_msg.get(key)

    def get_to_msg(self, key: Any) -> Any:
        """The to-message function of ``key``. Raises `TypeException` if none is registered."""
        return self._to_msg.get(key)

    def get_convert(self, key: Any) -> Any:
        """The direct conversion registered for ``key``. Raises `TypeException` if there is none."""
        if key not in self._convert.entries:
            raise TypeException(f"Type {key!s} if not loaded or supported")
        return self._convert.entries[key]


def convert(a: Any, b_type: Any) -> Any:
    """``a`` as a ``b_type``: a direct conversion, a copy, or through the message form."""
    registry = ConvertRegistration()
    try:
        return registry.get_convert((type(a), b_type))(a)
    except TypeException:
        if type(a) is b_type:
            return copy.deepcopy(a)
        to_msg = registry.get_to_msg(type(a))
        from_msg = registry.get_from_msg(b_type)
        return from_msg(to_msg(a))


def Stamped(obj: Any, stamp: Any, frame_id: str) -> Any:  # noqa: N802 - tf2_ros's name
    """``obj`` with a ``header`` of ``stamp`` and ``frame_id``."""
    from rosx.msg.codec.classes import get_message_class  # noqa: PLC0415 - message classes load on first use

    obj.header = get_message_class("std_msgs/Header")(frame_id=frame_id, stamp=stamp)
    return obj


def _zero() -> Any:
    from rosx.client.timing import Duration  # noqa: PLC0415 - rospy's Duration

    return Duration(0)


class BufferInterface:
    """The transform API every buffer offers, over its ``lookup_transform`` and
    ``lookup_transform_full``."""

    def __init__(self) -> None:
        self.registration = TransformRegistration()

    def transform(
        self, object_stamped: Any, target_frame: str, timeout: Any = None, new_type: Any = None
    ) -> Any:
        """``object_stamped`` in ``target_frame``, at its own stamp (waiting up to
        ``timeout`` for the transform), converted to ``new_type`` if given."""
        do_transform = self.registration.get(type(object_stamped))
        header = object_stamped.header
        result = do_transform(
            object_stamped,
            self.lookup_transform(
                target_frame, header.frame_id, header.stamp, _zero() if timeout is None else timeout
            ),
        )
        return result if not new_type else convert(result, new_type)

    def transform_full(
        self,
        object_stamped: Any,
        target_frame: str,
        target_time: Any,
        fixed_frame: str,
        timeout: Any = None,
        new_type: Any = None,
    ) -> Any:
        """`transform` between two times, through ``fixed_frame`` (constant over time)."""
        do_transform = self.registration.get(type(object_stamped))
        header = object_stamped.header
        result = do_transform(
            object_stamped,
            self.lookup_transform_full(
                target_frame,
                target_time,
                header.frame_id,
                header.stamp,
                fixed_frame,
                _zero() if timeout is None else timeout,
            ),
        )
        return result if not new_type else convert(result, new_type)

    def lookup_transform(
        self, target_frame: str, source_frame: str, time: Any, timeout: Any = None
    ) -> Any:
        """The ``TransformStamped`` taking data from ``source_frame`` to ``target_frame`` at
        ``time`` (0 for the latest), waiting up to ``timeout`` for it; a subclass implements it.

        Raises:
            LookupException, ConnectivityException, ExtrapolationException: tf2's errors.
        """
        raise NotImplementedException

    def lookup_transform_full(
        self,
        target_frame: str,
        target_time: Any,
        source_frame: str,
        source_time: Any,
        fixed_frame: str,
        timeout: Any = None,
    ) -> Any:
        """The transform from ``source_frame`` at ``source_time`` to ``target_frame`` at
        ``target_time``, through ``fixed_frame`` (which must not move between the two times);
        waits up to ``timeout``. A subclass implements it."""
        raise NotImplementedException

    def can_transform(
        self, target_frame: str, source_frame: str, time: Any, timeout: Any = None
    ) -> Any:
        """Whether `lookup_transform` would succeed, waiting up to ``timeout``; never raises
        tf2's errors. A subclass implements it."""
        raise NotImplementedException

    def can_transform_full(
        self,
        target_frame: str,
        target_time: Any,
        source_frame: str,
        source_time: Any,
        fixed_frame: str,
        timeout: Any = None,
    ) -> Any:
        """Whether `lookup_transform_full` would succeed, waiting up to ``timeout``. A subclass
        implements it."""
        raise NotImplementedException


def seconds(duration: Any) -> float:
    """A timeout (``rospy.Duration`` or seconds) in seconds, as tf2 reads it."""
    if duration is None:
        return 0.0
    if isinstance(duration, (int, float)):
        return float(duration)
    return stamps.to_sec(stamps.nanos(duration))


__all__ = [
    "BufferInterface",
    "ConvertRegistration",
    "NotImplementedException",
    "Stamped",
    "TransformRegistration",
    "TypeException",
    "convert",
    "seconds",
]
