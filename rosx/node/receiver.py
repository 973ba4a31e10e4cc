"""How a subscription's messages reach its callbacks: reader threads and one drop-oldest queue.

As in rospy, a topic's messages are read and handed to its callbacks by threads of the topic's
own, never by the I/O loop: a slow callback, or one that never returns, delays only its own
topic, never other topics, other nodes or the Slave API. Each publisher connection gets a
thread that blocks in ``recv`` on its socket. That is what keeps latency low: a message wakes
exactly one thread, woken directly by the kernel (a wait in ``epoll`` and a hand-off to another
thread each cost more than the rest of the path together).

The contract:

* The loop does each connection's handshake, then `Receiver.attach` starts the connection's
  thread, which reads in large reads (`IncomingStream.read`: what the socket holds, up to a few
  MiB) and queues the frames.
* Frames wait in one queue per subscription. With a positive ``queue_size`` only the newest
  frames are kept when the callbacks fall behind (ROS 1's drop-oldest semantics); ``None`` keeps
  everything.
* Whichever reader thread queued frames runs the callbacks, unless another one already is: the
  callbacks of a topic never run concurrently, and run in the order the frames were queued.
  Frames read when nothing is queued and no callback is running skip the queue (same order, one
  hand-off less on the latency path, and in a flood a few calls less per message). With one
  callback (typed or raw) the thread does that in one Python frame, from the read to the callback
  (`Receiver._read_direct`): after a pause that code runs with the CPU's caches cold, where
  each call costs microseconds. A latched
  message for a callback added late is queued by the loop and run by one of the node's worker
  threads (`Receiver.put`).
* A frame is decoded lazily, once per decoder, just before its callbacks run. Callback
  exceptions go to ``on_error`` (rospy logs ``bad callback``) and reading goes on.
* A stream that ends (peer closed, error, `Receiver.detach` shutting its socket down) has its
  socket closed by its thread, which then tells the loop (``IncomingStream.close``).
* Publishers in the same process (`rosx.node.local`) queue `LocalMessage` objects instead of
  frames, with `Receiver.put_local` on the publishing thread; the subscription's own local
  thread runs their callbacks. A bounded queue drops the oldest, as for frames; an unbounded
  one makes a synchronous publisher (``queue_size=None``) wait while more than `LOCAL_HIGH_WATER`
  messages are queued, as a full socket would. The local thread sleeps on a condition for
  `LOCAL_BATCH_WINDOW` after each message (a flood is taken in batches), then on a pipe, which
  the next message's publisher writes to without the GIL (it is handled at once). While a
  publisher of this process publishes a burst (`eager`), the thread sleeps on the pipe at once.
* Every thread that runs callbacks asks for a short time slice (`rosx.node.slices`).
* A drain (`rosx.node.subscription.Drain`) counts what has reached this host as what the
  streams have counted plus what their sockets hold, which misses a read that has taken bytes
  and not yet counted them. With `Receiver.exact` the threads wait for data with the bytes left
  in the socket, and mark the stream (``in_hand``) from before each read until its frames are
  counted, for the drain to wait out: a system call more for each read, for topics whose
  order against other topics matters (an action's feedback against its result).
"""

from __future__ import annotations

import contextlib
import os
import select
import socket
import threading
from collections import deque
from typing import TYPE_CHECKING, Any

from rosx.node import incoming, slices
from rosx.node.local import LocalMessage

if TYPE_CHECKING:
    from collections.abc import Callable, Sequence
    from concurrent.futures import Executor

    from rosx.msg.codec.parts import Locator
    from rosx.node.incoming import IncomingStream, Received
    from rosx.node.local import LocalLink
    from rosx.transport.loop_thread import LoopThread

    Decode = Callable[[Received, dict[str, str]], Any]
    #: A callback and the decoder of what it receives.
    Entry = tuple[Callable[[Any], object], Decode]
    #: A frame (or a message from this process), the header of its connection, and the only
    #: entry to run it for (or None: all).
    Item = tuple["Received | LocalMessage", dict[str, str], Entry | None]

#: With an unbounded queue, a synchronous in-process publisher waits while more wait than this.
LOCAL_HIGH_WATER = 10_000

