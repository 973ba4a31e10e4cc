"""Where tf's ROS-facing parts publish, subscribe and serve: a script's node or a given one.

tf2_ros's classes use the process's rospy node (`rosx.client`): that is what scripts get. rosx's
own tools (rviz, rqt_tf_tree, tf_echo, ``rosx sim``) run `rosx.node.Node` objects and hand one
in (``node=``). `endpoint` picks the side; both offer the same few calls, through the public
API of each layer and nothing else.
"""

from __future__ import annotations

import threading
import weakref
from typing import TYPE_CHECKING, Any, Protocol

if TYPE_CHECKING:
    from collections.abc import Callable

    from rosx.msg.codec.message import Message, ServiceDefinition
    from rosx.node import Node


class Handle(Protocol):
    """A subscription, publication or service: something to unregister."""

    def unregister(self) -> None:
        """Stop the subscription, publication or service."""


class Publishing(Handle, Protocol):
    """A handle that publishes: what tf's broadcasters need of a publisher."""

    def publish(self, msg: Any) -> None:
        """Publish ``msg`` (a ``tf2_msgs/TFMessage``)."""


class Endpoint(Protocol):
    """What tf needs of a node."""

    def name(self) -> str:
        """The node's name (``/unnamed`` before a script's ``init_node``)."""

    def ready(self) -> bool:
        """Whether the node runs (a script's before ``init_node`` does not)."""

    def is_shutdown(self) -> bool:
        """Whether the node is shutting down (a buffer's waiting lookup gives up then)."""

    def subscribe(
        self,
        topic: str,
        data_class: type[Message],
        callback: Callable[[Any], object],
        queue_size: int | None,
        tcp_nodelay: bool = False,
    ) -> Handle:
        """Subscribe to ``topic``, as rospy's ``Subscriber`` does."""

    def advertise(
        self, topic: str, data_class: type[Message], queue_size: int, latch: bool
    ) -> Publishing:
        """Advertise ``topic`` (latched for ``/tf_static``), as rospy's ``Publisher`` does."""

    def serve(
        self,
        name: str,
        service_class: type[ServiceDefinition],
        handler: Callable[[Any], object],
    ) -> Handle:
        """Provide service ``name`` (tf2_ros's buffer server), as rospy's ``Service`` does."""

    def key(self) -> object:
        """The same object for endpoints of one node (what per-node state is kept by)."""


class ScriptEndpoint:
    """The process's rospy-style node (`rosx.client`)."""

    def name(self) -> str:
        """The script's node name (rospy's ``get_name``)."""
        from rosx.client.lifecycle import get_name  # noqa: PLC0415 - only when asked

        return get_name()

    def ready(self) -> bool:
        """Whether the script has called ``init_node``."""
        from rosx.client import state  # noqa: PLC0415 - the rospy API loads only when used

        return state.CLIENT.initialized

    def is_shutdown(self) -> bool:
        """Whether the script's node is shutting down (rospy's ``is_shutdown``)."""
        from rosx.client.lifecycle import is_shutdown  # noqa: PLC0415 - the rospy API loads only when used

        return is_shutdown()

    def subscribe(
        self,
        topic: str,
        data_class: type[Message],
        callback: Callable[[Any], object],
        queue_size: int | None,
        tcp_nodelay: bool = False,
    ) -> Handle:
        """A rospy ``Subscriber`` on the script's node."""
        from rosx.client.topics import Subscriber  # noqa: PLC0415 - the rospy API loads only when used

        return Subscriber(
            topic, data_class, callback, queue_size=queue_size, tcp_nodelay=tcp_nodelay
        )

    def advertise(
        self, topic: str, data_class: type[Message], queue_size: int, latch: bool
    ) -> Publishing:
        """A rospy ``Publisher`` on the script's node."""
        from rosx.client.topics import Publisher  # noqa: PLC0415 - the rospy API loads only when used

        return Publisher(topic, data_class, queue_size=queue_size, latch=latch)

    def serve(
        self,
        name: str,
        service_class: type[ServiceDefinition],
        handler: Callable[[Any], object],
    ) -> Handle:
        """A rospy ``Service`` on the script's node."""
        from rosx.client.services import Service  # noqa: PLC0415 - the rospy API loads only when used

        return Service(name, service_class, handler)

    def key(self) -> object:
        """One key for the whole process: a script has one node."""
        return ScriptEndpoint


class NodeEndpoint:
    """A `rosx.node.Node` that rosx's code runs."""

    def __init__(self, node: Node) -> None:
        self.node = node

    def name(self) -> str:
        """The node's resolved name."""
        return self.node.name

    def ready(self) -> bool:
        """Whether the node still runs."""
        return not self.node.is_shutdown()

    def is_shutdown(self) -> bool:
        """Whether the node is shutting down or down."""
        return self.node.is_shutdown()

    def subscribe(
        self,
        topic: str,
        data_class: type[Message],
        callback: Callable[[Any], object],
        queue_size: int | None,
        tcp_nodelay: bool = False,
    ) -> Handle:
        """Subscribe on the node (`rosx.node.Node.subscribe`)."""
        return self.node.subscribe(
            topic, data_class, callback, queue_size=queue_size, tcp_nodelay=tcp_nodelay
        )

    def advertise(
        self, topic: str, data_class: type[Message], queue_size: int, latch: bool
    ) -> Publishing:
        """Advertise on the node (`rosx.node.Node.advertise`)."""
        return self.node.advertise(topic, data_class, queue_size=queue_size, latch=latch)

    def serve(
        self,
        name: str,
        service_class: type[ServiceDefinition],
        handler: Callable[[Any], object],
    ) -> Handle:
        """Provide the service on the node (`rosx.node.Node.advertise_service`)."""
        return self.node.advertise_service(name, service_class, handler)

    def key(self) -> object:
        """The node itself: per-node state is kept per `Node`."""
        return self.node


def endpoint(node: Node | None) -> Endpoint:
    """The script's node (``node`` None) or ``node``."""
    return ScriptEndpoint() if node is None else NodeEndpoint(node)


_SHARED_LOCK = threading.Lock()
_SHARED: weakref.WeakKeyDictionary[object, dict[str, Any]] = weakref.WeakKeyDictionary()


def shared(place: Endpoint, what: str, make: Callable[[], Any]) -> Any:
    """One ``what`` per node (made by ``make`` the first time): the publisher every
    broadcaster of a node uses, the ``~tf2_frames`` service of its first buffer."""
    with _SHARED_LOCK:
        mine = _SHARED.setdefault(place.key(), {})
        found = mine.get(what)
        if found is None:
            found = mine[what] = make()
        return found


def forget(place: Endpoint, what: str) -> None:
    """Drop the shared ``what`` of a node (it was unregistered)."""
    with _SHARED_LOCK:
        _SHARED.get(place.key(), {}).pop(what, None)


def message_class(name: str) -> type[Message]:
    """The class of message type ``name`` (``tf2_msgs/TFMessage``…)."""
    from rosx.msg.codec.classes import get_message_class  # noqa: PLC0415 - message classes load on first use

    return get_message_class(name)


def service_class(name: str) -> type[ServiceDefinition]:
    """The class of service type ``name`` (``tf2_msgs/FrameGraph``)."""
    from rosx.msg.codec.classes import get_service_class  # noqa: PLC0415 - message classes load on first use

    return get_service_class(name)


__all__ = [
    "Endpoint",
    "Handle",
    "NodeEndpoint",
    "Publishing",
    "ScriptEndpoint",
    "endpoint",
    "forget",
    "message_class",
    "service_class",
    "shared",
]
