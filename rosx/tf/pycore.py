"""``tf2_py.BufferCore``: the buffer core with the methods of ROS 1's Python binding.

ROS 1's ``tf2_ros.Buffer`` inherits ``tf2_py.BufferCore``, a C++ extension whose methods take
``geometry_msgs/TransformStamped`` messages and ``rospy`` times and give them back
(``set_transform``, ``lookup_transform_core``, ``can_transform_core`` → ``(1, '')`` or
``(0, reason)``, ``all_frames_as_yaml``…). `BufferCore` adds these to the pure core
(`rosx.tf.core.BufferCore`, whose raw methods — ``set``, ``lookup``, ``can``, ``frames`` — stay
available for rosx's own tools), converting times as the binding does (`rosx.tf.stamps`).
Refused transforms are reported on stderr as ROS 1's console prints them (``Warning: …``),
each distinct text once, not at every message as ROS 1 repeats it.
"""

from __future__ import annotations

import sys
import threading
from typing import TYPE_CHECKING, Any

from rosx.tf import core, stamps
from rosx.tf.exceptions import TransformException

if TYPE_CHECKING:
    from collections.abc import Callable

    from rosx.tf.core import Transform

_TRANSLATION_MEMBERS = "transform.translation must have members x, y, z"
_ROTATION_MEMBERS = "transform.rotation must have members w, x, y, z"
_TRANSLATION_TYPE = "transform.translation must be of type Vector3"
_ROTATION_TYPE = "transform.rotation must be of type Quaternion"


class _OncePerText:
    """Prints each refusal once: ROS 1 prints TF_REPEATED_DATA for every message, which
    buries a terminal (geometry2#467); the first tells the user what they need."""

    def __init__(self) -> None:
        self.seen: set[str] = set()
        self.lock = threading.Lock()

    def __call__(self, level: str, text: str) -> None:
        key = text.split(" at time ", 1)[0] if text.startswith("TF_") else text
        with self.lock:
            if key in self.seen:
                return
            self.seen.add(key)
        pad = "  " if level == "Error" else ""
        sys.stderr.write(f"{level}: {pad}{text}\n")
        sys.stderr.flush()


def stderr_report() -> Callable[[str, str], None]:
    """A reporter for `rosx.tf.core.BufferCore` that prints ROS 1's console lines."""
    return _OncePerText()


def _transform_of(msg: Any, exact_types: bool) -> tuple[str, str, int, Transform]:
    """The parent, child, stamp (ns) and transform of a TransformStamped-like object."""
    header = msg.header
    child = msg.child_frame_id
    parent = header.frame_id
    stamp = stamps.nanos(header.stamp)
    transform = msg.transform
    t = transform.translation
    r = transform.rotation
    if not (hasattr(t, "x") and hasattr(t, "y") and hasattr(t, "z")):
        raise TypeError(_TRANSLATION_TYPE if exact_types else _TRANSLATION_MEMBERS)
    if not (hasattr(r, "w") and hasattr(r, "x") and hasattr(r, "y") and hasattr(r, "z")):
        raise TypeError(_ROTATION_TYPE if exact_types else _ROTATION_MEMBERS)
    return (
        parent,
        child,
        stamp,
        (float(t.x), float(t.y), float(t.z), float(r.x), float(r.y), float(r.z), float(r.w)),
    )


def _message_classes() -> tuple[type[Any], type[Any]]:
    from rosx.client.timing import Time  # noqa: PLC0415 - rospy's Time, as the binding returns
    from rosx.msg.codec.classes import get_message_class  # noqa: PLC0415 - message classes load on first use

    return get_message_class("geometry_msgs/TransformStamped"), Time


