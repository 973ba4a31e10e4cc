"""actionlib's goal state machines as tables: the server's goal status, the client's
communication state, and the simple client's three states.

Rules (actionlib's protocol as ROS 1's actionlib implements it; wiki
actionlib/DetailedDescription):

- A server keeps one status per goal (`Status`, the numbers of ``actionlib_msgs/GoalStatus``).
  The user's calls and the cancel requests are events (`ServerEvent`); `SERVER` gives the status
  each event leads to from each status, and an event absent from a status's row is refused with
  `SERVER_REFUSALS`' text (ROS 1's). A cancel request for a status it does not change is not
  an error: it is ignored, and the user is not told of it.
- A client follows each goal it sent in a `CommState`, from the statuses the server reports
  (on ``status``, and in the result). `COMM` gives, for the state and the reported status, the
  states to pass through, in order (each one a transition the user's callback sees), or
  `NO_TRANSITION`, or `INVALID_TRANSITION` (an error to log; the state stays).
- A simple client follows one goal in a `SimpleGoalState`; `SIMPLE` maps its state and the
  goal's new `CommState` to its next state and what to do (`SimpleEffect`).

This module knows nothing of messages, topics, threads, clocks or logging: states in, states
out. The server, the clients and their tests use the same tables.
"""

from __future__ import annotations

from enum import IntEnum


class _Named(IntEnum):
    """An enumeration whose ``to_string(n)`` names a value as ROS 1's actionlib does."""

    @classmethod
    def to_string(cls, n: int) -> str:
        """The name of ``n`` (``NO_SUCH_STATE_<n>`` when it has none)."""
        try:
            return cls(n).name
        except ValueError:
            return f"NO_SUCH_STATE_{n}"


class Status(_Named):
    """A goal's status on the server (``actionlib_msgs/GoalStatus``'s constants)."""

    PENDING = 0
    ACTIVE = 1
    PREEMPTED = 2
    SUCCEEDED = 3
    ABORTED = 4
    REJECTED = 5
    PREEMPTING = 6
    RECALLING = 7
    RECALLED = 8
    LOST = 9


#: Statuses a goal never leaves.
TERMINAL = frozenset(
    {
        Status.PREEMPTED,
        Status.SUCCEEDED,
        Status.ABORTED,
        Status.REJECTED,
        Status.RECALLED,
        Status.LOST,
    }
)


class ServerEvent(_Named):
    """What happens to a goal on the server: the user's calls on its handle, and a cancel
    request arriving for it."""

    ACCEPT = 0
    CANCEL = 1
    REJECT = 2
    ABORT = 3
    SUCCEED = 4
    CANCEL_REQUEST = 5


_P, _A, _RG, _PG = Status.PENDING, Status.ACTIVE, Status.RECALLING, Status.PREEMPTING

#: The status each event leads to, by the status it happens in.
SERVER: dict[ServerEvent, dict[int, Status]] = {
    ServerEvent.ACCEPT: {_P: Status.ACTIVE, _RG: Status.PREEMPTING},
    ServerEvent.CANCEL: {
        _P: Status.RECALLED,
        _RG: Status.RECALLED,
        _A: Status.PREEMPTED,
        _PG: Status.PREEMPTED,
    },
    ServerEvent.REJECT: {_P: Status.REJECTED, _RG: Status.REJECTED},
    ServerEvent.ABORT: {_A: Status.ABORTED, _PG: Status.ABORTED},
    ServerEvent.SUCCEED: {_A: Status.SUCCEEDED, _PG: Status.SUCCEEDED},
    ServerEvent.CANCEL_REQUEST: {_P: Status.RECALLING, _A: Status.PREEMPTING},
}

#: What the server logs when the user's call is not allowed in the goal's status (``%d``: the
#: status), as ROS 1 words it.
SERVER_REFUSALS = {
    ServerEvent.ACCEPT: "To transition to an active state, the goal must be in a pending or "
    "recalling state, it is currently in state: %d",
    ServerEvent.CANCEL: "To transition to a cancelled state, the goal must be in a pending, "
    "recalling, active, or preempting state, it is currently in state: %d",
    ServerEvent.REJECT: "To transition to a rejected state, the goal must be in a pending or "
    "recalling state, it is currently in state: %d",
    ServerEvent.ABORT: "To transition to an aborted state, the goal must be in a preempting or "
    "active state, it is currently in state: %d",
    ServerEvent.SUCCEED: "To transition to a succeeded state, the goal must be in a preempting "
    "or active state, it is currently in state: %d",
}


def server_next(status: int, event: ServerEvent) -> Status | None:
    """The status ``event`` leads to from ``status``; None when it is not allowed there."""
    return SERVER[event].get(status)


class CommState(_Named):
    """What a client knows of a goal it sent (ROS 1's ``CommState``)."""

    WAITING_FOR_GOAL_ACK = 0
    PENDING = 1
    ACTIVE = 2
    WAITING_FOR_RESULT = 3
    WAITING_FOR_CANCEL_ACK = 4
    RECALLING = 5
    PREEMPTING = 6
    DONE = 7
    LOST = 8


NO_TRANSITION = -1
INVALID_TRANSITION = -2

# One letter a client state, for a table that reads as one: W (waiting for goal ack), P
# (pending), A (active), R (waiting for result), C (waiting for cancel ack), L (recalling),
# E (preempting), D (done); N no transition, X invalid transition.
W, P, A, R = (
    CommState.WAITING_FOR_GOAL_ACK,
    CommState.PENDING,
    CommState.ACTIVE,
    CommState.WAITING_FOR_RESULT,
)
C, L, E, D = (
    CommState.WAITING_FOR_CANCEL_ACK,
    CommState.RECALLING,
    CommState.PREEMPTING,
    CommState.DONE,
)
N, X = NO_TRANSITION, INVALID_TRANSITION

