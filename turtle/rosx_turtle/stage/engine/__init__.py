"""The simulator's engine: numpy over all robots and beams at once, no I/O, no clock, no ROS.

`grid` (the world as occupancy layers and a distance bound), `laser` (ray casting), `motion`
(kinematics, collisions), `simulation` (`StageSim`: a step of the world).
"""
