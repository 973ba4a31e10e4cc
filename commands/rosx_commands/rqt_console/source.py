"""Where rqt_console's entries come from: `Inbox` collects them from any thread, `LiveSource`
subscribes to ``/rosout_agg`` with a node of its own and fills an inbox.

The subscriber's thread only turns each ``rosgraph_msgs/Log`` into an `Entry` and appends it;
the app takes everything waiting a few times a second (`Inbox.take`), so a burst of thousands
of records a second costs the screen one update per period, not one per record. The inbox
holds at most ``limit`` entries (the oldest go), so a paused or busy screen cannot make it
grow without bound.
"""

from __future__ import annotations

import threading
from collections import deque
from typing import TYPE_CHECKING, Any, Protocol

from rosx_commands.rqt_console.model import DEFAULT_LIMIT, Entry, location

if TYPE_CHECKING:
    from rosx_commands.context import Environment

TOPIC = "/rosout_agg"


class Inbox:
    """Entries waiting for the screen; thread-safe."""

    def __init__(self, limit: int = DEFAULT_LIMIT) -> None:
        self._lock = threading.Lock()
        self._waiting: deque[Entry] = deque(maxlen=limit)
        self.overflow = 0
        # Many records share their topic list: one tuple each, not one per record.
        self._topics: dict[tuple[str, ...], tuple[str, ...]] = {}

    def put(self, entry: Entry) -> None:
        """Queue ``entry`` from any thread; when the inbox is full the oldest is dropped and
        counted in ``overflow``."""
        with self._lock:
            if len(self._waiting) == self._waiting.maxlen:
                self.overflow += 1
            self._waiting.append(entry)

    def put_message(self, message: Any) -> None:
        """Add one ``rosgraph_msgs/Log`` message."""
        topics = tuple(message.topics)
        topics = self._topics.setdefault(topics, topics)
        stamp = message.header.stamp
        self.put(
            Entry(
                stamp.secs + stamp.nsecs * 1e-9,
                message.level,
                message.name,
                message.msg,
                topics,
                location(message.file, message.function, message.line),
            )
        )

    def take(self) -> list[Entry]:
        """Everything waiting, oldest first."""
        with self._lock:
            entries = list(self._waiting)
            self._waiting.clear()
        return entries

    def __len__(self) -> int:
        with self._lock:
            return len(self._waiting)


class ConsoleSource(Protocol):
    """What the app reads: an inbox, and a line saying where the entries come from."""

    inbox: Inbox

    def start(self) -> str:
        """Start receiving; what the status line says about it. Raises on failure."""
        ...

    def close(self) -> None:
        """Stop receiving; the inbox keeps what it holds."""


class LiveSource:
    """``/rosout_agg`` of the master at ``uri``, through an anonymous node."""

    def __init__(self, env: Environment, uri: str, limit: int = DEFAULT_LIMIT) -> None:
        self.env = env
        self.uri = uri
        self.inbox = Inbox(limit)
        self._node: Any = None

    def start(self) -> str:
        """Subscribe to ``/rosout_agg`` with an anonymous ``rqt_console`` node; returns the
        status line's text. Raises when the master cannot be reached."""
        from rosx.msg.codec.classes import get_message_class  # noqa: PLC0415 - message classes load on first use
        from rosx.names.anonymous import anonymous_node_name  # noqa: PLC0415 - name rules load only when used
        from rosx.node import Node  # noqa: PLC0415 - the node runtime loads with the first node

        node = Node(
            anonymous_node_name("rqt_console"),
            master_uri=self.uri,
            environ=self.env.environ,
            rosout_enabled=False,
        ).start()
        self._node = node
        node.subscribe(TOPIC, get_message_class("rosgraph_msgs/Log"), self.inbox.put_message)
        return f"{TOPIC} at {self.uri}"

    def close(self) -> None:
        """Shut the node down; calling it again does nothing."""
        if self._node is not None:
            self._node.shutdown("rqt_console closed")
            self._node = None
