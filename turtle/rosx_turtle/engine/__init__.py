"""The turtlesim engine: the simulation as numpy code over all turtles at once.

State in, state out, no I/O, no clock, no ROS (this package imports numpy and the standard
library only). The caller passes wall-clock times and decides what to do with what a tick
reports (publish poses, print warnings, repaint).

Modules, one concept each:

- `constants`: turtlesim's numbers (world size, tick, timeout, default colours).
- `state`: `Turtles`, every turtle's state as parallel arrays sorted by name.
- `motion`: command timeout, integration and walls for one tick (`advance`, `WallHits`).
- `teleports`: queued teleports, applied at the start of a tick.
- `segments`: `Segments`, pen strokes as data. `raster`: the pixels a stroke covers.
- `canvas`: `Canvas`, the 500x500 RGB trail image the colour sensors read.
- `simulation`: `Simulation`, the pond's rules (spawn, kill, reset, clear, pens, teleports,
  commands) around `tick`; `TickReport`, what a tick produced.
"""

from __future__ import annotations

import importlib

TYPE_CHECKING = False
if TYPE_CHECKING:
    from rosx_turtle.engine.canvas import Canvas
    from rosx_turtle.engine.constants import CENTRE, PI, WORLD_SIZE
    from rosx_turtle.engine.motion import WallHits, wall_warning
    from rosx_turtle.engine.segments import Segments
    from rosx_turtle.engine.simulation import NameTakenError, Simulation, TickReport
    from rosx_turtle.engine.state import Turtles
    from rosx_turtle.engine.teleports import Teleport

_HOMES = {
    "CENTRE": "constants",
    "PI": "constants",
    "WORLD_SIZE": "constants",
    "Canvas": "canvas",
    "NameTakenError": "simulation",
    "Segments": "segments",
    "Simulation": "simulation",
    "Teleport": "teleports",
    "TickReport": "simulation",
    "Turtles": "state",
    "WallHits": "motion",
    "wall_warning": "motion",
}


def __getattr__(name: str) -> object:
    # Loaded on first use: `constants` alone (no numpy) serves programs that only need numbers.
    home = _HOMES.get(name)
    if home is None:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    return getattr(importlib.import_module(f"{__name__}.{home}"), name)


__all__ = [
    "CENTRE",
    "PI",
    "WORLD_SIZE",
    "Canvas",
    "NameTakenError",
    "Segments",
    "Simulation",
    "Teleport",
    "TickReport",
    "Turtles",
    "WallHits",
    "wall_warning",
]
