"""Topic statistics: what a rospy-style node's subscriptions publish on ``/statistics``.

When the parameter ``/enable_statistics`` is true as a node subscribes to a topic, each
publisher connection of that subscription reports its windows (`rosx.node.stats`) as
``rosgraph_msgs/TopicStatistics`` on ``/statistics``: topic, publishing and subscribing node,
window bounds, messages delivered and dropped (sequence gaps in the header), bytes, and the
mean, standard deviation and maximum of the gaps between arrivals and of the header stamps'
ages (zero for messages without a header). The window follows the parameters
``/statistics_window_min_elements`` (10), ``/statistics_window_max_elements`` (100),
``/statistics_window_min_size`` (4 s) and ``/statistics_window_max_size`` (64 s), read when the
subscription starts. ``/clock`` and ``/statistics`` themselves are not measured.
"""

from __future__ import annotations

import threading
import time
from typing import TYPE_CHECKING, Any

from rosx.client import state
from rosx.client.logs import logerr
from rosx.client.params import get_param
from rosx.node.stats import StatisticsWindow, WindowReport, WindowSettings

if TYPE_CHECKING:
    from rosx.node.handles import Publisher, Subscriber

#: Topics whose subscriptions are never measured.
UNMEASURED = ("/clock", "/statistics")
STATISTICS_TOPIC = "/statistics"
_TYPE = "rosgraph_msgs/TopicStatistics"

_lock = threading.Lock()
#: The node's ``/statistics`` publisher, made on the first report, and the node it belongs to.
_publisher: tuple[object, Publisher] | None = None


def _param(name: str, default: Any) -> Any:
    try:
        return get_param(name, default)
    except Exception:  # no master to ask: statistics stay off, as in rospy
        return default


def enabled() -> bool:
    """Whether ``/enable_statistics`` is set (false when the master cannot be asked)."""
    return bool(_param("/enable_statistics", False))


def settings() -> WindowSettings:
    """The window parameters, defaults where unset."""
    d = WindowSettings()
    return WindowSettings(
        min_elements=int(_param("/statistics_window_min_elements", d.min_elements)),
        max_elements=int(_param("/statistics_window_max_elements", d.max_elements)),
        min_window=float(_param("/statistics_window_min_size", d.min_window)),
        max_window=float(_param("/statistics_window_max_size", d.max_window)),
    )


def _statistics_publisher() -> Publisher | None:
    global _publisher  # noqa: PLW0603 - one /statistics publisher per process, made on first use
    from rosx.msg.codec.classes import get_message_class  # noqa: PLC0415 - on the first report

    node = state.CLIENT.node
    if node is None:  # shut down meanwhile
        return None
    with _lock:
        if _publisher is None or _publisher[0] is not node:
            cls = get_message_class(_TYPE)
            _publisher = (node, node.advertise(STATISTICS_TOPIC, cls, queue_size=10))
        return _publisher[1]


class SubscriptionStatistics:
    """The windows of one subscription, one per publishing node; called with each message."""

    def __init__(self, subscription: Subscriber, node_name: str, window: WindowSettings) -> None:
        self.subscription = subscription
        self.node_name = node_name
        self.window = window
        self.windows: dict[str, StatisticsWindow] = {}

    def __call__(self, msg: Any) -> None:
        """Measure one received message; a failure is logged, never passed to the subscription."""
        try:
            self._measure(msg)
        except Exception as exc:  # statistics never disturb the subscription
            logerr("Unexpected error during statistics measurement: %s", exc)

    def _measure(self, msg: Any) -> None:
        now = time.time_ns()
        publisher = getattr(msg, "_connection_header", {}).get("callerid", "")
        window = self.windows.get(publisher)
        if window is None:
            window = self.windows[publisher] = StatisticsWindow(self.window, window_start=now)
        stamp = seq = None
        if getattr(msg, "_has_header", False):
            header = msg.header
            stamp, seq = header.stamp.to_nsec(), header.seq
        report = window.arrived(now, self.subscription.bytes_from(publisher), stamp, seq)
        if report is not None:
            statistics = _statistics_publisher()
            if statistics is not None:
                statistics.publish(self._message(publisher, report))

    def _message(self, publisher: str, r: WindowReport) -> Any:
        from rosx.client.timing import Duration, Time  # noqa: PLC0415 - the rospy API loads only when used
        from rosx.msg.codec.classes import get_message_class  # noqa: PLC0415 - message classes load on first use

        d = Duration.from_nsec
        return get_message_class(_TYPE)(
            topic=self.subscription.name,
            node_pub=publisher,
            node_sub=self.node_name,
            window_start=Time.from_nsec(r.window_start),
            window_stop=Time.from_nsec(r.window_stop),
            delivered_msgs=r.delivered_msgs,
            dropped_msgs=r.dropped_msgs,
            traffic=r.traffic,
            period_mean=d(r.period_mean),
            period_stddev=d(r.period_stddev),
            period_max=d(r.period_max),
            stamp_age_mean=d(r.stamp_age_mean),
            stamp_age_stddev=d(r.stamp_age_stddev),
            stamp_age_max=d(r.stamp_age_max),
        )


def watch(subscriber: Subscriber, node_name: str) -> None:
    """Measure the topic of ``subscriber`` (a node's first subscriber of it) if statistics are
    enabled."""
    if subscriber.name in UNMEASURED or not enabled():
        return
    subscriber.add_monitor(SubscriptionStatistics(subscriber, node_name, settings()))


__all__ = ["STATISTICS_TOPIC", "SubscriptionStatistics", "enabled", "settings", "watch"]
