"""What roslaunch does when one of its processes exits: respawn and required as a table.

Events in, actions out; no process, no clock, no I/O (the monitor, `rosx.launch.run.monitor`,
does what the actions say). The rules are ROS 1's (``roslaunch.pmon``):

=========  ========  ==============================================================
required   respawn   when the process exits
=========  ========  ==============================================================
yes        either    `Action.REPORT_REQUIRED`, `Action.STOP_LAUNCH` (required wins)
no         yes       `Action.REPORT`, `Action.RESPAWN` (after ``respawn_delay`` s)
no         no        `Action.REPORT`, `Action.FORGET` (it ended for good)
=========  ========  ==============================================================

A report is an error (red) for a non-zero exit code and bold otherwise (`report_style`).
A respawn is due ``respawn_delay`` seconds after the death (`respawn_due`). The launch ends
(`launch_ends`) when asked to stop (a signal, a required process's exit), when the core it
started was shut down, or when a process ended for good and nothing is left: none running,
none waiting to respawn and no core of its own.
"""

from __future__ import annotations

from enum import Enum

TYPE_CHECKING = False
if TYPE_CHECKING:
    from collections.abc import Iterable


class Action(Enum):
    """What the monitor does about an exit, in the order the table gives."""

    #: ``REQUIRED process [NAME] has died!`` … ``Initiating shutdown!`` between rules of ``=``.
    REPORT_REQUIRED = "report required"
    #: ``[NAME] process has finished cleanly`` or ``… has died [pid, exit code, cmd]``.
    REPORT = "report"
    #: Stop every process and end the launch.
    STOP_LAUNCH = "stop launch"
    #: Start it again once `respawn_due`.
    RESPAWN = "respawn"
    #: Reap it and drop it from the running processes: it ended for good.
    FORGET = "forget"


#: (required, respawn) -> the actions for an exit, in order.
EXIT_RULES: dict[tuple[bool, bool], tuple[Action, ...]] = {
    (True, True): (Action.REPORT_REQUIRED, Action.STOP_LAUNCH),
    (True, False): (Action.REPORT_REQUIRED, Action.STOP_LAUNCH),
    (False, True): (Action.REPORT, Action.RESPAWN),
    (False, False): (Action.REPORT, Action.FORGET),
}


def on_exit(*, required: bool, respawn: bool) -> tuple[Action, ...]:
    """The actions for the exit of a process with these settings."""
    return EXIT_RULES[required, respawn]


def report_style(exit_code: int | None) -> str:
    """How a (not required) process's exit is reported: ``"error"`` for a non-zero exit code,
    ``"bold"`` otherwise (a clean exit, or one whose code is unknown)."""
    return "error" if exit_code else "bold"


def respawn_due(died_at: float, respawn_delay: float, now: float) -> bool:
    """Whether a process that died at ``died_at`` is to start again at ``now``."""
    return died_at + respawn_delay <= now


def next_wake(deaths: Iterable[tuple[float, float]], now: float, idle: float) -> float:
    """Seconds until the next respawn is due (``deaths``: death time and delay of each process
    waiting), at most ``idle``; never negative."""
    wake = idle
    for died_at, respawn_delay in deaths:
        wake = min(wake, died_at + respawn_delay - now)
    return max(wake, 0.0)


class Ending(Enum):
    """Why a launch ends."""

    #: A signal, a call to stop, or a required process's exit.
    STOP_REQUESTED = "stop requested"
    #: The core this launch started was asked to shut down.
    CORE_ENDED = "core ended"
    #: Every process ended and nothing keeps the launch alive (ROS 1: ``all processes on
    #: machine have died, roslaunch will exit``).
    ALL_DIED = "all died"


def launch_ends(
    *,
    stop_requested: bool,
    core_started: bool,
    core_ended: bool,
    ended_for_good: bool,
    running: int,
    respawning: int,
) -> Ending | None:
    """Whether the launch ends after a look at its processes, and why (None: it goes on).

    Args:
        stop_requested: A signal, a call or a required process asked it to stop.
        core_started: The launch started a core of its own (which keeps it alive).
        core_ended: That core was asked to shut down.
        ended_for_good: A process ended for good in this look.
        running: Processes still running (or started and not yet seen to end).
        respawning: Processes waiting to start again.
    """
    if stop_requested:
        return Ending.STOP_REQUESTED
    if core_started and core_ended:
        return Ending.CORE_ENDED
    if ended_for_good and not running and not respawning and not core_started:
        return Ending.ALL_DIED
    return None


__all__ = [
    "EXIT_RULES",
    "Action",
    "Ending",
    "launch_ends",
    "next_wake",
    "on_exit",
    "report_style",
    "respawn_due",
]
