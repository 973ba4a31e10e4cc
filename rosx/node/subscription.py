"""A node's subscription to one topic: its publisher connections and its subscribers' queues.

The contract (ROS wiki ROS/Slave_API ``publisherUpdate``, ROS/TCPROS):

* `Subscription.set_publishers` (on the loop) makes the connections match the publisher list
  the master sent: one `IncomingStream` per new publisher URI, vanished ones retired. The list
  returned by ``registerSubscriber`` is applied with ``additive=True`` when a
  ``publisherUpdate`` overtook it, so an older list never drops a newer publisher.
* A retired stream is no longer the publisher's connection (a new one is made if it comes
  back), but it is not cut: what the publisher sent before it left is still read and handed
  over, up to its end of the connection, as rospy does (it never drops a connection on
  ``publisherUpdate``). One whose publisher does not hang up is closed after `RETIRE_GRACE`
  seconds (roscpp drops it at once). So ``rostopic pub -1``'s message, sent just before it
  unregisters, arrives however late this node reads it.
* Once connected, streams are read by the subscription's `Receiver` thread, which also runs
  the callbacks of every `Subscriber` of the topic in the node (as rospy does), with one
  drop-oldest queue sized by the first subscriber's ``queue_size``.
* The last frame of each latching publisher is kept; a callback added later gets it first,
  as rospy's subscribers do.
* A publisher URI that belongs to a node of this process gets a `rosx.node.local.LocalLink`
  instead of a stream: no socket, no serialization (see `rosx.node.local`).
* A typed subscription decodes frames with its message class; a raw one (AnyMsg: type and
  md5sum ``*``) hands over `RawMessage` objects holding the bytes and what the publisher's
  header says about their type.
* Stopping without losing what has arrived (``rosbag record``): `Subscription.drain` notes what
  has reached this host so far (read, or still in each socket's buffer) and says when the
  callbacks have had it all; `Subscription.detach` then stops reading, and
  `Subscription.caught_up` says when what was read has been handled (once the connections it
  stopped have ended, so that a read in progress then is counted). A read that has taken
  bytes and not yet counted them escapes a drain unless `Subscription.make_drains_exact` was
  asked (an action client's feedback, which its result must not overtake).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from rosx.msg.codec.parts import FrameInParts, array_locator, decode_in_parts
from rosx.node import local
from rosx.node.incoming import IncomingStream
from rosx.node.receiver import Receiver
from rosx.wire.tcpros import WILDCARD, publisher_header, subscriber_header

#: Seconds a retired stream whose publisher keeps the connection open is still read.
RETIRE_GRACE = 2.0

if TYPE_CHECKING:
    import asyncio
    import socket
    from collections.abc import Awaitable, Callable
    from concurrent.futures import Executor

    from rosx.msg.codec.message import Message
    from rosx.node.incoming import Received
    from rosx.node.receiver import Decode, Entry
    from rosx.transport.loop_thread import LoopThread


class RawMessage:
    """A message kept as its serialized bytes (rospy's ``AnyMsg``).

    ``_buff`` holds the bytes; ``_type``, ``_md5sum`` and ``_message_definition`` are what the
    publisher's connection header said; ``_connection_header`` is that whole header.
    """

    __slots__ = ("_buff", "_connection_header")

    _type = WILDCARD
    _md5sum = WILDCARD

    def __init__(self, buff: bytes, connection_header: dict[str, str] | None = None) -> None:
        self._buff = buff
        self._connection_header = connection_header or {}

    @property
    def type(self) -> str:
        """The publisher's message type, e.g. ``geometry_msgs/Twist``."""
        return self._connection_header.get("type", WILDCARD)

    @property
    def md5sum(self) -> str:
        """The publisher's md5sum of the type."""
        return self._connection_header.get("md5sum", WILDCARD)

    @property
    def message_definition(self) -> str:
        """The publisher's full message definition (empty if it sent none)."""
        return self._connection_header.get("message_definition", "")

    def serialize(self, buff: Any) -> None:
        """Write the bytes as they came (so a raw message can be republished)."""
        buff.write(self._buff)

    def __len__(self) -> int:
        return len(self._buff)


def _raw(frame: Received, header: dict[str, str]) -> RawMessage:
    if isinstance(frame, FrameInParts):
        return RawMessage(frame.whole(), header)
    return RawMessage(frame if isinstance(frame, bytes) else bytes(frame), header)


def _raw_fresh(msg: RawMessage, frame: bytes) -> RawMessage:
    """`_raw` in the receiver's two lines (see `message_decoder`): ``msg`` a bare instance."""
    msg._buff = frame if frame.__class__ is bytes else bytes(frame)
    return msg


# A reader runs the two lines of a decoder itself where it can (`rosx.node.receiver`): a raw
# subscriber's too (a bridge's, a recorder's), on the same quick path as a typed one's.
setattr(_raw, "fresh", _raw_fresh)  # noqa: B010 - an attribute on a function
setattr(_raw, "instance_class", RawMessage)  # noqa: B010 - an attribute on a function


def message_decoder(cls: type[Message]) -> Callable[[Received, dict[str, str]], Message]:
    """Decode frames of ``cls``: a fresh instance per frame, ``_connection_header`` set."""
    from rosx.msg.codec.codegen import variant  # noqa: PLC0415 - generated on first use

    fresh = variant(cls, "deserialize_fresh")
    new = object.__new__
    locate = array_locator(cls)

    def decode(frame: Received, header: dict[str, str]) -> Message:
        msg: Message = fresh(new(cls), frame)
        msg._connection_header = header
        return msg

    def decode_parts(frame: Received, header: dict[str, str]) -> Message:
        if isinstance(frame, FrameInParts):
            msg = decode_in_parts(fresh, cls, frame)
        else:
            msg = fresh(new(cls), frame)
        msg._connection_header = header
        return msg

    decoder = decode if locate is None else decode_parts
    # What it makes: an in-process message of this class is handed over as a copy instead.
    setattr(decoder, "msg_class", cls)  # noqa: B010 - an attribute on a function
    # How: a reader may run the two lines of `decode` itself (`rosx.node.receiver`), and read
    # large frames in parts for it (`rosx.node.incoming`).
    setattr(decoder, "fresh", fresh)  # noqa: B010 - an attribute on a function
    setattr(decoder, "instance_class", cls)  # noqa: B010 - an attribute on a function
    setattr(decoder, "locate", locate)  # noqa: B010 - an attribute on a function
    return decoder


def _pending_bytes(sock: socket.socket | None) -> int:
    """Bytes waiting in ``sock``'s receive buffer (0 when unknown, or without a socket)."""
    if sock is None:
        return 0
    try:
        import fcntl  # noqa: PLC0415 - POSIX only; asked when a recording stops, not before
        import termios  # noqa: PLC0415 - as fcntl

        raw = fcntl.ioctl(sock.fileno(), termios.FIONREAD, b"\0\0\0\0")
    except (ImportError, OSError, ValueError):
        return 0
    return int.from_bytes(raw, "little")


class Drain:
    """What had reached this host for one subscription when it was made (`Subscription.drain`).

    `done` is true once every connection has been read that far (or has ended) and the
    callbacks have run for everything read.
    """

    def __init__(self, subscription: Subscription) -> None:
        self._subscription = subscription
        # What a stream has counted, then what its socket holds: a read between the two takes
        # bytes from the second that the first has not counted (`done` waits out such reads
        # with exact drains, `Subscription.make_drains_exact`), never counts them twice.
        self._targets = [
            (stream, stream.bytes_received + _pending_bytes(stream.sock))
            for stream in list(subscription.streams.values())
        ]

    def done(self) -> bool:
        """Whether the callbacks have had everything that had arrived."""
        # The streams first: a read counts its frames before its bytes, so `caught_up`, asked
        # after, compares every frame of the bytes seen here (counts only grow meanwhile).
        for stream, target in self._targets:
            if not stream.closed and (stream.in_hand or stream.bytes_received < target):
                return False
        return self._subscription.caught_up()


class Subscription:
    """Everything a node does to receive one topic (see the module's contract)."""

    def __init__(
        self,
        *,
        io: LoopThread,
        topic: str,
        msg_class: type[Message] | None,
        caller_id: str,
        workers: Executor,
        xmlrpc: Callable[..., Awaitable[Any]],
        queue_size: int | None = None,
        tcp_nodelay: bool = False,
        on_error: Callable[[str], None] | None = None,
    ) -> None:
        self.io = io
        self.topic = topic
        self.msg_class = msg_class
        self.type = msg_class._type if msg_class is not None else WILDCARD
        self.md5sum = msg_class._md5sum if msg_class is not None else WILDCARD
        self._caller_id = caller_id
        self._xmlrpc = xmlrpc
        self._on_error = on_error
        self._header = subscriber_header(
            callerid=caller_id,
            topic=topic,
            md5sum=self.md5sum,
            msg_type=self.type,
            message_definition=msg_class._full_text if msg_class is not None else "",
            tcp_nodelay=tcp_nodelay,
        )
        self.streams: dict[str, IncomingStream | local.LocalLink] = {}
        #: Streams of publishers no longer listed, read until they end (see the contract),
        #: and the timer that closes each one at the latest.
        self._retired: dict[IncomingStream, asyncio.TimerHandle] = {}
        #: The connections `detach` stopped.
        self._detached: list[IncomingStream | local.LocalLink] = []
        self.receiver = Receiver(
            io,
            workers,
            queue_size=queue_size,
            name=f"rosx-sub{topic}",
            on_error=self._callback_failed,
        )
        self.updates = 0
        self._monitors = 0
        #: Until this `time.monotonic` instant a ``publisherUpdate`` adds publishers and drops
        #: none (set while the nodes register again with a restarted master).
        self.keep_until = 0.0
        self.closed = False

    @staticmethod
    def decoder(
        msg_class: type[Message] | None,
    ) -> Callable[[Received, dict[str, str]], Any]:
        """How frames become what a callback receives: ``msg_class`` messages, or (``None``)
        `RawMessage` objects."""
        return _raw if msg_class is None else message_decoder(msg_class)

    # -- callbacks --------------------------------------------------------------------------

    def add(self, callback: Callable[[Any], object], decode: Decode) -> Entry:
        """Add a callback; it first gets the latched message of each latching publisher."""
        entry = self.receiver.add(callback, decode)
        self.io.call_soon(self._send_latched, entry)
        return entry

    def _send_latched(self, entry: Entry) -> None:
        for stream in self.streams.values():
            if stream.latched is not None:
                self.receiver.put(stream.latched, stream.header, entry)

    def remove(self, entry: Entry) -> None:
        """Remove a callback."""
        self.receiver.remove(entry)

    def add_monitor(self, callback: Callable[[Any], object]) -> None:
        """Have ``callback`` see every message before the subscribers' callbacks do (decoded
        as a subscriber's are). A monitor does not keep the subscription alive: it
        goes with the last subscriber."""
        entries = self.receiver.entries
        decode = entries[-1][1] if entries else self.decoder(self.msg_class)
        self.receiver.add(callback, decode, first=True)
        self._monitors += 1

    @property
    def callback_count(self) -> int:
        """Subscribers' callbacks still subscribed (monitors not counted)."""
        return len(self.receiver.entries) - self._monitors

    def publisher_ids(self) -> set[str]:
        """The publishers (caller ids) connected now."""
        return {s.header.get("callerid", "") for s in list(self.streams.values()) if s.connected}

    def bytes_from(self, callerid: str) -> int:
        """Bytes received so far from the publisher node ``callerid``'s connection."""
        return sum(
            s.bytes_received for s in self.streams.values() if s.header.get("callerid") == callerid
        )

    def drain(self) -> Drain:
        """What has reached this host so far, to wait for (`Drain.done`)."""
        return Drain(self)

    def make_drains_exact(self) -> None:
        """Have `drain` count a read that has taken bytes from a socket and not counted them
        yet, at a system call more for each read (see `rosx.node.receiver`'s contract); a
        connection already being read is, from its next message on."""
        self.receiver.exact = True

    def detach(self) -> None:
        """Stop reading every connection; what was read still reaches the callbacks."""
        streams = list(self.streams.values())
        # Those connected: one still connecting has read nothing, and may never end.
        self._detached = [stream for stream in streams if stream.connected]
        for stream in streams:
            if isinstance(stream, local.LocalLink):
                self.io.call_soon(stream.close)  # what it delivered is queued already
            else:
                self.receiver.detach(stream)

    def _detach_finished(self) -> bool:
        """Whether every connection `detach` stopped has ended: its thread has counted all it
        read (a read in progress when it was stopped included)."""
        return all(
            stream.closed if isinstance(stream, local.LocalLink) else stream.receiver is None
            for stream in self._detached  # a stream's thread lets go of it last of all
        )

    def caught_up(self) -> bool:
        """Whether the callbacks have run for every message read so far (or a bounded queue
        dropped it: dropped messages will never be handled); after `detach`, once the
        connections it stopped have ended, so that a read in progress then is counted."""
        return self._detach_finished() and self.receiver.caught_up()

    def _callback_failed(self, exc: BaseException, callback: Callable[[Any], object]) -> None:
        if self._on_error is not None:
            self._on_error(f"bad callback: {callback}\n{type(exc).__name__}: {exc}")

    # -- publishers (the loop) ---------------------------------------------------------------

    def set_publishers(self, uris: list[str], *, additive: bool = False) -> None:
        """Connect to new publishers and, unless ``additive``, drop those no longer listed."""
        if self.closed:
            return
        wanted = list(dict.fromkeys(uris))
        if not additive:
            for uri in list(self.streams):
                if uri not in wanted:
                    self._retire(self.streams.pop(uri))
        for uri in wanted:
            if uri not in self.streams and not self._connect_locally(uri):
                stream = IncomingStream(
                    io=self.io,
                    topic=self.topic,
                    publisher_uri=uri,
                    request_header=self._header,
                    md5sum=self.md5sum,
                    caller_id=self._caller_id,
                    xmlrpc=self._xmlrpc,
                    on_connected=self.receiver.attach,
                    on_close=self._on_stream_closed,
                    on_error=self._on_error,
                )
                self.streams[uri] = stream
                stream.start()

    def _connect_locally(self, uri: str) -> bool:
        found = local.publication_at(uri, self.topic)
        if found is None:
            return False
        publication, callerid = found
        info = publication.info
        if WILDCARD not in (self.md5sum, info.md5sum) and self.md5sum != info.md5sum:
            return False  # the TCPROS handshake reports the mismatch, as between processes
        link = local.LocalLink(
            publication=publication,
            receiver=self.receiver,
            callerid=self._caller_id,
            publisher_uri=uri,
            header=publisher_header(info, callerid=callerid),
            on_close=self._on_stream_closed,
        )
        self.streams[uri] = link
        link.start()
        return True

    def _retire(self, stream: IncomingStream | local.LocalLink) -> None:
        if isinstance(stream, local.LocalLink) or stream.closed:
            stream.close()  # in-process messages are queued as they are published
            return
        stream.retire()
        self._retired[stream] = self.io.loop.call_later(RETIRE_GRACE, stream.close)

    def _on_stream_closed(self, stream: IncomingStream | local.LocalLink) -> None:
        if self.streams.get(stream.publisher_uri) is stream:
            del self.streams[stream.publisher_uri]
        elif isinstance(stream, IncomingStream):
            timer = self._retired.pop(stream, None)
            if timer is not None:
                timer.cancel()

    def close(self) -> None:
        """Close every connection and stop every subscriber's thread."""
        self.closed = True
        for stream in [*self.streams.values(), *self._retired]:
            stream.close()
        self.receiver.stop()

    # -- statistics --------------------------------------------------------------------------

    def connection_count(self) -> int:
        """Publishers currently connected."""
        return sum(1 for s in self.streams.values() if s.connected)

    def bus_stats(self) -> list[object]:
        """``[topic, [[connId, bytesReceived, numMessages, dropEstimate, connected]...]]``."""
        return [
            self.topic,
            [
                [s.id, s.bytes_received, s.frames_received, -1, s.connected]
                for s in self.streams.values()
            ],
        ]

    def bus_info(self) -> list[list[object]]:
        """``getBusInfo`` rows: ``[connId, publisherUri, 'i', transport, topic, True, info]``
        (transport ``TCPROS``, ``UNIXROS`` for a rosx publisher of this machine, or
        ``INTRAPROCESS`` for a publisher of this process)."""
        return [
            [
                s.id,
                s.publisher_uri,
                "i",
                s.transport,
                self.topic,
                True,
                s.transport_info(),
            ]
            for s in self.streams.values()
            if s.connected
        ]
