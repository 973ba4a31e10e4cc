"""rospy's `Publisher` and `Subscriber`, and `wait_for_message`, over `rosx.node.Node`.

As in rospy, both may be created before `init_node` (they register when the node starts, and a
``~name`` is refused then), several of them may share a topic, and callbacks run on the
topic's own thread, so a program's main loop keeps running while messages arrive. A callback
that raises is reported as rospy reports it (``bad callback: …`` and the traceback, at ERROR)
and the subscription carries on. ``publish`` accepts a message, the fields of a new one, or
keyword fields. With ``/enable_statistics`` set, subscriptions report on ``/statistics``
(`rosx.client.statistics`).
"""

from __future__ import annotations

import threading
import time
import traceback
import warnings
from typing import TYPE_CHECKING, Any

from rosx.client import state, statistics
from rosx.client.anymsg import AnyMsg
from rosx.client.exceptions import ROSException, ROSInterruptException, ROSSerializationException
from rosx.client.logs import logerr
from rosx.msg.codec.message import Message, SerializationError

if TYPE_CHECKING:
    from collections.abc import Callable

    from rosx.node import Node
    from rosx.node import Publisher as NodePublisher
    from rosx.node import Subscriber as NodeSubscriber
    from rosx.node.subscription import RawMessage

_QUEUE_SIZE_WARNING = (
    "The publisher should be created with an explicit keyword argument 'queue_size'. "
    "Please see http://wiki.ros.org/rospy/Overview/Publishers%20and%20Subscribers "
    "for more information."
)
_POLL = 0.01


def _check_topic(name: object, data_class: object) -> None:
    if not name or not isinstance(name, str):
        raise ValueError("topic name is not a non-empty string")
    if data_class is None:
        raise ValueError("topic parameter 'data_class' is not initialized")
    if not isinstance(data_class, type):
        raise ValueError(f"data_class [{data_class}] is not a class")
    if not issubclass(data_class, Message):
        raise ValueError(
            f"data_class [{data_class.__class__.__name__}] is not a message data class"
        )


def args_kwds_to_message(
    data_class: type[Message], args: tuple[Any, ...], kwds: dict[str, Any]
) -> Message:
    """The message ``publish(*args, **kwds)`` means, by rospy's rules."""
    if args and kwds:
        raise TypeError("publish() can be called with arguments or keywords, but not both.")
    if kwds:
        return data_class(**kwds)
    if len(args) == 1:
        arg = args[0]
        if getattr(arg, "_md5sum", None) == data_class._md5sum or isinstance(arg, AnyMsg):
            return arg  # type: ignore[no-any-return]
        if isinstance(arg, Message):
            slots = data_class._slot_types
            if not slots:
                raise TypeError(f"expected [] but got [{arg._type}]")
            if arg._type != slots[0]:
                raise TypeError(f"expected [{slots[0]}] but got [{arg._type}]")
    return data_class(*args)


class _Topic:
    """What publishers and subscribers share: the names, the type, the registration."""

    def __init__(self, name: str, data_class: type[Message]) -> None:
        _check_topic(name, data_class)
        self._requested_name = name
        self.resolved_name: str | None = state.CLIENT.resolve_graph_name(name)
        self.name = self.resolved_name
        self.data_class: type[Message] | None = data_class
        self.type: str | None = data_class._type
        self.md5sum: str | None = data_class._md5sum
        self._lock = threading.Lock()
        self._closed = False

    def _attach(self, node: Node) -> None:
        raise NotImplementedError

    def unregister(self) -> None:
        """Stop publishing or subscribing; further calls do nothing."""
        with self._lock:
            if self._closed:
                return
            self._closed = True
        state.CLIENT.forget(self)
        self._release()
        self.resolved_name = self.type = self.md5sum = None
        self.data_class = None

    def _release(self) -> None:
        raise NotImplementedError


