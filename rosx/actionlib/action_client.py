"""The action client (``actionlib.action_client``): goals out, each followed by its own state
machine from the server's status, feedback and result.

`ActionClient` publishes ``goal`` and ``cancel`` and subscribes to ``status``, ``feedback`` and
``result`` (`rosx.actionlib.protocol`) with rospy's publishers and subscribers. Each goal sent
gets a `CommStateMachine`, which moves through `CommState` by `rosx.actionlib.states.COMM` and
calls the user's transition callback at each step; the user holds it through
`ClientGoalHandle`s, and the client follows it as long as a handle exists (weak references).

Two things differ from ROS 1's rospy actionlib, where its users met races:

- the goal's machine is tracked, and ``before_send`` sees its handle, before the goal is
  published, so no status, feedback or result of the goal can come first and be missed;
- feedback is never overtaken by its result: a result is acted on once the feedback that had
  reached this host when it arrived, including what a connection's thread was reading then
  (`make_drains_exact`), has been handed to the callbacks (the topics travel on different
  connections and threads); nor does it come before the goal is seen active: the feedback's
  own status moves a goal still waiting for acknowledgement.
"""

from __future__ import annotations

import itertools
import threading
import time
import weakref
from typing import TYPE_CHECKING, Any

from rosx.actionlib.protocol import action_types, msgs, seconds_of, topic
from rosx.actionlib.states import (
    AWAITING_RESULT,
    COMM,
    INVALID_TRANSITION,
    NO_TRANSITION,
    TERMINAL,
    UNLISTED_IS_NORMAL,
    CommState,
    Status,
    comm_next,
)
from rosx.client import lifecycle, logs, names, params, timing, topics

if TYPE_CHECKING:
    from collections.abc import Callable

    TransitionCallback = Callable[["ClientGoalHandle"], object]
    FeedbackCallback = Callable[["ClientGoalHandle", Any], object]

#: The states in which a goal's feedback may be the first news of its acceptance.
_BEFORE_ACKNOWLEDGEMENT = frozenset({CommState.WAITING_FOR_GOAL_ACK, CommState.PENDING})
#: How long a result waits for the feedback sent before it to reach the callbacks.
FEEDBACK_DRAIN_LIMIT = 1.0
_POLL = 0.01


def get_name_of_constant(C: Any, n: int) -> str:  # noqa: N803 - actionlib's name
    """The name of the int constant of class ``C`` equal to ``n`` (``NO_SUCH_STATE_<n>``)."""
    for key, value in vars(C).items():
        if isinstance(value, int) and not key.startswith("_") and value == n:
            return str(key)
    members = getattr(C, "__members__", {})
    for key, value in members.items():
        if value == n:
            return str(key)
    return f"NO_SUCH_STATE_{n}"


class TerminalState:
    """The statuses a finished goal can have (``actionlib_msgs/GoalStatus``'s numbers)."""

    RECALLED = int(Status.RECALLED)
    REJECTED = int(Status.REJECTED)
    PREEMPTED = int(Status.PREEMPTED)
    ABORTED = int(Status.ABORTED)
    SUCCEEDED = int(Status.SUCCEEDED)
    LOST = int(Status.LOST)

    @classmethod
    def to_string(cls, n: int) -> str:
        """The constant's name for ``n`` (``"SUCCEEDED"``), as actionlib prints terminal states."""
        return get_name_of_constant(cls, n)


def give_goal_status_its_names() -> None:
    """``GoalStatus.to_string(n)``, as ROS 1's actionlib adds it to the message class."""
    goal_status = msgs().GoalStatus
    if not hasattr(goal_status, "to_string"):
        goal_status.to_string = classmethod(get_name_of_constant)  # type: ignore[attr-defined]


