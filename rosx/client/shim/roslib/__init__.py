"""``roslib`` for scripts that rosx runs: ``load_manifest`` (which has nothing to do under
catkin), ``roslib.packages``, ``roslib.message`` and ``roslib.names``, served by
`rosx.client.roslib`. A Python that cannot import rosx gets the next ``roslib`` on its path
instead (see ``rospy``).
"""

from __future__ import annotations

try:
    from rosx.client.roslib import is_interactive, load_manifest, set_interactive
except ImportError:
    from _rosx_shim import load_next  # type: ignore[import-not-found]

    load_next("roslib")
else:
    from rosx.client.ros1_names import use_ros1_names as _use_ros1_names

    from . import message, names, packages

    _use_ros1_names("rosx.client.roslib", "rosx.client.rospkg")

    __all__ = ["is_interactive", "load_manifest", "message", "names", "packages", "set_interactive"]
