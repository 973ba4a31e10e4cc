"""A node's publication of one topic: its subscribers' connections, its latch, its statistics.

Publishing serializes a message once, into one frame (length prefix included), and hands that
same bytes object to every subscriber's `OutgoingStream`, whatever their number. A message
holding a large byte array (an image, a point cloud) is framed in parts instead, the array
itself one of them, sent without a serialized copy (`rosx.msg.codec.parts`). A latching
publication keeps the last frame and sends it to each new subscriber right after the header
(ROS wiki ROS/TCPROS). Messages with a ``std_msgs/Header`` get the publication's sequence
number in ``header.seq``, from 1 as rospy counts (from 0, as roscpp, for a node that asks).

Subscribers of the same process are `rosx.node.local.LocalLink` objects: each gets a copy of
the message object (never serialized), queued on its subscription's receiver from the
publishing thread; the frame is built only when a socket subscriber or a latch needs it.

Within a burst the publishing thread gives way to the subscribers on this machine after each
message, so each is handled as it is published (`rosx.node.slices.Handoff`); whether a TCP
subscriber is on this machine is decided once, when it connects.

The first message of a burst runs with the CPU's caches cold: the process slept, and on a
shared host whatever ran meanwhile took the caches. Each call and each ``with`` on its way to
the socket then costs microseconds rather than nanoseconds, so the way is kept short: a type of
a fixed size packs its frame in one call (its generated ``_frame``), and locks are taken with
``acquire``/``release``, which runs about half the code of ``with`` (positional arguments too:
``acquire(blocking=False)`` parses keywords, cold, for 8 µs). Measured on a two-CPU virtual
machine, side by side with the longer way: a Twist's first ``publish`` after 10 ms asleep took
37-40 µs instead of 48-54 µs, where a bare ``send`` of the same bytes takes 16-20 µs
(bench/README.md, "A burst's first message").

`Publication.accept` runs on the I/O loop when the node's TCPROS server has accepted a
subscriber's header (`rosx.wire.tcpros.accept_subscriber`); ``publish`` runs on any thread, so
the sequence number and the byte count (``getBusStats``) change only under the publication's
lock: ``+=`` on an attribute is a read and a write, and a thread switch between the two would
lose a concurrent publisher's update.
"""

from __future__ import annotations

import ipaddress
import socket
import threading
import time
from typing import TYPE_CHECKING

from rosx.msg.codec.clone import clone
from rosx.msg.codec.message import Message as MessageBase
from rosx.msg.codec.message import serialize_frame
from rosx.msg.codec.parts import frame_parts, in_parts
from rosx.node import slices, unixros
from rosx.node.incoming import connection_ids, describe_connection
from rosx.node.local import INTRAPROCESS, LocalMessage
from rosx.node.outgoing import OutgoingStream, configure_nodelay, frame_size, unsent_probe
from rosx.wire.header import encode_header
from rosx.wire.tcpros import Publication as PublicationInfo

if TYPE_CHECKING:
    from collections.abc import Callable, Mapping
    from typing import Protocol

    from rosx.msg.codec.message import Message
    from rosx.node.local import LocalLink
    from rosx.node.outgoing import Frame
    from rosx.transport.loop_thread import LoopThread
    from rosx.wire.tcpros import SubscriberAccepted

    class PeerWatcher(Protocol):
        """What `Publication.add_watcher` takes: told of subscribers as they come and go."""

        def subscribed(self, publish_one: Callable[[Message], None]) -> None:
            """A subscriber connected; ``publish_one`` publishes to it alone."""

        def unsubscribed(self, remaining: int) -> None:
            """A subscriber left; ``remaining`` are still connected."""


_clock = time.perf_counter_ns


def _on_this_machine(sock: socket.socket, peer: str) -> bool:
    """Whether a TCP connection's peer is this machine: a loopback address, or the connection's
    own address at both ends."""
    try:
        return ipaddress.ip_address(peer).is_loopback or peer == sock.getsockname()[0]
    except (OSError, ValueError):
        return False


