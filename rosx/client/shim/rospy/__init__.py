"""``rospy`` for scripts that rosx runs: rosx's rospy-compatible API (`rosx.client`).

This directory is put on ``sys.path`` (and ``PYTHONPATH``) only for the scripts that rosx runs
(``rosx rosrun``, ``rosx run-script``, a shell that sourced a workspace's ``devel/setup.bash``);
nothing named ``rospy`` is installed. Importing it also makes ``<package>.msg`` and
``<package>.srv`` importable. A Python that cannot import rosx (say, a ROS 1 installation's own)
gets the next ``rospy`` on its path instead, so ROS 1 keeps working in the same shell.
"""

from __future__ import annotations

import importlib

#: rospy's modules that its ``__init__`` imports, so that ``rospy.topics.Publisher`` works.
_SUBMODULES = (
    "exceptions",
    "impl",
    "msg",
    "msproxy",
    "names",
    "rostime",
    "service",
    "timer",
    "topics",
)

try:
    import rosx.client as _client
    from rosx.client.modules import install as _install
    from rosx.client.ros1_names import use_ros1_names as _use_ros1_names
except ImportError:
    from _rosx_shim import load_next  # type: ignore[import-not-found]

    load_next("rospy")
else:
    _install()
    _use_ros1_names()  # tracebacks print rospy.exceptions.ROSInitException, as rospy's do
    globals().update({name: getattr(_client, name) for name in _client.__all__ if name != "Header"})
    __all__ = list(_client.__all__)

    def __getattr__(name: str) -> object:
        if name == "Header":  # built on first use: it needs the standard type store
            return _client.Header
        if name in _SUBMODULES:  # rospy's own __init__ imports them: rospy.names.x works
            return importlib.import_module(f"{__name__}.{name}")
        raise AttributeError(f"module 'rospy' has no attribute {name!r}")
