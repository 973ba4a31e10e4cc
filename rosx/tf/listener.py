"""``tf2_ros.TransformListener``: a buffer filled from ``/tf`` and ``/tf_static``.

Each transform of each ``tf2_msgs/TFMessage`` goes into the buffer, credited to the node that
sent it (its ``callerid``, which view_frames shows as the broadcaster); those of the latched
``/tf_static`` are kept as static. When time jumps back (a bag played again) the buffer is
cleared, as ROS 1 does, with its warning.
"""

from __future__ import annotations

import threading
import time
from typing import TYPE_CHECKING, Any

from rosx.tf import ros, stamps

if TYPE_CHECKING:
    from rosx.node import Node
    from rosx.tf.pycore import BufferCore


class TransformListener:
    """tf2_ros's ``TransformListener(buffer, queue_size=None, buff_size=65536,
    tcp_nodelay=False)``; ``node=`` listens as that `rosx.node.Node` instead of the script."""

    def __init__(
        self,
        buffer: BufferCore,
        queue_size: int | None = None,
        buff_size: int = 65536,
        tcp_nodelay: bool = False,
        node: Node | None = None,
    ) -> None:
        self.buffer = buffer
        self.last_update = time.time_ns()
        self.last_update_lock = threading.Lock()
        place = ros.endpoint(node)
        tf_message = ros.message_class("tf2_msgs/TFMessage")
        self.tf_sub = place.subscribe("/tf", tf_message, self.callback, queue_size, tcp_nodelay)
        self.tf_static_sub = place.subscribe(
            "/tf_static", tf_message, self.static_callback, queue_size, tcp_nodelay
        )

    def unregister(self) -> None:
        """Stop listening."""
        self.tf_sub.unregister()
        self.tf_static_sub.unregister()

    def check_for_reset(self) -> None:
        """Clear the buffer when the clock went back since the last message."""
        with self.last_update_lock:
            now = time.time_ns()
            if now < self.last_update:
                from rosx.client.logs import logwarn  # noqa: PLC0415 - rare

                jump = stamps.to_sec(self.last_update - now)
                logwarn(f"Detected jump back in time of {jump:f}s. Clearing TF buffer.")
                self.buffer.clear()
            self.last_update = now

    def callback(self, data: Any) -> None:
        """Store the transforms of a ``/tf`` message."""
        self._store(data, False)

    def static_callback(self, data: Any) -> None:
        """Store the transforms of a ``/tf_static`` message, as static."""
        self._store(data, True)

    def _store(self, data: Any, is_static: bool) -> None:
        self.check_for_reset()
        header = getattr(data, "_connection_header", None) or {}
        who = header.get("callerid", "default_authority")
        put = self.buffer.set
        for t in data.transforms:
            h = t.header
            tr = t.transform
            v = tr.translation
            r = tr.rotation
            put(
                h.frame_id,
                t.child_frame_id,
                stamps.nanos(h.stamp),
                (v.x, v.y, v.z, r.x, r.y, r.z, r.w),
                who,
                is_static,
            )


__all__ = ["TransformListener"]