class BufferCore(core.BufferCore):
    """tf2_py's ``BufferCore(cache_time=rospy.Duration(10))`` (see the module docstring)."""

    def __init__(self, cache_time: Any = None) -> None:
        length = core.DEFAULT_CACHE_TIME if cache_time is None else stamps.nanos(cache_time)
        super().__init__(length, stderr_report())
        self._classes: tuple[type[Any], type[Any]] | None = None

    # -- messages in and out -----------------------------------------------------------------

    def set_transform(self, transform: Any, authority: str) -> None:
        """Store a ``geometry_msgs/TransformStamped`` sent by ``authority``."""
        parent, child, stamp, values = _transform_of(transform, False)
        self.set(parent, child, stamp, values, str(authority), False)

    def set_transform_static(self, transform: Any, authority: str) -> None:
        """Store a static ``geometry_msgs/TransformStamped`` (valid at every time)."""
        parent, child, stamp, values = _transform_of(transform, True)
        self.set(parent, child, stamp, values, str(authority), True)

    def message(self, target: str, source: str, stamp: int, values: Transform) -> Any:
        """A ``geometry_msgs/TransformStamped`` from ``source`` to ``target`` at ``stamp``."""
        classes = self._classes
        if classes is None:
            classes = self._classes = _message_classes()
        msg_class, time_class = classes
        msg = msg_class()
        header = msg.header
        # divmod's pair is already canonical: the constructor's checks would only cost time
        when: Any = object.__new__(time_class)
        when.secs, when.nsecs = divmod(stamp, stamps.SECOND)
        header.stamp = when
        header.frame_id = target
        msg.child_frame_id = source
        transform = msg.transform
        t = transform.translation
        t.x, t.y, t.z = values[0], values[1], values[2]
        r = transform.rotation
        r.x, r.y, r.z, r.w = values[3], values[4], values[5], values[6]
        return msg

    def lookup_transform_core(self, target_frame: str, source_frame: str, time: Any) -> Any:
        """The transform from ``source_frame`` to ``target_frame`` at ``time`` (a
        ``rospy.Time``; 0 for the latest), as a ``TransformStamped``.

        Raises:
            TransformException: ROS 1's subclass and text.
        """
        stamp, values = self.lookup(target_frame, source_frame, stamps.nanos(time))
        return self.message(target_frame, source_frame, stamp, values)

    def lookup_transform_full_core(
        self,
        target_frame: str,
        target_time: Any,
        source_frame: str,
        source_time: Any,
        fixed_frame: str,
    ) -> Any:
        """The transform from ``source_frame`` at ``source_time`` to ``target_frame`` at
        ``target_time``, through ``fixed_frame`` (constant over time)."""
        stamp, values = self.lookup_full(
            target_frame,
            stamps.nanos(target_time),
            source_frame,
            stamps.nanos(source_time),
            fixed_frame,
        )
        return self.message(target_frame, source_frame, stamp, values)

    def can_transform_core(
        self, target_frame: str, source_frame: str, time: Any
    ) -> tuple[int, str]:
        """``(1, '')`` when the lookup would succeed, else ``(0, why)``, as ROS 1's binding."""
        ok, text = self.can(target_frame, source_frame, stamps.nanos(time))
        return int(ok), text

    def can_transform_full_core(
        self,
        target_frame: str,
        target_time: Any,
        source_frame: str,
        source_time: Any,
        fixed_frame: str,
    ) -> tuple[int, str]:
        """`can_transform_core` through a fixed frame."""
        ok, text = self.can_full(
            target_frame,
            stamps.nanos(target_time),
            source_frame,
            stamps.nanos(source_time),
            fixed_frame,
        )
        return int(ok), text

    def get_latest_common_time(self, target_frame: str, source_frame: str) -> Any:
        """The latest time both frames (and the chain between them) have data for."""
        stamp = self.latest_common_time(target_frame, source_frame)
        time_class = _message_classes()[1]
        secs, nsecs = divmod(stamp, stamps.SECOND)
        return time_class(secs, nsecs)

    # -- descriptions ------------------------------------------------------------------------

    def all_frames_as_yaml(self) -> str:
        """Each frame's parent, broadcaster, rate and buffered span, as YAML."""
        return self.frames_as_yaml()

    def all_frames_as_string(self) -> str:
        """``Frame X exists with parent Y.`` for each frame."""
        return self.frames_as_string()

    def _allFramesAsDot(self, time: Any = None) -> str:  # noqa: N802 - tf2_py's name
        return self.frames_as_dot(0.0 if time is None else stamps.to_sec(stamps.nanos(time)))

    def _frameExists(self, frame_id: str) -> bool:  # noqa: N802 - tf2_py's name
        return self.frame_exists(frame_id)

    def _getFrameStrings(self) -> list[str]:  # noqa: N802 - tf2_py's name
        return self.frame_names()

    def _chain(
        self,
        target_frame: str,
        target_time: Any,
        source_frame: str,
        source_time: Any,
        fixed_frame: str,
    ) -> list[str]:
        """The frames between ``source_frame`` and ``target_frame`` (tf2's
        ``_chainAsVector``)."""
        return self.chain(
            target_frame,
            stamps.nanos(target_time),
            source_frame,
            stamps.nanos(source_time),
            fixed_frame,
        )


__all__ = ["BufferCore", "TransformException", "stderr_report"]
