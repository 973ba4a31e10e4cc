"""turtlesim's tutorial nodes: `draw_square` and `mimic`."""
