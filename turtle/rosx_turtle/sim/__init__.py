"""``rosx sim``: Lab 1 in one process, a master, ``/rosout``, turtlesim, teleop and a screen.

- `run`: `run_sim(argv, env)`, the command.
- `host`: `SimHost`, the core (`rosx.core.Core`), the nodes and the feeds the screen follows.
"""

from __future__ import annotations

from rosx_turtle.sim.run import run_sim

__all__ = ["run_sim"]