class ClientGoalHandle:
    """The user's handle on one goal; equal handles follow the same goal."""

    def __init__(self, comm_state_machine: CommStateMachine | None) -> None:
        self.comm_state_machine = comm_state_machine

    def __eq__(self, o: object) -> bool:
        if not isinstance(o, ClientGoalHandle) or not o:
            return False
        return self.comm_state_machine == o.comm_state_machine

    def __ne__(self, o: object) -> bool:
        return not self == o

    def __hash__(self) -> int:
        return hash(self.comm_state_machine)

    def cancel(self) -> None:
        """Ask the server to cancel this goal."""
        machine = self.comm_state_machine
        if machine is None:
            return
        with machine.mutex:
            cancel = msgs().GoalID(stamp=timing.Time(0), id=machine.action_goal.goal_id.id)
            machine.send_cancel_fn(cancel)
            machine.transition_to(CommState.WAITING_FOR_CANCEL_ACK)

    def get_comm_state(self) -> int:
        """The goal's `CommState`."""
        if not self.comm_state_machine:
            logs.logerr("Trying to get_comm_state on an inactive ClientGoalHandle.")
            return CommState.LOST
        return self.comm_state_machine.state

    def get_goal_status(self) -> int:
        """The goal's last status from the server (``actionlib_msgs/GoalStatus``'s number)."""
        if not self.comm_state_machine:
            logs.logerr("Trying to get_goal_status on an inactive ClientGoalHandle.")
            return int(Status.PENDING)
        return int(self.comm_state_machine.latest_goal_status.status)

    def get_goal_status_text(self) -> str:
        """The text the server gave with the goal's last status."""
        if not self.comm_state_machine:
            logs.logerr("Trying to get_goal_status_text on an inactive ClientGoalHandle.")
            return "ERROR: Trying to get_goal_status_text on an inactive ClientGoalHandle."
        return str(self.comm_state_machine.latest_goal_status.text)

    def get_result(self) -> Any:
        """The goal's result (an ``XResult``), or None before it arrived."""
        if not self.comm_state_machine:
            logs.logerr("Trying to get_result on an inactive ClientGoalHandle.")
            return None
        latest = self.comm_state_machine.latest_result
        return None if latest is None else latest.result

    def get_terminal_state(self) -> int:
        """How the goal ended (a `TerminalState`); meaningful once the comm state is DONE."""
        machine = self.comm_state_machine
        if not machine:
            logs.logerr("Trying to get_terminal_state on an inactive ClientGoalHandle.")
            return int(Status.LOST)
        with machine.mutex:
            if machine.state != CommState.DONE:
                logs.logwarn(
                    "Asking for the terminal state when we're in [%s]",
                    CommState.to_string(machine.state),
                )
            status = int(machine.latest_goal_status.status)
            if status in TERMINAL:
                return status
            logs.logerr("Asking for a terminal state, but the goal status is %d", status)
            return int(Status.LOST)


