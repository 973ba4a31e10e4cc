"""tf's and tf2's command-line tools, as ROS 1's C++ programs (and Python scripts) behave.

- `echo`: ``tf_echo SOURCE TARGET [RATE]`` (``rosrun tf tf_echo``, ``rosx tf_echo``).
- `static`: tf2_ros's ``static_transform_publisher`` (latched on ``/tf_static``) and tf's
  (``/tf`` again every period, stamped ahead).
- `monitor`: ``tf_monitor [FRAME_A FRAME_B]``: broadcasters, rates and delays.
- `frames`: what ``view_frames`` writes: ``frames.gv``, then ``frames.pdf`` with Graphviz's
  ``dot``, or the tree as text where Graphviz is missing.

The C++ programs' command lines are roscpp's (remapping arguments, ``_param:=value``), their
nodes anonymous as roscpp names them, their logs roscpp's lines (`rosx_turtle.console`).
"""

from __future__ import annotations
