"""``rosbag`` for scripts that rosx runs: ROS 1's bag API, served by `rosx.bag.api`.

Like ``rospy`` (in the client layer's shim directory), this directory (`rosx.bag.SHIM_DIR`) is
on ``sys.path`` only for the scripts rosx runs; it is part of the bag layer's import path, not
of its code. A Python that cannot import rosx gets the next ``rosbag`` on its path instead
(``_rosx_shim``, in the client layer's shim directory).
"""

from __future__ import annotations

try:
    from rosx.bag import api as _api
    from rosx.client.modules import install as _install
except ImportError:
    from _rosx_shim import load_next  # type: ignore[import-not-found]

    load_next("rosbag")
else:
    _install()
    globals().update({name: getattr(_api, name) for name in _api.__all__})
    __all__ = list(_api.__all__)
