"""The terminal UI (textual): the pond for turtlesim_node and ``rosx sim``'s screen.

- `factory`: `make_pond_app` and `make_sim_app`, the only way the apps are built.
- `pond_app`, `sim_app`: the apps, composition and key bindings only.
- `pond`: `PondView`; `status`: `PoseLine`; `log_line`: `LogLine`; `pose`: `PosePanel`;
  `teleop`: `TeleopPad`; `graph_table`, `topics`, `nodes`: the graph tables.
- `feed`: `Feed`, newest values from other threads to widgets; `graph`: `Graph` and the
  thread that watches the master; `log`: log records for the screen; `link`: `SimLink`, what
  ``rosx sim``'s screen needs.
- `running`: running an app until quit, signal or node shutdown; `pond_run`: turtlesim_node
  drawing its pond when stdout is a terminal.

`factory`, `graph`, `link`, `log`, `running` and `pond_run` import no textual themselves; the
modules with widgets, messages and apps do, and only the code paths that draw import those.
"""
