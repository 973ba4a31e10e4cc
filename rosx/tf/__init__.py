"""tf2 for rosx: coordinate frames over time, as ROS 1's tf2_ros (and tf) keep them.

    from rosx.tf import Buffer, TransformListener

    buffer = Buffer(node=node)                  # or Buffer() in a script, after init_node
    listener = TransformListener(buffer, node=node)
    t = buffer.lookup_transform("map", "base_link", rospy.Time())   # TransformStamped
    stamp, (x, y, z, qx, qy, qz, qw) = buffer.lookup("map", "base_link", 0)  # raw, in ns

Layer 8, beside the workspace, on the client (`rosx.client`) and node (`rosx.node`) layers
through their public API. The pure core comes first, with no I/O or clock:

- `stamps`: times as integer nanoseconds, converted as ROS 1's binding converts them.
- `cache`: each frame's transforms over time (bisect, tf2's interpolation and texts).
- `core`: `core.BufferCore`, the frames and tf2's search between two of them;
  `linear`: tf2's matrix arithmetic; `describe`: the frames as YAML and Graphviz text.
- `exceptions`: ``TransformException`` and its five subclasses, with ROS 1's texts.

Then what faces ROS: `pycore` (tf2_py's ``BufferCore``: messages and ``rospy`` times in and
out), `interface` (``transform()`` through registered types), `buffer` (`Buffer`: waits and the
``~tf2_frames`` service), `listener` (`TransformListener`), `broadcaster`
(`TransformBroadcaster`, `StaticTransformBroadcaster`), `ros` (the script's node or a given
`rosx.node.Node`). ``shim/`` holds the modules scripts import by ROS 1's names (``tf2_ros``,
``tf2_py``, ``tf2_geometry_msgs``, ``tf``), put on their path like ``rospy``'s (`SHIM_DIR`).

Names load on first use; importing this package loads none of its modules.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from rosx._lazy import lazy_names

TYPE_CHECKING = False
if TYPE_CHECKING:
    from rosx.tf.broadcaster import StaticTransformBroadcaster, TransformBroadcaster
    from rosx.tf.buffer import Buffer
    from rosx.tf.exceptions import (
        ConnectivityException,
        ExtrapolationException,
        InvalidArgumentException,
        LookupException,
        TimeoutException,
        TransformException,
    )
    from rosx.tf.listener import TransformListener
    from rosx.tf.pycore import BufferCore

#: The import-path entry of the ROS 1 modules scripts import from this layer.
SHIM_DIR = Path(__file__).resolve().parent / "shim"

_HOMES = {
    "Buffer": "rosx.tf.buffer",
    "BufferCore": "rosx.tf.pycore",
    "ConnectivityException": "rosx.tf.exceptions",
    "ExtrapolationException": "rosx.tf.exceptions",
    "InvalidArgumentException": "rosx.tf.exceptions",
    "LookupException": "rosx.tf.exceptions",
    "StaticTransformBroadcaster": "rosx.tf.broadcaster",
    "TimeoutException": "rosx.tf.exceptions",
    "TransformBroadcaster": "rosx.tf.broadcaster",
    "TransformException": "rosx.tf.exceptions",
    "TransformListener": "rosx.tf.listener",
}

_load = lazy_names(__name__, _HOMES)


def __getattr__(name: str) -> Any:
    return _load(name)


__all__ = [
    "SHIM_DIR",
    "Buffer",
    "BufferCore",
    "ConnectivityException",
    "ExtrapolationException",
    "InvalidArgumentException",
    "LookupException",
    "StaticTransformBroadcaster",
    "TimeoutException",
    "TransformBroadcaster",
    "TransformException",
    "TransformListener",
]
