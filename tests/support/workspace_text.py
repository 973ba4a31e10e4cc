"""The workspace tests' shared facts: the tutorial package's dependencies, a terminal-like stream."""

from __future__ import annotations

import io

#: ``rospack depends beginner_tutorials`` in ROS/Tutorials/CreatingPackage (Noetic).
TUTORIAL_DEPENDS = [
    "cpp_common", "rostime", "roscpp_traits", "roscpp_serialization", "catkin", "genmsg", "genpy",
    "message_runtime", "gencpp", "geneus", "gennodejs", "genlisp", "message_generation",
    "rosbuild", "rosconsole", "std_msgs", "rosgraph_msgs", "xmlrpcpp", "roscpp", "rosgraph",
    "ros_environment", "rospack", "roslib", "rospy",
]  # fmt: skip


class TerminalText(io.StringIO):
    """A stream that says it is a terminal."""

    def isatty(self) -> bool:
        return True
