"""``rosbag`` for scripts that rosx runs: ROS 1's bag API, served by `rosx.bag.api`.

Like ``rospy`` (in the client layer's shim directory), this directory (`rosx.bag.SHIM_DIR`) is
on ``sys.path`` only for the scripts rosx runs; it is part of the bag layer's import path, not
of its code. A Python that cannot import rosx gets the next ``rosbag`` on its path instead.
"""

from __future__ import annotations

import importlib.machinery
import importlib.util
import sys
from pathlib import Path


def _defer_to_next_rosbag() -> None:
    here = Path(__file__).resolve().parent.parent
    path = [p for p in sys.path if Path(p or ".").resolve() != here]
    spec = importlib.machinery.PathFinder.find_spec("rosbag", path)
    if spec is None or spec.loader is None:
        raise ImportError(
            "this rosbag is rosx's, and this Python cannot import rosx "
            f"({sys.executable}); run the script with `rosx rosrun PACKAGE SCRIPT`"
        )
    module = importlib.util.module_from_spec(spec)
    sys.modules["rosbag"] = module
    spec.loader.exec_module(module)


try:
    from rosx.bag import api as _api
    from rosx.client.modules import install as _install
except ImportError:
    _defer_to_next_rosbag()
else:
    _install()
    globals().update({name: getattr(_api, name) for name in _api.__all__})
    __all__ = list(_api.__all__)
