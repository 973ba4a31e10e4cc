"""Recording topics into bags: a node's raw subscriptions feeding a `BagWriter`.

The recorder never decodes a message. It subscribes with rospy's ``AnyMsg`` (type ``*``), so
every publisher's frames arrive as `RawMessage` objects carrying the bytes and the publisher's
connection header; each (topic, header) pair becomes one connection of the bag, as in ROS 1.

The contract (ROS 1's ``rosbag record``, tools/rosbag/src/recorder.cpp):

* A callback only stamps the message with ROS time (the wall clock, or ``/clock`` under
  ``/use_sim_time``) and queues it; one writer thread
  writes the queue to the bag, so a slow disk never stalls a subscription. The queue holds at
  most ``buffer_size`` bytes (0: unbounded); when full, the oldest queued message is dropped with
  ROS 1's warning (at most one every 5 s). Every message the queue holds when recording stops
  is written before the bag closes.
* The file is ``NAME.bag.active`` while being written; each chunk reaches the disk when it
  closes (at ``chunk_size`` bytes, or after `FLUSH_PERIOD` seconds), so a recorder that is
  killed leaves a bag that ``rosbag reindex`` restores; on a clean stop the index is written
  and the file renamed to ``NAME.bag``.
* Topics: those named (resolved in the node's namespace), ``all`` topics, those matching
  ``regex`` patterns (whole-name matches), those a ``node`` subscribes to; minus ``exclude``.
  Topics that appear later are picked up by asking the master every `DISCOVERY_PERIOD` s.
* A write that fails (a full disk) stops the recording with one error line; the bag is closed
  with what reached the disk before (see `rosx.bag.writer`), renamed, and opens.
* ``limit`` messages per topic, then that topic is unsubscribed; when every named topic has
  its count, recording stops. ``max_size`` / ``max_duration`` stop the recording, or with
  ``split`` start the next file ``NAME_<n>.bag``, keeping at most ``max_splits`` files.
* ``repeat_latched``: each new file starts with the messages of latching publishers, stamped
  with the time the file opens (ROS 1 keeps the first message of each publisher; rosx keeps
  its last, the one a new subscriber would be given). ``publish``: each time a file opens,
  its name is published, latched, as a ``std_msgs/String`` on ``begin_write`` (resolved in
  the recorder's namespace).
"""

from __future__ import annotations

import contextlib
import os
import re
import threading
import time
from collections import deque
from pathlib import Path
from typing import TYPE_CHECKING, Any

from rosx.bag.writer import DEFAULT_CHUNK_THRESHOLD, BagWriter, open_unbuffered
from rosx.master.client import MasterError

if TYPE_CHECKING:
    from collections.abc import Callable

    from rosx.bag.writer import Opener
    from rosx.node import Node, Publisher, RawMessage, Subscriber

#: Seconds between two looks at the master for new topics.
DISCOVERY_PERIOD = 0.5
#: Seconds after which an open chunk is written out even if it is not full.
FLUSH_PERIOD = 1.0
#: Seconds `Recorder.stop` waits for messages already read to reach the queue.
DRAIN_TIMEOUT = 30.0
_WARN_PERIOD = 5.0
#: Wall seconds without ``/clock`` under ``/use_sim_time`` before ROS 1's warning (as its own).
CLOCK_WAIT = 2.0


