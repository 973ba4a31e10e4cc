"""What ``rostopic hz``, ``bw`` and ``delay`` measure, and the text they print each second.

Also the rates and bandwidths of ``rosx rqt_topic``: one home for a topic's statistics.

Pure bookkeeping: each tracker is fed arrival times (and sizes or stamps) by a subscriber's
callback and asked for its report by the printing loop; neither sockets nor clocks live here,
the caller passes the current time in. The rules are ROS 1's:

* **hz** keeps the gaps between arrivals (the first message only starts the clock) in a window
  of ``-w`` messages (``-1``: 50 000) and reports their mean as a rate, their min, max and
  population standard deviation, and the window as the number of gaps plus one; a report with
  no message since the previous one is ``no new messages``. Several topics print as a table,
  numbers with four significant digits.
* **bw** keeps the last ``-w`` (default 100) arrival times and sizes and reports bytes per
  second from the oldest kept arrival to now, with the mean, min and max size, in B, KB or MB
  (steps of 1000, chosen by the rate) with two decimals; fewer than two messages print nothing.
* **delay** keeps the differences between arrival time and ``header.stamp`` (again the first
  message only starts the clock) and reports them like hz; nothing is printed before the
  first difference.
* **topic statistics** (what a subscriber publishes on ``/statistics`` when
  ``/enable_statistics`` is set, rosgraph_msgs/TopicStatistics) keep, per publisher connection,
  a window of arrival times, stamp ages, sequence gaps and bytes. A message arriving more than
  one report period after the last report closes the window (the very first message does);
  the period starts at 1 s and doubles while a window holds fewer than the minimum number of
  messages (up to the maximum window length), halves while it holds more than the maximum
  (down to the minimum length). Times are integer nanoseconds here.
"""

from __future__ import annotations

import math
import threading
from collections import deque
from dataclasses import dataclass, field

#: hz's and delay's cap on the window (``-w -1`` means "everything" up to this many).
MAX_WINDOW = 50000
#: bw's window when ``-w`` is not given.
DEFAULT_BW_WINDOW = 100
NO_NEW_MESSAGES = "no new messages"
#: What hz and delay print when ROS time reads 0 again after messages were measured.
TIME_RESET = "time has reset, resetting counters"

Summary = tuple[float, float, float, float, int]


def _summary(values: deque[float]) -> Summary:
    """Mean, min, max, standard deviation and window (values + 1) of a non-empty window."""
    n = len(values)
    mean = sum(values) / n
    std_dev = math.sqrt(sum((x - mean) ** 2 for x in values) / n)
    return mean, min(values), max(values), std_dev, n + 1


class _Gaps:
    """Successive differences, the first event only setting the start (hz's and delay's rule)."""

    def __init__(self, window: int) -> None:
        if window < 0:
            window = MAX_WINDOW
        # ROS 1 drops the oldest value once there are more than window - 1 of them.
        self.values: deque[float] = deque(maxlen=max(window - 1, 0))
        self.t0 = -1.0
        self.tn = 0.0
        self.last_printed = 0.0


def _dropped(gaps: _Gaps) -> bool:
    """Drop the values of ``gaps``, keeping its start (as ROS 1 does); whether it had any."""
    had = bool(gaps.values)
    gaps.values.clear()
    return had


class HzTracker:
    """Arrival statistics of one or more topics (``rostopic hz``)."""

    def __init__(self, window: int = -1) -> None:
        self.window = window
        self._topics: dict[str, _Gaps] = {}
        self._lock = threading.Lock()

    def _gaps(self, topic: str) -> _Gaps:
        gaps = self._topics.get(topic)
        if gaps is None:
            gaps = self._topics[topic] = _Gaps(self.window)
        return gaps

    def arrived(self, topic: str, now: float) -> None:
        """A message of ``topic`` arrived at ``now`` (seconds)."""
        with self._lock:
            gaps = self._gaps(topic)
            if gaps.t0 < 0 or gaps.t0 > now:
                gaps.t0 = gaps.tn = now
                gaps.values.clear()
            else:
                gaps.values.append(now - gaps.tn)
                gaps.tn = now

    def time_reset(self, topic: str) -> bool:
        """ROS time read 0 when a message of ``topic`` came (simulated time restarted): the
        gaps so far are dropped. True when there were any (ROS 1 then prints
        `TIME_RESET`)."""
        with self._lock:
            return _dropped(self._gaps(topic))

    def rate(self, topic: str) -> Summary | None:
        """``(rate, min gap, max gap, std dev, window)``, or None with nothing new to report."""
        with self._lock:
            gaps = self._gaps(topic)
            if not gaps.values or gaps.tn == gaps.last_printed:
                return None
            mean, low, high, std_dev, window = _summary(gaps.values)
            gaps.last_printed = gaps.tn
        return (1.0 / mean if mean > 0 else 0.0), low, high, std_dev, window

    def report(self, topics: list[str]) -> str:
        """What ``rostopic hz`` prints each second for ``topics`` (no final newline)."""
        if len(topics) == 1:
            found = self.rate(topics[0])
            if found is None:
                return NO_NEW_MESSAGES
            rate, low, high, std_dev, window = found
            return (
                f"average rate: {rate:.3f}\n"
                f"\tmin: {low:.3f}s max: {high:.3f}s std dev: {std_dev:.5f}s window: {window}"
            )
        rows: list[tuple[str, Summary]] = []
        for topic in topics:
            found = self.rate(topic)
            if found is not None:
                rows.append((topic, found))
        if not rows:
            return NO_NEW_MESSAGES
        return hz_table(rows)


