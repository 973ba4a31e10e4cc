"""The subscriber end of one TCPROS topic connection (ROS wiki ROS/TCPROS, ROS/Slave_API).

`IncomingStream.start` runs the handshake on the I/O loop: ask the publisher's Slave API for a
channel (``requestTopic``, offering UNIXROS first: `rosx.node.unixros`), connect to the Unix
socket or the host and port it names, send the subscriber's header and check the publisher's
(the same over either). Then ``on_connected`` hands the stream to its subscription's
`Receiver` thread, which calls `IncomingStream.read` whenever the socket is readable: large
reads parsed by a `FrameReader`, except a read that is exactly one whole frame (the usual one on
a topic whose subscriber keeps up), handed over as it is. A frame of 64 KiB or more is read by
``recv_into`` straight into a buffer of its own once its length is known (what a read took of
it beyond the length is copied there once), and handed over as a ``memoryview`` of it: the
kernel's copy is then the only one before the decoder's (``bytes`` fields copy once; ``numpy``
arrays read the buffer in place). The next large frame reuses that buffer when nothing views
it any more (`IncomingStream._buffer`). A reader given a locator (`rosx.msg.codec.parts.
array_locator`: every callback takes messages of a type whose large byte array is a field of
its own) takes a large frame in three parts instead (`IncomingStream._read_in_parts`): the
bytes before the array, the array read by the kernel straight into the ``bytes`` the message
will hold (``MSG_WAITALL``), the rest; the kernel's copy is then the only one. ``on_close`` is
called once, on the loop, when the stream ends. The byte and frame counts (``getBusStats``)
are written by that one thread only (and by the handshake, before it starts).

Retries follow rospy: a publisher whose XML-RPC server refuses the connection, or that refuses
the topic, is given up at once; other failures to reach it (timeouts, unreachable hosts, a
broken header exchange) are retried after 0.5 s, doubling up to 30 s, for as long as the
publisher still lists the topic in ``getPublications``. A header refused by the publisher
(``error=``) ends the stream, as does the publisher closing it: rospy does not reconnect to a
publisher that hung up, and a publisher that comes back is announced by ``publisherUpdate``.
"""

from __future__ import annotations

import asyncio
import itertools
import socket
import struct
from typing import TYPE_CHECKING, Any, Protocol

from rosx.master.client import MasterError
from rosx.msg.codec.parts import LARGE, FrameInParts
from rosx.node import unixros
from rosx.transport.errors import ConnectError, TransportError
from rosx.wire.errors import ProtocolError
from rosx.wire.framing import DEFAULT_MAX_FRAME_SIZE, DEFAULT_MAX_HEADER_SIZE, FrameReader
from rosx.wire.header import Refused, decode_header, encode_header
from rosx.wire.tcpros import check_publisher_reply

if TYPE_CHECKING:
    from collections.abc import Awaitable, Callable, Sequence

    from rosx.msg.codec.parts import Locator
    from rosx.transport.loop_thread import LoopThread

    #: A frame as a reader hands it over: its payload, whole or in parts.
    Received = bytes | memoryview | FrameInParts

    class Detacher(Protocol):
        """The receiver thread that owns a connected stream's socket."""

        def detach(self, stream: IncomingStream) -> None:
            """Stop reading ``stream``: the receiver's thread for it wakes, closes the socket and
            exits."""


#: Connection ids, unique in the process (rospy numbers its transports the same way).
connection_ids = itertools.count(1)

_CONNECT_TIMEOUT = 30.0
#: The size of a read: a read of fewer bytes took all the socket held.
RECV_SIZE = 256 * 1024
# Bytes read from one socket before the callbacks run: enough to drain a backlog.
_READ_BOUND = 8 * 1024 * 1024
# A frame at least this large is read straight into a buffer of its own (`_read_large`).
_DIRECT = 64 * 1024
_DONTWAIT = getattr(socket, "MSG_DONTWAIT", 0)
_PEEK = getattr(socket, "MSG_PEEK", 0)
_WAITALL = getattr(socket, "MSG_WAITALL", 0)
#: Bytes a reader given a locator looks at before it reads a frame: enough for the small
#: fields before an image's or a point cloud's data.
_HEAD = 4096
#: A frame's length prefix.
U32 = struct.Struct("<I")


