"""A node's publication of one topic: its subscribers' connections, its latch, its statistics.

Publishing serializes a message once, into one frame (length prefix included), and hands that
same bytes object to every subscriber's `OutgoingStream`, whatever their number. A latching
publication keeps the last frame and sends it to each new subscriber right after the header
(ROS wiki ROS/TCPROS). Messages with a ``std_msgs/Header`` get the publication's sequence
number in ``header.seq``, as rospy does.

`Publication.accept` runs on the I/O loop when the node's TCPROS server has accepted a
subscriber's header (`rosx.wire.tcpros.accept_subscriber`); ``publish`` runs on any thread, so
the sequence number and the byte count (``getBusStats``) change only under the publication's
lock: ``+=`` on an attribute is a read and a write, and a thread switch between the two would
lose a concurrent publisher's update.
"""

from __future__ import annotations

import io
import struct
import threading
from typing import TYPE_CHECKING

from rosx.node.incoming import connection_ids
from rosx.node.outgoing import OutgoingStream, configure_nodelay
from rosx.wire.header import encode_header
from rosx.wire.tcpros import Publication as PublicationInfo

if TYPE_CHECKING:
    import socket

    from rosx.msg.codec.message import Message
    from rosx.transport.loop_thread import LoopThread
    from rosx.wire.tcpros import SubscriberAccepted

_U32 = struct.Struct("<I")
_PREFIX = b"\0\0\0\0"


def serialize_frame(msg: Message) -> bytes:
    """``msg`` in the ROS 1 wire format, as one TCPROS frame (uint32 length prefix first)."""
    buff = io.BytesIO()
    buff.write(_PREFIX)
    msg.serialize(buff)
    size = buff.tell() - 4
    buff.seek(0)
    buff.write(_U32.pack(size))
    return buff.getvalue()


class SubscriberLink:
    """One subscriber connected to a publication (what ``getBusInfo`` reports)."""

    __slots__ = ("callerid", "id", "local", "remote", "stream")

    def __init__(
        self, stream: OutgoingStream, callerid: str, local: tuple[str, int], remote: tuple[str, int]
    ) -> None:
        self.id = next(connection_ids)
        self.stream = stream
        self.callerid = callerid
        self.local = local
        self.remote = remote

    def transport_info(self) -> str:
        """rospy's description of the connection (``rosnode info`` parses it)."""
        return (
            f"TCPROS connection on port {self.local[1]} to "
            f"[{self.remote[0]}:{self.remote[1]} on socket {self.stream.fileno}]"
        )


class Publication:
    """Everything a node does to publish one topic (see the module's docstring)."""

    def __init__(
        self,
        io: LoopThread,
        info: PublicationInfo,
        *,
        queue_size: int | None,
        has_header: bool = False,
    ) -> None:
        self.io = io
        self.info = info
        self.topic = info.topic
        self.queue_size = queue_size
        self._has_header = has_header
        self._lock = threading.Lock()
        self.links: tuple[SubscriberLink, ...] = ()
        self.latched: bytes | None = None
        #: The last ``header.seq`` given (messages with a header only).
        self.seq = 0
        self.bytes_published = 0
        self.closed = False

    @property
    def latching(self) -> bool:
        """Whether new subscribers get the last message."""
        return self.info.latching

    def set_latching(self, latch: bool) -> None:
        """Turn latching on (rospy turns it on if any publisher of the topic latches)."""
        if latch and not self.info.latching:
            info = self.info
            self.info = PublicationInfo(
                info.topic, info.type, info.md5sum, info.message_definition, latching=True
            )

    # -- any thread --------------------------------------------------------------------------

    def publish(self, msg: Message) -> None:
        """Serialize ``msg`` once and queue it for every subscriber."""
        if self._has_header:
            with self._lock:
                self.seq += 1
                msg.header.seq = self.seq
        self.publish_frame(serialize_frame(msg))

    def publish_frame(self, frame: bytes) -> None:
        """Queue an already serialized frame (length prefix included) for every subscriber."""
        if self.closed:
            return
        size = len(frame)
        with self._lock:
            if self.info.latching:
                self.latched = frame
            links = self.links
            self.bytes_published += size
        for link in links:
            link.stream.send(frame)

    def connection_count(self) -> int:
        """Subscribers currently connected."""
        return len(self.links)

    # -- the loop ----------------------------------------------------------------------------

    def accept(self, sock: socket.socket, accepted: SubscriberAccepted) -> SubscriberLink:
        """Serve a subscriber whose header was accepted: reply, send the latch, then stream."""
        configure_nodelay(sock, bool(accepted.tcp_nodelay))
        local = sock.getsockname()[:2]
        remote = sock.getpeername()[:2]
        stream = OutgoingStream(sock, self.io, self.queue_size, self._closed_stream)
        link = SubscriberLink(stream, accepted.callerid, local, remote)
        with self._lock:
            stream.send(encode_header(accepted.reply))
            if self.latched is not None:
                stream.send(self.latched)
            self.links = (*self.links, link)
        return link

    def _closed_stream(self, stream: OutgoingStream) -> None:
        with self._lock:
            self.links = tuple(link for link in self.links if link.stream is not stream)

    def close(self) -> None:
        """Disconnect every subscriber; further publishing does nothing."""
        self.closed = True
        with self._lock:
            links, self.links = self.links, ()
        for link in links:
            link.stream.close()

    # -- statistics --------------------------------------------------------------------------

    def bus_stats(self) -> list[object]:
        """``[topic, messageDataSent, [[connId, bytes, numMessages, connected]...]]``."""
        return [
            self.topic,
            self.bytes_published,
            [
                [link.id, link.stream.bytes_sent, link.stream.frames_sent, not link.stream.closed]
                for link in self.links
            ],
        ]

    def bus_info(self) -> list[list[object]]:
        """``getBusInfo`` rows: ``[connId, destId, 'o', 'TCPROS', topic, connected, info]``."""
        return [
            [link.id, link.callerid, "o", "TCPROS", self.topic, True, link.transport_info()]
            for link in self.links
        ]