def hz_table(rows: list[tuple[str, Summary]]) -> str:
    """The multi-topic table of ``rostopic hz``, ending with a blank line.

    ROS 1 collects each topic's window twice into the window column, so row ``i`` shows the
    window of topic ``i // 2``; the column is reproduced as it prints.
    """
    header = ["topic", "rate", "min_delta", "max_delta", "std_dev", "window"]
    windows = [str(summary[4]) for _, summary in rows for _ in range(2)]
    columns: dict[str, list[str]] = {
        "topic": [topic for topic, _ in rows],
        "rate": [f"{summary[0]:.4}" for _, summary in rows],
        "min_delta": [f"{summary[1]:.4}" for _, summary in rows],
        "max_delta": [f"{summary[2]:.4}" for _, summary in rows],
        "std_dev": [f"{summary[3]:.4}" for _, summary in rows],
        "window": windows,
    }
    widths = [max(len(name), *(len(cell) for cell in columns[name])) for name in header]
    titles = "   ".join(name.center(width) for name, width in zip(header, widths, strict=True))
    body = "\n".join(
        "   ".join(
            columns[name][row].ljust(width) for name, width in zip(header, widths, strict=True)
        )
        for row in range(len(rows))
    )
    rule = "=" * (sum(widths) + 3 * (len(header) - 1))
    return f"{titles}\n{rule}\n{body}\n"


class BandwidthTracker:
    """Sizes of the last messages of a topic (``rostopic bw``)."""

    def __init__(self, window: int | None = None) -> None:
        self.window = window or DEFAULT_BW_WINDOW
        self.times: deque[float] = deque()
        self.sizes: deque[int] = deque()
        self._lock = threading.Lock()

    def arrived(self, size: int, now: float) -> None:
        """A message of ``size`` bytes arrived at ``now`` (seconds)."""
        with self._lock:
            self.times.append(now)
            self.sizes.append(size)
            if len(self.times) > self.window:
                self.times.popleft()
                self.sizes.popleft()

    def rate(self, now: float) -> float | None:
        """Bytes per second at ``now`` over the window, or None (fewer than two messages)."""
        with self._lock:
            if len(self.times) < 2:
                return None
            elapsed = now - self.times[0]
            return sum(self.sizes) / elapsed if elapsed > 0 else math.inf

    def report(self, now: float) -> str | None:
        """What ``rostopic bw`` prints at ``now``, or None (fewer than two messages)."""
        with self._lock:
            n = len(self.times)
            if n < 2:
                return None
            total = sum(self.sizes)
            elapsed = now - self.times[0]
            low, high = min(self.sizes), max(self.sizes)
        bytes_per_s = total / elapsed if elapsed > 0 else math.inf
        values = [bytes_per_s, total / n, low, high]
        if bytes_per_s < 1000:
            rate, mean, smallest, largest = (f"{v:.2f}B" for v in values)
        elif bytes_per_s < 1000000:
            rate, mean, smallest, largest = (f"{v / 1000:.2f}KB" for v in values)
        else:
            rate, mean, smallest, largest = (f"{v / 1000000:.2f}MB" for v in values)
        return f"average: {rate}/s\n\tmean: {mean} min: {smallest} max: {largest} window: {n}"


