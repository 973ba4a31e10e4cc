"""``rosx sim --robot``: the robot lab in one process, as ``rosx sim`` is turtlesim's.

- `plan`: which world, map and topics the lab runs (`LabPlan`, `plan_lab`), no I/O.
- `host`: `LabHost`, the core, stageros, map_server, ``map`` → ``odom`` and the teleop node,
  and the feeds the screen follows.
- `run`: `run_lab`, the command's body once ``rosx sim`` has read its options.
"""