class CommStateMachine:
    """What the client knows of one goal, moved by `rosx.actionlib.states.COMM`."""

    def __init__(
        self,
        action_goal: Any,
        transition_cb: TransitionCallback | None,
        feedback_cb: FeedbackCallback | None,
        send_goal_fn: Callable[[Any], object],
        send_cancel_fn: Callable[[Any], object],
    ) -> None:
        self.action_goal = action_goal
        self.transition_cb = transition_cb
        self.feedback_cb = feedback_cb
        self.send_goal_fn = send_goal_fn
        self.send_cancel_fn = send_cancel_fn
        self.state = CommState.WAITING_FOR_GOAL_ACK
        self.mutex = threading.RLock()
        self.latest_goal_status = msgs().GoalStatus(status=int(Status.PENDING))
        self.latest_result: Any = None
        #: The stamp (ns, the server's clock) of the feedback that told of the goal's
        #: acceptance before any status array did (`update_feedback`). A status array stamped
        #: no later was sent before the acceptance and may arrive after that feedback (another
        #: topic): that it does not list the goal does not make the goal lost.
        self._accepted_by_feedback = -1

    def __eq__(self, o: object) -> bool:
        if not isinstance(o, CommStateMachine):
            return False
        return bool(self.action_goal.goal_id.id == o.action_goal.goal_id.id)

    def __hash__(self) -> int:
        return hash(self.action_goal.goal_id.id)

    def set_state(self, state: CommState) -> None:
        """Move to ``state`` without telling the transition callback (`transition_to` tells it)."""
        self.state = state

    def update_status(self, status_array: Any) -> None:
        """Follow what a ``GoalStatusArray`` says of this goal."""
        own = self.action_goal.goal_id.id
        found = next((s for s in status_array.status_list if s.goal_id.id == own), None)
        self.update_from(found, status_array.header.stamp.to_nsec())

    def update_from(self, status: Any, sent: int | None = None) -> None:
        """Follow the goal's ``GoalStatus`` as a status array listed it (None: not listed);
        ``sent``: the array's stamp (ns)."""
        with self.mutex:
            if self.state == CommState.DONE:
                return
            if status is None:
                older = sent is not None and sent <= self._accepted_by_feedback
                if self.state not in UNLISTED_IS_NORMAL and not older:
                    self._mark_as_lost()
                return
            self.latest_goal_status = status
            steps = comm_next(self.state, status.status)
            if steps == NO_TRANSITION:
                return
            if steps == INVALID_TRANSITION:
                if status.status not in COMM[self.state]:
                    logs.logerr("Got an unknown status from the ActionServer: %i", status.status)
                else:
                    logs.logerr(
                        "Invalid goal status transition from %s to %s",
                        CommState.to_string(self.state),
                        get_name_of_constant(msgs().GoalStatus, status.status),
                    )
                return
            assert isinstance(steps, tuple)
            for state in steps:
                self.transition_to(state)

    def transition_to(self, state: CommState) -> None:
        """Enter ``state`` and tell the transition callback."""
        self.state = state
        if self.transition_cb:
            self.transition_cb(ClientGoalHandle(self))

    def _mark_as_lost(self) -> None:
        self.latest_goal_status.status = int(Status.LOST)
        self.transition_to(CommState.DONE)

    def update_result(self, action_result: Any) -> None:
        """The goal's result arrived: the goal is done."""
        if self.action_goal.goal_id.id != action_result.status.goal_id.id:
            return
        with self.mutex:
            self.latest_goal_status = action_result.status
            self.latest_result = action_result
            if self.state in AWAITING_RESULT:
                self.update_from(action_result.status)
                self.transition_to(CommState.DONE)
            elif self.state == CommState.DONE:
                logs.logerr("Got a result when we were already in the DONE state")
            else:
                logs.logerr("In a funny state: %i", self.state)

    def update_feedback(self, action_feedback: Any) -> None:
        """Feedback for the goal: to the feedback callback, unless the goal is done.

        Feedback comes from an accepted goal, and may arrive before the status that says so
        (another topic): its own status moves a goal still waiting for acknowledgement first,
        so the transition callback hears of the goal going active before any feedback. A
        status array sent before the acceptance may still come after it: its silence about
        the goal is then no loss (`update_from`).
        """
        status = action_feedback.status
        if self.action_goal.goal_id.id != status.goal_id.id:
            return
        if self.state in _BEFORE_ACKNOWLEDGEMENT:
            with self.mutex:
                if self.state in _BEFORE_ACKNOWLEDGEMENT and isinstance(
                    comm_next(self.state, status.status), tuple
                ):
                    self._accepted_by_feedback = action_feedback.header.stamp.to_nsec()
                    self.update_from(status)
        if self.feedback_cb and self.state != CommState.DONE:
            self.feedback_cb(ClientGoalHandle(self), action_feedback.feedback)


_goal_numbers = itertools.count(1)


