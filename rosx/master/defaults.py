"""Where the master is when nothing says otherwise: ROS 1's port 11311 on ``localhost``.

The one home of these values: roscore, roslaunch, ``rosx sim``, the tools, the node runtime,
the rospy-compatible API and the environment ``rosx shell-init`` writes all read them here.
Pure (no import at all), so the launch plan may use them without reaching the network code.
"""

from __future__ import annotations

TYPE_CHECKING = False
if TYPE_CHECKING:
    from collections.abc import Mapping

#: The port roscore listens on unless told otherwise (``roscore -p``, ``roslaunch -p``).
DEFAULT_MASTER_PORT = 11311
#: Where the master is when neither ``ROS_MASTER_URI`` nor ``__master:=`` says.
DEFAULT_MASTER_URI = f"http://localhost:{DEFAULT_MASTER_PORT}"


def master_uri(environ: Mapping[str, str], override: str | None = None) -> str:
    """The master's URI: ``override`` (``__master:=``), else ``ROS_MASTER_URI``, else the
    default."""
    return override or environ.get("ROS_MASTER_URI") or DEFAULT_MASTER_URI


__all__ = ["DEFAULT_MASTER_PORT", "DEFAULT_MASTER_URI", "master_uri"]
