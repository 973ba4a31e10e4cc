"""The robot simulator: Stage's 2-D worlds with stage_ros's topics, drawn in the terminal.

- `world`: the world file read without I/O (`worldfile`: syntax → entities; `model`: entities
  → `World`), images (`images`) and the loading shell (`load`).
- `engine`: pure numpy — the occupancy grid (`grid`), every laser beam cast at once (`laser`),
  the robots' motion, collisions and stalls (`motion`), and `StageSim` around them
  (`simulation`).
- `node`: stageros, the engine behind stage_ros's topics, frames, parameters and services
  (`stageros`), and the program (`run`).
- `view`: the world drawn in a terminal, as the turtle's pond is.
"""
