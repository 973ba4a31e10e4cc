"""rosx: the ROS 1 (Noetic) command-line world in pure Python, wire-compatible with ROS 1."""

__version__ = "0.1.0"
