"""``rosgraph`` for scripts that rosx runs: ``Master``, its errors, ``names``, ``roslogging``.

Served by `rosx.client.rosgraph`. A Python that cannot import rosx gets the next ``rosgraph``
on its path instead (see ``rospy``).
"""

from __future__ import annotations

try:
    import rosx.client.rosgraph as _rosgraph
except ImportError:
    from _rosx_shim import load_next  # type: ignore[import-not-found]

    load_next("rosgraph")
else:
    from rosx.client.ros1_names import use_ros1_names as _use_ros1_names

    from . import masterapi, names, roslogging

    _use_ros1_names("rosx.client.rosgraph")  # rosgraph.masterapi.MasterError in tracebacks

    globals().update({name: getattr(_rosgraph, name) for name in _rosgraph.__all__})
    __all__ = list(_rosgraph.__all__)
    __all__ += ["masterapi", "names", "roslogging"]
