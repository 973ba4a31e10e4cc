"""The pond drawn as terminal text: no terminal, no event loop, just arrays and rich segments.

- `scene`: `Scene` and `TurtlePose`, what is drawn; `adapt`: scenes from the engine.
- `fit`: the square world in an area of any shape.
- `raster`: the trail canvas shrunk to the pond's pixels; `sprite`: the turtles.
- `halfblock`: pixels to cells (two per cell); `renderer`: `PondRenderer`, all of it per scene.
- `status`: poses as text.

Imports numpy and rich; only the terminal UI (`rosx_turtle.tui`) and benchmarks import it.
"""
