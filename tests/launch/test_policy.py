"""roslaunch's rules for an exiting process, as a table: no process, no clock."""

from __future__ import annotations

import pytest

from rosx.launch.run.policy import (
    Action,
    Ending,
    launch_ends,
    next_wake,
    on_exit,
    report_style,
    respawn_due,
)


@pytest.mark.parametrize(
    ("required", "respawn", "actions"),
    [
        (True, False, (Action.REPORT_REQUIRED, Action.STOP_LAUNCH)),
        (True, True, (Action.REPORT_REQUIRED, Action.STOP_LAUNCH)),  # required wins
        (False, True, (Action.REPORT, Action.RESPAWN)),
        (False, False, (Action.REPORT, Action.FORGET)),
    ],
)
def test_what_follows_an_exit(required: bool, respawn: bool, actions: tuple[Action, ...]) -> None:
    assert on_exit(required=required, respawn=respawn) == actions


@pytest.mark.parametrize(
    ("code", "style"), [(0, "bold"), (None, "bold"), (1, "error"), (-15, "error")]
)
def test_a_failure_is_reported_as_an_error(code: int | None, style: str) -> None:
    assert report_style(code) == style


def test_a_respawn_waits_for_its_delay() -> None:
    assert not respawn_due(died_at=10.0, respawn_delay=2.0, now=11.9)
    assert respawn_due(died_at=10.0, respawn_delay=2.0, now=12.0)
    assert respawn_due(died_at=10.0, respawn_delay=0.0, now=10.0)


def test_the_monitor_wakes_for_the_next_respawn_or_after_idling() -> None:
    assert next_wake([], now=5.0, idle=0.5) == 0.5
    assert next_wake([(5.0, 0.2), (4.0, 3.0)], now=5.0, idle=0.5) == pytest.approx(0.2)
    assert next_wake([(1.0, 1.0)], now=5.0, idle=0.5) == 0.0  # overdue: at once


def _ends(
    *,
    stop_requested: bool = False,
    core_started: bool = False,
    core_ended: bool = False,
    ended_for_good: bool = False,
    running: int = 0,
    respawning: int = 0,
) -> Ending | None:
    return launch_ends(
        stop_requested=stop_requested,
        core_started=core_started,
        core_ended=core_ended,
        ended_for_good=ended_for_good,
        running=running,
        respawning=respawning,
    )


def test_when_the_launch_ends() -> None:
    assert _ends(stop_requested=True, running=3) is Ending.STOP_REQUESTED
    assert _ends(core_started=True, core_ended=True, running=2) is Ending.CORE_ENDED
    assert _ends(ended_for_good=True) is Ending.ALL_DIED
    # Something keeps it going: a process running or waiting to respawn, or a core of its own.
    assert _ends(ended_for_good=True, running=1) is None
    assert _ends(ended_for_good=True, respawning=1) is None
    assert _ends(ended_for_good=True, core_started=True) is None
    # Nothing ended in this look: a launch of no nodes at all waits.
    assert _ends() is None
