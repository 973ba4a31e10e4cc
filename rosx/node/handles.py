"""What `Node.advertise`, `Node.subscribe` and `Node.advertise_service` hand back.

Several handles may share one topic in a node, as in rospy: publishers of a topic share its
`Publication` (and its connections); subscribers share its `Subscription` (its connections,
its queue and the threads that run their callbacks). The topic is unregistered from the master
when its last handle is.

A handle is the door to its topic or service for tools and libraries: what they need of the
connections (who is connected, who has been sent what, stopping a subscription without losing
what arrived) is a method here, so nothing above the node runtime handles links, streams or
sockets. ARCHITECTURE.md lists these methods ("New libraries stay on public doors"). Each handle
is given its release by the node that made it (a closure), so it calls nothing private of the
node.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from rosx.wire.framing import length_prefix

if TYPE_CHECKING:
    from collections.abc import Callable
    from typing import Any

    from rosx.msg.codec.message import Message
    from rosx.node.node import Node
    from rosx.node.publication import PeerWatcher, Publication
    from rosx.node.receiver import Entry
    from rosx.node.service import ServiceServer
    from rosx.node.subscription import Drain, Subscription


class Publisher:
    """Publishes one topic; `publish` may be called from any thread."""

    def __init__(
        self,
        node: Node,
        publication: Publication,
        data_class: type[Message],
        release: Callable[[], None],
    ) -> None:
        self.node = node
        self.publication = publication
        self.name = publication.topic
        self.type = publication.info.type
        self.data_class = data_class
        self.closed = False
        self._release = release

    def publish(self, msg: Message) -> None:
        """Send ``msg`` to every subscriber (serialized once). Does nothing once unregistered.

        Raises:
            TypeError: ``msg`` is not a message of the topic's type.
        """
        if msg.__class__ is not self.data_class and getattr(msg, "_type", None) != self.type:
            raise TypeError(f"expected [{self.type}] but got [{getattr(msg, '_type', type(msg))}]")
        if not self.closed:
            self.publication.publish(msg)

    def publish_serialized(self, payload: bytes) -> None:
        """Send a message already serialized in the topic's type (no length prefix)."""
        if not self.closed:
            self.publication.publish_frame(length_prefix(len(payload)) + payload)

    def flush(self) -> None:
        """Write out now what a flood of this topic holds back (small messages published
        microseconds apart go out together), so that no message published after this call,
        on any topic, reaches a subscriber first: an action's result after its feedback."""
        if not self.closed:
            self.publication.flush()

    def get_num_connections(self) -> int:
        """Subscribers currently connected."""
        return self.publication.connection_count()

    def delivered_to(self) -> set[str]:
        """The subscribers (caller ids) that have every message published so far: a socket's
        are with the kernel, which delivers them even after this node closes the connection."""
        return self.publication.delivered_to()

    def subscriber_ids(self) -> set[str]:
        """The subscribers (caller ids) connected now (an action client asks whether its
        server's node is among them)."""
        return self.publication.subscriber_ids()

    def add_watcher(self, watcher: PeerWatcher) -> None:
        """Tell ``watcher`` of the subscribers that connect and leave from now on (rospy's
        ``SubscribeListener``); it is called on the thread that saw the change."""
        self.publication.add_watcher(watcher)

    def unregister(self) -> None:
        """Stop publishing through this handle (the topic goes when its last handle does)."""
        if not self.closed:
            self.closed = True
            self._release()


class Subscriber:
    """Receives one topic into one callback, run on the topic's receiver thread."""

    def __init__(
        self,
        node: Node,
        subscription: Subscription,
        entry: Entry,
        data_class: type[Message] | None,
        release: Callable[[], None],
    ) -> None:
        self.node = node
        self.subscription = subscription
        self.entry = entry
        self.name = subscription.topic
        self.type = subscription.type
        self.data_class = data_class
        self.closed = False
        self._release = release

    def get_num_connections(self) -> int:
        """Publishers currently connected."""
        return self.subscription.connection_count()

    @property
    def callback_count(self) -> int:
        """Callbacks of the topic's subscribers in this node (this one included)."""
        return self.subscription.callback_count

    def add_monitor(self, callback: Callable[[Any], object]) -> None:
        """Have ``callback`` see every message of the topic before the subscribers' callbacks
        do; it goes with the topic's last subscriber."""
        self.subscription.add_monitor(callback)

    def publisher_ids(self) -> set[str]:
        """The publishers (caller ids) connected now."""
        return self.subscription.publisher_ids()

    def bytes_from(self, callerid: str) -> int:
        """Bytes received so far from the publisher node ``callerid``."""
        return self.subscription.bytes_from(callerid)

    def drain(self) -> Drain:
        """What has reached this host for the topic so far (read, or in a socket's buffer):
        its ``done()`` is true once the callbacks have had it all."""
        return self.subscription.drain()

    def make_drains_exact(self) -> None:
        """Have `drain` also count what a connection's thread is reading at that moment, at a
        system call more for each read: for a topic that another must not overtake."""
        self.subscription.make_drains_exact()

    def detach(self) -> None:
        """Stop reading the topic's connections; what was read still reaches the callbacks
        (`caught_up` says when), and `unregister` follows."""
        self.subscription.detach()

    def caught_up(self) -> bool:
        """Whether the callbacks have run for every message of the topic read so far (but
        those the subscriber's queue dropped, which never will be)."""
        return self.subscription.caught_up()

    def unregister(self) -> None:
        """Stop this callback (the topic is unsubscribed when its last subscriber goes)."""
        if not self.closed:
            self.closed = True
            self._release()


class ServiceHandle:
    """A service this node provides."""

    def __init__(self, node: Node, server: ServiceServer, release: Callable[[], None]) -> None:
        self.node = node
        self.server = server
        self.name = server.name
        self.uri = server.uri
        self.closed = False
        self._release = release

    def shutdown(self) -> None:
        """Stop providing the service and unregister it from the master."""
        if not self.closed:
            self.closed = True
            self._release()

    unregister = shutdown


__all__ = ["Publisher", "ServiceHandle", "Subscriber"]
