"""What `Node.advertise`, `Node.subscribe` and `Node.advertise_service` hand back.

Several handles may share one topic in a node, as in rospy: publishers of a topic share its
`Publication` (and its connections); subscribers share its `Subscription` (its connections,
its queue and the threads that run their callbacks). The topic is unregistered from the master
when its last handle is.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from rosx.node.publication import serialize_frame
from rosx.wire.framing import length_prefix

if TYPE_CHECKING:
    from rosx.msg.codec.message import Message
    from rosx.node.node import Node
    from rosx.node.publication import Publication
    from rosx.node.receiver import Entry
    from rosx.node.service import ServiceServer
    from rosx.node.subscription import Subscription


class Publisher:
    """Publishes one topic; `publish` may be called from any thread."""

    def __init__(self, node: Node, publication: Publication, data_class: type[Message]) -> None:
        self.node = node
        self.publication = publication
        self.name = publication.topic
        self.type = publication.info.type
        self.data_class = data_class
        self.closed = False

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

    def get_num_connections(self) -> int:
        """Subscribers currently connected."""
        return self.publication.connection_count()

    def unregister(self) -> None:
        """Stop publishing through this handle (the topic goes when its last handle does)."""
        if not self.closed:
            self.closed = True
            self.node._release_publication(self.publication)


class Subscriber:
    """Receives one topic into one callback, run on the topic's receiver thread."""

    def __init__(
        self,
        node: Node,
        subscription: Subscription,
        entry: Entry,
        data_class: type[Message] | None,
    ) -> None:
        self.node = node
        self.subscription = subscription
        self.entry = entry
        self.name = subscription.topic
        self.type = subscription.type
        self.data_class = data_class
        self.closed = False

    def get_num_connections(self) -> int:
        """Publishers currently connected."""
        return self.subscription.connection_count()

    def unregister(self) -> None:
        """Stop this callback (the topic is unsubscribed when its last subscriber goes)."""
        if not self.closed:
            self.closed = True
            self.node._release_subscriber(self)


class ServiceHandle:
    """A service this node provides."""

    def __init__(self, node: Node, server: ServiceServer) -> None:
        self.node = node
        self.server = server
        self.name = server.name
        self.uri = server.uri
        self.closed = False

    def shutdown(self) -> None:
        """Stop providing the service and unregister it from the master."""
        if not self.closed:
            self.closed = True
            self.node._release_service(self.server)

    unregister = shutdown


__all__ = ["Publisher", "ServiceHandle", "Subscriber", "serialize_frame"]
