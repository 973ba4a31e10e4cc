"""Not executable: roslaunch cannot start it as a node."""
