"""In-process topic links: a publisher and a subscriber in one process, without a socket.

As roscpp's intra-process links: when the master names a publisher whose Slave API URI belongs
to a node of this process (any `Node` object; they register here when their servers start),
the subscription connects to that node's `Publication` directly instead of asking for a TCPROS
channel. Each message is then copied once when published (`rosx.msg.codec.clone`: the
publisher may change its message afterwards, as rospy code often does) and queued on the
subscription's `Receiver`, whose local thread runs the callbacks; nothing is serialized unless
a callback wants raw bytes. Everything else is as over a socket: the master, other processes
(``rostopic echo/hz/bw`` connect over TCPROS as before), the order of messages, latching (a
late subscriber gets the last message), the subscriber's ``queue_size`` (drop-oldest), the
connection header in ``_connection_header``. ``getBusInfo`` lists such a connection with
roscpp's transport name, ``INTRAPROCESS``.

``ROSX_INTRAPROCESS=0`` in the environment of a process makes its nodes use TCPROS among
themselves too (`ENABLED`; benchmarks compare both paths with it).

The registry and the links change on the I/O loop, except `LocalLink.deliver`, which runs on
the publishing thread.
"""

from __future__ import annotations

import os
import threading
from typing import TYPE_CHECKING, Any

from rosx.msg.codec.clone import clone
from rosx.msg.codec.message import serialize_frame
from rosx.node.incoming import connection_ids

if TYPE_CHECKING:
    from collections.abc import Callable

    from rosx.node.publication import Publication
    from rosx.node.receiver import Decode, Receiver


#: The transport name ``getBusInfo`` reports for a connection within this process (roscpp's).
INTRAPROCESS = "INTRAPROCESS"

#: Whether nodes of this process link in-process (read when a subscription connects).
ENABLED = os.environ.get("ROSX_INTRAPROCESS", "1") != "0"

_lock = threading.Lock()
_nodes: dict[str, tuple[str, Callable[[str], Publication | None]]] = {}


def register(uri: str, name: str, publications: Callable[[str], Publication | None]) -> None:
    """Make node ``name``, at Slave API ``uri``, reachable in-process (``publications(topic)``
    gives its publication of a topic)."""
    with _lock:
        _nodes[uri] = (name, publications)


def unregister(uri: str) -> None:
    """Forget the node at ``uri`` (it shuts down)."""
    with _lock:
        _nodes.pop(uri, None)


def publication_at(uri: str, topic: str) -> tuple[Publication, str] | None:
    """The publication of ``topic`` by a node of this process at ``uri``, and the node's name;
    None if there is none."""
    node = _nodes.get(uri)
    if node is None or not ENABLED:
        return None
    name, lookup = node
    publication = lookup(topic)
    if publication is None or publication.closed:
        return None
    return publication, name


class LocalMessage:
    """A message published in this process: a private copy taken when it was published.

    Each callback gets a copy of its own (`rosx.msg.codec.clone`), as each would get its own
    decoded message from a socket: the first callback takes the publish-time copy itself unless
    it is kept (a latched message), later ones a copy made before any callback runs. A callback
    whose class is not the message's (a raw ``AnyMsg`` subscriber) gets it serialized.
    """

    __slots__ = ("kept", "msg")

    def __init__(self, msg: Any, *, kept: bool = False) -> None:
        self.msg = msg
        self.kept = kept

    def message(self, decode: Decode, header: dict[str, str]) -> Any:
        """What the callback of a subscription with one callback receives."""
        msg = self.msg
        if getattr(decode, "msg_class", None) is not msg.__class__:
            return self.messages([decode], header)[0]
        if self.kept:
            msg = clone(msg)  # a latched message, kept as published
        else:
            self.kept = True  # the usual case: the callback takes the copy made at publish
        msg._connection_header = header
        return msg

    def messages(self, decoders: list[Decode], header: dict[str, str]) -> list[Any]:
        """What each of ``decoders``' callbacks receives, in order: copies made before any
        callback runs, so that none sees what another does to its message."""
        msg = self.msg
        cls = msg.__class__
        out: list[Any] = []
        frame: bytes | None = None
        for decode in decoders:
            if getattr(decode, "msg_class", None) is cls:
                copy = clone(msg) if self.kept or out else msg
                copy._connection_header = header
                out.append(copy)
            else:
                if frame is None:
                    frame = serialize_frame(msg)[4:]
                out.append(decode(frame, header))
        if not self.kept:
            self.kept = True  # handed out: a latched replay copies it
        return out


class LocalLink:
    """One in-process connection, both ends: what the publication and the subscription list."""

    def __init__(
        self,
        *,
        publication: Publication,
        receiver: Receiver,
        callerid: str,
        publisher_uri: str,
        header: dict[str, str],
        on_close: Callable[[LocalLink], None],
    ) -> None:
        #: The subscription's connection id, and the publication's.
        self.id = next(connection_ids)
        self.publisher_id = next(connection_ids)
        self.publication = publication
        self.receiver = receiver
        self.callerid = callerid
        self.publisher_uri = publisher_uri
        self.header = header
        self.latching = header.get("latching") == "1"
        self.latched: bytes | LocalMessage | None = None
        self._on_close = on_close
        self._block = publication.queue_size
        self.connected = False
        self.closed = False
        self.frames_received = 0
        self.bytes_received = 0
        #: Never: a message published in this process is counted as it is queued (as for
        #: streams, what `Drain` looks at).
        self.in_hand = False
        #: No socket (what code that handles streams and links alike may look at).
        self.sock: None = None
        #: The transport's name in ``getBusInfo`` (as for streams).
        self.transport = INTRAPROCESS

    # -- the loop ----------------------------------------------------------------------------

    def start(self) -> None:
        """Connect to the publication (its latched message comes first)."""
        self.receiver.start_local()
        self.connected = True
        self.publication.attach_local(self)

    def close(self) -> None:
        """Disconnect (idempotent); either end may call it."""
        if self.closed:
            return
        self.closed = True
        self.connected = False
        self.publication.detach_local(self)
        self._on_close(self)

    # -- the publishing thread ---------------------------------------------------------------

    def deliver(self, payload: bytes | LocalMessage) -> None:
        """Queue one message (a copy, or a frame's bytes without length prefix)."""
        if self.closed:
            return
        self.frames_received += 1
        if isinstance(payload, bytes):
            self.bytes_received += len(payload)
        if self.latching:
            self.latched = payload
        self.receiver.put_local(payload, self.header, publisher_queue=self._block)

    # -- reporting ---------------------------------------------------------------------------

    def transport_info(self) -> str:
        """roscpp's description of an intra-process connection: the transport's name."""
        return INTRAPROCESS