class GoalManager:
    """The goals of one client, by goal id, each followed while a handle of it exists."""

    def __init__(self, ActionSpec: Any) -> None:  # noqa: N803 - actionlib's name
        types = action_types(ActionSpec)
        self.ActionSpec = ActionSpec
        self.ActionGoal = types.goal
        self.ActionResult = types.result
        self.ActionFeedback = types.feedback
        self.list_mutex = threading.RLock()
        self.statuses: dict[str, weakref.ref[CommStateMachine]] = {}
        self.send_goal_fn: Callable[[Any], object] | None = None
        self.cancel_fn: Callable[[Any], object] | None = None

    def _generate_id(self) -> Any:
        now = timing.Time.now()
        number = next(_goal_numbers)
        return msgs().GoalID(id=f"{names.get_caller_id()}-{number}-{now.to_sec():.3f}", stamp=now)

    def register_send_goal_fn(self, fn: Callable[[Any], object]) -> None:
        """Set how goals are sent (the client's ``goal`` publisher); every `init_goal` uses it."""
        self.send_goal_fn = fn

    def register_cancel_fn(self, fn: Callable[[Any], object]) -> None:
        """Set how a cancel request is sent (the client's ``cancel`` publisher)."""
        self.cancel_fn = fn

    def init_goal(
        self,
        goal: Any,
        transition_cb: TransitionCallback | None = None,
        feedback_cb: FeedbackCallback | None = None,
        *,
        before_send: Callable[[ClientGoalHandle], object] | None = None,
    ) -> ClientGoalHandle:
        """Send ``goal`` and follow it; ``before_send`` gets the handle before it is sent."""
        header = self.ActionGoal().header
        header.stamp = timing.get_rostime()
        action_goal = self.ActionGoal(header=header, goal_id=self._generate_id(), goal=goal)
        assert self.send_goal_fn is not None and self.cancel_fn is not None
        machine = CommStateMachine(
            action_goal, transition_cb, feedback_cb, self.send_goal_fn, self.cancel_fn
        )
        handle = ClientGoalHandle(machine)
        goal_id = action_goal.goal_id.id
        with self.list_mutex:
            self.statuses[goal_id] = weakref.ref(machine, lambda _: self._forget(goal_id))
        if before_send is not None:
            before_send(handle)
        self.send_goal_fn(action_goal)
        return handle

    def _forget(self, goal_id: str) -> None:
        with self.list_mutex:
            ref = self.statuses.get(goal_id)
            if ref is not None and ref() is None:
                del self.statuses[goal_id]

    def _get_live_statuses(self) -> list[CommStateMachine]:
        with self.list_mutex:
            live = [ref() for ref in self.statuses.values()]
        return [machine for machine in live if machine is not None]

    def machine_of(self, goal_id: str) -> CommStateMachine | None:
        """The machine of the goal ``goal_id``, if it is followed."""
        with self.list_mutex:
            ref = self.statuses.get(goal_id)
        return None if ref is None else ref()

    def update_statuses(self, status_array: Any) -> None:
        """Every followed goal learns what a status array says of it."""
        listed = {status.goal_id.id: status for status in status_array.status_list}
        sent = status_array.header.stamp.to_nsec()
        for machine in self._get_live_statuses():
            machine.update_from(listed.get(machine.action_goal.goal_id.id), sent)

    def update_results(self, action_result: Any) -> None:
        """Pass a ``result`` message to the state machine of its goal; others' goals are ignored."""
        machine = self.machine_of(action_result.status.goal_id.id)
        if machine is not None:
            machine.update_result(action_result)

    def update_feedbacks(self, action_feedback: Any) -> None:
        """Pass a ``feedback`` message to the state machine of its goal; others' goals are
        ignored."""
        machine = self.machine_of(action_feedback.status.goal_id.id)
        if machine is not None:
            machine.update_feedback(action_feedback)


