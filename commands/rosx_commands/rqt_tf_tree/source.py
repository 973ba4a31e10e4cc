"""What rqt_tf_tree shows: the frames a buffer holds, as rows of a tree.

`tree_rows` is pure: frames (`rosx.tf.core.FrameInfo`) and the time in, the rows out, each
root followed by its subtree in name order. `LiveTfSource` fills a `rosx.tf.Buffer` from
``/tf`` and ``/tf_static`` through the tool's node (started on first use).
"""

from __future__ import annotations

import time
from typing import TYPE_CHECKING, NamedTuple, Protocol

from rosx_commands.toolnode import ToolNode

if TYPE_CHECKING:
    from collections.abc import Sequence

    from rosx.tf import Buffer
    from rosx.tf.core import FrameInfo
    from rosx_commands.context import Environment


class Row(NamedTuple):
    """One frame of the tree: its depth and what rqt_tf_tree labels its edge with."""

    depth: int
    frame: str
    broadcaster: str
    rate: float | None  # None: a root (no transform of its own)
    delay: float | None  # seconds since the newest transform; None for static frames
    buffer_length: float
    static: bool


class TfSource(Protocol):
    """Where the frames come from."""

    def frames(self) -> Sequence[FrameInfo]:
        """Every frame the buffer has heard of, with its parent, broadcaster, rate and delay."""

    def now(self) -> float:
        """ROS time in seconds, which the delays are measured from."""
        ...

    def close(self) -> None:
        """Release the source's node."""


def tree_rows(frames: Sequence[FrameInfo], now: float) -> list[Row]:
    """The frames in tree order: each root (a frame that is only a parent), then its
    children depth-first, in name order. A frame whose parent loops back is listed last."""
    from rosx.tf.describe import rate  # noqa: PLC0415 - tf code loads only when used

    by_parent: dict[str, list[FrameInfo]] = {}
    known = {f.name for f in frames if f.parent}
    for frame in frames:
        if frame.parent:
            by_parent.setdefault(frame.parent, []).append(frame)
    roots = sorted({p for p in by_parent if p not in known})
    rows: list[Row] = []
    seen: set[str] = set()

    def visit(name: str, depth: int) -> None:
        for child in sorted(by_parent.get(name, []), key=lambda f: f.name):
            if child.name in seen:
                continue
            seen.add(child.name)
            static = child.newest == 0 and child.oldest == 0
            rows.append(
                Row(
                    depth,
                    child.name,
                    child.authority,
                    rate(child),
                    None if static else now - child.newest / 1e9,
                    (child.newest - child.oldest) / 1e9,
                    static,
                )
            )
            visit(child.name, depth + 1)

    for root in roots:
        rows.append(Row(0, root, "", None, None, 0.0, False))
        visit(root, 1)
    for frame in frames:  # a loop has no root to hang from
        if frame.parent and frame.name not in seen:
            seen.add(frame.name)
            rows.append(Row(0, frame.name, frame.authority, rate(frame), None, 0.0, False))
    return rows


class LiveTfSource(ToolNode):
    """A buffer listening as the tool's node (``/rqt_tf_tree_<pid>_<ms>``)."""

    def __init__(self, env: Environment) -> None:
        super().__init__(env, "rqt_tf_tree")
        self._buffer: Buffer | None = None

    def frames(self) -> Sequence[FrameInfo]:
        """The frames heard on ``/tf`` and ``/tf_static`` so far; the first call starts the
        listener (under ``/use_sim_time``, on ``/clock``'s time), so frames appear from the next
        call."""
        if self._buffer is None:
            from rosx.node.simtime import follow_sim_time  # noqa: PLC0415 - with the node runtime
            from rosx.tf import Buffer, TransformListener  # noqa: PLC0415 - tf code loads only when used

            node = self._started()
            follow_sim_time(node)  # as rqt's rospy node: /clock's time under /use_sim_time
            self._buffer = Buffer(node=node, debug=False)
            TransformListener(self._buffer, node=node)
        return self._buffer.frames()

    def now(self) -> float:
        """The node's ROS time (the wall clock before the node starts), in seconds."""
        node = self._node
        return time.time() if node is None else node.clock.now().to_sec()


__all__ = ["LiveTfSource", "Row", "TfSource", "tree_rows"]