class Publisher(_Topic):
    """Publishes messages of ``data_class`` on topic ``name``.

    ``queue_size`` bounds each subscriber's queue (oldest dropped); ``None`` publishes
    synchronously, with rospy's warning. ``latch`` sends the last message to late subscribers.
    """

    def __init__(
        self,
        name: str,
        data_class: type[Message],
        subscriber_listener: object = None,
        tcp_nodelay: bool = False,
        latch: bool = False,
        headers: dict[str, str] | None = None,
        queue_size: int | None = None,
    ) -> None:
        super().__init__(name, data_class)
        self.latch = latch
        self.headers = dict(headers or {})
        self.subscriber_listener = subscriber_listener
        self.queue_size = queue_size
        self.impl: NodePublisher | None = None
        if queue_size is None:
            warnings.warn(_QUEUE_SIZE_WARNING, SyntaxWarning, stacklevel=2)
        state.CLIENT.attach(self)

    def _attach(self, node: Node) -> None:
        assert self.data_class is not None
        impl = node.advertise(
            self._requested_name,
            self.data_class,
            queue_size=self.queue_size,
            latch=self.latch,
            headers=self.headers,
        )
        with self._lock:
            if not self._closed:
                self.impl = impl
                self.resolved_name = self.name = impl.name
                if self.subscriber_listener is not None:
                    impl.add_watcher(_ListenerWatcher(self, self.subscriber_listener))
                return
        impl.unregister()

    def _release(self) -> None:
        impl, self.impl = self.impl, None
        if impl is not None:
            impl.unregister()

    def publish(self, *args: Any, **kwds: Any) -> None:
        """Publish a message: an instance, or the arguments of a new one.

        Raises:
            ROSException: the publisher was unregistered, or `init_node` was not called.
            ROSSerializationException: a field holds a value that cannot be sent.
        """
        if self._closed:
            raise ROSException("publish() to an unregistered() handle")
        impl = self.impl
        if impl is None or not state.CLIENT.initialized:
            raise ROSException(
                "ROS node has not been initialized yet. Please call init_node() first"
            )
        assert self.data_class is not None
        message = args_kwds_to_message(self.data_class, args, kwds)
        try:
            if isinstance(message, AnyMsg):
                impl.publish_serialized(_raw_bytes(message))
            else:
                impl.publish(message)
        except SerializationError as exc:
            raise ROSSerializationException(str(exc)) from None

    def get_num_connections(self) -> int:
        """The number of subscribers connected."""
        impl = self.impl
        return impl.get_num_connections() if impl is not None else 0


def _raw_bytes(message: AnyMsg) -> bytes:
    buff = message.buffer()
    try:
        return bytes(buff)
    except TypeError:
        raise ROSSerializationException(
            f"AnyMsg holds a {type(buff).__name__}, not serialized bytes"
        ) from None


class Subscriber(_Topic):
    """Calls ``callback(msg)`` (or ``callback(msg, callback_args)``) for each message."""

    def __init__(
        self,
        name: str,
        data_class: type[Message],
        callback: Callable[..., object] | None = None,
        callback_args: Any = None,
        queue_size: int | None = None,
        buff_size: int = 65536,
        tcp_nodelay: bool = False,
    ) -> None:
        super().__init__(name, data_class)
        if queue_size == 0:
            raise ROSException("queue size may not be set to zero")
        if queue_size is not None and not isinstance(queue_size, int):
            raise ROSException("queue size must be an integer")
        self.callback = callback
        self.callback_args = callback_args
        self.queue_size = queue_size if queue_size is None or queue_size > 0 else None
        self.tcp_nodelay = tcp_nodelay
        self.impl: NodeSubscriber | None = None
        state.CLIENT.attach(self)

    def _attach(self, node: Node) -> None:
        data_class = self.data_class
        assert data_class is not None
        raw = issubclass(data_class, AnyMsg)
        impl = node.subscribe(
            self._requested_name,
            None if raw else data_class,
            self._deliver_raw if raw else self._deliver,
            queue_size=self.queue_size,
            tcp_nodelay=self.tcp_nodelay,
        )
        if impl.callback_count == 1:  # the node's first subscriber of the topic
            statistics.watch(impl, node.name)
        with self._lock:
            if not self._closed:
                self.impl = impl
                self.resolved_name = self.name = impl.name
                return
        impl.unregister()

    def _release(self) -> None:
        impl, self.impl = self.impl, None
        self.callback = self.callback_args = None
        if impl is not None:
            impl.unregister()

    def _deliver_raw(self, raw: RawMessage) -> None:
        self._deliver(AnyMsg.from_raw(raw._buff, raw._connection_header))

    def _deliver(self, msg: Any) -> None:
        callback, extra = self.callback, self.callback_args
        if callback is None:
            return
        try:
            if extra is not None:
                callback(msg, extra)
            else:
                callback(msg)
        except Exception:
            if not state.CLIENT.is_shutdown():
                logerr("bad callback: %s\n%s", callback, traceback.format_exc())

    def get_num_connections(self) -> int:
        """The number of publishers connected."""
        impl = self.impl
        return impl.get_num_connections() if impl is not None else 0