class SubscriberLink:
    """One subscriber connected to a publication (what ``getBusInfo`` reports)."""

    __slots__ = ("callerid", "id", "info", "nearby", "stream", "transport")

    def __init__(
        self,
        stream: OutgoingStream,
        callerid: str,
        transport: str,
        info: str,
        *,
        nearby: bool = False,
    ) -> None:
        self.id = next(connection_ids)
        self.stream = stream
        self.callerid = callerid
        #: ``TCPROS`` or ``UNIXROS`` (`rosx.node.unixros`), and the connection's description.
        self.transport = transport
        self.info = info
        #: Whether the subscriber runs on this machine (a publisher hands off to it in bursts).
        self.nearby = nearby

    @classmethod
    def connected(
        cls, stream: OutgoingStream, callerid: str, unix_address: str | None
    ) -> SubscriberLink:
        """The link of a connected socket, described as rospy describes its connections."""
        sock = stream.sock
        if sock.family == socket.AF_UNIX:
            transport, remote = unixros.PROTOCOL, (unix_address or "", 0)
            nearby = True
        else:
            transport, remote = "TCPROS", sock.getpeername()[:2]
            nearby = _on_this_machine(sock, remote[0])
        info = describe_connection(sock, stream.fileno, remote)
        return cls(stream, callerid, transport, info, nearby=nearby)

    def transport_info(self) -> str:
        """rospy's description of the connection (``rosnode info`` parses it)."""
        return self.info


