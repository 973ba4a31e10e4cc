"""turtlesim's numbers: world size, tick, timeout, default colours (ROS 1 Noetic).

The world is measured in metres of 45 px (the height of turtlesim's sprites) on a 500x500 px
canvas, so it spans ``(500 - 1) / 45`` m, computed in float32 as turtlesim does. Positions
inside the engine use turtlesim's internal frame: x to the right, y **down from the top edge**
(``internal_y = WORLD_SIZE - world_y``); the published pose uses the world frame (y up).
"""

from __future__ import annotations

import struct

_F32 = struct.Struct("<f")


def f32(value: float) -> float:
    """``value`` rounded to float32 (as a message field or a C++ ``float`` holds it)."""
    result: float = _F32.unpack(_F32.pack(value))[0]
    return result


#: turtlesim's own value of pi (a literal, not M_PI); theta is kept in [-PI, PI).
PI = 3.14159265
#: The simulation step: the 16 ms timer interval in seconds, whatever time really passed.
DT = 0.016
#: The timer interval in seconds (the node's tick period).
TICK_PERIOD = 0.016
#: Seconds of wall time one cmd_vel message keeps a turtle moving.
COMMAND_TIMEOUT = 1.0

#: Pixels per metre: the sprites' height.
METER_PX = 45
#: The canvas is CANVAS_PX x CANVAS_PX pixels.
CANVAS_PX = 500
#: The world's width and height in metres, 11.088889122009277 (float32).
WORLD_SIZE = f32(f32(CANVAS_PX - 1) / f32(METER_PX))
#: Where turtle1 starts, on both axes: 5.544444561004639.
CENTRE = f32(WORLD_SIZE / 2.0)

#: The canvas colour unless ``~background_r/g/b`` say otherwise (#4556ff).
DEFAULT_BACKGROUND = (69, 86, 255)
#: A new turtle's pen: colour #b3b8ff, 3 px wide, on.
DEFAULT_PEN = (179, 184, 255)
DEFAULT_PEN_WIDTH = 3
#: A pen set with width 0 is a fresh pen, 1 px wide.
FRESH_PEN_WIDTH = 1
#: How many turtle sprites there are to choose from at each spawn.
SPRITE_COUNT = 14
