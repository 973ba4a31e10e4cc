"""turtlesim_node: the simulator as a ROS 1 node.

- `turtlesim`: `TurtlesimNode` (the node as a library object, with `snapshot` and
  `add_tick_listener` for views) and `PondSnapshot`.
- `turtle_io`: one turtle's topics and services. `inbox`: callbacks waiting for the tick
  thread. `ticker`: the 16 ms timer thread.
- `run`: `run_turtlesim(argv, env)`, the program.
"""

from __future__ import annotations

import importlib

TYPE_CHECKING = False
if TYPE_CHECKING:
    from rosx_turtle.node.run import run_turtlesim
    from rosx_turtle.node.turtlesim import PondSnapshot, TurtlesimNode

_HOMES = {"PondSnapshot": "turtlesim", "TurtlesimNode": "turtlesim", "run_turtlesim": "run"}


def __getattr__(name: str) -> object:
    # Loaded on first use: the ticker alone (used by draw_square) needs no numpy.
    home = _HOMES.get(name)
    if home is None:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    return getattr(importlib.import_module(f"{__name__}.{home}"), name)


__all__ = ["PondSnapshot", "TurtlesimNode", "run_turtlesim"]
