"""Playing bags back: raw publications, one per topic, timed as the messages were recorded.

The player never decodes a message: each topic is advertised with the type, md5sum and
definition its connection recorded (latching if a recorded publisher latched), and the stored
bytes are published as they are. Messages of every bag are merged in time order.

Timing (ROS 1's ``rosbag play``, tools/rosbag/src/player.cpp): a message recorded ``d``
seconds after the first one played is published ``d / rate`` seconds after playback began,
plus the time spent paused; ``immediate`` publishes without waiting; ``skip_empty`` shortens
gaps longer than that many seconds to nothing. ``start`` and ``duration`` select a window of
the bags (seconds from the bags' start; the status line's duration counts from the window's
first message to its last, as ROS 1's does); ``loop`` plays again from the start; ``keep_alive``
keeps the node (and its latched topics) up until stopped. With ``clock`` the bag time is
published on ``/clock`` at ``hz``. `Player.toggle_pause`, `Player.step` and
`Player.toggle_pause_topics` serve the keys, and `Player.serve_pause` the ``~pause_playback``
service (``std_srvs/SetBool``: true pauses, false resumes); `Player.wait_for_subscribers`
holds playback until every topic has a subscriber.

``pause_topics``: playback pauses before each message of those topics (``t`` turns this off
and on). ``rate_control_topic`` (`Player.watch_rate_control`): playback waits while the bag
time runs more than ``rate_control_max_delay`` seconds ahead of the header stamp of the last
message heard on that topic, which must begin with a ``Header``.
"""

from __future__ import annotations

import heapq
import struct
import threading
import time
from typing import TYPE_CHECKING, Any

from rosx.signals import wait

if TYPE_CHECKING:
    from collections.abc import Callable, Iterator

    from rosx.bag.reader import BagReader, Connection
    from rosx.node import Node, Publisher, RawMessage, Subscriber

_NS = 1_000_000_000
#: Seconds between two status lines.
_STATUS_PERIOD = 0.1


class PlayOptions:
    """What ``rosbag play`` was asked to do (see the module's docstring)."""

    def __init__(
        self,
        *,
        prefix: str = "",
        quiet: bool = False,
        immediate: bool = False,
        pause: bool = False,
        queue_size: int = 100,
        clock: bool = False,
        hz: float = 100.0,
        delay: float = 0.2,
        rate: float = 1.0,
        start: float = 0.0,
        duration: float | None = None,
        skip_empty: float | None = None,
        loop: bool = False,
        keep_alive: bool = False,
        topics: list[str] | None = None,
        pause_topics: list[str] | None = None,
        rate_control_topic: str = "",
        rate_control_max_delay: float = 1.0,
    ) -> None:
        self.prefix = prefix
        self.quiet = quiet
        self.immediate = immediate
        self.pause = pause
        self.queue_size = queue_size
        self.clock = clock
        self.hz = hz
        self.delay = delay
        self.rate = rate
        self.start = start
        self.duration = duration
        self.skip_empty = skip_empty
        self.loop = loop
        self.keep_alive = keep_alive
        self.topics = topics or []
        self.pause_topics = set(pause_topics or [])
        self.rate_control_topic = rate_control_topic
        self.rate_control_max_delay = rate_control_max_delay