def describe_connection(sock: socket.socket, fileno: int, remote: tuple[str, int]) -> str:
    """A topic connection as ``getBusInfo`` describes it, in rospy's shape (``rosnode info``
    parses it): over TCP, this end's port and ``remote`` host and port; over a Unix socket,
    ``remote``'s first item is the publisher's UNIXROS address (`rosx.node.unixros`)."""
    if sock.family == socket.AF_UNIX:
        return unixros.transport_info(remote[0], sock, fileno)
    return (
        f"TCPROS connection on port {sock.getsockname()[1]} to "
        f"[{remote[0]}:{remote[1]} on socket {fileno}]"
    )


class GiveUp(Exception):  # noqa: N818 - a signal between helpers, not an error for users
    """The publisher cannot be reached and should not be retried."""


def _tcpros_address(params: object) -> tuple[str, int] | None:
    """``(host, port)`` of a ``requestTopic`` answer ``["TCPROS", host, port]``; None if not one."""
    if not isinstance(params, list) or len(params) != 3 or params[0] != "TCPROS":
        return None
    host, port = params[1], params[2]
    if isinstance(port, str) and port.isascii() and port.isdigit():
        port = int(port)
    if not isinstance(host, str) or not host or type(port) is not int or not 0 < port < 0x10000:
        return None
    return host, port


