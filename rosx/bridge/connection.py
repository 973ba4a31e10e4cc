"""One client of a bridge's WebSocket server: its socket, its queues and who writes them.

A connection reads on the event loop and writes from whichever thread has something for it.
The contract:

* **Reading** is the loop's: bytes go into the connection's sans-I/O protocol object
  (`websockets.server.ServerProtocol`, touched by the loop alone), which does the opening
  handshake, parses frames (a frame over the size limit is refused from its header) and
  answers pings and close frames. Complete messages wait in an inbox that a worker thread of
  the server hands to the `Handler`, one at a time and in order; a client sending faster than
  they are handled is not read until the inbox has room.
* **What waits to be written**: the protocol's own bytes (the handshake's answer, pongs, the
  closing handshake), control frames (statuses, service calls and answers: `send`, kept in
  order, at most `MAX_CONTROL`), and one queue per topic (`queue_message`) holding at most the
  subscription's ``queue_length`` messages: when a topic's queue is full its oldest message
  is dropped and counted, so a slow client never holds up the others or grows the server's
  memory. Topics take turns. A message is rendered into frames (encoded) only when it is
  taken to be written, so a message dropped for a slow client costs nothing.
* **Writing**: one thread at a time holds the writer's role (`_writing`). A message queued
  for a client whose queues are empty, after a pause (`DIRECT_GAP_NS`), is written at once by
  the thread that queued it (the topic's reader, a request's worker): no hand-off to the loop
  on the latency path. Messages that follow each other closely (a flood) are left to the loop,
  woken once, which writes up to `BATCH_FRAMES` frames with one system call (and takes turns
  with the loop's other work after `LOOP_BATCHES` batches). Frames are written by
  `rosx.bridge.wsframes`, a large payload beside its header, never copied into one buffer.
  Writes never block: what the socket does not take waits, and the loop writes it when the
  socket is writable again.
* **Closing**: a close frame (the client's, answered by the protocol, or the server's, after
  what was queued before it) ends the data frames; the server then half-closes the TCP
  connection and waits up to `CLOSE_TIMEOUT` for the client to close its side. The socket is
  closed on the loop, never while another thread writes to it; the handler hears of it last
  (`Handler.closed`, after the client's last message).
"""

from __future__ import annotations

import contextlib
import socket
import threading
import time
from collections import deque
from typing import TYPE_CHECKING, Any, Generic, TypeVar

from websockets.frames import Frame as WsFrame
from websockets.frames import Opcode
from websockets.http11 import Request
from websockets.protocol import SEND_EOF, State

from rosx.bridge import wsframes

if TYPE_CHECKING:
    from websockets.server import ServerProtocol

    from rosx.bridge.ops import Frame, Pieces
    from rosx.bridge.websocket import WebSocketServer

S = TypeVar("S")

#: Control frames (statuses, service calls and answers) a client may have waiting.
MAX_CONTROL = 10_000
#: The most frames written to a socket with one system call.
BATCH_FRAMES = 64
#: Frames taken from the queues at once while a batch is made.
TAKE = 16
#: Batches the loop writes for one connection before its other work has a turn.
LOOP_BATCHES = 4
#: A message queued at least this long after the previous one for the same client is written
#: by the thread that queued it (nanoseconds); closer ones are left to the loop, in batches.
DIRECT_GAP_NS = 1_000_000
#: Messages from a client waiting to be handled before its socket is no longer read.
INBOX_LIMIT = 64
#: Bytes read from a socket at once.
RECV_SIZE = 256 << 10
#: Seconds a client has to complete the opening handshake.
HANDSHAKE_TIMEOUT = 10.0
#: Seconds a client has to close its side once the server has closed the connection.
CLOSE_TIMEOUT = 10.0

#: In the list of bytes to write: once written, close the socket.
_FINISH = b"finish"
#: In a client's inbox: it has gone (the handler's `closed` comes after its messages).
_GONE = object()