class Player:
    """One ``rosbag play`` run on a started node (see the module's docstring)."""

    def __init__(
        self,
        node: Node,
        bags: list[BagReader],
        options: PlayOptions,
        status: Callable[[str], None] | None = None,
        say: Callable[[str], None] | None = None,
    ) -> None:
        self.node = node
        self.bags = bags
        self.options = options
        self.status = status
        self.say = say  # other text for the terminal, even with ``quiet``
        self._publishers: dict[str, Publisher] = {}
        self._cond = threading.Condition()
        self.paused = options.pause
        self._steps = 0
        self._stopped = threading.Event()
        self._bag_now = 0
        self.published = 0
        self.pause_for_topics = bool(options.pause_topics)
        self._rate_control: Subscriber | None = None
        #: The header stamp (ns) last heard on the rate control topic.
        self._rate_stamp = 0
        self._first = 0
        self._total = 0.0
        self._last_status = 0.0
        self._last_state = ""
        #: (wall time it was due, wall time it went) of each message, when asked for.
        self.timing: list[tuple[float, float]] | None = None

    # -- control (any thread) ----------------------------------------------------------------

    def toggle_pause(self) -> None:
        """Pause, or resume."""
        with self._cond:
            self.paused = not self.paused
            self._cond.notify_all()

    def step(self) -> None:
        """While paused: publish the next message."""
        with self._cond:
            if self.paused:
                self._steps += 1
                self._cond.notify_all()

    def serve_pause(self) -> None:
        """Serve ``~pause_playback``, as ROS 1's player does."""
        from rosx.msg.codec.classes import get_service_class  # noqa: PLC0415 - message classes load on first use

        set_bool = get_service_class("std_srvs/SetBool")
        self.node.advertise_service("~pause_playback", set_bool, self._pause_requested)

    def _pause_requested(self, request: Any) -> dict[str, object]:
        pause = bool(request.data)
        with self._cond:
            changed = pause != self.paused
            self.paused = pause
            self._cond.notify_all()
        if changed:
            message = f"Playback is now {'paused' if pause else 'resumed'}"
        else:
            message = f"Bag is already {'paused' if pause else 'running'}."
        return {"success": changed, "message": message}

    def toggle_pause_topics(self) -> None:
        """Stop, or start again, pausing on ``pause_topics``."""
        with self._cond:
            self.pause_for_topics = not self.pause_for_topics

    def stop(self) -> None:
        """End playback (the run returns soon after)."""
        self._stopped.set()
        with self._cond:
            self._cond.notify_all()

    @property
    def stopped(self) -> bool:
        """Whether `stop` was called."""
        return self._stopped.is_set()

    # -- setting up --------------------------------------------------------------------------

    def _connections(self) -> dict[int, list[int]]:
        wanted = set(self.options.topics)
        return {
            i: [c.id for c in bag.connections.values() if not wanted or c.topic in wanted]
            for i, bag in enumerate(self.bags)
        }

    def advertise(self) -> None:
        """Advertise every topic to be played."""
        chosen = self._connections()
        by_topic: dict[str, list[Connection]] = {}
        for i, bag in enumerate(self.bags):
            for conn_id in chosen[i]:
                conn = bag.connections[conn_id]
                by_topic.setdefault(conn.topic, []).append(conn)
        for topic, conns in by_topic.items():
            first = conns[0]
            self._publishers[topic] = self.node.advertise_raw(
                self.options.prefix + topic,
                first.type,
                first.md5sum,
                first.message_definition,
                queue_size=self.options.queue_size,
                latch=any(c.latching for c in conns),
            )

    def _window(self) -> tuple[int, int | None]:
        """The bag times (ns) asked for: ``start`` seconds after the bags' first message, and
        ``duration`` seconds on (None: to the end)."""
        starts = [b.start_time for b in self.bags if b.start_time is not None]
        first = (min(starts) if starts else 0) + int(self.options.start * _NS)
        last = first + int(self.options.duration * _NS) if self.options.duration else None
        return first, last

    def _span(self) -> tuple[int, int] | None:
        """The times (ns) of the first and the last message to be played, as ROS 1's status
        line counts them."""
        chosen = self._connections()
        first, last = self._window()
        spans = [
            span
            for i, bag in enumerate(self.bags)
            if chosen[i] and (span := bag.span(set(chosen[i]), first, last)) is not None
        ]
        if not spans:
            return None
        return min(s[0] for s in spans), max(s[1] for s in spans)

    def _messages(self) -> Iterator[tuple[Connection, int, bytes]]:
        chosen = self._connections()
        first, last = self._window()
        streams = [
            bag.messages(set(chosen[i]), first, last)
            for i, bag in enumerate(self.bags)
            if chosen[i]
        ]
        return heapq.merge(*streams, key=lambda m: m[1])

    def watch_rate_control(self) -> None:
        """Subscribe to ``rate_control_topic`` (any type whose first field is a Header)."""
        self._rate_control = self.node.subscribe(
            self.options.rate_control_topic, None, self._heard_rate_control, queue_size=10
        )

    def _heard_rate_control(self, msg: RawMessage) -> None:
        definition = msg._connection_header.get("message_definition", "")
        first = next(
            (line for line in definition.split("\n") if line and not line.startswith("#")), ""
        )
        if not first.startswith(("Header ", "std_msgs/Header ")) or len(msg._buff) < 12:
            if self.say is not None:
                self.say(
                    "\nWARNING: Rate control topic is bad, header is not first. "
                    "MSG may be malformed.\n"
                )
            return
        secs, nsecs = struct.unpack_from("<iI", msg._buff, 4)
        with self._cond:
            self._rate_stamp = secs * _NS + nsecs
            self._cond.notify_all()

    def _delayed(self) -> bool:
        """Whether the bag time runs too far ahead of the rate control topic."""
        if self._rate_control is None:
            return False
        ahead = self._bag_now - self._rate_stamp
        return ahead > self.options.rate_control_max_delay * _NS

    def wait_for_subscribers(self) -> bool:
        """Wait until every played topic has a subscriber; False if stopped first."""
        while not self._stopped.wait(0.02):
            if all(pub.get_num_connections() > 0 for pub in self._publishers.values()):
                return True
        return False

    # -- playing -----------------------------------------------------------------------------

    def run(self) -> None:
        """Play (and loop, and keep alive) until done or stopped."""
        clock = None
        if self.options.clock:
            clock = threading.Thread(
                target=self._publish_clock, name="rosx-play-clock", daemon=True
            )
            clock.start()
        try:
            while not self.stopped:
                self._play_once()
                if not self.options.loop:
                    break
            if self.options.keep_alive:
                wait(self._stopped)
        finally:
            self._stopped.set()
            if clock is not None:
                clock.join()

    def _play_once(self) -> None:
        span = self._span()
        if span is None:
            return
        rate = self.options.rate if self.options.rate > 0 else 1.0
        skip = int(self.options.skip_empty * _NS) if self.options.skip_empty else 0
        origin_wall: float | None = None
        origin_bag = 0
        previous = 0
        self._first, self._total = span[0], (span[1] - span[0]) / _NS
        for conn, stamp, data in self._messages():
            if origin_wall is None:
                origin_wall, origin_bag, previous = time.monotonic(), stamp, stamp
                with self._cond:
                    # Each pass starts level with the rate control topic, as ROS 1's does.
                    self._bag_now = self._rate_stamp = stamp
            if skip and stamp - previous > skip:
                origin_bag += stamp - previous
            previous = stamp
            due = origin_wall + (stamp - origin_bag) / _NS / rate
            if self.pause_for_topics and conn.topic in self.options.pause_topics:
                with self._cond:
                    self.paused = True
            shift = self._wait(due)
            if shift is None:
                return
            origin_wall += shift
            self._bag_now = stamp
            publisher = self._publishers.get(conn.topic)
            if publisher is not None:
                publisher.publish_serialized(data)
                self.published += 1
                if self.timing is not None:
                    self.timing.append((due + shift, time.monotonic()))
            self._show_status("PAUSED " if self.paused else "RUNNING")

    def _show_status(self, state: str) -> None:
        """ROS 1's status line, at most every _STATUS_PERIOD, and at once when the state
        changes."""
        now = time.monotonic()
        if self.status is None or (
            now - self._last_status < _STATUS_PERIOD and state == self._last_state
        ):
            return
        self._last_status, self._last_state = now, state
        stamp = self._bag_now
        line = (
            f"\r [{state}]  Bag Time: {stamp / _NS:13.6f}   "
            f"Duration: {(stamp - self._first) / _NS:.6f} / {self._total:.6f}   "
        )
        if state == "DELAYED":
            delay = max(time.time_ns() - self._rate_stamp, 0) / _NS
            line += f"Delay: {delay:.2f} \r"
        else:
            line += "            \r"
        self.status(line)

    def _wait(self, due: float) -> float | None:
        """Sleep until ``due`` (wall, monotonic), honouring pauses and the rate control topic;
        the time spent held back, or None once stopped."""
        paused_for = 0.0
        with self._cond:
            while True:
                if self.stopped:
                    return None
                if self.paused:
                    if self._steps:
                        self._steps -= 1
                        return max(paused_for, time.monotonic() - due)
                    self._show_status("PAUSED ")
                    began = time.monotonic()
                    self._cond.wait(0.1)
                    paused_for += time.monotonic() - began
                    continue
                if self._delayed():
                    self._show_status("DELAYED")
                    began = time.monotonic()
                    self._cond.wait(0.1)
                    paused_for += time.monotonic() - began
                    continue
                if self.options.immediate:
                    return paused_for
                remaining = due + paused_for - time.monotonic()
                if remaining <= 0:
                    return paused_for
                # A timed wait wakes within ~0.1 ms; spinning through the last stretch instead made
                # the player the first thread a busy machine preempts (bench/README.md, play).
                self._cond.wait(min(remaining, 0.1))

    def _publish_clock(self) -> None:
        from rosx.msg.codec.classes import get_message_class  # noqa: PLC0415 - message classes load on first use
        from rosx.msg.codec.rostime import Time  # noqa: PLC0415 - message classes load on first use

        clock_class = get_message_class("rosgraph_msgs/Clock")
        publisher = self.node.advertise("/clock", clock_class, queue_size=1)
        period = 1.0 / self.options.hz if self.options.hz > 0 else 0.01
        while not self._stopped.wait(period):
            if self._bag_now:
                msg = clock_class()
                msg.clock = Time(self._bag_now // _NS, self._bag_now % _NS)
                publisher.publish(msg)


__all__ = ["PlayOptions", "Player"]