#: The reported statuses, in the order of `_ROWS`' columns.
_COLUMNS = (
    Status.PENDING,
    Status.ACTIVE,
    Status.PREEMPTED,
    Status.SUCCEEDED,
    Status.ABORTED,
    Status.REJECTED,
    Status.PREEMPTING,
    Status.RECALLING,
    Status.RECALLED,
)
_ROWS: dict[CommState, tuple[tuple[CommState, ...] | int, ...]] = {
    #   PENDING ACTIVE  PREEMPTED   SUCCEEDED ABORTED  REJECTED PREEMPTING RECALLING RECALLED
    W: ((P,),   (A,),   (A, E, R),  (A, R),   (A, R),  (P, R),  (A, E),    (P, L),   (P, R)),
    P: (N,      (A,),   (A, E, R),  (A, R),   (A, R),  (R,),    (A, E),    (L,),     (L, R)),
    A: (X,      N,      (E, R),     (R,),     (R,),    X,       (E,),      X,        X),
    R: (X,      N,      N,          N,        N,       N,       X,         X,        N),
    C: (N,      N,      (E, R),     (E, R),   (E, R),  (R,),    (E,),      (L,),     (L, R)),
    L: (X,      X,      (E, R),     (E, R),   (E, R),  (R,),    (E,),      N,        (R,)),
    E: (X,      X,      (R,),       (R,),     (R,),    X,       N,         X,        X),
    D: (X,      X,      N,          N,        N,       N,       X,         X,        N),
}  # fmt: skip
#: For each client state, each status the server reports: the states to pass through, or
#: `NO_TRANSITION`, or `INVALID_TRANSITION`.
COMM: dict[CommState, dict[int, tuple[CommState, ...] | int]] = {
    state: dict(zip(_COLUMNS, row, strict=True)) for state, row in _ROWS.items()
}
del W, P, A, R, C, L, E, D, N, X

#: States in which a result is still awaited (a result then ends the goal).
AWAITING_RESULT = frozenset(CommState) - {CommState.DONE, CommState.LOST}

#: States in which a goal the server's status no longer lists is not lost (it was not seen
#: yet, or its result is on its way).
UNLISTED_IS_NORMAL = frozenset(
    {CommState.WAITING_FOR_GOAL_ACK, CommState.WAITING_FOR_RESULT, CommState.DONE}
)


def comm_next(state: CommState, status: int) -> tuple[CommState, ...] | int:
    """What a reported ``status`` does to a goal in ``state`` (see `COMM`); a status the table
    does not know (LOST, or a number outside `Status`) is `INVALID_TRANSITION`."""
    return COMM[state].get(status, INVALID_TRANSITION)


class SimpleGoalState(_Named):
    """A simple client's view of its one goal (ROS 1's ``SimpleGoalState``)."""

    PENDING = 0
    ACTIVE = 1
    DONE = 2


class SimpleEffect(_Named):
    """What a simple client does on a transition of its goal."""

    NOTHING = 0
    ACTIVE_CALLBACK = 1  # call the active callback
    DONE_CALLBACK = 2  # call the done callback, then wake those waiting for the result
    UNEXPECTED = 3  # log that this transition should not happen here
    DONE_TWICE = 4  # log that the goal finished twice


_SP, _SA, _SD = SimpleGoalState.PENDING, SimpleGoalState.ACTIVE, SimpleGoalState.DONE
_E = SimpleEffect

#: ``(simple state, new comm state) -> (next simple state, effect)``; pairs not listed change
#: nothing.
SIMPLE: dict[tuple[SimpleGoalState, CommState], tuple[SimpleGoalState, SimpleEffect]] = {
    (_SP, CommState.ACTIVE): (_SA, _E.ACTIVE_CALLBACK),
    (_SD, CommState.ACTIVE): (_SD, _E.UNEXPECTED),
    (_SA, CommState.RECALLING): (_SA, _E.UNEXPECTED),
    (_SD, CommState.RECALLING): (_SD, _E.UNEXPECTED),
    (_SP, CommState.PREEMPTING): (_SA, _E.ACTIVE_CALLBACK),
    (_SD, CommState.PREEMPTING): (_SD, _E.UNEXPECTED),
    (_SP, CommState.DONE): (_SD, _E.DONE_CALLBACK),
    (_SA, CommState.DONE): (_SD, _E.DONE_CALLBACK),
    (_SD, CommState.DONE): (_SD, _E.DONE_TWICE),
}


def simple_next(state: SimpleGoalState, comm: CommState) -> tuple[SimpleGoalState, SimpleEffect]:
    """The simple client's next state and effect when its goal enters ``comm``."""
    return SIMPLE.get((state, comm), (state, SimpleEffect.NOTHING))


__all__ = [
    "AWAITING_RESULT",
    "COMM",
    "INVALID_TRANSITION",
    "NO_TRANSITION",
    "SERVER",
    "SERVER_REFUSALS",
    "SIMPLE",
    "TERMINAL",
    "UNLISTED_IS_NORMAL",
    "CommState",
    "ServerEvent",
    "SimpleEffect",
    "SimpleGoalState",
    "Status",
    "comm_next",
    "server_next",
    "simple_next",
]