class SubscribeListener:
    """rospy's hook for subscriber (dis)connections (``Publisher(subscriber_listener=...)``).

    Each call runs on a thread of its own, as rospy's run on the thread of the connection.
    """

    def peer_subscribe(
        self,
        topic_name: str,
        topic_publish: Callable[..., object],
        peer_publish: Callable[[Any], object],
    ) -> None:
        """A subscriber connected: ``topic_publish`` publishes to all, ``peer_publish`` to it
        alone."""

    def peer_unsubscribe(self, topic_name: str, num_peers: int) -> None:
        """A subscriber left; ``num_peers`` remain."""


class _ListenerWatcher:
    """A `SubscribeListener` as the node's publication tells it of its subscribers."""

    def __init__(self, publisher: Publisher, listener: Any) -> None:
        self.publisher = publisher
        self.listener = listener

    def subscribed(self, publish_one: Callable[[Message], None]) -> None:
        topic = self.publisher.resolved_name
        self._run(self.listener.peer_subscribe, topic, self.publisher.publish, publish_one)

    def unsubscribed(self, remaining: int) -> None:
        self._run(self.listener.peer_unsubscribe, self.publisher.resolved_name, remaining)

    @staticmethod
    def _run(hook: Callable[..., object], *args: object) -> None:
        def call() -> None:
            try:
                hook(*args)
            except Exception:
                if not state.CLIENT.is_shutdown():
                    logerr("bad subscriber listener: %s\n%s", hook, traceback.format_exc())

        threading.Thread(target=call, name="rosx-subscribe-listener", daemon=True).start()


def wait_for_message(topic: str, topic_type: type[Message], timeout: float | None = None) -> Any:
    """Subscribe to ``topic``, receive one message, unsubscribe; return the message.

    Raises:
        ROSException: ``timeout`` seconds (or a `Duration`) passed first.
        ROSInterruptException: the node shut down meanwhile.
    """
    received: list[Any] = []
    arrived = threading.Event()

    def take(msg: Any) -> None:
        if not received:
            received.append(msg)
            arrived.set()

    seconds = None if timeout is None else getattr(timeout, "to_sec", lambda: timeout)()
    deadline = None if seconds is None else time.monotonic() + float(seconds)
    subscriber = Subscriber(topic, topic_type, take)
    try:
        while not state.CLIENT.is_shutdown() and not arrived.wait(_POLL):
            if deadline is not None and time.monotonic() >= deadline:
                raise ROSException(f"timeout exceeded while waiting for message on topic {topic}")
    finally:
        subscriber.unregister()
    if not received:
        raise ROSInterruptException("rospy shutdown")
    return received[0]


__all__ = [
    "Publisher",
    "SubscribeListener",
    "Subscriber",
    "args_kwds_to_message",
    "wait_for_message",
]
