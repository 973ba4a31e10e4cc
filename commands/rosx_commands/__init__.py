"""The rosx command line: one typer app per ROS tool, composed under ``rosx``."""