class Connection(Generic[S]):
    """One client of ``server`` on the accepted, non-blocking ``sock``. See the module docstring.

    ``session`` is the protocol core's session (set when the handshake succeeds; the handler
    sees the connection only then) and ``lock`` guards it. ``dropped`` counts, per topic, the
    messages dropped for this client.
    """

    def __init__(self, server: WebSocketServer[S], sock: socket.socket) -> None:
        self.server = server
        self.loop = server.loop
        self.sock = sock
        self.fd = sock.fileno()
        if sock.family in (socket.AF_INET, socket.AF_INET6):
            # Each message goes out as it is written: without this a small frame waits for the
            # client's acknowledgement of the previous one, which it may delay by 40 ms.
            sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        try:
            self.remote_address: Any = sock.getpeername()
        except OSError:  # gone already: the first read says so
            self.remote_address = ("", 0)
        self.protocol: ServerProtocol = server.protocol()
        self.session: S = None  # type: ignore[assignment] # set by the handshake
        self.lock = threading.Lock()
        self.dropped: dict[str, int] = {}
        #: When the client last sent something (the loop's clock): how long it has been idle.
        self.since = self.loop.time()
        self.request: Request | None = None
        self._q = threading.Lock()  # guards everything below but the loop's own state
        self._wire: deque[bytes] = deque()
        self._control: deque[list[Frame]] = deque()
        self._topics: dict[str, deque[Any]] = {}
        self._turns: deque[str] = deque()
        self._open = False  # data frames may still be sent
        self._writing = False  # a thread holds the writer's role
        self._foreign = False  # ... and it is not the loop's
        self._finished = False
        self._closing: tuple[int, str] | None = None
        self._last_queued = 0
        self._pending: list[bytes | memoryview] = []  # the writer's: framed, not yet written
        self._inbox: deque[Any] = deque()
        self._handling = False
        self._paused = False
        self._parts: list[bytes | bytearray | memoryview] = []  # the loop's: a message so far
        self._text = False
        self._timer = self.loop.call_later(HANDSHAKE_TIMEOUT, self._finish)

    def start(self) -> None:
        """Read the client (on the loop)."""
        self.loop.add_reader(self.fd, self._readable)

    # -- what the graph side calls (any thread) -----------------------------------------------

    def send(self, frames: list[Frame]) -> None:
        """Queue control frames; written at once when nothing else is being written."""
        with self._q:
            if not self._open or len(self._control) >= MAX_CONTROL:
                return
            self._control.append(frames)
            if self._writing:
                return
            self._writing = self._foreign = True
        self._flush(on_loop=False)

    def queue_message(self, topic: str, message: Any, bound: int) -> bool:
        """Queue a message of ``topic``, keeping at most ``bound`` of the topic waiting;
        True if the oldest was dropped for it."""
        stamp = time.monotonic_ns()
        with self._q:
            if not self._open:
                return False
            gap, self._last_queued = stamp - self._last_queued, stamp
            if (
                gap >= DIRECT_GAP_NS
                and not self._writing
                and not self._turns
                and not self._control
                and not self._wire
            ):
                # Nothing waits and nothing is being written, after a pause: this thread
                # writes the message now, without queueing it.
                self._writing = self._foreign = True
                direct = True
            else:
                direct = dropped = False
                queue = self._topics.get(topic)
                if queue is None or queue.maxlen != max(1, bound):
                    queue = self._topics[topic] = deque(queue or (), maxlen=max(1, bound))
                if len(queue) == queue.maxlen:
                    self.dropped[topic] = self.dropped.get(topic, 0) + 1
                    dropped = True
                elif not queue:
                    self._turns.append(topic)
                queue.append(message)
                if self._writing:
                    return dropped
                self._writing = True
        if direct:
            self._write_now(message)
            return False
        self.loop.call_soon_threadsafe(self._resume)
        return dropped

    def close(self, code: int, reason: str) -> None:
        """Close the connection with ``code`` once what is queued before it has been sent."""
        with self._q:
            if self._closing is not None or not self._open:
                return
            self._closing = (code, reason)
            if self._writing:
                return
            self._writing = True
        self.loop.call_soon_threadsafe(self._resume)

    def dropped_total(self) -> int:
        """Messages dropped for this client so far, all topics together."""
        return sum(self.dropped.values())

    def busy(self) -> bool:
        """Whether anything waits to be written or handled for this client."""
        return bool(self._writing or self._inbox or self._turns or self._control)

    # -- writing (the thread holding the writer's role) ----------------------------------------

    def _resume(self) -> None:
        with self._q:
            self._foreign = False
        self._flush(on_loop=True)

    def _write_now(self, message: Any) -> None:
        """Write one message at once (holding the writer's role, nothing else waiting)."""
        pending = self._pending
        with self.lock:
            frames = self.server.handler.render(self.session, message)
        for frame in frames:
            pending += wsframes.wire(frame)
        if pending and not self._write(pending, on_loop=False):
            return
        with self._q:
            done = not (self._wire or self._control or self._turns or self._closing)
            if done:
                self._writing = self._foreign = False
                finished = self._finished
        if not done:
            self._flush(on_loop=False)  # whatever came meanwhile
        elif finished:  # the loop finished the connection while this thread wrote
            self.loop.call_soon_threadsafe(self._finish)

    def _flush(self, on_loop: bool) -> None:
        """Write what waits, holding the writer's role; give the role back, or pass it to the
        loop (more waits) or to the socket's writable callback (the socket is full)."""
        batches = 0
        pending = self._pending
        while True:
            end = self._fill(pending)
            if pending and not self._write(pending, on_loop):
                return
            if end is SEND_EOF:
                self._shut_writing()
                if on_loop:
                    self._wait_for_close()
                else:
                    self.loop.call_soon_threadsafe(self._wait_for_close)
            elif end is _FINISH:
                self._release(finish=True, on_loop=on_loop)
                return
            batches += 1
            with self._q:
                more = bool(self._wire or (self._open and (self._control or self._turns)))
                closing = self._open and self._closing is not None and not self._control
                if not more and not closing:
                    self._writing = self._foreign = False
                    finished = self._finished
                    break
                if not closing and on_loop and batches < LOOP_BATCHES:
                    continue
            # More waits, or the server's close frame is due: the loop goes on, in a turn of
            # its own (the protocol object is the loop's).
            if on_loop:
                self.loop.call_soon(self._resume)
            else:
                self.loop.call_soon_threadsafe(self._resume)
            if closing and on_loop:
                self._send_close()
            return
        if finished:  # the loop finished the connection while this thread wrote
            self.loop.call_soon_threadsafe(self._finish)

    def _fill(self, pending: list[bytes | memoryview]) -> bytes | None:
        """Frame what waits into ``pending``, up to a batch; returns `SEND_EOF` or `_FINISH`
        when the protocol's bytes reach the end of the connection."""
        end: bytes | None = None
        count = len(pending)
        while count < BATCH_FRAMES:
            controls: list[list[Frame]] = []
            messages: list[Any] = []
            with self._q:
                wire = self._wire
                while wire:
                    data = wire.popleft()
                    if data is SEND_EOF or data is _FINISH:
                        end = data
                        wire.clear()
                        break
                    pending.append(data)
                    count += 1
                if end is not None or not self._open:
                    return end
                control, turns, topics = self._control, self._turns, self._topics
                taken = 0
                while control and taken < TAKE:
                    controls.append(control.popleft())
                    taken += 1
                while turns and taken < TAKE:
                    topic = turns.popleft()
                    queue = topics.get(topic)
                    if not queue:
                        continue
                    messages.append(queue.popleft())
                    taken += 1
                    if queue:
                        turns.append(topic)
            if not taken:
                return None
            frames: list[Frame | Pieces] = [frame for group in controls for frame in group]
            if messages:
                render, session = self.server.handler.render, self.session
                with self.lock:  # rendered here, only if it is sent
                    for message in messages:
                        frames += render(session, message)
            for frame in frames:
                pending += wsframes.wire(frame)
            count += len(frames)
        return end

    def _write(self, pending: list[bytes | memoryview], on_loop: bool) -> bool:
        """Write ``pending``; True when all of it went. Otherwise the rest waits, and the
        writer's role passes to the socket's writable callback (or the connection is lost)."""
        try:
            sent = _sendmsg(self.sock, pending)
        except (BlockingIOError, InterruptedError):
            sent = 0
        except OSError:
            pending.clear()
            self._release(finish=True, on_loop=on_loop)
            return False
        index = 0
        while index < len(pending) and sent >= len(pending[index]):
            sent -= len(pending[index])
            index += 1
        del pending[:index]
        if not pending:
            return True
        if sent:
            pending[0] = memoryview(pending[0])[sent:]
        if on_loop:
            self._wait_writable()
        else:
            self.loop.call_soon_threadsafe(self._wait_writable)
        return False

    def _wait_writable(self) -> None:
        with self._q:
            self._foreign = False
            finished = self._finished
        if finished:
            self._finish()
        else:
            self.loop.add_writer(self.fd, self._writable)

    def _writable(self) -> None:
        self.loop.remove_writer(self.fd)
        self._flush(on_loop=True)

    def _release(self, *, finish: bool, on_loop: bool) -> None:
        with self._q:
            self._writing = self._foreign = False
            self._open = False
        if finish:
            if on_loop:
                self._finish()
            else:
                self.loop.call_soon_threadsafe(self._finish)

    def _shut_writing(self) -> None:
        with contextlib.suppress(OSError):
            self.sock.shutdown(socket.SHUT_WR)

    # -- the protocol object (on the loop) -------------------------------------------------------

    def _readable(self) -> None:
        try:
            data = self.sock.recv(RECV_SIZE)
        except (BlockingIOError, InterruptedError):
            return
        except OSError:
            self._finish()
            return
        protocol = self.protocol
        if data:
            protocol.receive_data(data)
            self.since = self.loop.time()
        else:
            protocol.receive_eof()
        for event in protocol.events_received():
            if isinstance(event, Request):
                self._handshake(event)
            elif isinstance(event, WsFrame):
                self._frame(event)
        self._put_wire(protocol.data_to_send(), finish=not data)

    def _handshake(self, request: Request) -> None:
        protocol, handler = self.protocol, self.server.handler
        refusal = handler.refuse(request)
        response = protocol.accept(request) if refusal is None else protocol.reject(*refusal)
        protocol.send_response(response)
        if protocol.state is not State.OPEN:
            return
        self._timer.cancel()
        self.request = request
        self.session = handler.session(self)
        with self._q:
            self._open = True
        self._put_wire(protocol.data_to_send())  # the answer before anything the handler sends
        self.server.opened(self)

    def _frame(self, frame: WsFrame) -> None:
        opcode = frame.opcode
        if opcode is Opcode.TEXT or opcode is Opcode.BINARY:
            self._text = opcode is Opcode.TEXT
            self._parts = [frame.data]
        elif opcode is Opcode.CONT:
            self._parts.append(frame.data)
        else:
            return  # pings are answered by the protocol, close frames end the data frames
        if not frame.fin:
            return
        data = b"".join(self._parts)
        self._parts = []
        if not self._text:
            self._deliver(data)
            return
        try:
            self._deliver(data.decode())
        except UnicodeDecodeError as exc:
            self.protocol.fail(1007, f"invalid UTF-8 at position {exc.start}")

    def _put_wire(self, data: list[bytes], *, finish: bool = False) -> None:
        """Queue bytes of the protocol (and, with ``finish``, the socket's end after them)."""
        if self.protocol.state is not State.OPEN:
            for index, chunk in enumerate(data):
                if self.session is not None and wsframes.closes_with(
                    chunk, wsframes.MESSAGE_TOO_BIG
                ):
                    reason = wsframes.close_reason(chunk)
                    status = self.server.handler.oversized(self.session, reason)
                    if status is not None:
                        data[index:index] = wsframes.wire(status)
                    break
        if finish:
            data.append(_FINISH)
        if not data:
            return
        with self._q:
            if self.protocol.state is not State.OPEN:
                self._open = False
            self._wire.extend(data)
            if self._writing:
                return
            self._writing = True
        self._flush(on_loop=True)

    def _send_close(self) -> None:
        with self._q:
            closing = self._closing
        if closing is not None and self.protocol.state is State.OPEN:
            self.protocol.send_close(*closing)
            self._wait_for_close()
            self._put_wire(self.protocol.data_to_send())

    def _wait_for_close(self) -> None:
        """Give the client `CLOSE_TIMEOUT` to close its side (the server has ended its own)."""
        self._timer.cancel()
        if not self._finished:
            self._timer = self.loop.call_later(CLOSE_TIMEOUT, self._finish)

    def abort(self, code: int, reason: str) -> None:
        """Close at once, with a close frame if nothing is half written (on the loop)."""
        with self._q:
            quiet = not self._writing and not self._pending
        if quiet and self.protocol.state is State.OPEN:
            self.protocol.send_close(code, reason)
            for data in self.protocol.data_to_send():
                try:
                    self.sock.send(data)
                except OSError:
                    break
        self._finish()

    # -- the handler's side: messages in order, on a worker ------------------------------------

    def _deliver(self, item: object) -> None:
        with self._q:
            self._inbox.append(item)
            start = not self._handling
            self._handling = True
            pause = item is not _GONE and len(self._inbox) >= INBOX_LIMIT and not self._paused
            if pause:
                self._paused = True
        if pause:
            self.loop.remove_reader(self.fd)
        if start:
            with contextlib.suppress(RuntimeError):  # the server is closing
                self.server.pool.submit(self._handle)

    def _handle(self) -> None:
        handler = self.server.handler
        while True:
            with self._q:
                if not self._inbox:
                    self._handling = False
                    resume, self._paused = self._paused, False
                    break
                item = self._inbox.popleft()
            if item is _GONE:
                handler.closed(self)
            else:
                handler.receive(self, item)
        if resume:
            self.loop.call_soon_threadsafe(self._resume_reading)

    def _resume_reading(self) -> None:
        if not self._finished:
            self.loop.add_reader(self.fd, self._readable)

    # -- the end (on the loop) -------------------------------------------------------------------

    def _finish(self) -> None:
        """Close the socket (once no other thread writes to it) and tell the handler."""
        with self._q:
            first = not self._finished
            self._finished = True
            self._open = False
            self._control.clear()
            self._topics.clear()
            self._turns.clear()
            foreign = self._writing and self._foreign
        if first:
            self._timer.cancel()
            self.loop.remove_reader(self.fd)
            self.loop.remove_writer(self.fd)
            was_open = self.server.forget(self)
            if was_open:
                self._deliver(_GONE)
        if foreign:
            return  # the writing thread sees `_finished` and calls again
        if self.sock.fileno() >= 0:
            self.sock.close()


def _sendmsg(sock: socket.socket, buffers: list[bytes | memoryview]) -> int:
    return sock.sendmsg(buffers)


if not hasattr(socket.socket, "sendmsg"):  # Windows: no gathering write

    def _sendmsg(sock: socket.socket, buffers: list[bytes | memoryview]) -> int:
        return sock.send(b"".join(buffers))


__all__ = ["Connection"]
