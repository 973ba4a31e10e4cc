"""What every shim package of rosx (``rospy``, ``rosbag``, ``tf2_ros``, ``actionlib``…) does
when this Python cannot import rosx.

The shim folders (``shim/`` in each layer that serves a ROS 1 module) are on ``sys.path`` of the
scripts rosx runs and of shells that sourced a workspace; a Python without rosx (say, a ROS 1
installation's own) gets the next module of that name on its path instead, so ROS 1's tools keep
working in the same shell. This module sits in the client layer's shim folder, which goes on the
path with the others (`rosx_commands.scripts.shim_dirs`).
"""

from __future__ import annotations

import importlib.machinery
import importlib.util
import sys
from pathlib import Path

#: rosx's package folder. Every shim folder is inside it (``rosx/<layer>/shim``), and no module
#: of another installation is, so the next module is looked for outside it: skipping only the
#: calling shim's folder would find another layer's shim of the same name, or the caller again.
_ROSX = Path(__file__).resolve().parents[2]


def _outside_rosx(entry: str) -> bool:
    """Whether the ``sys.path`` entry ``entry`` is not rosx's package folder or inside it."""
    folder = Path(entry or ".").resolve()
    return folder != _ROSX and _ROSX not in folder.parents


def load_next(name: str) -> None:
    """Put the next module called ``name`` on ``sys.path`` (not one of rosx's shims) in its place.

    Raises:
        ImportError: there is none; the message says how to run the script instead.
    """
    path = [entry for entry in sys.path if _outside_rosx(entry)]
    spec = importlib.machinery.PathFinder.find_spec(name, path)
    if spec is None or spec.loader is None:
        raise ImportError(
            f"this {name} is rosx's, and this Python cannot import rosx "
            f"({sys.executable}); run the script with `rosx rosrun PACKAGE SCRIPT`, "
            "or with the Python that rosx is installed in"
        )
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
