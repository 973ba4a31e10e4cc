"""actionlib's state tables, without a socket: the server's statuses, the client's comm states,
the simple client's states; the client's table checked against Debian's actionlib."""

from __future__ import annotations

import json
import subprocess

import pytest

from rosx.actionlib.states import (
    COMM,
    INVALID_TRANSITION,
    NO_TRANSITION,
    SERVER_REFUSALS,
    CommState,
    ServerEvent,
    SimpleEffect,
    SimpleGoalState,
    Status,
    comm_next,
    server_next,
    simple_next,
)
from tests.support.ros1 import ROS1_PYTHON, needs_ros1, ros1_environ, ros1_python_imports


def _walk(status: Status, *events: ServerEvent) -> list[Status | None]:
    seen: list[Status | None] = []
    current: Status | None = status
    for event in events:
        current = server_next(current, event) if current is not None else None
        seen.append(current)
    return seen


def test_a_goal_is_accepted_then_ends() -> None:
    accept, succeed = ServerEvent.ACCEPT, ServerEvent.SUCCEED
    assert _walk(Status.PENDING, accept, succeed) == [Status.ACTIVE, Status.SUCCEEDED]
    assert _walk(Status.PENDING, accept, ServerEvent.ABORT) == [Status.ACTIVE, Status.ABORTED]
    assert _walk(Status.PENDING, ServerEvent.REJECT) == [Status.REJECTED]


def test_a_cancel_request_recalls_a_pending_goal_and_preempts_an_active_one() -> None:
    cancel_request, cancel = ServerEvent.CANCEL_REQUEST, ServerEvent.CANCEL
    assert _walk(Status.PENDING, cancel_request, cancel) == [Status.RECALLING, Status.RECALLED]
    assert _walk(Status.ACTIVE, cancel_request, cancel) == [Status.PREEMPTING, Status.PREEMPTED]
    # accepted after the cancel request arrived: it starts preempting
    assert _walk(Status.PENDING, cancel_request, ServerEvent.ACCEPT) == [
        Status.RECALLING,
        Status.PREEMPTING,
    ]
    # a preempting goal may still succeed or abort
    assert server_next(Status.PREEMPTING, ServerEvent.SUCCEED) == Status.SUCCEEDED
    assert server_next(Status.PREEMPTING, ServerEvent.ABORT) == Status.ABORTED


@pytest.mark.parametrize("ended", sorted(set(Status) - {Status.PENDING}))
def test_nothing_but_a_pending_goal_can_be_rejected(ended: Status) -> None:
    if ended == Status.RECALLING:
        assert server_next(ended, ServerEvent.REJECT) == Status.REJECTED
    else:
        assert server_next(ended, ServerEvent.REJECT) is None


def test_an_ended_goal_takes_no_event() -> None:
    for status in (Status.SUCCEEDED, Status.ABORTED, Status.PREEMPTED, Status.RECALLED):
        for event in ServerEvent:
            assert server_next(status, event) is None, (status, event)
    assert server_next(17, ServerEvent.ACCEPT) is None


def test_refusals_are_ros1s_texts() -> None:
    assert SERVER_REFUSALS[ServerEvent.SUCCEED] % 3 == (
        "To transition to a succeeded state, the goal must be in a preempting or active "
        "state, it is currently in state: 3"
    )
    assert ServerEvent.CANCEL_REQUEST not in SERVER_REFUSALS  # ignored, never an error


def test_the_client_passes_through_the_states_it_missed() -> None:
    # A goal done before the client heard of it being active: ACTIVE, then waiting for the result.
    assert comm_next(CommState.WAITING_FOR_GOAL_ACK, Status.SUCCEEDED) == (
        CommState.ACTIVE,
        CommState.WAITING_FOR_RESULT,
    )
    assert comm_next(CommState.PENDING, Status.RECALLED) == (
        CommState.RECALLING,
        CommState.WAITING_FOR_RESULT,
    )
    assert comm_next(CommState.ACTIVE, Status.ACTIVE) == NO_TRANSITION
    assert comm_next(CommState.ACTIVE, Status.PENDING) == INVALID_TRANSITION
    assert comm_next(CommState.ACTIVE, Status.LOST) == INVALID_TRANSITION
    assert comm_next(CommState.DONE, 42) == INVALID_TRANSITION


def test_the_simple_client_goes_active_once_and_done_once() -> None:
    pending, active, done = SimpleGoalState.PENDING, SimpleGoalState.ACTIVE, SimpleGoalState.DONE
    assert simple_next(pending, CommState.ACTIVE) == (active, SimpleEffect.ACTIVE_CALLBACK)
    assert simple_next(pending, CommState.PREEMPTING) == (active, SimpleEffect.ACTIVE_CALLBACK)
    assert simple_next(active, CommState.ACTIVE) == (active, SimpleEffect.NOTHING)
    assert simple_next(active, CommState.DONE) == (done, SimpleEffect.DONE_CALLBACK)
    assert simple_next(pending, CommState.DONE) == (done, SimpleEffect.DONE_CALLBACK)
    assert simple_next(done, CommState.DONE) == (done, SimpleEffect.DONE_TWICE)
    assert simple_next(active, CommState.RECALLING) == (active, SimpleEffect.UNEXPECTED)
    assert simple_next(pending, CommState.WAITING_FOR_RESULT) == (pending, SimpleEffect.NOTHING)


def test_states_are_named_as_ros1_names_them() -> None:
    assert CommState.to_string(3) == "WAITING_FOR_RESULT"
    assert SimpleGoalState.to_string(2) == "DONE"
    assert Status.to_string(12) == "NO_SUCH_STATE_12"


_DEBIAN_TABLE = """
import json
from actionlib.action_client import _transitions
print(json.dumps({k: {s: v for s, v in row.items()} for k, row in _transitions.items()}))
"""


@needs_ros1
@pytest.mark.skipif(
    not ros1_python_imports("actionlib"), reason="Debian's python3-actionlib is absent"
)
def test_the_client_table_is_debians() -> None:
    done = subprocess.run(
        [ROS1_PYTHON, "-c", _DEBIAN_TABLE],
        capture_output=True,
        text=True,
        env=ros1_environ(),
        check=True,
        timeout=60,
    )
    theirs = json.loads(done.stdout)
    ours = {
        str(int(state)): {
            str(status): list(step) if isinstance(step, tuple) else step
            for status, step in row.items()
        }
        for state, row in COMM.items()
    }
    assert ours == {
        state: {
            status: step if isinstance(step, list) else _one(step) for status, step in row.items()
        }
        for state, row in theirs.items()
    }


def _one(step: int) -> list[int] | int:
    """ROS 1 writes a one-state step as the state itself; the table here as a 1-tuple."""
    return step if step in (NO_TRANSITION, INVALID_TRANSITION) else [step]
