"""``tf2_ros.Buffer``: the buffer scripts and rosx's tools look transforms up in.

A `Buffer` is tf2_py's core (`rosx.tf.pycore.BufferCore`) with tf2_ros's calls on top:
``lookup_transform``/``can_transform`` (and their ``_full`` forms) that wait up to a timeout for
the transform to become available, ``transform()`` (`rosx.tf.interface`), and the node's
``~tf2_frames`` service (``tf2_msgs/FrameGraph``, the frames as YAML), advertised by the first
buffer of each node as ROS 1's is — view_frames.py asks it.

Waiting differs from ROS 1 in how, not in what: ROS 1 polls ``can_transform`` every 1 % of the
timeout; this buffer sleeps until a transform arrives (the core tells it), so a wait ends as
soon as the answer is known. A buffer built before a script's ``init_node`` (or with no master
running) works offline and serves nothing; ROS 1's would fail to contact the master.

``node=`` makes a buffer of a `rosx.node.Node` (rosx's own tools) instead of the script's.
"""

from __future__ import annotations

import threading
import time as _time
from typing import TYPE_CHECKING, Any

from rosx.tf import ros, stamps
from rosx.tf.interface import BufferInterface, seconds
from rosx.tf.pycore import BufferCore

if TYPE_CHECKING:
    from rosx.node import Node

#: ROS 1's polling interval, as a share of the timeout (kept for scripts that set it).
DEFAULT_CAN_TRANSFORM_POLLING_SCALE = 0.01
#: How often a wait looks at whether the node shut down meanwhile.
_SHUTDOWN_POLL = 0.1


class Buffer(BufferCore, BufferInterface):
    """tf2_ros's ``Buffer(cache_time=None, debug=True)``.

    Args:
        cache_time: how long to keep each frame's transforms (a ``rospy.Duration``; 10 s).
        debug: advertise ``~tf2_frames`` unless the node already has it.
        node: the node to serve from; the script's (`rosx.client`) when None.
    """

    def __init__(
        self, cache_time: Any = None, debug: bool = True, node: Node | None = None
    ) -> None:
        BufferCore.__init__(self, cache_time)
        BufferInterface.__init__(self)
        self.CAN_TRANSFORM_POLLING_SCALE = DEFAULT_CAN_TRANSFORM_POLLING_SCALE
        self._endpoint = ros.endpoint(node)
        self._changed = threading.Condition()
        self._waiters = 0
        self.add_listener(self._notify)
        self.frame_server: Any = None
        if debug and self._endpoint.ready():
            self.frame_server = ros.shared(self._endpoint, "tf2_frames", self._serve_frames)

    def _serve_frames(self) -> Any:
        frame_graph = ros.service_class("tf2_msgs/FrameGraph")
        response = frame_graph._response_class
        return self._endpoint.serve(
            "~tf2_frames", frame_graph, lambda _request: response(self.all_frames_as_yaml())
        )

    def _notify(self) -> None:
        if self._waiters:
            with self._changed:
                self._changed.notify_all()

    def _wait(self, timeout: Any, ready: Any) -> None:
        """Wait until ``ready()``, ``timeout`` passes, or the node shuts down."""
        limit = seconds(timeout)
        if limit <= 0:
            return
        deadline = _time.monotonic() + limit
        with self._changed:
            self._waiters += 1
            try:
                while not ready():
                    left = deadline - _time.monotonic()
                    if left <= 0 or self._endpoint.is_shutdown():
                        return
                    self._changed.wait(min(left, _SHUTDOWN_POLL))
            finally:
                self._waiters -= 1

    # -- tf2_ros's calls ---------------------------------------------------------------------

    def lookup_transform(
        self, target_frame: str, source_frame: str, time: Any, timeout: Any = None
    ) -> Any:
        """The ``geometry_msgs/TransformStamped`` taking data in ``source_frame`` to
        ``target_frame`` at ``time`` (``rospy.Time()``: the latest), waiting up to
        ``timeout`` for it.

        Raises:
            TransformException: ROS 1's subclass and text, once the timeout passed.
        """
        asked = stamps.nanos(time)
        if timeout is not None:
            self._wait(timeout, lambda: self.can(target_frame, source_frame, asked)[0])
        found, values = self.lookup(target_frame, source_frame, asked)
        return self.message(target_frame, source_frame, found, values)

    def lookup_transform_full(
        self,
        target_frame: str,
        target_time: Any,
        source_frame: str,
        source_time: Any,
        fixed_frame: str,
        timeout: Any = None,
    ) -> Any:
        """`lookup_transform` between two times, through ``fixed_frame``."""
        if timeout is not None:
            self.can_transform_full(
                target_frame, target_time, source_frame, source_time, fixed_frame, timeout
            )
        return self.lookup_transform_full_core(
            target_frame, target_time, source_frame, source_time, fixed_frame
        )

    def can_transform(
        self,
        target_frame: str,
        source_frame: str,
        time: Any,
        timeout: Any = None,
        return_debug_tuple: bool = False,
    ) -> Any:
        """1 when the transform is available (within ``timeout``), else 0, as ROS 1's C++
        core answers; ``(answer, why)`` with ``return_debug_tuple``."""
        asked = stamps.nanos(time)
        if timeout is not None:
            self._wait(timeout, lambda: self.can(target_frame, source_frame, asked)[0])
        ok, text = self.can(target_frame, source_frame, asked)
        return (int(ok), text) if return_debug_tuple else int(ok)

    def can_transform_full(
        self,
        target_frame: str,
        target_time: Any,
        source_frame: str,
        source_time: Any,
        fixed_frame: str,
        timeout: Any = None,
        return_debug_tuple: bool = False,
    ) -> Any:
        """`can_transform` between two times, through ``fixed_frame``."""
        args = (
            target_frame,
            stamps.nanos(target_time),
            source_frame,
            stamps.nanos(source_time),
            fixed_frame,
        )
        if timeout is not None:
            self._wait(timeout, lambda: self.can_full(*args)[0])
        ok, text = self.can_full(*args)
        return (int(ok), text) if return_debug_tuple else int(ok)


__all__ = ["DEFAULT_CAN_TRANSFORM_POLLING_SCALE", "Buffer"]