class Publication:
    """Everything a node does to publish one topic (see the module's docstring)."""

    def __init__(
        self,
        io: LoopThread,
        info: PublicationInfo,
        *,
        queue_size: int | None,
        has_header: bool = False,
        first_seq: int = 1,
    ) -> None:
        self.io = io
        self.info = info
        self.topic = info.topic
        self.queue_size = queue_size
        self._has_header = has_header
        self._lock = threading.Lock()
        self.links: tuple[SubscriberLink, ...] = ()
        #: Subscribers in this process (`rosx.node.local`).
        self.local_links: tuple[LocalLink, ...] = ()
        self.latched: Frame | None = None
        #: The latched message as published in this process (None: only `latched` holds it).
        self.latched_local: LocalMessage | None = None
        #: The last ``header.seq`` given (messages with a header only); the first message gets
        #: ``first_seq``: 1 as rospy counts, 0 as roscpp does.
        self.seq = first_seq - 1
        self.bytes_published = 0
        self.closed = False
        #: The node's UNIXROS address, for describing connections (`rosx.node.unixros`).
        self.unix_address: str | None = None
        self._handoff = slices.Handoff() if slices.HANDOFF_ENABLED else None
        #: Whether any socket subscriber runs on this machine (`SubscriberLink.nearby`).
        self._nearby = False
        #: What the receivers of `local_links` were last told (`Receiver.eager`).
        self._eager = False
        #: The one subscriber's stream when it is the only one to send to and nothing keeps
        #: the frame (no latch): `publish` then sends it the shortest way.
        self._sole: OutgoingStream | None = None
        #: The last class whose frames were made whole by its ``_frame`` (`_frame_of`).
        self._whole: type | None = None
        #: Told of each subscriber that connects, with a way to publish to it alone, and of
        #: each that leaves, with how many remain (`add_watcher`; rospy's SubscribeListener).
        self._watchers: tuple[PeerWatcher, ...] = ()

    @property
    def latching(self) -> bool:
        """Whether new subscribers get the last message."""
        return self.info.latching

    def set_latching(self, latch: bool) -> None:
        """Turn latching on (rospy turns it on if any publisher of the topic latches)."""
        if latch and not self.info.latching:
            info = self.info
            with self._lock:
                self.info = PublicationInfo(
                    info.topic,
                    info.type,
                    info.md5sum,
                    info.message_definition,
                    latching=True,
                    headers=info.headers,
                )
                self._set_links(self.links)  # the latch needs every frame

    def add_headers(self, headers: Mapping[str, str]) -> None:
        """Add fields to the connection header of subscribers that connect from now on
        (rospy's ``headers=``; a field already there is replaced)."""
        with self._lock:
            info = self.info
            merged = dict(info.headers)
            merged.update({str(key): str(value) for key, value in headers.items()})
            self.info = PublicationInfo(
                info.topic,
                info.type,
                info.md5sum,
                info.message_definition,
                latching=info.latching,
                headers=tuple(merged.items()),
            )

    # -- any thread --------------------------------------------------------------------------

    def publish(self, msg: Message) -> None:
        """Queue ``msg`` for every subscriber: a copy for each one in this process, and one
        frame, serialized once, for all the others."""
        if self._has_header:
            lock = self._lock
            lock.acquire()
            try:
                self.seq += 1
                msg.header.seq = self.seq
            finally:
                lock.release()
        if self.local_links:
            self._publish_with_local(msg)
            return
        # The usual case: no subscriber in this process. The hand-off counts the message
        # after it is sent (only what follows the send depends on it): a burst's first
        # message reaches the socket with one call less, cold.
        sole = self._sole
        if sole is None:
            self._send_frame(self._frame_of(msg))
            handoff = self._handoff
            if handoff is not None and self._nearby and handoff.start():
                self._give_way()
            return
        # One subscriber, no latch: `_frame_of` and `_send_frame` inlined, the bytes counted
        # after the send. For a subscriber on this machine the clock is read once, for the
        # stream and the hand-off. A stream holding frames back after the send has had this
        # frame less than `FLOOD_GAP_NS` after the one before, in a run of more than
        # `HOLD_RUN` frames so spaced: the hand-off's run is past its burst, and the hand-off
        # only notes the time (as `Handoff.start` would, minus a call a message in a flood).
        if msg.__class__ is self._whole:
            frame: Frame = msg._frame()
            size = len(frame)
        else:
            frame = self._frame_of(msg)
            size = frame_size(frame)
        nearby = self._nearby
        now = _clock() if nearby else 0
        sole.send(frame, now)
        lock = self._lock
        lock.acquire()
        try:
            self.bytes_published += size
        finally:
            lock.release()
        handoff = self._handoff
        if handoff is not None and nearby:
            if sole.holding:
                handoff.last = now
            elif handoff.start(now=now):
                self._give_way()

    def _publish_with_local(self, msg: Message) -> None:
        burst = self._burst()
        if not self.closed:
            if self.info.latching:
                # One copy kept as the latch; every callback gets a copy of it. As for frames,
                # a subscriber attached meanwhile gets either this message or the latch.
                kept = LocalMessage(clone(msg), kept=True)
                with self._lock:
                    self.latched_local = kept
                    local = self.local_links
                for link in local:
                    link.deliver(kept)
            else:
                for link in self.local_links:
                    link.deliver(LocalMessage(clone(msg)))
            if not self.links and not self.info.latching:
                if burst:
                    self._give_way()
                return
        self._send_frame(self._frame_of(msg))
        if burst:
            self._give_way()

    def publish_frame(self, frame: bytes) -> None:
        """Queue an already serialized frame (length prefix included) for every subscriber."""
        burst = self._burst()
        if self.local_links and not self.closed:
            payload = frame[4:]
            with self._lock:
                self.latched_local = None
                local = self.local_links
            for link in local:
                link.deliver(payload)
        self._send_frame(frame)
        if burst:
            self._give_way()

    def _frame_of(self, msg: Message) -> Frame:
        """``msg`` as one frame for the sockets: whole, or in parts when it may hold a large
        byte array (`rosx.msg.codec.parts`)."""
        cls = msg.__class__
        if cls is self._whole:
            return msg._frame()
        if not isinstance(msg, MessageBase):
            return serialize_frame(msg)  # a class of another library
        if in_parts(cls):
            return frame_parts(msg)
        self._whole = cls
        return msg._frame()

    def _send_frame(self, frame: Frame) -> None:
        if self.closed:
            return
        lock = self._lock
        lock.acquire()
        try:
            if self.info.latching:
                self.latched = frame
            links = self.links
            self.bytes_published += frame_size(frame)
        finally:
            lock.release()
        for link in links:
            link.stream.send(frame)

    # A burst's messages are handled as they are published (`rosx.node.slices.Handoff`):
    # the local threads of subscribers in this process sleep on their pipes meanwhile, and
    # the publishing thread gives way to the readers of subscribers on this machine.

    def _burst(self) -> bool:
        handoff = self._handoff
        if handoff is None:
            return False
        local = self.local_links
        if not local:
            return self._nearby and handoff.start()
        burst = handoff.start(self._caught_up)
        if burst is not self._eager:
            self._eager = burst
            for link in local:
                link.receiver.eager = burst
        return burst

    def _caught_up(self) -> bool:
        return all(link.receiver.idle for link in self.local_links)

    def _give_way(self) -> None:
        # Only after `_burst` said yes, so there is a hand-off. A subscriber in this process
        # needs the GIL too.
        assert self._handoff is not None
        self._handoff.give_way(release_gil=bool(self.local_links))

    def flush(self) -> None:
        """Write the frames a flood holds back (`rosx.node.outgoing`) now, so that nothing
        published after this call, on this topic or another, reaches a subscriber before them."""
        for link in self.links:
            link.stream.flush()

    def connection_count(self) -> int:
        """Subscribers currently connected (in this process or not)."""
        return len(self.links) + len(self.local_links)

    def delivered_to(self) -> set[str]:
        """The subscribers (caller ids) that have the messages published so far.

        A socket subscriber has them once its connection carried the header and a message and
        has nothing left queued: the bytes are then with the kernel, which delivers them even
        after this process closes the connection. A subscriber of this process has them once
        one message was queued for it.
        """
        delivered = {
            link.callerid
            for link in self.links
            if link.stream.frames_sent >= 2 and not link.stream.queued
        }
        delivered.update(link.callerid for link in self.local_links if link.frames_received)
        return delivered

    def subscriber_ids(self) -> set[str]:
        """The subscribers (caller ids) connected now, over a socket or in this process."""
        return {link.callerid for link in self.links} | {link.callerid for link in self.local_links}

    def add_watcher(self, watcher: PeerWatcher) -> None:
        """Tell ``watcher`` of the subscribers that connect and leave from now on: it is
        called on the thread that saw the change, and must not wait."""
        with self._lock:
            self._watchers = (*self._watchers, watcher)

    def _publish_to(self, stream: OutgoingStream, msg: Message) -> None:
        """Send ``msg`` to one subscriber only."""
        if not self.closed:
            frame = self._frame_of(msg)
            stream.send(frame)
            with self._lock:
                self.bytes_published += frame_size(frame)

    def _subscribed(self, publish_one: Callable[[Message], None]) -> None:
        for watcher in self._watchers:
            watcher.subscribed(publish_one)

    def _unsubscribed(self) -> None:
        if self._watchers:
            remaining = self.connection_count()
            for watcher in self._watchers:
                watcher.unsubscribed(remaining)

    # -- the loop ----------------------------------------------------------------------------

    def accept(self, sock: socket.socket, accepted: SubscriberAccepted) -> SubscriberLink:
        """Serve a subscriber whose header was accepted: reply, send the latch, then stream."""
        unread = None
        if sock.family == socket.AF_UNIX:
            unixros.configure_publisher(sock)
            unread = unixros.unread_probe(sock)
        else:
            configure_nodelay(sock, bool(accepted.tcp_nodelay))
            if not self.queue_size:
                # Over TCP a flood is held back only for a queue that drops nothing. With a
                # bounded one, batches fill the kernel's buffers sooner than a message a
                # ``send`` does, and the queue then drops: a roscpp subscriber, queue_size=100,
                # lost about 10 000 of 200 000 Twists, received 0.8 times as fast.
                unread = unsent_probe(sock)
        # Over TCP a synchronous publisher (queue_size=None) of small messages waits soon for
        # a subscriber that is behind: a roscpp subscriber then has the CPU the publisher
        # would have spent running ahead (the stream paces only where it can).
        stream = OutgoingStream(
            sock, self.io, self.queue_size, self._closed_stream, unread=unread, paced=True
        )
        link = SubscriberLink.connected(stream, accepted.callerid, self.unix_address)
        with self._lock:
            stream.send(encode_header(accepted.reply))
            if self.latched is not None:
                stream.send(self.latched)
            self._set_links((*self.links, link))
        if self._watchers:
            self._subscribed(lambda msg: self._publish_to(stream, msg))
        return link

    def attach_local(self, link: LocalLink) -> None:
        """Serve a subscriber of this process: the latched message first, then every message."""
        with self._lock:
            if self.latched_local is not None:
                link.deliver(self.latched_local)
            elif self.latched is not None:
                latched = self.latched
                whole = latched if isinstance(latched, bytes) else b"".join(latched)
                link.deliver(whole[4:])
            self.local_links = (*self.local_links, link)
        if self._watchers:
            self._subscribed(lambda msg: link.deliver(LocalMessage(clone(msg))))

    def detach_local(self, link: LocalLink) -> None:
        """Stop serving a subscriber of this process."""
        with self._lock:
            before = self.local_links
            self.local_links = tuple(other for other in before if other is not link)
        if len(self.local_links) < len(before):
            self._unsubscribed()

    def _set_links(self, links: tuple[SubscriberLink, ...]) -> None:
        # Under the lock; `_nearby` and `_sole` follow the links (and the latch), read
        # without the lock when publishing.
        self.links = links
        self._nearby = any(link.nearby for link in links)
        latching = self.info.latching
        self._sole = links[0].stream if len(links) == 1 and not latching else None

    def _closed_stream(self, stream: OutgoingStream) -> None:
        with self._lock:
            before = self.links
            self._set_links(tuple(link for link in before if link.stream is not stream))
        if len(self.links) < len(before) and not self.closed:
            self._unsubscribed()

    def close(self) -> None:
        """Disconnect every subscriber; further publishing does nothing."""
        self.closed = True
        with self._lock:
            links = self.links
            self._set_links(())
            local = self.local_links
        for link in links:
            link.stream.close()
        for local_link in local:
            local_link.close()

    # -- statistics --------------------------------------------------------------------------

    def bus_stats(self) -> list[object]:
        """``[topic, messageDataSent, [[connId, bytes, numMessages, connected]...]]``."""
        return [
            self.topic,
            self.bytes_published,
            [
                [link.id, link.stream.bytes_sent, link.stream.frames_sent, not link.stream.closed]
                for link in self.links
            ]
            + [
                [link.publisher_id, link.bytes_received, link.frames_received, not link.closed]
                for link in self.local_links
            ],
        ]

    def bus_info(self) -> list[list[object]]:
        """``getBusInfo`` rows: ``[connId, destId, 'o', transport, topic, connected, info]``
        (transport ``TCPROS``, or ``INTRAPROCESS`` for a subscriber of this process)."""
        rows: list[list[object]] = [
            [link.id, link.callerid, "o", link.transport, self.topic, True, link.info]
            for link in self.links
        ]
        rows += [
            [link.publisher_id, link.callerid, "o", INTRAPROCESS, self.topic, True, INTRAPROCESS]
            for link in self.local_links
        ]
        return rows