class DelayTracker:
    """Differences between arrival and ``header.stamp`` (``rostopic delay``)."""

    def __init__(self, window: int = -1) -> None:
        self._gaps = _Gaps(window)
        self._lock = threading.Lock()

    def arrived(self, now: float, stamp: float) -> None:
        """A message stamped ``stamp`` arrived at ``now`` (both in seconds)."""
        with self._lock:
            gaps = self._gaps
            if gaps.t0 < 0 or gaps.t0 > now:
                gaps.t0 = gaps.tn = now
                gaps.values.clear()
            else:
                gaps.values.append(now - stamp)
                gaps.tn = now

    def time_reset(self) -> bool:
        """ROS time read 0 when a message came: the delays so far are dropped. True when
        there were any (ROS 1 then prints `TIME_RESET`)."""
        with self._lock:
            return _dropped(self._gaps)

    def report(self) -> str | None:
        """What ``rostopic delay`` prints each second, or None before the first delay."""
        with self._lock:
            gaps = self._gaps
            if not gaps.values:
                return None
            if gaps.tn == gaps.last_printed:
                return NO_NEW_MESSAGES
            mean, low, high, std_dev, window = _summary(gaps.values)
            gaps.last_printed = gaps.tn
        return (
            f"average delay: {mean:.3f}\n"
            f"\tmin: {low:.3f}s max: {high:.3f}s std dev: {std_dev:.5f}s window: {window}"
        )


@dataclass(frozen=True)
class WindowSettings:
    """The ``/statistics_window_*`` parameters: messages per window, window length (s)."""

    min_elements: int = 10
    max_elements: int = 100
    min_window: float = 4.0
    max_window: float = 64.0


@dataclass
class WindowReport:
    """One window of one connection; times and durations in nanoseconds."""

    window_start: int
    window_stop: int
    delivered_msgs: int
    dropped_msgs: int
    traffic: int
    period_mean: int = 0
    period_stddev: int = 0
    period_max: int = 0
    stamp_age_mean: int = 0
    stamp_age_stddev: int = 0
    stamp_age_max: int = 0


def _mean_std_max(values: list[int]) -> tuple[int, int, int]:
    mean = sum(values) / len(values)
    std = math.sqrt(sum((v - mean) ** 2 for v in values) / len(values))
    return round(mean), round(std), max(values)


@dataclass
class StatisticsWindow:
    """The statistics of one publisher connection of a subscription (see the module)."""

    settings: WindowSettings
    window_start: int
    frequency: float = 1.0
    last_report: int = 0
    last_seq: int = 0
    dropped: int = 0
    bytes_reported: int = 0
    bytes_seen: int = 0
    arrivals: list[int] = field(default_factory=list)
    ages: list[int] = field(default_factory=list)

    def arrived(
        self, now: int, total_bytes: int, stamp: int | None = None, seq: int | None = None
    ) -> WindowReport | None:
        """A message arrived at ``now``; ``total_bytes`` is what the connection has carried so
        far, ``stamp`` and ``seq`` its header's (None without a header). Returns the closed
        window's report when this message closes it."""
        self.arrivals.append(now)
        self.bytes_seen = total_bytes
        if stamp is not None:
            self.ages.append(now - stamp)
        if seq is not None:
            if seq != self.last_seq + 1:
                self.dropped += 1
            self.last_seq = seq
        if now > self.last_report + round(1e9 / self.frequency):
            self.last_report = now
            return self._close(now)
        return None

    def _close(self, now: int) -> WindowReport:
        report = WindowReport(
            window_start=self.window_start,
            window_stop=now,
            delivered_msgs=len(self.arrivals),
            dropped_msgs=self.dropped,
            traffic=self.bytes_seen - self.bytes_reported,
        )
        if self.ages:
            mean, std, high = _mean_std_max(self.ages)
            report.stamp_age_mean, report.stamp_age_stddev, report.stamp_age_max = mean, std, high
        if len(self.arrivals) > 1:
            periods = [b - a for a, b in zip(self.arrivals, self.arrivals[1:], strict=False)]
            mean, std, high = _mean_std_max(periods)
            report.period_mean, report.period_stddev, report.period_max = mean, std, high
        settings, count, period = self.settings, len(self.arrivals), 1.0 / self.frequency
        if count > settings.max_elements and period / 2 >= settings.min_window:
            self.frequency *= 2
        if count < settings.min_elements and period * 2 <= settings.max_window:
            self.frequency /= 2
        self.arrivals, self.ages, self.dropped = [], [], 0
        self.window_start = now
        self.bytes_reported = self.bytes_seen
        return report
