"""What the shim packages here (``rospy``, ``rosgraph``) do when this Python cannot import rosx.

They are on ``sys.path`` of the scripts rosx runs and of shells that sourced a workspace; a
Python without rosx (say, a ROS 1 installation's own) gets the next module of that name on its
path instead, so ROS 1's tools keep working in the same shell.
"""

from __future__ import annotations

import importlib.machinery
import importlib.util
import sys
from pathlib import Path

_HERE = Path(__file__).resolve().parent


def load_next(name: str) -> None:
    """Put the next module called ``name`` on ``sys.path`` (not this directory's) in its place.

    Raises:
        ImportError: there is none; the message says how to run the script instead.
    """
    path = [p for p in sys.path if Path(p or ".").resolve() != _HERE]
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
