"""The action server (``actionlib.action_server``): goals and cancel requests in, a handle per
goal to the user's callbacks, status, feedback and results out.

It subscribes to ``goal`` and ``cancel`` and publishes ``status`` (latched, every
1/``actionlib_status_frequency`` s, 5 Hz by default, and at every change), ``feedback`` and
``result`` (`rosx.actionlib.protocol`), with rospy's publishers and subscribers: it is a rospy
client of the node as a script's code is. Its policy is none: the user's goal callback decides
(`ServerGoalHandle`). As ROS 1's:

- a cancel request names a goal id, or a stamp (every goal at or before it), or neither (every
  goal); one for a goal not received yet is kept (RECALLING) and recalls the goal when it comes;
  a goal stamped at or before the latest cancel stamp is canceled on arrival;
- a goal received twice is handled once;
- a goal leaves the status list ``status_list_timeout`` seconds (5 by default, parameter
  ``<ns>/status_list_timeout``) after it ended.

Everything happens under ``lock`` (a reentrant lock the goal handles share). Feedback that a
quick series of messages has held back (`rosx.node.outgoing`) is written out before a result is
published, so that no result leaves before the feedback sent ahead of it (rosx's client then
hands that feedback over first: `rosx.actionlib.action_client`).
"""

from __future__ import annotations

import threading
from typing import TYPE_CHECKING, Any

from rosx.actionlib.goal_id_generator import GoalIDGenerator
from rosx.actionlib.protocol import action_types, msgs, topic
from rosx.actionlib.server_goal_handle import ServerGoalHandle
from rosx.actionlib.states import Status
from rosx.actionlib.status_tracker import HandleTrackerDeleter, StatusTracker
from rosx.client import lifecycle, logs, params, timing, topics

if TYPE_CHECKING:
    from collections.abc import Callable


def nop_cb(goal_handle: ServerGoalHandle) -> None:
    """The cancel callback of a server given none."""


