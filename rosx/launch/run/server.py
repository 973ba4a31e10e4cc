"""The roslaunch server: the launcher's own XML-RPC API, as ROS 1's parent roslaunch serves it.

roslaunch prints ``started roslaunch server URI`` and records the URI in
``/roslaunch/uris/host_<host>__<port>``; tools ask it about the launch's processes. Served here:
``get_pid``, ``get_node_names`` (the processes running), ``list_processes`` (running and ended,
with their spawn counts), ``process_info NAME`` and ``list_children`` (always none: rosx starts
no remote launchers). Each answers ``[code, message, value]`` as ROS 1's does.
"""

from __future__ import annotations

import os
from typing import TYPE_CHECKING, Any

from rosx.transport.address import advertised_host, bind_host
from rosx.transport.loop_thread import ServerThread

if TYPE_CHECKING:
    from collections.abc import Mapping

    from rosx.launch.run.monitor import LocalProcess, ProcessMonitor


def _info(process: LocalProcess, alive: bool) -> dict[str, Any]:
    info: dict[str, Any] = {
        "spawn_count": process.spawn_count,
        "args": process.argv,
        "env": process.environ,
        "package": process.package,
        "name": process.name,
        "alive": alive,
        "respawn": process.respawn,
        "respawn_delay": process.respawn_delay,
        "required": process.required,
        "pid": process.pid,
        "log_output": process.log_output,
    }
    if process.exit_code is not None:
        info["exit_code"] = process.exit_code
    return info


class LaunchHandlers:
    """The methods of the roslaunch server, over one `ProcessMonitor`."""

    def __init__(self, monitor: ProcessMonitor) -> None:
        self._monitor = monitor

    def get_pid(self) -> list[Any]:
        """``get_pid``: roslaunch's own process id."""
        pid = os.getpid()
        return [1, str(pid), pid]

    def get_node_names(self) -> list[Any]:
        """``get_node_names``: the names of the nodes still running."""
        return [1, "node names", [p.name for p in list(self._monitor.procs)]]

    def list_processes(self) -> list[Any]:
        """``list_processes``: ``[[name, spawn count], ...]`` for running and for dead processes."""
        active = [[p.name, p.spawn_count] for p in list(self._monitor.procs)]
        dead = [[p.name, p.spawn_count] for p in list(self._monitor.dead)]
        return [1, "processes on parent machine", [active, dead]]

    def process_info(self, name: str) -> list[Any]:
        """``process_info``: what roslaunch knows of process ``name`` (``-1`` if none runs by
        that name)."""
        for process in list(self._monitor.procs):
            if process.name == name:
                return [1, "process info", _info(process, True)]
        return [-1, "no process by that name", {}]

    def list_children(self) -> list[Any]:
        """``list_children``: always empty; rosx starts no remote roslaunch children."""
        return [1, "roslaunch children", []]


class LaunchServer(ServerThread):
    """The roslaunch server of one launch, on a free port of the advertised host."""

    def __init__(self, monitor: ProcessMonitor, environ: Mapping[str, str]) -> None:
        handlers = LaunchHandlers(monitor)
        methods = {
            "get_pid": handlers.get_pid,
            "get_node_names": handlers.get_node_names,
            "list_processes": handlers.list_processes,
            "process_info": handlers.process_info,
            "list_children": handlers.list_children,
        }
        super().__init__(
            methods, host=bind_host(environ), port=0, advertised_host=advertised_host(environ)
        )


__all__ = ["LaunchHandlers", "LaunchServer"]
