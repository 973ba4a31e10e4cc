"""What ``rosx rqt_topic`` shows of a topic, and where it gets it.

`TopicSource` is what the view asks: the topics and their types (the master's), and for each
monitored topic its `Reading` (bandwidth, rate, the latest message). `LiveTopicSource`
subscribes raw to each monitored topic (every message counted with its size, as ``rostopic
bw`` does, with `rosx.node.stats`) and decodes only the latest message when the view asks.
`fields` turns a message into the rows of its tree.
"""

from __future__ import annotations

import threading
import time
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Protocol

from rosx.graph.state import registrations
from rosx_commands.toolnode import ToolNode

if TYPE_CHECKING:
    from collections.abc import Callable

    from rosx.node import RawMessage, Subscriber
    from rosx.node.stats import BandwidthTracker, HzTracker
    from rosx_commands.context import Environment

CALLER_ID = "/rqt_topic"
#: Elements of an array shown in the tree; the rest are counted.
MAX_ITEMS = 32


@dataclass(frozen=True)
class Reading:
    """A monitored topic now: bytes per second, messages per second (None before two
    messages), how many arrived, and the latest message (None before the first)."""

    bandwidth: float | None = None
    rate: float | None = None
    count: int = 0
    message: object | None = None


@dataclass(frozen=True)
class Field:
    """One row of a message's tree: a field (or array element), its value as text (empty for
    a message or an array) and its own rows."""

    name: str
    value: str = ""
    children: tuple[Field, ...] = ()


class TopicSource(Protocol):
    """Where rqt_topic gets its topics and measures them (`LiveTopicSource`, or a test's)."""

    def topics(self) -> list[tuple[str, str]]:
        """``(topic, type)`` of every published topic, sorted; may block."""
        ...

    def monitor(self, topic: str, type_name: str) -> None:
        """Start counting ``topic``'s messages; may block."""
        ...

    def unmonitor(self, topic: str) -> None:
        """Stop counting ``topic``'s messages."""

    def reading(self, topic: str) -> Reading:
        """``topic``'s bandwidth, rate, count and latest message so far (empty if not monitored)."""

    def close(self) -> None:
        """Release the source's node."""


class _Monitored:
    def __init__(self, type_name: str) -> None:
        from rosx.node.stats import BandwidthTracker, HzTracker  # noqa: PLC0415 - the node runtime loads with the first node

        self.type_name = type_name
        self.hz: HzTracker = HzTracker(window=100)
        self.bw: BandwidthTracker = BandwidthTracker()
        self.count = 0
        self.latest: RawMessage | None = None
        self.decoded: tuple[RawMessage, object] | None = None
        self.rate: float | None = None
        self.subscriber: Subscriber | None = None


class LiveTopicSource(ToolNode):
    """A master's topics through one node of its own (``/rqt_topic_<pid>_<ms>``)."""

    def __init__(self, env: Environment, clock: Callable[[], float] = time.monotonic) -> None:
        super().__init__(env, "rqt_topic")
        self._clock = clock
        self._monitored: dict[str, _Monitored] = {}
        self._lock = threading.Lock()

    def topics(self) -> list[tuple[str, str]]:
        """``(topic, type)`` of every topic with a publisher, sorted ("unknown type" when the
        master has none); blocks on the master."""
        master = self.env.master(CALLER_ID)
        try:
            published = set(registrations(master).publishers)
            types = master.topic_types()
        finally:
            master.close()
        return sorted((t, types.get(t, "unknown type")) for t in published)

    def monitor(self, topic: str, type_name: str) -> None:
        """Subscribe to ``topic`` without decoding, counting rate, bandwidth and messages; a
        topic already monitored is left alone."""
        with self._lock:
            if topic in self._monitored:
                return
            watched = self._monitored[topic] = _Monitored(type_name)
        clock = self._clock

        def arrived(message: RawMessage) -> None:
            now = clock()
            watched.hz.arrived(topic, now)
            watched.bw.arrived(len(message._buff), now)
            watched.count += 1
            watched.latest = message

        watched.subscriber = self._started().subscribe(topic, None, arrived)

    def unmonitor(self, topic: str) -> None:
        """Unsubscribe from ``topic``; one not monitored is ignored."""
        with self._lock:
            watched = self._monitored.pop(topic, None)
        if watched is not None and watched.subscriber is not None:
            watched.subscriber.unregister()

    def reading(self, topic: str) -> Reading:
        """``topic``'s readings now: bandwidth, rate, count, and the latest message decoded once."""
        watched = self._monitored.get(topic)
        if watched is None:
            return Reading()
        found = watched.hz.rate(topic)
        if found is not None:
            watched.rate = found[0]
        return Reading(
            watched.bw.rate(self._clock()), watched.rate, watched.count, self._decoded(watched)
        )

    def _decoded(self, watched: _Monitored) -> object | None:
        latest = watched.latest
        if latest is None:
            return None
        if watched.decoded is not None and watched.decoded[0] is latest:
            return watched.decoded[1]
        from rosx.msg.codec.classes import get_message_class  # noqa: PLC0415 - message classes load on first use

        type_name = latest.type if latest.type != "*" else watched.type_name
        try:
            message: object = get_message_class(type_name, self._types())().deserialize(
                latest._buff
            )
        except Exception as error:
            message = f"cannot decode {type_name}: {error}"
        watched.decoded = (latest, message)
        return message


def fields(message: object) -> tuple[Field, ...]:
    """The rows of ``message``'s tree: one per field, nested messages and arrays with rows of
    their own (the first `MAX_ITEMS` elements)."""
    if isinstance(message, str):  # a message that could not be decoded
        return (Field("error", message),)
    return tuple(_field(name, getattr(message, name)) for name in _slots(message))


def _slots(value: object) -> list[str]:
    if hasattr(value, "secs") and hasattr(value, "nsecs"):  # time and duration, as rqt_topic
        return ["secs", "nsecs"]
    return list(getattr(value, "__slots__", ())) if hasattr(value, "_slot_types") else []


def _field(name: str, value: Any) -> Field:
    if hasattr(value, "_slot_types"):
        return Field(name, "", fields(value))
    if isinstance(value, list | tuple | bytes) or _is_array(value):
        items = list(value[:MAX_ITEMS])
        rows = tuple(_field(f"[{i}]", item) for i, item in enumerate(items))
        if len(value) > MAX_ITEMS:
            rows += (Field(f"… {len(value) - MAX_ITEMS} more"),)
        return Field(name, f"[{len(value)} items]" if len(value) else "[]", rows)
    return Field(name, _text(value))


def _is_array(value: object) -> bool:
    return type(value).__name__ == "ndarray"


def _text(value: object) -> str:
    if isinstance(value, float):
        return f"{value:.6g}"
    if isinstance(value, str):
        return repr(value)
    if hasattr(value, "item"):  # a numpy scalar
        return _text(value.item())
    return str(value)


def bytes_per_second(value: float | None) -> str:
    """A bandwidth as rqt_topic shows it: B/s, KB/s or MB/s with two decimals."""
    if value is None:
        return ""
    if value < 1000:
        return f"{value:.2f}B/s"
    if value < 1_000_000:
        return f"{value / 1000:.2f}KB/s"
    return f"{value / 1_000_000:.2f}MB/s"