class ActionServer:
    """Serves the action ``ns`` of type ``ActionSpec`` (an ``XAction`` class).

    ``goal_cb(handle)`` hears of each new goal, ``cancel_cb(handle)`` of each cancel request
    that changed a goal's status. Give ``auto_start=False`` and call `start` once ready.
    """

    def __init__(
        self,
        ns: str,
        ActionSpec: Any,  # noqa: N803 - actionlib's name
        goal_cb: Callable[[ServerGoalHandle], object],
        cancel_cb: Callable[[ServerGoalHandle], object] = nop_cb,
        auto_start: bool = True,
    ) -> None:
        self.ns = ns
        types = action_types(ActionSpec)
        self.ActionSpec = ActionSpec
        self.ActionGoal = types.goal
        self.ActionResult = types.result
        self.ActionResultType = types.result_type
        self.ActionFeedback = types.feedback
        self.goal_sub: topics.Subscriber | None = None
        self.cancel_sub: topics.Subscriber | None = None
        self.status_pub: topics.Publisher | None = None
        self.result_pub: topics.Publisher | None = None
        self.feedback_pub: topics.Publisher | None = None
        self.lock = threading.RLock()
        self.status_timer: timing.Timer | None = None
        self.status_list: list[StatusTracker] = []
        self._next_prune = -1  # ns; -1: walk the list at the next publication
        self.last_cancel = timing.Time()
        self.status_list_timeout = timing.Duration()
        self.id_generator = GoalIDGenerator()
        self.goal_callback = goal_cb
        self.cancel_callback = cancel_cb
        self.auto_start = auto_start
        self.started = False
        self.status_frequency = 5.0
        if auto_start:
            logs.logwarn(
                "You've passed in true for auto_start to the python action server, you should "
                "always pass in false to avoid race conditions."
            )
            self.start()

    def register_goal_callback(self, cb: Callable[[ServerGoalHandle], object]) -> None:
        """Call ``cb`` for new goals instead of the goal callback given so far."""
        self.goal_callback = cb

    def register_cancel_callback(self, cancel_cb: Callable[[ServerGoalHandle], object]) -> None:
        """Call ``cancel_cb`` for cancel requests instead of the one given so far."""
        self.cancel_callback = cancel_cb

    def start(self) -> None:
        """Advertise and subscribe the action's topics, and publish the status list."""
        with self.lock:
            self.initialize()
            self.started = True
            self.publish_status()

    def stop(self) -> None:
        """Stop serving: the topics go (no goal should be in progress)."""
        with self.lock:
            self.started = False
            for handle in (self.status_timer,):
                if handle is not None:
                    handle.shutdown()
            for endpoint in (
                self.goal_sub,
                self.cancel_sub,
                self.status_pub,
                self.feedback_pub,
                self.result_pub,
            ):
                if endpoint is not None:
                    endpoint.unregister()

    def initialize(self) -> None:
        """The topics and the status timer, with the parameters rospy's actionlib reads."""
        queue = params.get_param("actionlib_server_pub_queue_size", 50)
        self.pub_queue_size = queue if queue >= 0 else 50
        self.status_pub = topics.Publisher(
            topic(self.ns, "status"),
            msgs().GoalStatusArray,
            latch=True,
            queue_size=self.pub_queue_size,
        )
        self.result_pub = topics.Publisher(
            topic(self.ns, "result"), self.ActionResult, queue_size=self.pub_queue_size
        )
        self.feedback_pub = topics.Publisher(
            topic(self.ns, "feedback"), self.ActionFeedback, queue_size=self.pub_queue_size
        )
        sub_queue = params.get_param("actionlib_server_sub_queue_size", -1)
        self.sub_queue_size = sub_queue if sub_queue >= 0 else None
        self.goal_sub = topics.Subscriber(
            topic(self.ns, "goal"),
            self.ActionGoal,
            callback=self.internal_goal_callback,
            queue_size=self.sub_queue_size,
        )
        self.cancel_sub = topics.Subscriber(
            topic(self.ns, "cancel"),
            msgs().GoalID,
            callback=self.internal_cancel_callback,
            queue_size=self.sub_queue_size,
        )
        self.status_frequency = self._status_frequency()
        self.status_list_timeout = timing.Duration.from_sec(
            params.get_param(topic(self.ns, "status_list_timeout"), 5.0)
        )
        if self.status_frequency > 0.0:
            period = timing.Duration.from_sec(1.0 / self.status_frequency)
            self.status_timer = timing.Timer(period, self.publish_status_async)

    def _status_frequency(self) -> float:
        deprecated = topic(self.ns, "status_frequency")
        if params.has_param(deprecated):
            logs.logwarn(
                "You're using the deprecated status_frequency parameter, please switch to "
                "actionlib_status_frequency."
            )
            return float(params.get_param(deprecated, 5.0))
        found = params.search_param("actionlib_status_frequency")
        return 5.0 if found is None else float(params.get_param(found, 5.0))

    # -- out -----------------------------------------------------------------------------------

    def publish_result(self, status: Any, result: Any) -> None:
        """Publish ``result`` for the goal of ``status``, then the status list."""
        with self.lock:
            message = self.ActionResult()
            message.header.stamp = timing.Time.now()
            message.status = status
            message.result = result
            if not lifecycle.is_shutdown() and self.result_pub is not None:
                feedback = None if self.feedback_pub is None else self.feedback_pub.impl
                if feedback is not None:
                    feedback.flush()  # the goal's last feedback goes before its result
                self.result_pub.publish(message)
            self.publish_status()

    def publish_feedback(self, status: Any, feedback: Any) -> None:
        """Publish ``feedback`` for the goal of ``status``."""
        with self.lock:
            message = self.ActionFeedback()
            message.header.stamp = timing.Time.now()
            message.status = status
            message.feedback = feedback
            if not lifecycle.is_shutdown() and self.feedback_pub is not None:
                self.feedback_pub.publish(message)

    def publish_status_async(self, event: object) -> None:
        """The status timer's callback."""
        with self.lock:
            if self.started:
                self.publish_status()

    def publish_status(self) -> None:
        """Publish the status list, first dropping the goals whose time in it is up."""
        with self.lock:
            now = timing.Time.now()
            self._prune(now.to_nsec())
            array = msgs().GoalStatusArray()
            array.status_list = [tracker.status for tracker in self.status_list]
            array.header.stamp = now
            if not lifecycle.is_shutdown() and self.status_pub is not None:
                self.status_pub.publish(array)

    def _prune(self, now: int) -> None:
        """Drop the goals whose time in the list ended before ``now`` (ns). The list is only
        walked once the earliest such time has come (or while no goal has one): it is published
        at every transition, and holds every goal of the last ``status_list_timeout``."""
        if now < self._next_prune:
            return
        timeout = self.status_list_timeout.to_nsec()
        kept: list[StatusTracker] = []
        earliest = -1
        for tracker in self.status_list:
            ended = tracker.handle_destruction_time
            since = ended.secs * 1_000_000_000 + ended.nsecs
            if since:
                due = since + timeout
                if due < now:
                    continue
                earliest = due if earliest < 0 else min(earliest, due)
            kept.append(tracker)
        self.status_list = kept
        self._next_prune = earliest

    # -- in ------------------------------------------------------------------------------------

    def internal_cancel_callback(self, goal_id: Any) -> None:
        """A cancel request: every goal it names is told (`set_cancel_requested`)."""
        with self.lock:
            if not self.started:
                return
            zero = timing.Time()
            everything = goal_id.id == "" and goal_id.stamp == zero
            found = False
            for tracker in list(self.status_list):
                listed = tracker.status.goal_id
                this_one = goal_id.id == listed.id
                before = goal_id.stamp != zero and listed.stamp <= goal_id.stamp
                if not (everything or this_one or before):
                    continue
                found = found or this_one
                if tracker.handle_tracker is None:
                    tracker.handle_tracker = HandleTrackerDeleter(self, tracker)
                    tracker.handle_destruction_time = timing.Time.now()
                handle = ServerGoalHandle(tracker, self, tracker.handle_tracker)
                if handle.set_cancel_requested():
                    self.cancel_callback(handle)
            if goal_id.id != "" and not found:
                # A cancel that overtook its goal: the goal is recalled when it arrives.
                early = StatusTracker(goal_id, int(Status.RECALLING))
                early.handle_destruction_time = timing.Time.now()
                self.status_list.append(early)
            self.last_cancel = max(self.last_cancel, goal_id.stamp)

    def internal_goal_callback(self, goal: Any) -> None:
        """A goal: handed to the goal callback, unless it was seen or canceled already."""
        with self.lock:
            if not self.started:
                return
            for tracker in self.status_list:
                if goal.goal_id.id != tracker.status.goal_id.id:
                    continue
                if tracker.status.status == Status.RECALLING:
                    tracker.status.status = int(Status.RECALLED)
                    self.publish_result(tracker.status, self.ActionResultType())
                if tracker.handle_tracker is None:
                    tracker.handle_destruction_time = timing.Time.now()
                return
            tracker = StatusTracker(None, None, goal)
            self.status_list.append(tracker)
            tracker.handle_tracker = HandleTrackerDeleter(self, tracker)
            handle = ServerGoalHandle(tracker, self, tracker.handle_tracker)
            stamp = goal.goal_id.stamp
            if stamp != timing.Time() and stamp <= self.last_cancel:
                handle.set_canceled(
                    None,
                    "This goal handle was canceled by the action server because its timestamp "
                    "is before the timestamp of the last cancel request",
                )
            else:
                self.goal_callback(handle)


__all__ = ["ActionServer", "nop_cb"]
