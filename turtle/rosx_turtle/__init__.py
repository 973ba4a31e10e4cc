"""turtlesim for rosx: the simulator, its node, the keyboard teleop and the tutorial nodes.

The ``turtlesim`` package itself (its ``package.xml``, ``msg/``, ``srv/``, ``launch/`` and the
programs rosrun starts) is in rosx's Noetic prefix, ``rosx/packages/noetic``, with the other
packages rosx ships. Subpackages and modules:

- `engine`: the simulation as pure numpy code (no I/O, no clock, no ROS).
- `node`: turtlesim_node around the engine (`TurtlesimNode`, `run_turtlesim`).
- `teleop`: turtle_teleop_key (`run_teleop`); `keyboard`: the terminal in raw mode.
- `tutorials`: draw_square and mimic.
- `roscpp`, `console`, `program`, `env`: what these programs share as roscpp-like nodes.
- `executables`: ``python -m rosx_turtle NAME`` runs a program by name (the files in
  ``lib/turtlesim``, as rosrun does).

Importing this package imports nothing else; numpy loads with the engine only.
"""