class RecordOptions:
    """What ``rosbag record`` was asked to do (see the module's contract)."""

    def __init__(
        self,
        *,
        topics: list[str] | None = None,
        record_all: bool = False,
        regex: bool = False,
        exclude: str = "",
        prefix: str = "",
        append_date: bool = True,
        split: bool = False,
        max_size: int = 0,
        max_duration: float = 0.0,
        max_splits: int = 0,
        limit: int = 0,
        node: str = "",
        compression: str = "none",
        buffer_size: int = 256 * 1024 * 1024,
        chunk_size: int = DEFAULT_CHUNK_THRESHOLD,
        tcp_nodelay: bool = False,
        repeat_latched: bool = False,
        publish: bool = False,
    ) -> None:
        self.topics = sorted(set(topics or []))  # ROS 1's keeps them in a std::set
        self.record_all = record_all
        self.regex = regex
        self.exclude = re.compile(exclude) if exclude else None
        self.patterns = [re.compile(t) for t in self.topics] if regex else []
        self.prefix = prefix
        self.append_date = append_date
        self.split = split
        self.max_size = max_size
        self.max_duration = max_duration
        self.max_splits = max_splits
        self.limit = limit
        self.node = node
        self.compression = compression
        self.buffer_size = buffer_size
        self.chunk_size = chunk_size
        self.tcp_nodelay = tcp_nodelay
        self.repeat_latched = repeat_latched
        self.publish = publish


def bag_name(prefix: str, append_date: bool, split_index: int | None, now: float) -> str:
    """ROS 1's file name: ``PREFIX_DATE_N.bag`` with the parts that apply."""
    if prefix.endswith(".bag"):
        prefix = prefix[:-4]
    parts = [prefix] if prefix else []
    if append_date:
        parts.append(time.strftime("%Y-%m-%d-%H-%M-%S", time.localtime(now)))
    if split_index is not None:
        parts.append(str(split_index))
    if not parts:
        raise ValueError(
            "Bag filename is empty (neither of these was specified: prefix, append_date, split)"
        )
    return "_".join(parts) + ".bag"