class IncomingStream:
    """One subscription's connection to one publisher (see the module's contract)."""

    def __init__(
        self,
        *,
        io: LoopThread,
        topic: str,
        publisher_uri: str,
        request_header: dict[str, str],
        md5sum: str,
        caller_id: str,
        xmlrpc: Callable[..., Awaitable[Any]],  # (uri, method, *params) -> reply value
        on_connected: Callable[[IncomingStream], None],
        on_close: Callable[[IncomingStream], None],
        on_error: Callable[[str], None] | None = None,
    ) -> None:
        self.id = next(connection_ids)
        self._io = io
        self.topic = topic
        self.publisher_uri = publisher_uri
        self._request = encode_header(request_header)
        self._md5sum = md5sum
        self._caller_id = caller_id
        self._xmlrpc = xmlrpc
        self._on_connected = on_connected
        self._on_close = on_close
        self._on_error = on_error
        self.header: dict[str, str] = {}
        self.latching = False
        self.latched: Received | None = None
        self.sock: socket.socket | None = None
        #: ``TCPROS`` or ``UNIXROS`` (`rosx.node.unixros`), the publisher's address (a Unix
        #: socket's with port 0), and the connection's description, once connected.
        self.transport = "TCPROS"
        self.remote: tuple[str, int] = ("", 0)
        self.info = ""
        self._unix_failed = False
        self.fileno = -1
        self.connected = False
        self.closed = False
        self.retired = False
        self.bytes_received = 0
        self.frames_received = 0
        #: Whether a read may have taken bytes from the socket that the two counts above do not
        #: have yet: set around each read by a receiver whose drains are exact
        #: (`rosx.node.receiver.Receiver.exact`), and waited out by `Drain`.
        self.in_hand = False
        self._reader = FrameReader(DEFAULT_MAX_HEADER_SIZE)
        #: What each read reads into (`read`, or a receiver's own reads: `whole_frame`,
        #: `read_on`), and a view of it.
        self.scratch = bytearray(RECV_SIZE)
        self.view = memoryview(self.scratch)
        #: The buffer of the last large frame, kept to read the next one into (`_buffer`).
        self._spare: bytearray | None = None
        #: Whether a reader given a locator looks at the next frame before reading it (after
        #: a large frame, and at first): a topic of small frames is read as any other.
        self._look = True
        self._task: asyncio.Task[None] | None = None
        #: The receiver thread reading this stream once connected (see `Receiver`).
        self.receiver: Detacher | None = None

    # -- lifecycle (on the loop) -------------------------------------------------------------

    def start(self) -> None:
        """Begin connecting (on the loop)."""
        self._task = self._io.loop.create_task(self._run())

    def close(self) -> None:
        """End the stream (on the loop); idempotent."""
        if self.closed:
            return
        self.closed = True
        self.connected = False
        if self._task is not None and not self._task.done():
            self._task.cancel()
        if self.receiver is not None:
            self.receiver.detach(self)  # the receiver's thread closes the socket
        elif self.sock is not None:
            self.sock.close()
        self._on_close(self)

    async def _run(self) -> None:
        interval = 0.5
        try:
            while not self.closed:
                try:
                    await self._connect()
                    return
                except GiveUp as exc:
                    self._report(str(exc))
                    break
                except (OSError, ProtocolError, TimeoutError, TransportError) as exc:
                    self._drop_socket()
                    self._report(f"unable to connect to [{self.publisher_uri}]: {exc}")
                if self.retired:
                    break
                await asyncio.sleep(interval)
                interval = min(interval * 2, 30.0)
                if not await self._still_publisher():
                    break
        except asyncio.CancelledError:
            return
        if not self.connected:
            self.close()

    def retire(self) -> None:
        """The publisher is no longer listed: go on connecting and reading to the end, but
        without retries or error reports (see `rosx.node.subscription`)."""
        self.retired = True

    def _report(self, text: str) -> None:
        if self._on_error is not None and not self.closed and not self.retired:
            self._on_error(f"[{self.topic}] {text}")

    def _drop_socket(self) -> None:
        if self.sock is not None:
            self.sock.close()
            self.sock = None

    async def _still_publisher(self) -> bool:
        try:
            topics = await self._xmlrpc(self.publisher_uri, "getPublications", self._caller_id)
        except Exception:  # any failure means: no longer reachable as one
            return False
        return any(isinstance(t, list) and t and t[0] == self.topic for t in topics)

    async def _connect(self) -> None:
        loop = self._io.loop
        protocols: list[list[str]] = [["TCPROS"]]
        offer = None if self._unix_failed else unixros.offer()
        if offer is not None:
            protocols.insert(0, offer)
        try:
            params = await self._xmlrpc(
                self.publisher_uri, "requestTopic", self._caller_id, self.topic, protocols
            )
        except ConnectError as exc:
            raise GiveUp(f"publisher [{self.publisher_uri}] cannot be reached: {exc}") from None
        except MasterError as exc:
            raise GiveUp(f"requestTopic to [{self.publisher_uri}] failed: {exc}") from None
        unix = unixros.parse_reply(params) if offer is not None else None
        sock = await (self._open_unix(unix) if unix is not None else self._open_tcp(params))
        if sock is None:
            # Not reachable from here after all (another network namespace): use TCPROS.
            self._unix_failed = True
            await self._connect()
            return
        await loop.sock_sendall(sock, self._request)
        reply = await asyncio.wait_for(self._read_header(sock), _CONNECT_TIMEOUT)
        verdict = check_publisher_reply(reply, topic=self.topic, md5sum=self._md5sum)
        if isinstance(verdict, Refused):
            raise GiveUp(verdict.reason)
        self.header = verdict.header
        self.latching = verdict.latching
        self.fileno = sock.fileno()
        self.info = describe_connection(sock, self.fileno, self.remote)
        self.connected = True
        self._reader.max_frame_size = DEFAULT_MAX_FRAME_SIZE
        self._on_connected(self)

    async def _open_unix(self, address: str) -> socket.socket | None:
        """Connect to a publisher's UNIXROS socket; None if that cannot be done."""
        sock = self.sock = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
        sock.setblocking(False)
        try:
            await asyncio.wait_for(
                self._io.loop.sock_connect(sock, unixros.socket_address(address)),
                _CONNECT_TIMEOUT,
            )
        except (OSError, TimeoutError):
            self._drop_socket()
            return None
        self.transport = unixros.PROTOCOL
        self.remote = (address, 0)
        return sock

    async def _open_tcp(self, params: object) -> socket.socket:
        """Connect to the TCPROS address of a ``requestTopic`` answer."""
        address = _tcpros_address(params)
        if address is None:
            raise GiveUp(f"publisher returned invalid protocol choice: {params}")
        host, port = address
        family = socket.AF_INET6 if ":" in host else socket.AF_INET
        sock = self.sock = socket.socket(family, socket.SOCK_STREAM)
        sock.setblocking(False)
        try:
            await asyncio.wait_for(self._io.loop.sock_connect(sock, (host, port)), _CONNECT_TIMEOUT)
        except ConnectionRefusedError as exc:
            raise GiveUp(f"unable to connect to publisher at {host}:{port}: {exc}") from None
        self.transport = "TCPROS"
        self.remote = (host, port)
        return sock

    async def _read_header(self, sock: socket.socket) -> dict[str, str]:
        reader = self._reader
        while True:
            data = await self._io.loop.sock_recv(sock, 65536)
            if not data:
                raise ConnectionResetError("publisher closed the connection during the handshake")
            reader.feed(data)
            block = reader.next_frame()
            if block is not None:
                self.bytes_received += reader.buffered  # messages sent right behind it
                return decode_header(block)

    # -- the data path (on the receiver's thread) --------------------------------------------

    def read(self, locate: Locator | None = None) -> Sequence[Received] | None:
        """Wait for data, read what the socket holds (up to a bound), return complete frames.

        The socket is blocking: the first read waits; later ones (after a full buffer) take
        only what is already there. ``None`` means the stream has ended (closed, failed, or out
        of sync); the caller then closes the socket and tells the loop. With ``locate``, a
        large frame whose array it finds is read in parts (`_read_in_parts`).
        """
        sock = self.sock
        if sock is None or self.closed:
            return None
        scratch = self.scratch
        whole = not self._reader.buffered  # a read may then hold exactly one frame
        if whole and locate is not None and self._look and _PEEK and _WAITALL:
            frames = self._read_in_parts(sock, locate)
            if frames != ():
                return frames
        elif not whole:
            pending = self._reader.pending()
            if pending >= _DIRECT:
                return self._read_large(sock, pending)
            if not pending and self._reader.buffered >= 4:
                # A length out of bounds behind frames already handed over (`read_on`): the
                # stream ends now, not once the publisher sends more.
                return self.take_frames()
        try:
            size = sock.recv_into(scratch)
        except (BlockingIOError, InterruptedError):
            return ()
        except OSError:
            return None
        if whole and 4 <= size < RECV_SIZE and U32.unpack_from(scratch)[0] == size - 4:
            return (self.whole_frame(size),)
        return self.read_on(sock, size)

    def whole_frame(self, size: int) -> bytes:
        """The frame of a read of ``size`` bytes into `scratch` that is one whole frame and
        nothing else (the usual read on a topic whose subscriber keeps up), counted."""
        frame = bytes(self.view[4:size])
        self.frames_received += 1
        self.bytes_received += size
        if self.latching:
            self.latched = frame
        return frame

    def read_on(self, sock: socket.socket, size: int) -> Sequence[Received] | None:
        """The complete frames after a read of ``size`` bytes into `scratch` that was not one
        whole frame alone, with what more the socket holds already (up to a bound); ``None``:
        the stream has ended (``size`` 0) or is out of sync."""
        if size == 0:
            return None
        reader = self._reader
        if not reader.buffered and size >= 4:
            # The read begins a frame: if it is a large one that goes on after the read, the
            # rest goes straight into a buffer of its own, the read's part copied there once.
            length = U32.unpack_from(self.scratch)[0]
            if _DIRECT <= length <= reader.max_frame_size and size < 4 + length:
                return self._read_large(sock, length, size)
        view = self.view
        reader.feed(view[:size])
        total = size
        taken: list[bytes] = []
        while size == RECV_SIZE and _DONTWAIT and total < _READ_BOUND:
            if reader.pending() >= _DIRECT:
                break  # the rest of that frame goes straight into its own buffer
            # The frames read so far are taken before the next read: the reader then holds
            # at most a frame's head to join with it, never a backlog to copy again and again.
            try:
                taken += reader.frames()
            except ProtocolError:
                break  # reported below, once the frames before it are taken
            try:
                size = sock.recv_into(self.scratch, 0, _DONTWAIT)
            except (BlockingIOError, InterruptedError):
                break
            except OSError:
                return None
            if size == 0:
                break  # deliver what came; the next read sees the end
            total += size
            reader.feed(view[:size])
        frames = self.take_frames(taken)
        self.bytes_received += total  # after the frames: a drain reads the bytes first
        return frames

    @property
    def buffered(self) -> int:
        """Bytes read and not yet handed over as frames (part of a frame)."""
        return self._reader.buffered

    def _read_large(
        self, sock: socket.socket, size: int, read: int = 0
    ) -> Sequence[Received] | None:
        """Read the rest of a frame of ``size`` bytes into a buffer of its own (`_buffer`).
        Its first bytes are in `scratch` after the length prefix, ``read`` bytes read in all
        (a read that began the frame), or else held by the frame reader."""
        buff = self._buffer(size)
        with memoryview(buff) as view:
            if read:
                got = head = read - 4
                view[:got] = self.view[4:read]
            else:
                got = head = self._reader.take_pending(buff)
            while got < size:
                try:
                    count = sock.recv_into(view[got:size])
                except InterruptedError:
                    continue
                except OSError:
                    return None
                if count == 0:
                    return None
                got += count
        self.frames_received += 1
        self.bytes_received += 4 + size if read else size - head
        self._look = True  # the next may be large too: look at it before reading it
        frame = memoryview(buff) if len(buff) == size else memoryview(buff)[:size]
        if self.latching:
            self.latched = frame
        return [frame]

    def _read_in_parts(self, sock: socket.socket, locate: Locator) -> Sequence[Received] | None:
        """Read the next frame in three parts (`rosx.msg.codec.parts.FrameInParts`) if it is a
        large one whose array ``locate`` finds in its first bytes; ``()``: nothing was read,
        read it as any frame. ``None``: the stream has ended."""
        scratch = self.scratch
        view = self.view
        try:
            seen = sock.recv_into(scratch, _HEAD, _PEEK)
        except (BlockingIOError, InterruptedError):
            return ()
        except OSError:
            return None
        if seen < 4:
            return None if seen == 0 else ()
        (length,) = U32.unpack_from(scratch)
        if not _DIRECT <= length <= self._reader.max_frame_size:
            self._look = length >= _DIRECT  # small frames: read as any other from now on
            return ()
        at = locate(view[4:seen])
        if at is None and seen < _HEAD:
            # The frame's first bytes are still coming: wait for them (it has 64 KiB or more).
            try:
                seen = sock.recv_into(scratch, _HEAD, _PEEK | _WAITALL)
            except OSError:
                return ()
            at = locate(view[4:seen])
        if at is None:
            return ()
        (count,) = U32.unpack_from(scratch, 4 + at)
        rest = length - at - 4 - count
        if count < LARGE or rest < 0:
            return ()  # a small array, or a frame that does not hold it: decoded as usual
        try:
            took = sock.recv_into(scratch, 8 + at, _WAITALL)  # what was looked at: there
            if took != 8 + at:
                return None
            head = bytes(view[4 : 8 + at])
            array = self._read_exactly(sock, count)
            tail = self._read_exactly(sock, rest) if rest else b""
        except OSError:
            return None
        if array is None or tail is None:
            return None
        self.frames_received += 1
        self.bytes_received += 4 + length
        frame = FrameInParts(head, array, tail)
        if self.latching:
            self.latched = frame
        return (frame,)

    @staticmethod
    def _read_exactly(sock: socket.socket, count: int) -> bytes | None:
        """``count`` bytes read into a ``bytes`` of their own (None: the stream ended)."""
        data = sock.recv(count, _WAITALL)
        if len(data) == count:
            return data
        parts = [data]  # a signal cut the wait short: the rest, then one copy
        got = len(data)
        while got < count:
            if not data:
                return None
            data = sock.recv(count - got, _WAITALL)
            parts.append(data)
            got += len(data)
        return b"".join(parts)

    def _buffer(self, size: int) -> bytearray:
        """A buffer for a large frame of ``size`` bytes: the last one when nothing views it any
        more and it is large enough (not more than twice), else a new one.

        A new ``bytearray`` is zeroed by Python before the frame is read into it, and a fresh
        one costs page faults too: for 10 MiB both took about as long as the kernel's copy of
        the frame. A frame's buffer is still in use while anything holds a view of it (a
        queued frame, a latch, a raw subscriber's message, a numpy array read in place):
        then ``pop`` refuses to resize it, and another is made.
        """
        spare = self._spare
        if spare is not None and size <= len(spare) <= 2 * size:
            try:
                spare.append(spare.pop())
            except BufferError:
                pass
            else:
                return spare
        spare = self._spare = bytearray(size)
        return spare

    def take_frames(self, taken: list[bytes] | None = None) -> Sequence[Received] | None:
        """The complete frames buffered so far, after those ``taken`` from the reader already
        and not yet counted (``None``: the stream is out of sync, and nothing was taken)."""
        try:
            frames = self._reader.frames()
        except ProtocolError as exc:
            if not taken:
                self._report(f"dropping connection to [{self.publisher_uri}]: {exc}")
                return None
            frames = []  # the next read finds it again, after these are delivered
        if taken:
            taken += frames
            frames = taken
        if frames:
            self.frames_received += len(frames)
            if self.latching:
                self.latched = frames[-1]
        return frames

    # -- reporting ---------------------------------------------------------------------------

    def transport_info(self) -> str:
        """rospy's description of the connection (``rosnode info`` parses it)."""
        return self.info