class ActionClient:
    """A client of the action ``ns`` of type ``ActionSpec`` (an ``XAction`` class)."""

    def __init__(self, ns: str, ActionSpec: Any) -> None:  # noqa: N803 - actionlib's name
        give_goal_status_its_names()
        self.ns = ns
        self.last_status_msg: Any = None
        types = action_types(ActionSpec)
        self.ActionSpec = ActionSpec
        self.ActionGoal = types.goal
        self.ActionResult = types.result
        self.ActionFeedback = types.feedback
        queue = params.get_param("actionlib_client_pub_queue_size", 10)
        self.pub_queue_size = queue if queue >= 0 else 10
        self.pub_goal = topics.Publisher(
            topic(ns, "goal"), self.ActionGoal, queue_size=self.pub_queue_size
        )
        self.pub_cancel = topics.Publisher(
            topic(ns, "cancel"), msgs().GoalID, queue_size=self.pub_queue_size
        )
        self.manager = GoalManager(ActionSpec)
        self.manager.register_send_goal_fn(self.pub_goal.publish)
        self.manager.register_cancel_fn(self.pub_cancel.publish)
        sub_queue = params.get_param("actionlib_client_sub_queue_size", -1)
        self.sub_queue_size = sub_queue if sub_queue >= 0 else None
        # Each status message lists every goal the server has: only the newest one counts (a
        # goal's transitions skipped with older ones are passed through, `states.COMM`), so
        # unless a queue size is asked for, older ones waiting are dropped unread.
        self.status_sub = topics.Subscriber(
            topic(ns, "status"),
            msgs().GoalStatusArray,
            callback=self._status_cb,
            queue_size=1 if self.sub_queue_size is None else self.sub_queue_size,
        )
        self.result_sub = topics.Subscriber(
            topic(ns, "result"),
            self.ActionResult,
            callback=self._result_cb,
            queue_size=self.sub_queue_size,
        )
        self.feedback_sub = topics.Subscriber(
            topic(ns, "feedback"),
            self.ActionFeedback,
            callback=self._feedback_cb,
            queue_size=self.sub_queue_size,
        )
        if self.feedback_sub.impl is not None:  # a result waits for the feedback before it
            self.feedback_sub.impl.make_drains_exact()

    def stop(self) -> None:
        """Close the action's topics."""
        for endpoint in (
            self.pub_goal,
            self.pub_cancel,
            self.status_sub,
            self.result_sub,
            self.feedback_sub,
        ):
            endpoint.unregister()

    def send_goal(
        self,
        goal: Any,
        transition_cb: TransitionCallback | None = None,
        feedback_cb: FeedbackCallback | None = None,
        *,
        before_send: Callable[[ClientGoalHandle], object] | None = None,
    ) -> ClientGoalHandle:
        """Send ``goal`` (an ``XGoal``). ``transition_cb(handle)`` is called at each change of
        its comm state, ``feedback_cb(handle, feedback)`` for each feedback."""
        return self.manager.init_goal(goal, transition_cb, feedback_cb, before_send=before_send)

    def cancel_all_goals(self) -> None:
        """Ask the server to cancel every goal it has."""
        self.pub_cancel.publish(msgs().GoalID(stamp=timing.Time.from_sec(0.0), id=""))

    def cancel_goals_at_and_before_time(self, time: Any) -> None:
        """Ask the server to cancel every goal stamped at or before ``time``."""
        self.pub_cancel.publish(msgs().GoalID(stamp=time, id=""))

    def wait_for_action_server_to_start(self, timeout: Any = None) -> bool:
        """The old name of `wait_for_server`."""
        return self.wait_for_server(timeout)

    def wait_for_server(self, timeout: Any = None) -> bool:
        """Wait until a server publishes status and is connected on all five topics; a zero
        ``timeout`` (the default) waits for ever. True when it is."""
        seconds = seconds_of(timeout)
        deadline = time.monotonic() + seconds
        while not lifecycle.is_shutdown():
            if self._server_connected():
                return True
            if seconds > 0.0 and time.monotonic() >= deadline:
                return False
            time.sleep(_POLL)
        return False

    def _server_connected(self) -> bool:
        status = self.last_status_msg
        if status is None:
            return False
        server = status._connection_header.get("callerid")
        goal, cancel = self.pub_goal.impl, self.pub_cancel.impl
        result, feedback = self.result_sub.impl, self.feedback_sub.impl
        if goal is None or cancel is None or result is None or feedback is None:
            return False
        return (
            server in goal.subscriber_ids()
            and server in cancel.subscriber_ids()
            and server in result.publisher_ids()
            and server in feedback.publisher_ids()
        )

    def _status_cb(self, msg: Any) -> None:
        self.last_status_msg = msg
        self.manager.update_statuses(msg)

    def _result_cb(self, msg: Any) -> None:
        self._feedback_before(msg)
        self.manager.update_results(msg)

    def _feedback_before(self, result: Any) -> None:
        """Wait (a little at most) for the feedback that reached this host before ``result``
        to reach the callbacks, if the goal is one this client follows."""
        feedback = self.feedback_sub.impl
        if feedback is None or self.manager.machine_of(result.status.goal_id.id) is None:
            return
        drain = feedback.drain()
        deadline = time.monotonic() + FEEDBACK_DRAIN_LIMIT
        while not drain.done() and time.monotonic() < deadline:
            time.sleep(0.0005)

    def _feedback_cb(self, msg: Any) -> None:
        self.manager.update_feedbacks(msg)


__all__ = [
    "ActionClient",
    "ClientGoalHandle",
    "CommState",
    "CommStateMachine",
    "GoalManager",
    "TerminalState",
    "get_name_of_constant",
    "give_goal_status_its_names",
]
