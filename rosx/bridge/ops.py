"""What the rosbridge core hands its shell: events to carry out on the graph, and frames.

The core (`rosx.bridge.protocol`) decides; the shell (`rosx.bridge.graph_side` and the
WebSocket server) acts. Every event is a plain value; a `Reaction` is what one input gave:
frames for this client and events for the shell, in order.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from rosx.msg.codec.message import Message, ServiceDefinition

#: A frame to send: text (JSON) or bytes (CBOR).
Frame = str | bytes
#: A binary frame in pieces, sent one after the other (a large message's bytes go out as they
#: came, never copied into one buffer).
Pieces = tuple[bytes, ...]


@dataclass(frozen=True, slots=True)
class Advertise:
    """Publish ``topic`` with ``msg_class`` for this client (the bridge node's publisher)."""

    topic: str
    msg_class: type[Message]
    latch: bool
    queue_size: int


@dataclass(frozen=True, slots=True)
class Unadvertise:
    """This client stops publishing ``topic``."""

    topic: str


@dataclass(frozen=True, slots=True)
class Publish:
    """Publish ``message`` on ``topic``, which this client advertised."""

    topic: str
    message: Message


@dataclass(frozen=True, slots=True)
class PublishUntyped:
    """Publish ``values`` on ``topic``, which this client did not advertise: the shell finds
    the topic's type in the graph and hands it back to `Session.publish_typed`."""

    topic: str
    values: Any
    id: object


@dataclass(frozen=True, slots=True)
class Subscribe:
    """This client's first subscription to ``topic``; ``type`` None: whatever it carries."""

    topic: str
    type: str | None
    id: object


@dataclass(frozen=True, slots=True)
class Unsubscribe:
    """This client's last subscription to ``topic`` went."""

    topic: str


@dataclass(frozen=True, slots=True)
class CallService:
    """Call ``service`` with ``args``; the shell finds its type, fills the request with
    `Session.service_request_message` and answers with `Session.service_done`/``_failed``."""

    service: str
    args: Any
    id: object


@dataclass(frozen=True, slots=True)
class AdvertiseService:
    """Serve ``service`` on the graph; its calls go to this client."""

    service: str
    service_class: type[ServiceDefinition]


@dataclass(frozen=True, slots=True)
class UnadvertiseService:
    """Stop serving ``service``."""

    service: str


@dataclass(frozen=True, slots=True)
class ServiceReply:
    """The client answered call ``request_id``: ``response``, or ``error`` (result false)."""

    request_id: str
    response: Message | None
    error: str | None


@dataclass(frozen=True, slots=True)
class Close:
    """Close the connection with WebSocket close ``code`` and ``reason``."""

    code: int
    reason: str


Event = (
    Advertise
    | Unadvertise
    | Publish
    | PublishUntyped
    | Subscribe
    | Unsubscribe
    | CallService
    | AdvertiseService
    | UnadvertiseService
    | ServiceReply
    | Close
)


@dataclass(slots=True)
class Reaction:
    """Frames for the client, events for the shell and errors for the server's log, from one
    input."""

    frames: list[Frame] = field(default_factory=list)
    events: list[Event] = field(default_factory=list)
    #: What the client was told is wrong (whatever its status level), for the server's log.
    errors: list[str] = field(default_factory=list)

    def extend(self, other: Reaction) -> None:
        """Append ``other``'s frames, events and errors after this one's."""
        self.frames += other.frames
        self.events += other.events
        self.errors += other.errors


__all__ = [
    "Advertise",
    "AdvertiseService",
    "CallService",
    "Close",
    "Event",
    "Frame",
    "Pieces",
    "Publish",
    "PublishUntyped",
    "Reaction",
    "ServiceReply",
    "Subscribe",
    "Unadvertise",
    "UnadvertiseService",
    "Unsubscribe",
]