class Recorder:
    """One ``rosbag record`` run on a started node (see the module's contract)."""

    def __init__(
        self,
        node: Node,
        options: RecordOptions,
        log: Callable[[str, str], None],
        *,
        opener: Opener = open_unbuffered,
    ) -> None:
        self.node = node
        self._opener = opener
        self.options = options
        self.log = log  # (level, text): "INFO", "WARN", "ERROR"
        self._lock = threading.Condition()
        self._queue: deque[tuple[str, dict[str, str], int, bytes]] = deque()
        self._queued_bytes = 0
        self._last_warning = 0.0
        self._subscribers: dict[str, Subscriber] = {}
        self._counts: dict[str, int] = {}
        self._done_topics: set[str] = set()
        self._stopping = threading.Event()
        self._closing = False
        #: Set once recording has stopped for good (all written, files closed).
        self.finished = threading.Event()
        self.error: str | None = None
        self._writer: BagWriter | None = None
        self._target = ""
        self._split_index = 0
        self._files: deque[str] = deque()
        self._started = time.time()
        self._file_start = 0
        self._threads: list[threading.Thread] = []
        self.written = 0
        self.dropped = 0
        self._failure: OSError | None = None
        self._conns: dict[tuple[str, int], int] = {}
        self._headers_kept: list[dict[str, str]] = []
        #: With ``repeat_latched``: the last message of each latching (topic, publisher).
        self._latched: dict[tuple[str, str], tuple[dict[str, str], bytes]] = {}
        self._begin_write: Publisher | None = None

    # -- lifecycle ---------------------------------------------------------------------------

    def start(self) -> None:
        """Subscribe to the named topics, open the first bag, start the writer (and discovery,
        when asked).

        As ROS 1's (roscpp's ``ros::Time::now()``), messages are stamped with ROS time: with
        ``/use_sim_time`` set, the time on ``/clock``, and nothing is recorded while it reads 0.
        """
        from rosx.node.simtime import follow_sim_time  # noqa: PLC0415 - with the recording

        if follow_sim_time(self.node):
            waiter = threading.Thread(target=self._warn_without_clock, name="rosx-record-clock")
            waiter.daemon = True
            self._threads.append(waiter)
            waiter.start()
        if self.options.publish:
            from rosx.msg.codec.classes import get_message_class  # noqa: PLC0415 - message classes load on first use

            string = get_message_class("std_msgs/String")
            self._begin_write = self.node.advertise("begin_write", string, queue_size=1, latch=True)
        # ROS 1's order of the log lines: the named topics' subscriptions, then the file. What
        # arrives meanwhile waits in the queue for the writer thread.
        for topic in self.options.topics if not self.options.regex else []:
            self._subscribe(self.node.resolve(topic), named=topic)
        self._open_bag()
        writer = threading.Thread(target=self._write_loop, name="rosx-record", daemon=True)
        self._threads.append(writer)
        writer.start()
        if self.options.record_all or self.options.regex or self.options.node:
            self._discover()
            watcher = threading.Thread(target=self._watch, name="rosx-record-master", daemon=True)
            self._threads.append(watcher)
            watcher.start()

    def stop(self) -> None:
        """Stop reading, write everything received, close the bag (idempotent, any thread).

        The connections are shut first; what their reader threads had already taken in still
        reaches the callbacks (waited for, up to `DRAIN_TIMEOUT`), then the writer's queue.
        """
        self._closing = True
        subscribers = list(self._subscribers.values())
        # What had reached this host when asked to stop (read, or in each socket's buffer).
        drains = [sub.drain() for sub in subscribers]
        deadline = time.monotonic() + DRAIN_TIMEOUT
        while time.monotonic() < deadline and not all(drain.done() for drain in drains):
            time.sleep(0.01)
        for sub in subscribers:
            sub.detach()
        while time.monotonic() < deadline and not all(sub.caught_up() for sub in subscribers):
            time.sleep(0.01)
        for sub in subscribers:
            with contextlib.suppress(Exception):
                sub.unregister()
        self._stopping.set()
        with self._lock:
            self._lock.notify_all()
        for thread in self._threads:
            if thread is not threading.current_thread():
                thread.join()
        self.finished.set()

    def request_stop(self) -> None:
        """Ask the recording to stop (from a callback or a thread that must not wait)."""
        if not self._stopping.is_set():
            self._stopping.set()
            with self._lock:
                self._lock.notify_all()

    @property
    def stopping(self) -> bool:
        """Whether recording has been asked to stop."""
        return self._stopping.is_set()

    # -- subscriptions -----------------------------------------------------------------------

    def _wanted(self, topic: str, from_node: bool = False) -> bool:
        if topic in self._subscribers or topic in self._done_topics:
            return False
        if self.options.exclude is not None and self.options.exclude.fullmatch(topic):
            return False
        if self.options.record_all or from_node:
            return True
        if self.options.regex:
            return any(p.fullmatch(topic) for p in self.options.patterns)
        return topic in self.options.topics

    def _subscribe(self, topic: str, named: str = "") -> None:
        """Subscribe to ``topic``, logged by the name the user gave (``named``), as ROS 1's."""
        if topic in self._subscribers or self._stopping.is_set() or self._closing:
            return
        self.log("INFO", f"Subscribing to {named or topic}")

        def queue(msg: RawMessage, topic: str = topic) -> None:
            self._on_message(topic, msg)

        self._subscribers[topic] = self.node.subscribe(
            topic, None, queue, queue_size=None, tcp_nodelay=self.options.tcp_nodelay
        )

    def _discover(self) -> None:
        try:
            topics = [t for t, _ in self.node.master.call("getPublishedTopics", "")]
        except Exception:  # a master gone for a moment: look again later
            return
        for topic in sorted(topics):
            if self._wanted(topic):
                self._subscribe(topic)
        if self.options.node:
            for topic in self._node_subscriptions():
                if self._wanted(topic, from_node=True):
                    self._subscribe(topic)

    def _node_subscriptions(self) -> list[str]:
        master = self.node.master
        try:
            uri = str(master.call("lookupNode", self.node.resolve(self.options.node)))
        except Exception:
            return []
        try:
            subscriptions = master.node_call(uri, "getSubscriptions", timeout=2.0)
        except MasterError:
            self.log("ERROR", f"Node at: [{uri}] failed to return subscriptions.")
            return []
        except Exception:
            return []
        return [str(t) for t, _ in subscriptions]

    def _watch(self) -> None:
        while not self._stopping.wait(DISCOVERY_PERIOD):
            self._discover()

    # -- the queue ---------------------------------------------------------------------------

    def _on_message(self, topic: str, msg: RawMessage) -> None:
        stamp = self._now_ns()
        if not stamp:  # no /clock yet: ROS 1's rosbag record waits for a valid time
            return
        if self._stopping.is_set() or topic in self._done_topics:
            return
        data = msg._buff
        header = msg._connection_header  # one dict per publisher connection, never changed
        limit = self.options.limit
        with self._lock:
            if limit:
                count = self._counts.get(topic, 0)
                if count >= limit:
                    return
                self._counts[topic] = count + 1
            self._queue.append((topic, header, stamp, data))
            self._queued_bytes += len(data)
            if self.options.repeat_latched and header.get("latching") == "1":
                self._latched[topic, header.get("callerid", "")] = (header, data)
            budget = self.options.buffer_size
            while budget and self._queued_bytes > budget and len(self._queue) > 1:
                dropped = self._queue.popleft()
                self._queued_bytes -= len(dropped[3])
                self.dropped += 1
                now = time.monotonic()
                if now > self._last_warning + _WARN_PERIOD:
                    self._last_warning = now
                    self.log(
                        "WARN", "rosbag record buffer exceeded.  Dropping oldest queued message."
                    )
            self._lock.notify()
        if limit and self._counts[topic] >= limit:
            self._topic_done(topic)

    def _topic_done(self, topic: str) -> None:
        self._done_topics.add(topic)
        sub = self._subscribers.pop(topic, None)
        if sub is not None:
            threading.Thread(target=sub.unregister, daemon=True).start()
        named = {self.node.resolve(t) for t in self.options.topics}
        if not self.options.regex and named and named <= self._done_topics:
            self.request_stop()

    # -- the writer thread -------------------------------------------------------------------

    def _write_loop(self) -> None:
        last_flush = time.monotonic()
        try:
            while True:
                with self._lock:
                    if not self._queue and not self._stopping.is_set():
                        self._lock.wait(FLUSH_PERIOD / 2)
                    batch, self._queue = self._queue, deque()
                    self._queued_bytes = 0
                for topic, header, stamp, data in batch:
                    self._write(topic, header, stamp, data)
                now = time.monotonic()
                if now - last_flush >= FLUSH_PERIOD and self._writer is not None:
                    self._writer.flush()
                    last_flush = now
                self._check_wall_duration()
                if self._stopping.is_set() and not self._queue:
                    break
        except OSError as exc:
            self._failure = exc
        finally:
            self._close_bag()
            self.request_stop()

    def _connection(self, writer: BagWriter, topic: str, header: dict[str, str]) -> int:
        key = (topic, id(header))
        conn = self._conns.get(key)
        if conn is None:
            recorded = dict(header)
            recorded["topic"] = topic
            conn = self._conns[key] = writer.add_connection(topic, recorded)
            self._headers_kept.append(header)  # keeps id(header) unique while cached
        return conn

    def _write(self, topic: str, header: dict[str, str], stamp: int, data: bytes) -> None:
        writer = self._writer
        if writer is None:
            return
        if not self._file_start:  # simulated time read 0 when the bag opened
            self._file_start = stamp
        if self.options.max_duration and stamp - self._file_start > self.options.max_duration * 1e9:
            if not self.options.split:
                self.request_stop()
                return
            while stamp - self._file_start > self.options.max_duration * 1e9:
                self._next_file()
                self._file_start += int(self.options.max_duration * 1e9)
            writer = self._writer
            assert writer is not None
        writer.write(self._connection(writer, topic, header), stamp, data)
        self.written += 1
        if self.options.max_size and writer.size > self.options.max_size:
            if self.options.split:
                self._next_file()
            else:
                self.request_stop()

    def _check_wall_duration(self) -> None:
        """``--duration`` reached even without a message: on the wall clock since recording
        began, or in simulated time since the bag began."""
        limit = self.options.max_duration
        if not limit or self.options.split:
            return
        if self.node.clock.is_wallclock:
            elapsed = time.time() - self._started
        else:
            now = self._now_ns()
            elapsed = (now - self._file_start) / 1e9 if now and self._file_start else 0.0
        if elapsed > limit:
            self.request_stop()

    def _warn_without_clock(self) -> None:
        """ROS 1's warning when ``/use_sim_time`` is set and ``/clock`` has said nothing for
        `CLOCK_WAIT` s: a parameter left over from a simulator otherwise records nothing,
        silently."""
        if not self._stopping.wait(CLOCK_WAIT) and not self._now_ns():
            self.log(
                "WARN",
                "/use_sim_time set to true and no clock published.  "
                "Still waiting for valid time...",
            )

    def _now_ns(self) -> int:
        """ROS time in nanoseconds (0 in simulated time before the first /clock)."""
        clock = self.node.clock
        return time.time_ns() if clock.is_wallclock else clock.now().to_nsec()

    # -- files -------------------------------------------------------------------------------

    def _open_bag(self) -> None:
        split = self._split_index if self.options.split else None
        self._target = bag_name(self.options.prefix, self.options.append_date, split, time.time())
        self._conns = {}
        self._writer = BagWriter(
            self._target + ".active",
            compression=self.options.compression,
            chunk_threshold=self.options.chunk_size,
            opener=self._opener,
        )
        if not self._file_start:
            self._file_start = self._now_ns()
        self.log("INFO", f"Recording to '{self._target}'.")
        if self._begin_write is not None:
            self._begin_write.publish(self._begin_write.data_class(data=self._target))

    def _close_bag(self) -> None:
        writer, self._writer = self._writer, None
        if writer is None:
            self._report_failure(None)
            return
        self.log("INFO", f"Closing '{self._target}'.")
        try:
            writer.close()
        except OSError as exc:
            if writer.failed is None:
                self.log("ERROR", f"Error closing '{self._target}': {exc}")
                return
            self._failure = exc
        Path(writer.path).replace(self._target)
        self._report_failure(writer)

    def _report_failure(self, writer: BagWriter | None) -> None:
        """The one error line of a write that failed (a full disk), once the bag is closed."""
        if self._failure is None or self.error is not None:
            return
        self.error = (
            f"Error writing to '{self._target}': {self._failure.strerror or self._failure}."
        )
        self.error += "  Recording stopped"
        if writer is not None:
            self.error += f"; the bag keeps the {writer.message_count} messages written before"
        self.error += "."
        self.log("ERROR", self.error)

    def _next_file(self) -> None:
        self._close_bag()
        self._split_index += 1
        if self.options.max_splits > 0:
            self._files.append(self._target)
            if len(self._files) > self.options.max_splits:
                oldest = self._files.popleft()
                try:
                    Path(oldest).unlink()
                except OSError as exc:
                    self.log("ERROR", f"Unable to remove {oldest}: {os.strerror(exc.errno or 0)}")
        self._open_bag()
        with self._lock:
            latched = list(self._latched.items())
        writer = self._writer
        assert writer is not None
        now = self._now_ns()
        for (topic, _), (header, data) in latched:
            writer.write(self._connection(writer, topic, header), now, data)

    @property
    def target(self) -> str:
        """The name of the bag being written (without ``.active``)."""
        return self._target

    def stats(self) -> dict[str, Any]:
        """Messages written and dropped so far."""
        return {"written": self.written, "dropped": self.dropped}


__all__ = ["RecordOptions", "Recorder", "bag_name"]