#: Seconds the local thread waits for the next message in the way that batches a flood.
LOCAL_BATCH_WINDOW = 0.0002
#: Seconds `Receiver.start_local` waits for the local thread to be ready (it goes on anyway).
LOCAL_START_TIMEOUT = 5.0

_ON_CONDITION = 1
_ON_PIPE = 2
#: The local thread sleeps on its pipe and has been rung: it is waking (and may be waiting for
#: the GIL), later messages need not ring again.
_RUNG = 3


class Receiver:
    """A subscription's queue, callbacks and reader threads (see the module's contract)."""

    def __init__(
        self,
        io: LoopThread,
        workers: Executor,
        *,
        queue_size: int | None,
        name: str,
        on_error: Callable[[BaseException, Callable[[Any], object]], None] | None = None,
    ) -> None:
        self._io = io
        self._workers = workers
        self._name = name
        self._on_error = on_error
        self._queue: deque[Item] = deque()
        #: The queue's bound (None: unbounded). Not the deque's ``maxlen``: a frame it drops
        #: must be counted (`dropped`), and a deque drops silently.
        self._limit = queue_size if queue_size else None
        self._dispatching = threading.Lock()
        self.entries: tuple[Entry, ...] = ()
        self._streams: set[IncomingStream] = set()
        self._stopped = False
        self._local: threading.Thread | None = None
        #: The condition's lock, taken directly on the publishing path (`_ring`): a
        #: condition's ``with`` runs Python code of its own, costly when cold.
        self._wake_lock = threading.Lock()
        self._wake = threading.Condition(self._wake_lock)
        #: The local thread's pipe (read end, write end) while it runs; it sleeps reading it.
        self._doorbell: tuple[int, int] | None = None
        #: How the local thread sleeps, if it does: 0, `_ON_CONDITION`, `_ON_PIPE` or
        #: `_RUNG`.
        self._sleeping = 0
        self._waiting_publishers = 0
        #: Set by a publisher of this process while it publishes a burst
        #: (`rosx.node.slices.Handoff`): the local thread then sleeps on its pipe at once, so
        #: each message of the burst is handled as it is published, not after the burst.
        self.eager = False
        self._counting = threading.Lock()
        #: `received` (frames and messages taken in) against `handled` (those whose callbacks
        #: have run) and `dropped` (those a bounded queue let go) says how far the callbacks
        #: are behind (`caught_up`). A connected stream's frames are counted by its own thread
        #: alone (``frames_received``), so reading costs no lock; the rest (queued by the loop
        #: or in this process, or from ended streams) under `_counting`, which also guards the
        #: set of streams, the drops, and every append to the queue (a bounded queue's drops
        #: are counted exactly). `handled` grows only under the dispatch lock.
        self._received_before = 0
        self.handled = 0
        self.dropped = 0
        #: The callbacks whose locator `_locator` found last, and that locator.
        self._located: tuple[tuple[Entry, ...] | None, Locator | None] = (None, None)
        #: Whether drains are exact (see the module's contract): read by each thread before
        #: each read.
        self.exact = False

    # -- callbacks (any thread) --------------------------------------------------------------

    def add(
        self, callback: Callable[[Any], object], decode: Decode, *, first: bool = False
    ) -> Entry:
        """Add a callback (after the others, or before them with ``first``); returns its entry
        (to remove it, or to queue frames for it alone)."""
        entry = (callback, decode)
        self.entries = (entry, *self.entries) if first else (*self.entries, entry)
        return entry

    def remove(self, entry: Entry) -> None:
        """Remove a callback (it may still be running)."""
        self.entries = tuple(e for e in self.entries if e is not entry)

    def put(
        self,
        frame: Received | LocalMessage,
        header: dict[str, str],
        only: Entry | None = None,
    ) -> None:
        """Queue one frame for every callback, or only for ``only`` (a latched message).

        A worker thread runs the callbacks, unless a reader thread already is running them.
        """
        if self._stopped:
            return
        self._enqueue([(frame, header, only)], 1)
        with contextlib.suppress(RuntimeError):  # the node has shut its workers down
            self._workers.submit(self._dispatch_all)

    def put_local(
        self,
        payload: bytes | LocalMessage,
        header: dict[str, str],
        *,
        publisher_queue: int | None = 0,
    ) -> None:
        """Queue a message published in this process (on the publishing thread); the local
        thread runs its callbacks.

        The subscription's ``queue_size`` bounds the queue (drop-oldest). When it is unbounded,
        the publisher's ``queue_size`` decides what happens past `LOCAL_HIGH_WATER` messages,
        as it decides what happens when a socket is full: ``None`` waits, a positive size
        drops the oldest, ``0`` keeps everything.
        """
        if self._stopped:
            return
        queue = self._queue
        limit = self._limit
        if limit is None and publisher_queue != 0 and len(queue) >= LOCAL_HIGH_WATER:
            if publisher_queue is None:
                self._wait_for_room()
            else:
                limit = LOCAL_HIGH_WATER  # the publisher's drop-oldest, past the high water
        # `_enqueue` for one message, inlined (a burst's cold path): counted, and a bounded
        # queue's oldest dropped and counted, under one lock.
        lock = self._counting
        lock.acquire()
        try:
            self._received_before += 1
            if limit is not None:
                while len(queue) >= limit:
                    try:
                        queue.popleft()
                    except IndexError:
                        break
                    self.dropped += 1
            queue.append((payload, header, None))
        finally:
            lock.release()
        # The local thread (started when the link connected, `start_local`) sets `_sleeping`
        # before its last look at the queue, so a message appended before that look is seen,
        # and one after it finds the flag set.
        sleeping = self._sleeping
        if sleeping == _ON_PIPE:
            # Rung once until it has woken: each ring is a write that lets the GIL go, and a
            # publisher that lets it go for every message keeps the woken thread from ever
            # taking it (CPython asks the holder to switch only after a switch interval in
            # which nobody else took the GIL): a flood would go by without its callbacks.
            self._sleeping = _RUNG
            self._ring()
        elif sleeping == _ON_CONDITION:
            with self._wake:
                self._wake.notify_all()

    @property
    def idle(self) -> bool:
        """Whether the local thread sleeps on its pipe, not yet rung: it has had nothing to do
        for a while (`LOCAL_BATCH_WINDOW`), or a burst is on (`eager`)."""
        return self._sleeping == _ON_PIPE

    def _ring(self) -> None:
        # The local thread sleeps in a read of its pipe, not on a condition, so that it is
        # woken by a system call, made without the GIL: it can run at once (`slices`), not
        # after this thread next lets the GIL go. The local thread closes the pipe under the
        # lock; acquire/release as in `rosx.node.publication`, for a burst's cold first message.
        lock = self._wake_lock
        lock.acquire()
        try:
            if self._doorbell is not None:
                os.write(self._doorbell[1], b"\0")
        finally:
            lock.release()

    def _wait_for_room(self) -> None:
        queue = self._queue
        with self._wake:
            self._waiting_publishers += 1
            try:
                while len(queue) >= LOCAL_HIGH_WATER and not self._stopped:
                    self._wake.wait(1.0)
            finally:
                self._waiting_publishers -= 1

    def start_local(self) -> None:
        """Start the local thread, which runs the callbacks of messages published in this
        process, if it has not started; return once it is ready for them.

        Called when an in-process link connects, not at its first message: what the thread
        does before it waits for messages (asking for a short slice, which loads ``ctypes``
        the first time) lets the GIL go and takes it back each time, and against a publisher
        already flooding each take waits a whole switch interval (5 ms), while the messages
        pile up.
        """
        with self._wake:
            if self._local is not None or self._stopped:
                return
            self._doorbell = os.pipe()
            ready = threading.Event()
            self._local = threading.Thread(
                target=self._local_loop,
                args=(self._doorbell[0], ready),
                name=f"{self._name}-local",
                daemon=True,
            )
            self._local.start()
        ready.wait(LOCAL_START_TIMEOUT)

    def _local_loop(self, bell: int, ready: threading.Event) -> None:
        queue = self._queue
        wake = self._wake
        slices.request_short_slice()
        ready.set()
        try:
            while not self._stopped:
                if queue:
                    self._dispatch_all()
                    if self._waiting_publishers:
                        with wake:
                            wake.notify_all()
                    continue
                # Messages coming faster than a wake-up costs are taken in batches: for a
                # while after each one the thread waits on the condition, which a publisher
                # notifies holding the GIL, so it goes on publishing until it lets the GIL
                # go. Then the thread sleeps on its pipe, and the next message, after a
                # pause or within a burst (`eager`), is handled as soon as it is published.
                if not self.eager:
                    with wake:
                        self._sleeping = _ON_CONDITION
                        try:
                            if not queue and not self._stopped:
                                wake.wait(LOCAL_BATCH_WINDOW)
                        finally:
                            self._sleeping = 0
                    if queue or self._stopped:
                        continue
                self._sleeping = _ON_PIPE
                try:
                    if not queue and not self._stopped:
                        os.read(bell, 4096)  # one byte or more: wake-ups since the last look
                finally:
                    self._sleeping = 0
        finally:
            with wake:
                ends, self._doorbell = self._doorbell, None
            for end in ends or ():
                os.close(end)

    # -- connections -------------------------------------------------------------------------

    def attach(self, stream: IncomingStream) -> None:
        """Start the reader thread of a connected stream (called on the loop)."""
        if self._stopped or stream.sock is None:
            stream.close()
            return
        stream.receiver = self
        stream.sock.setblocking(True)
        with self._counting:
            self._streams.add(stream)
        threading.Thread(
            target=self._read_loop, args=(stream,), name=self._name, daemon=True
        ).start()

    def detach(self, stream: IncomingStream | LocalLink) -> None:
        """End a stream's reading: its thread wakes, closes the socket and exits."""
        sock = stream.sock
        if sock is not None:
            with contextlib.suppress(OSError):
                sock.shutdown(socket.SHUT_RDWR)

    def stop(self) -> None:
        """Stop every reader thread and drop what is queued; a running callback finishes."""
        self._stopped = True
        with self._counting:
            self.dropped += len(self._queue)
            self._queue.clear()
        for stream in list(self._streams):
            self.detach(stream)
        with self._wake:
            self._wake.notify_all()
        self._ring()

    # -- the threads -------------------------------------------------------------------------

    def _read_loop(self, stream: IncomingStream) -> None:
        queue = self._queue
        lock = self._dispatching
        slices.request_short_slice()
        try:
            frames = stream.take_frames()  # what came with the header (a latched message)
            while frames is not None and not self._stopped:
                if frames:
                    header = stream.header
                    if len(frames) == 1 and not queue and lock.acquire(False):
                        # Nothing waits and no callback runs: run this frame's callbacks now,
                        # without the trip through the queue (the same order either way).
                        try:
                            if not self._stopped:
                                self._run(frames[0], header, self.entries)
                        finally:
                            lock.release()
                        if queue:
                            self._dispatch_all()
                    elif not queue and lock.acquire(False):
                        # Several frames, nothing waits, no callback runs: run them here, in
                        # order, without the trip through the queue (a flood's usual read).
                        try:
                            rest = self._run_frames(frames, header)
                        finally:
                            lock.release()
                        if rest:
                            self._enqueue([(frame, header, None) for frame in rest])
                        if queue:
                            self._dispatch_all()
                    else:
                        self._enqueue([(frame, header, None) for frame in frames])
                        self._dispatch_all()
                frames = ()  # handed over: a large frame's buffer may serve the next read
                entries = self.entries
                locate = self._locator(entries)
                if self.exact:
                    frames = self._read_counted(stream, locate)
                elif (
                    locate is None
                    and len(entries) == 1
                    and not stream.buffered
                    and getattr(entries[0][1], "fresh", None) is not None
                ):
                    frames = self._read_direct(stream, entries)
                else:
                    frames = stream.read(locate)
        finally:
            with self._counting:
                self._streams.discard(stream)
                self._received_before += stream.frames_received
            stream.receiver = None
            sock, stream.sock = stream.sock, None
            if sock is not None:
                sock.close()
            self._io.call_soon(stream.close)

    def _locator(self, entries: tuple[Entry, ...]) -> Locator | None:
        """How the readers find the large byte array of frames for ``entries``: when every
        callback takes messages of one type that has one (`rosx.node.subscription.
        message_decoder`), they read large frames in parts (`rosx.node.incoming`)."""
        located = self._located
        if located[0] is entries:
            return located[1]
        decoders = [decode for _, decode in entries]
        locate = getattr(decoders[0], "locate", None) if decoders else None
        cls = getattr(decoders[0], "msg_class", None) if decoders else None
        if any(getattr(d, "msg_class", None) is not cls for d in decoders[1:]):
            locate = None
        if any(getattr(d, "locate", None) is None for d in decoders):
            locate = None
        self._located = (entries, locate)
        return locate

    def _run_frames(self, frames: Sequence[Received], header: dict[str, str]) -> Sequence[Received]:
        """Run the callbacks of ``frames`` in order (holding the dispatch lock), for as long as
        the callbacks stay the same and the receiver runs; returns the frames left. A bounded
        queue keeps only the newest of a read, as if the frames had been queued."""
        size = self._limit
        if size is not None and len(frames) > size:
            self._drop(len(frames) - size)
            frames = frames[-size:]
        entries = self.entries
        if len(entries) != 1 or getattr(entries[0][1], "fresh", None) is None:
            for index, frame in enumerate(frames):
                if self._stopped or self.entries is not entries:
                    return frames[index:]
                self._run(frame, header, entries)
            return ()
        # One callback: `_run` and the decoder (`message_decoder`, or a raw one) inlined.
        callback, decode = entries[0]
        fresh = decode.fresh  # type: ignore[attr-defined]
        cls = decode.instance_class  # type: ignore[attr-defined]
        new = object.__new__
        for index, frame in enumerate(frames):
            if self._stopped or self.entries is not entries:
                return frames[index:]
            try:
                msg = fresh(new(cls), frame)
                msg._connection_header = header
                callback(msg)
            except Exception as exc:  # a user's callback must not end the thread
                if self._on_error is not None and not self._stopped:
                    self._on_error(exc, callback)
            self.handled += 1
        return ()

    @staticmethod
    def _read_counted(stream: IncomingStream, locate: Locator | None) -> Sequence[Received] | None:
        """`IncomingStream.read` for exact drains (see the module's contract): wait until the
        socket has data (or has ended) without taking it, then read and count it with the stream
        marked as holding bytes it has not counted."""
        sock = stream.sock
        if sock is None or stream.closed:
            return None
        waiting = select.poll()
        waiting.register(sock, select.POLLIN)
        try:
            waiting.poll()
        except OSError:
            return None
        stream.in_hand = True
        try:
            return stream.read(locate)
        finally:
            stream.in_hand = False

    def _read_direct(
        self, stream: IncomingStream, entries: tuple[Entry, ...]
    ) -> Sequence[Received] | None:
        """Read ``stream`` and run the one callback of ``entries`` for each read that is one
        whole frame, for as long as nothing waits, no callback runs and the callbacks stay
        ``entries``; then return what `IncomingStream.read` would return (``()``: nothing).

        `read` and `_run` in one frame, for the usual case: after a pause, this is the code
        a message meets first on this side, cold, where each call costs microseconds.
        """
        sock = stream.sock
        if sock is None or stream.closed:
            return None
        recv_into = sock.recv_into
        scratch = stream.scratch
        view = stream.view
        unpack = incoming.U32.unpack_from
        whole = incoming.RECV_SIZE
        queue = self._queue
        lock = self._dispatching
        header = stream.header
        callback, decode = entries[0]
        fresh = decode.fresh  # type: ignore[attr-defined]
        cls = decode.instance_class  # type: ignore[attr-defined]
        new = object.__new__
        while True:
            try:
                size = recv_into(scratch)
            except (BlockingIOError, InterruptedError):
                return ()
            except OSError:
                return None
            if not (4 <= size < whole and unpack(scratch)[0] == size - 4):
                return stream.read_on(sock, size)
            if (
                queue
                or self.entries is not entries
                or self._stopped
                or self.exact  # asked meanwhile: the reads after this one are counted
                or not lock.acquire(False)
            ):
                return (stream.whole_frame(size),)
            # `IncomingStream.whole_frame`, `_run` and the decoder, inlined.
            frame = bytes(view[4:size])
            stream.frames_received += 1
            stream.bytes_received += size
            if stream.latching:
                stream.latched = frame
            try:
                msg = fresh(new(cls), frame)
                msg._connection_header = header
                callback(msg)
            except Exception as exc:  # a user's callback must not end the thread
                if self._on_error is not None and not self._stopped:
                    self._on_error(exc, callback)
            self.handled += 1
            lock.release()
            if queue:
                self._dispatch_all()

    @property
    def received(self) -> int:
        """Frames and messages queued or run so far."""
        with self._counting:
            return self._received_before + sum(s.frames_received for s in self._streams)

    def caught_up(self) -> bool:
        """Whether every frame and message taken in so far has had its callbacks run, or was
        dropped by the bounded queue (drop-oldest): nothing taken in is still to be handled."""
        with self._counting:
            received = self._received_before + sum(s.frames_received for s in self._streams)
            dropped = self.dropped
        # Read after `received`: what grows meanwhile only makes the answer later, not wrong.
        return received <= self.handled + dropped

    def _enqueue(self, items: list[Item], counted: int = 0) -> None:
        """Append ``items`` to the queue, ``counted`` of them taken in now (the rest are a
        stream's frames, counted by its thread); a bounded queue drops the oldest to make room
        (of the queue, then of ``items``), each drop counted."""
        queue = self._queue
        limit = self._limit
        with self._counting:
            self._received_before += counted
            if self._stopped:
                self.dropped += len(items)
                return
            if limit is not None:
                if len(items) > limit:
                    self.dropped += len(items) - limit
                    items = items[-limit:]
                while len(queue) + len(items) > limit:
                    try:
                        queue.popleft()
                    except IndexError:  # the callbacks took it meanwhile
                        break
                    self.dropped += 1
            queue.extend(items)

    def _drop(self, frames: int) -> None:
        with self._counting:
            self.dropped += frames

    def _dispatch_all(self) -> None:
        # Another thread may queue frames just after this one found the queue empty, then
        # fail to take the lock this one still holds: so look again after releasing it.
        queue = self._queue
        lock = self._dispatching
        while queue and lock.acquire(False):
            try:
                while queue and not self._stopped:
                    self._dispatch(queue.popleft())
            except IndexError:
                pass
            finally:
                lock.release()

    def _dispatch(self, item: Item) -> None:
        frame, header, only = item
        entries = (only,) if only is not None else self.entries
        if isinstance(frame, LocalMessage):
            self._dispatch_local(frame, header, entries)
        else:
            self._run(frame, header, entries)

    def _run(self, frame: Received, header: dict[str, str], entries: tuple[Entry, ...]) -> None:
        if len(entries) == 1:  # the usual subscription: one callback, one decoded message
            callback, decode = entries[0]
            try:
                callback(decode(frame, header))
            except Exception as exc:  # a user's callback must not end the thread
                if self._on_error is not None and not self._stopped:
                    self._on_error(exc, callback)
            self.handled += 1
            return
        decoded: dict[Any, Any] = {}
        for entry in entries:
            callback, decode = entry
            try:
                msg = decoded.get(decode)
                if msg is None:
                    msg = decoded[decode] = decode(frame, header)
                callback(msg)
            except Exception as exc:  # a user's callback must not end the thread
                if self._on_error is not None and not self._stopped:
                    self._on_error(exc, callback)
        self.handled += 1

    def _dispatch_local(
        self, local: LocalMessage, header: dict[str, str], entries: tuple[Entry, ...]
    ) -> None:
        if len(entries) == 1:  # the usual subscription: one callback, no lists (cold, quicker)
            callback, decode = entries[0]
            try:
                callback(local.message(decode, header))
            except Exception as exc:  # the callback's, or a raw subscriber's serialization
                if self._on_error is not None and not self._stopped:
                    self._on_error(exc, callback)
            self.handled += 1
            return
        try:
            messages = local.messages([decode for _, decode in entries], header)
        except Exception as exc:  # a message that cannot be serialized for a raw subscriber
            if self._on_error is not None and entries and not self._stopped:
                self._on_error(exc, entries[0][0])
            messages = []
        for (callback, _), msg in zip(entries, messages, strict=False):
            try:
                callback(msg)
            except Exception as exc:  # a user's callback must not end the thread
                if self._on_error is not None and not self._stopped:
                    self._on_error(exc, callback)
        self.handled += 1
