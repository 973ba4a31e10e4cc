r"""`Feed`: the latest value from a worker thread, handed to widgets through their message queues.

The simulator ticks on its own thread 62.5 times a second; the graph watcher polls on another.
Neither touches a widget: they `offer` values to a feed, and the feed posts a small `FeedReady`
message to each listening widget (``post_message`` is thread-safe) unless one is already
waiting. A widget that falls behind skips stale values instead of queueing them: it `take`\s
the newest one, and never more than one message per listener is in flight.
"""

from __future__ import annotations

import threading
from typing import TYPE_CHECKING, Any, Generic, TypeVar, cast

from textual.message import Message  # noqa: TID253 - TUI code

if TYPE_CHECKING:
    from textual.message_pump import MessagePump

T = TypeVar("T")


class FeedReady(Message, bubble=False):
    """A new value waits in ``feed``."""

    def __init__(self, feed: Feed[Any]) -> None:
        super().__init__()
        self.feed = feed


class Feed(Generic[T]):
    """Newest-value mailbox from any thread to the widgets that `listen`."""

    def __init__(self, value: T | None = None) -> None:
        self._lock = threading.Lock()
        self._value = value
        self._waiting: dict[MessagePump, bool] = {}

    @property
    def value(self) -> T | None:
        """The newest value (None before the first)."""
        with self._lock:
            return self._value

    def listen(self, widget: MessagePump) -> None:
        """Send ``widget`` a `FeedReady` now (if there is a value) and after each `offer`."""
        with self._lock:
            self._waiting[widget] = self._value is not None
            if self._value is None:
                return
        widget.post_message(FeedReady(self))

    def forget(self, widget: MessagePump) -> None:
        """Stop sending ``widget`` anything."""
        with self._lock:
            self._waiting.pop(widget, None)

    def offer(self, value: T) -> None:
        """Make ``value`` the newest (from any thread) and tell the listeners."""
        with self._lock:
            self._value = value
            wake = [widget for widget, waiting in self._waiting.items() if not waiting]
            for widget in wake:
                self._waiting[widget] = True
        for widget in wake:
            if not widget.post_message(FeedReady(self)):
                self.forget(widget)

    def take(self, widget: MessagePump) -> T | None:
        """The newest value, for ``widget`` (on its thread); re-arms its next `FeedReady`."""
        with self._lock:
            if widget in self._waiting:
                self._waiting[widget] = False
            return self._value


class Follows(Generic[T]):
    """Mixin for a widget that shows the values of one feed: it listens while mounted and
    calls ``show(value)`` with the newest value each time the feed says there is one."""

    feed: Feed[T] | None

    def show(self, value: T) -> None:
        """Show ``value`` (on the widget's thread)."""
        raise NotImplementedError

    def on_mount(self) -> None:
        """Start listening to the feed (textual runs this besides a subclass's own ``on_mount``)."""
        if self.feed is not None:
            self.feed.listen(cast("MessagePump", self))

    def on_unmount(self) -> None:
        """Stop listening to the feed, so an unmounted widget is not sent its values."""
        if self.feed is not None:
            self.feed.forget(cast("MessagePump", self))

    def on_feed_ready(self, message: FeedReady) -> None:
        """Show the feed's newest value if this widget has not seen it yet."""
        if self.feed is not None and message.feed is self.feed:
            value = self.feed.take(cast("MessagePump", self))
            if value is not None:
                self.show(value)
