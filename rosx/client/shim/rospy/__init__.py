"""``rospy`` for scripts that rosx runs: rosx's rospy-compatible API (`rosx.client`).

This directory is put on ``sys.path`` (and ``PYTHONPATH``) only for the scripts that rosx runs
(``rosx rosrun``, ``rosx run-script``, a shell that sourced a workspace's ``devel/setup.bash``);
nothing named ``rospy`` is installed. Importing it also makes ``<package>.msg`` and
``<package>.srv`` importable. A Python that cannot import rosx (say, a ROS 1 installation's own)
gets the next ``rospy`` on its path instead, so ROS 1 keeps working in the same shell.
"""

from __future__ import annotations

import importlib.machinery
import importlib.util
import sys
from pathlib import Path


def _defer_to_next_rospy() -> None:
    here = Path(__file__).resolve().parent.parent
    path = [p for p in sys.path if Path(p or ".").resolve() != here]
    spec = importlib.machinery.PathFinder.find_spec("rospy", path)
    if spec is None or spec.loader is None:
        raise ImportError(
            "this rospy is rosx's, and this Python cannot import rosx "
            f"({sys.executable}); run the script with `rosx rosrun PACKAGE SCRIPT`, "
            "or with the Python that rosx is installed in"
        )
    module = importlib.util.module_from_spec(spec)
    sys.modules["rospy"] = module
    spec.loader.exec_module(module)


try:
    import rosx.client as _client
    from rosx.client.modules import install as _install
except ImportError:
    _defer_to_next_rospy()
else:
    _install()
    globals().update({name: getattr(_client, name) for name in _client.__all__ if name != "Header"})
    __all__ = list(_client.__all__)

    def __getattr__(name: str) -> object:
        if name == "Header":  # built on first use: it needs the standard type store
            return _client.Header
        raise AttributeError(f"module 'rospy' has no attribute {name!r}")
