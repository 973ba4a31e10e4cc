"""The tools of ``rosx``, by name: where each is (``module:function``) and its line of help.

The dispatcher (`rosx_commands.main`) and the menu (`rosx_commands.menu`) both read `TOOLS`;
a tool's module is imported by name (`load_tool`) only when the tool runs, so neither imports
a tool, and ``rosx rostopic list`` loads the rostopic module alone.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable, Sequence

from rosx_commands.context import Environment

Tool = Callable[[Sequence[str], Environment], int]

#: Tool name → (module:function, one-line help).
TOOLS: dict[str, tuple[str, str]] = {
    "roscore": ("rosx_commands.roscore:roscore", "Start a master, parameter server and /rosout."),
    "rosmsg": ("rosx_commands.rosmsg:rosmsg", "Show information about ROS message types."),
    "rossrv": ("rosx_commands.rosmsg:rossrv", "Show information about ROS service types."),
    "rostopic": ("rosx_commands.rostopic:rostopic", "Print information about ROS topics."),
    "rosnode": ("rosx_commands.rosnode:rosnode", "Print information about ROS nodes."),
    "rosservice": ("rosx_commands.rosservice:rosservice", "List, inspect and call ROS services."),
    "rosparam": ("rosx_commands.rosparam:rosparam", "Get and set ROS parameters."),
    "roslaunch": (
        "rosx_commands.roslaunch:roslaunch",
        "Start the nodes and parameters of launch files (and a core when none runs).",
    ),
    "rosbag": (
        "rosx_commands.rosbag:rosbag",
        "Record, play back and inspect bag files (ROS 1's format 2.0).",
    ),
    "rqt_graph": (
        "rosx_commands.rqt_graph:rqt_graph",
        "Show the ROS graph of nodes and topics, live.",
    ),
    "rqt_console": (
        "rosx_commands.rqt_console:rqt_console",
        "Show the log of every node (/rosout_agg), filtered and highlighted.",
    ),
    "rqt_logger_level": (
        "rosx_commands.rqt_logger_level:rqt_logger_level",
        "Show and set the logger levels of running nodes.",
    ),
    "rqt_plot": (
        "rosx_commands.rqt_plot:rqt_plot",
        "Plot numeric fields of topics live (TOPIC/FIELD...).",
    ),
    "rqt_topic": (
        "rosx_commands.rqt_topic:rqt_topic",
        "Monitor topics: type, bandwidth, rate and the latest message.",
    ),
    "rqt_tf_tree": (
        "rosx_commands.rqt_tf_tree:rqt_tf_tree",
        "Show the tf tree live: frames, broadcasters, rates and delays.",
    ),
    "rqt": ("rosx_commands.rqt:rqt", "The rqt tools as tabs of one terminal app."),
    "rviz": (
        "rosx_commands.rviz:rviz",
        "rviz's 2-D displays and tools: maps, lasers, tf, paths, markers; goals and poses.",
    ),
    "axclient": (
        "rosx_commands.actionlib_tools:axclient",
        "Send goals to an action server and watch them (actionlib_tools' axclient.py).",
    ),
    "axserver": (
        "rosx_commands.actionlib_tools:axserver",
        "Serve an action by hand: feedback, succeed, abort (actionlib_tools' axserver.py).",
    ),
    "sim": ("rosx_commands.sim:sim", "Run a master, turtlesim and teleop in one terminal UI."),
    "rosbridge": (
        "rosx_commands.rosbridge:rosbridge",
        "Serve the ROS graph to browser tools (rosbridge v2, Foxglove WebSocket).",
    ),
    "tf_echo": (
        "rosx_commands.tf_tools.echo:tf_echo",
        "Print the transform between two tf frames (SOURCE TARGET [RATE]).",
    ),
    "tf_monitor": (
        "rosx_commands.tf_tools.monitor:tf_monitor",
        "Show tf's broadcasters, their rates and delays ([FRAME_A FRAME_B]).",
    ),
    "static_transform_publisher": (
        "rosx_commands.tf_tools.static:static_transform_publisher",
        "Publish a static transform on /tf_static (x y z yaw pitch roll|qx qy qz qw FRAME CHILD).",
    ),
    "catkin_create_pkg": (
        "rosx_commands.catkin_create_pkg:catkin_create_pkg",
        "Create a new catkin package.",
    ),
    "catkin_make": ("rosx_commands.catkin_make:catkin_make", "Build a catkin workspace."),
    "rospack": ("rosx_commands.rospack:rospack", "Find ROS packages and their dependencies."),
    "rosrun": ("rosx_commands.rosrun:rosrun", "Run an executable of a ROS package."),
    "roscd": ("rosx_commands.roscd:roscd", "Where roscd goes (roscd itself is a shell function)."),
    "rosls": ("rosx_commands.roscd:rosls", "List a package's directory."),
    "rosclean": ("rosx_commands.rosclean:rosclean", "Check or purge the ROS log folders."),
    "shell-init": (
        "rosx_commands.shell_init:shell_init",
        "Print shell functions: ROS 1's command names, roscd, rosls.",
    ),
    "rosed": ("rosx_commands.rosed:rosed", "Edit a file of a ROS package with $EDITOR."),
    "roscp": ("rosx_commands.rosed:roscp", "Copy a file of a ROS package."),
    "roswtf": (
        "rosx_commands.roswtf:roswtf",
        "Check the ROS environment and the running graph for problems.",
    ),
    "rosversion": (
        "rosx_commands.rosversion:rosversion",
        "Print a package's version or the ROS distribution.",
    ),
    "rosmsg-proto": (
        "rosx_commands.rosmsg_proto:rosmsg_proto",
        "Print a default message or service request as YAML (for tab completion).",
    ),
    "rossrv-proto": (
        "rosx_commands.rosmsg_proto:rosmsg_proto",
        "The same as rosmsg-proto.",
    ),
    "complete": (
        "rosx_commands.complete:complete",
        "Print the completions of a ROS command line (used by the shells' tab completion).",
    ),
    "run-script": (
        "rosx_commands.run_script:run_script",
        "Run a Python script with rosx's rospy and message modules.",
    ),
}


def load_tool(name: str) -> Tool:
    """The function of tool ``name`` (a key of `TOOLS`), its module imported now."""
    module_name, _, function = TOOLS[name][0].partition(":")
    tool: Tool = getattr(importlib.import_module(module_name), function)
    return tool


__all__ = ["TOOLS", "Tool", "load_tool"]
