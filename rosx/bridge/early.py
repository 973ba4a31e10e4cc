"""Messages a client publishes just after advertising, kept for the subscribers still connecting.

A page advertises a topic and publishes at once (roslibjs sends both as soon as its socket
opens, as the roslibjs tutorial's ``cmdVel.publish(twist)`` does); the graph's subscribers
learn of the new publisher from the master and connect milliseconds later, so a plain
publisher sends that message to nobody. As rosbridge_suite does (its
``PublisherConsistencyListener``), the messages of a publisher's first second are kept, and
each subscriber that connects within that second is sent them.
"""

from __future__ import annotations

import threading
import time
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from collections.abc import Callable

    from rosx.msg.codec.message import Message

#: How long (seconds) after advertising a publisher keeps what it publishes, as rosbridge_suite.
WINDOW = 1.0


class EarlyMessages:
    """One publisher's first messages; a `rosx.node.Publisher` watcher (``add_watcher``)."""

    def __init__(self, clock: Callable[[], float] = time.monotonic, window: float = WINDOW) -> None:
        self._clock = clock
        self._until: float | None = clock() + window
        self._kept: list[Message] = []
        self._lock = threading.Lock()

    def _open(self) -> bool:
        """Whether the window is still open (forgets what it kept once it is not)."""
        if self._until is not None and self._clock() > self._until:
            self._until, self._kept = None, []
        return self._until is not None

    def keep(self, message: Message) -> None:
        """Note ``message``, published now (before it is published, so none is missed)."""
        if self._until is None:
            return
        with self._lock:
            if self._open():
                self._kept.append(message)

    def subscribed(self, publish_one: Callable[[Message], None]) -> None:
        """A subscriber connected: send it what was published before it came, within the window."""
        with self._lock:
            kept = list(self._kept) if self._open() else []
        for message in kept:
            publish_one(message)

    def unsubscribed(self, remaining: int) -> None:
        """A subscriber left; nothing to do."""


__all__ = ["WINDOW", "EarlyMessages"]
