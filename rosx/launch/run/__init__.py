"""Running a launch plan: everything of roslaunch that starts processes, opens sockets, runs
threads, waits in ``select`` or handles signals.

- `runner`: `LaunchRun`, ROS 1's parent roslaunch: the run id and log folder, the roslaunch
  server, the master (or a core of its own), the parameters, the nodes, the shutdown.
- `monitor`: `LocalProcess` and `ProcessMonitor`, the processes started, watched, restarted and
  stopped; the rules it follows for an exit (respawn, required) are `policy`'s.
- `policy`: respawn and required as a table, events in, actions out: no process, no clock.
- `zygote`: the fork server that starts Python nodes with ``rospy`` already loaded.
- `server`: the roslaunch XML-RPC server.
- `console`: roslaunch's lines on the terminal and in its log file.
- `command`: the command of a ``<param command="…">``, run while the plan is read.

The plan (`rosx.launch`: XML → model, substitution, printing) imports nothing of this package:
an import contract keeps it free of processes, sockets, threads, select and signals.
"""
