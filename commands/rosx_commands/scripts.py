"""The import path of the ROS Python scripts rosx runs: every layer's shim directory.

Each layer that serves a ROS 1 module to scripts keeps it in a directory of its own
(``rospy``: `rosx.client.script.SHIM_DIR`; ``rosbag``: `rosx.bag.SHIM_DIR`; ``tf2_ros``,
``tf``…: `rosx.tf.SHIM_DIR`; ``actionlib``: `rosx.actionlib.SHIM_DIR`), so no layer's code
imports a higher one. The commands, above them all, put them together here for ``rosrun``,
``run-script`` and the ``devel/setup.sh`` of ``catkin_make``.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from pathlib import Path


def shim_dirs() -> tuple[Path, ...]:
    """The shim directories, in the order they go on ``sys.path`` / ``PYTHONPATH``."""
    from rosx import actionlib, bag, tf  # noqa: PLC0415 - constants only: these load no module
    from rosx.client import script  # noqa: PLC0415 - the rospy API loads only when used

    return (script.SHIM_DIR, bag.SHIM_DIR, tf.SHIM_DIR, actionlib.SHIM_DIR)
