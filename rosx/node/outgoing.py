"""One publisher-to-subscriber TCPROS stream: frames written from any thread, never blocking I/O.

The contract (ROS wiki ROS/TCPROS; rospy's and roscpp's publisher queues):

* `OutgoingStream.send` takes one complete frame (length prefix included) from any thread. When
  nothing is queued it is written straight away with one non-blocking ``send`` on the caller's
  thread, so an idle connection adds no thread hand-off to a message's latency. Whatever the
  kernel does not take is queued; the queue is flushed, as many frames as are waiting in one
  ``sendmsg``, when the socket is writable (``POLLOUT``, the room roscpp's publisher waits
  for too), by the I/O loop, and by `send` every `FLUSH_EVERY` frames, which asks the socket
  first: a publisher ahead of a slow peer does not gather and offer its whole queue to a
  socket without room. Before a bounded queue drops a frame, `send` offers the queue as it is.
* A frame is one ``bytes`` object, or a tuple of its parts in order (`Frame`): a large field is
  then sent from the message itself (`rosx.msg.codec.parts`), each part a buffer of the same
  ``sendmsg``, never joined into a copy. The parts must not change while the frame is queued
  (they are ``bytes``: they cannot).
* ``queue_size`` bounds the queue: a positive size drops the *oldest* queued frame when a new
  one would exceed it (ROS 1's semantics), never the frame already partly on the wire; ``0``
  means unbounded; ``None`` means no frame is dropped and `send` blocks its (non-loop) caller
  while more than `high_water` bytes wait, as rospy's synchronous publish blocks. A stream
  made ``paced`` (a TCP link of such a publisher) waits sooner while its frames are small: its
  kernel takes no more than `PACED_BYTES` not yet sent (``TCP_NOTSENT_LOWAT``), and `send`
  waits while more than that wait here, so a publisher of a flood ahead of a slower
  subscriber waits for it instead of running on with both kernels' buffers and megabytes of
  its own queue full. The first frame of `HOLD_SIZE` bytes or more ends the pacing for good:
  large messages move faster with the kernel's buffers full.
* The queue and the byte and frame counts (``getBusStats``) change only under the stream's
  lock, whichever thread writes.
* A peer that closes, resets or sends garbage ends the stream; `on_close` is then called once,
  on the loop. Bytes a subscriber sends after its header are read and ignored: reading is how
  a closed peer is noticed before the next publish. `close` first writes what waits, as far
  as the socket takes it.
* In a flood to a peer that is behind, small frames are held back and written together, one
  ``sendmsg`` for many instead of one ``send`` each: fewer system calls for the publisher,
  fewer and larger reads for the subscriber. Whether the peer is behind, the stream asks its
  socket (the ``unread`` probe): over a Unix socket, what the peer has not read yet
  (`rosx.node.unixros.unread_probe`); over TCP, what this end's kernel has not sent yet
  (`unsent_probe`: the peer's window is full, or Nagle's algorithm waits for the peer to
  acknowledge what it has), bytes that a frame written now would wait behind anyway.
  Holding starts only once frames have come less than `FLOOD_GAP_NS` apart for `HOLD_RUN`
  frames and the probe says so (it is asked every `PROBE_EVERY` frames), so a lone message,
  a ping-pong and a burst the reader keeps up with are written at once, as above. What is
  held goes out every `HOLD_PROBE_EVERY` frames if the probe finds nothing waiting, once
  `HOLD_FRAMES` frames or `HOLD_BYTES` bytes wait, with a frame of `HOLD_SIZE` bytes or
  more, with the first frame after a pause or in parts (that frame goes as it would unheld,
  and holding stops), by `close`, and at the latest `HOLD_TICK` seconds later (the I/O loop
  writes it if the publisher has stopped), or by `OutgoingStream.flush` (what another
  topic's next message must not overtake): the same bytes in the same order. A bounded
  queue holds no more than its size, so holding drops nothing.

What this module must not know: topics, message types, headers. It moves frames.
"""

from __future__ import annotations

import os
import select
import socket
import sys
import threading
import time
from collections import deque
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from collections.abc import Callable, Iterable

    from rosx.transport.loop_thread import LoopThread

    #: One frame: its bytes, or its parts in order (see the module's contract).
    Frame = bytes | tuple[bytes, ...]

#: With ``queue_size=None``, `OutgoingStream.send` blocks while more bytes than this wait.
HIGH_WATER = 4 * 1024 * 1024

#: A paced stream (see the module's contract): the bytes its kernel may hold unsent, and that
#: may wait in its queue, before `OutgoingStream.send` waits. Next to a roscpp subscriber on a
#: machine of two cores, 200 000 Twists from a publisher so paced arrived 1.1-1.2 times as
#: fast as from one that wrote them all ahead, in six comparisons of seven, when the machine
#: had a core to spare (bench/README.md, "A publisher that waits");
#: 16 KiB paced too closely (0.6 times: every wake-up of the loop wrote a few frames), 32 KiB
#: and 1-2 MiB gained less.
PACED_BYTES = 512 * 1024

# sendmsg takes at most IOV_MAX (1024 on Linux) buffers.
_MAX_IOV = 512

#: While frames wait, a new frame tries to write them once every this many frames (the I/O
#: loop writes them too, whenever the socket is writable).
FLUSH_EVERY = 16

#: Whether streams that can ask whether their peer is behind hold frames back while it is
#: (``ROSX_BATCH=0`` says no).
HOLD_ENABLED = os.environ.get("ROSX_BATCH", "1") != "0"
#: Frames of a flood's run (each sent less than `FLOOD_GAP_NS` after the one before) before the
#: peer is asked whether it is behind: a burst the reader keeps up with never asks.
HOLD_RUN = 16
#: A pause between two frames that ends a run, and writes what is held (a Python publisher in
#: a loop publishes every 1-3 µs; a ping-pong may make runs too, but its peer has read all).
FLOOD_GAP_NS = 20_000
#: Frames between two questions to the peer's socket (each is a system call) before holding,
#: and while holding: the held frames go when the peer has read what it had, waking it once
#: for that many frames (a reader woken on an idle CPU of a virtual machine costs its waker
#: several microseconds).
PROBE_EVERY = 8
HOLD_PROBE_EVERY = 32
#: At most this many frames, and this many bytes, are held.
HOLD_FRAMES = 256
HOLD_BYTES = 256 * 1024
#: A frame this large is never held (its copy costs more than its system call).
HOLD_SIZE = 4096
#: Held frames wait at most about this long (seconds): the I/O loop writes them.
HOLD_TICK = 0.001
_HOLD_TICK_NS = int(HOLD_TICK * 1e9)

_clock = time.perf_counter_ns


def _nothing_unread() -> int:
    return 0


def frame_size(frame: Frame) -> int:
    """The bytes of a frame, whole or in parts."""
    if isinstance(frame, bytes):
        return len(frame)
    return sum(len(part) for part in frame)


def _unsent(frame: Frame, head: int) -> list[bytes | memoryview]:
    """The buffers of ``frame`` after its first ``head`` bytes."""
    if isinstance(frame, bytes):
        return [memoryview(frame)[head:] if head else frame]
    buffers: list[bytes | memoryview] = []
    for part in frame:
        if head >= len(part):
            head -= len(part)
            continue
        buffers.append(memoryview(part)[head:] if head else part)
        head = 0
    return buffers


class OutgoingStream:
    """Frames to one peer over a connected non-blocking socket (see the module's contract)."""

    def __init__(
        self,
        sock: socket.socket,
        io: LoopThread,
        queue_size: int | None,
        on_close: Callable[[OutgoingStream], None] | None = None,
        *,
        unread: Callable[[], int] | None = None,
        paced: bool = False,
    ) -> None:
        """``unread`` says how many bytes sent are still waiting (the peer has not read them,
        or the kernel has not sent them): given, frames may be held back while some wait.
        ``paced``: with ``queue_size=None``, over TCP (a Unix socket is never paced), wait
        sooner while frames are small (see the module's contract)."""
        sock.setblocking(False)
        self.sock = sock
        self.fileno = sock.fileno()
        self._io = io
        self._limit = queue_size if queue_size else 0
        self._blocking = queue_size is None
        self.paced = paced and self._blocking and _limit_unsent(sock, PACED_BYTES)
        #: With ``queue_size=None``, `send` blocks while more bytes than this wait.
        self.high_water = PACED_BYTES if self.paced else HIGH_WATER
        self._on_close = on_close
        self._lock = threading.Lock()
        self._drained = threading.Condition(self._lock)
        self._pending: deque[Frame] = deque()
        self._pending_bytes = 0
        self._head_sent = 0  # bytes of _pending[0] already written
        self._queued_since = 0  # frames queued since a queued frame last tried to write
        #: Holding frames back (see the contract): the question to the peer's socket, the
        #: time of the last frame and the frames of its run, how many frames are held, whether
        #: the loop's timer runs.
        self._can_hold = unread is not None and HOLD_ENABLED
        self._unread = unread or _nothing_unread
        self._last_ns = 0
        self._run = 0
        #: Whether what `_pending` holds is held back (the socket is not full): the frame
        #: last sent came less than `FLOOD_GAP_NS` after the one before, in a run of more
        #: than `HOLD_RUN` such frames. Read without the lock by the publication.
        self.holding = False
        self._held = 0
        self._hold_frames = min(HOLD_FRAMES, self._limit) if self._limit else HOLD_FRAMES
        self._ticking = False
        #: Asks whether the socket has room, before `send` offers it the queue.
        self._room = select.poll()
        self._room.register(self.fileno, select.POLLOUT)
        self.closed = False
        self.bytes_sent = 0
        self.frames_sent = 0
        self.dropped = 0
        io.call_soon(self._watch)

    # -- any thread --------------------------------------------------------------------------

    def send(self, frame: Frame, now: int = 0) -> None:
        """Queue ``frame`` for the peer (written at once when nothing else is waiting);
        ``now``, when given, is the time of its publishing (`time.perf_counter_ns`), read
        once for this and the publication's hand-off (`rosx.node.slices.Handoff`)."""
        # acquire/release, not ``with``: a burst's first message runs this with the CPU's
        # caches cold, when less code is quicker (see `rosx.node.publication`).
        lock = self._lock
        lock.acquire()
        try:
            if self.closed:
                return
            if self.holding:
                # A flood's usual frame, held with those before it (`_hold_locked`, inlined).
                # Only whole frames are held: a frame in parts ends the run as a pause does.
                now = now or _clock()
                gap = now - self._last_ns
                self._last_ns = now
                if gap < FLOOD_GAP_NS and frame.__class__ is bytes:
                    self._pending.append(frame)
                    size = len(frame)
                    held_bytes = self._pending_bytes = self._pending_bytes + size
                    held = self._held = self._held + 1
                    if held >= self._hold_frames or held_bytes >= HOLD_BYTES or size >= HOLD_SIZE:
                        self._release_locked(keep=True)
                    elif not held % HOLD_PROBE_EVERY and not self._unread():
                        self._release_locked(keep=True)  # the peer has read all it had
                    return
                # A pause: what was held goes, then this frame at once.
                self._run = 0
                self._release_locked(keep=False)
            elif self._can_hold and self._hold_locked(frame, now or _clock()):
                return
            if self.paced and (frame.__class__ is not bytes or len(frame) >= HOLD_SIZE):
                self._end_pacing_locked()
            if self._pending:
                self._enqueue_locked(frame)
                return
            try:
                if frame.__class__ is bytes:
                    sent = self.sock.send(frame)
                else:
                    sent = self.sock.sendmsg(frame)  # type: ignore[arg-type]
            except (BlockingIOError, InterruptedError):
                sent = 0
            except OSError:
                self._fail_locked()
                return
            self.bytes_sent += sent
            size = len(frame) if frame.__class__ is bytes else frame_size(frame)
            if sent == size:
                self.frames_sent += 1
                return
            self._pending.append(frame)
            self._head_sent = sent
            self._pending_bytes = size - sent
            self._io.call_soon(self._start_writing)
        finally:
            lock.release()

    def _hold_locked(self, frame: Frame, now: int) -> bool:
        """Whether to start holding frames back with ``frame``, sent at ``now`` (see the
        module's contract): a flood's run is long enough, and the peer has not read what it
        was sent."""
        gap = now - self._last_ns
        self._last_ns = now
        if gap >= FLOOD_GAP_NS:
            self._run = 0
            return False
        run = self._run = self._run + 1
        if run < HOLD_RUN or run % PROBE_EVERY or self._pending or self._hold_frames < 2:
            return False
        if frame.__class__ is not bytes:
            return False
        size = len(frame)
        if size >= HOLD_SIZE or not self._unread():
            return False
        self._pending.append(frame)
        self._pending_bytes += size
        self.holding = True
        self._held = 1
        if not self._ticking:
            self._ticking = True
            self._io.call_soon(self._tick_later)
        return True

    def _end_pacing_locked(self) -> None:
        # A large message: the kernel takes as much as it will again, and the queue waits
        # as any other does (see the module's contract).
        self.paced = False
        self.high_water = HIGH_WATER
        _limit_unsent(self.sock, 0)  # 0: the system's default, no limit
        self._drained.notify_all()

    def _release_locked(self, *, keep: bool) -> None:
        """Write the held frames; go on holding if ``keep`` (and the socket took them all)."""
        # While holding, the queue holds only whole frames (`bytes`), none of them half
        # sent, and fewer than `_MAX_IOV`: `sendmsg` takes the queue as it is.
        self._flush_locked(held=True)
        self._held = 0
        if self._pending and not self.closed:
            # The socket is full: the loop writes the rest when it can, as for any frames
            # the socket did not take.
            self.holding = False
            self._io.call_soon(self._start_writing)
        else:
            self.holding = keep and not self.closed

    def _enqueue_locked(self, frame: Frame) -> None:
        # Frames already wait: this one joins them, then whatever the socket takes now goes.
        pending = self._pending
        pending.append(frame)
        self._pending_bytes += len(frame) if frame.__class__ is bytes else frame_size(frame)
        # Whatever the peer has read since makes room now, not when the loop next gets
        # the GIL (up to a switch interval, 5 ms, behind a publishing thread): the queue
        # goes out in one ``sendmsg``, coalesced (a Unix socket's buffer counts each
        # ``send`` of a small frame as a whole kernel buffer). Before a frame would be
        # dropped (a frame the socket takes is not lost), and once every `FLUSH_EVERY` frames
        # if the socket is writable: a peer slower than the publisher keeps the socket full,
        # and gathering the queue's buffers for a ``sendmsg`` the socket refuses cost the
        # publisher more than its messages did (next to a roscpp subscriber over TCP: 60 % of
        # the publisher's time, 0.85 of a CPU), taken from the subscriber when they share
        # the machine.
        limit = self._limit
        self._queued_since += 1
        if limit and len(pending) > limit:
            self._queued_since = 0
            self._flush_locked()  # whatever the socket takes is not dropped
        elif self._queued_since >= FLUSH_EVERY:
            self._queued_since = 0
            if self._room.poll(0):
                self._flush_locked()
        if not pending:
            return
        # A head half on the wire is no longer queued, and dropping it would corrupt
        # the stream: the oldest frame that may go is the one after it.
        partial = 1 if self._head_sent else 0
        if limit and len(pending) - partial > limit:
            victim = pending[partial]
            del pending[partial]
            self._pending_bytes -= frame_size(victim)
            self.dropped += 1
        elif (
            self._blocking
            and self._pending_bytes > self.high_water
            and not self._io.in_loop_thread()
        ):
            while not self.closed and self._pending_bytes > self.high_water:
                self._drained.wait(1.0)

    def flush(self) -> None:
        """Write the frames held back now, as a pause in the flood would (see the contract):
        they reach the socket before anything sent after this call, on any stream."""
        lock = self._lock
        lock.acquire()
        try:
            if self.holding and not self.closed:
                self._last_ns = 0  # the next frame starts a run, as after a pause
                self._release_locked(keep=False)
        finally:
            lock.release()

    @property
    def queued(self) -> int:
        """Frames waiting to be written."""
        return len(self._pending)

    def close(self) -> None:
        """End the stream (idempotent), after writing what waits as far as the socket takes
        it; `on_close` runs on the loop."""
        with self._lock:
            if self.closed:
                return
            if self._pending:
                self._flush_locked()
            if not self.closed:
                self._fail_locked()

    # -- the loop ----------------------------------------------------------------------------

    def _fail_locked(self) -> None:
        self.closed = True
        self._pending.clear()
        self._pending_bytes = 0
        self._drained.notify_all()
        self._io.call_soon(self._teardown)

    def _teardown(self) -> None:
        loop = self._io.loop
        loop.remove_reader(self.fileno)
        loop.remove_writer(self.fileno)
        try:
            self.sock.close()
        finally:
            if self._on_close is not None:
                callback, self._on_close = self._on_close, None
                callback(self)

    def _watch(self) -> None:
        if not self.closed:
            self._io.loop.add_reader(self.fileno, self._on_readable)

    def _on_readable(self) -> None:
        try:
            data = self.sock.recv(4096)
        except (BlockingIOError, InterruptedError):
            return
        except OSError:
            data = b""
        if not data:
            self.close()

    def _tick_later(self) -> None:
        self._io.loop.call_later(HOLD_TICK, self._tick)

    def _tick(self) -> None:
        # Held frames go out now; the timer goes on while frames come (a flood), and stops
        # after a tick without any (the next frame held starts it again).
        with self._lock:
            active = _clock() - self._last_ns < _HOLD_TICK_NS
            if self.holding and not self.closed:
                self._release_locked(keep=active)
            self._ticking = active and not self.closed
        if self._ticking:
            self._tick_later()

    def _start_writing(self) -> None:
        if not self.closed:
            self._io.loop.add_writer(self.fileno, self._on_writable)

    def _on_writable(self) -> None:
        # Held frames go by the holding's rules (`_release_locked`, which hands them back to
        # this writer if the socket cannot take them): a part of one written here would be
        # written again with the others, which are whole frames by then.
        with self._lock:
            if not self.closed and self._pending and not self.holding:
                self._flush_locked()
            if self.closed or not self._pending or self.holding:
                self._io.loop.remove_writer(self.fileno)

    def _flush_locked(self, *, held: bool = False) -> None:
        """Write as many queued frames as the socket takes, in one ``sendmsg`` (any thread);
        ``held``: the queue is frames held back (see `_release_locked`)."""
        pending = self._pending
        buffers: Iterable[bytes | memoryview]
        if held:
            buffers = pending  # type: ignore[assignment]  # whole frames only
        else:
            head = self._head_sent
            buffers = []
            for frame in pending:
                if len(buffers) >= _MAX_IOV:
                    break
                if frame.__class__ is bytes and not head:
                    buffers.append(frame)
                else:
                    buffers.extend(_unsent(frame, head))
                head = 0
        try:
            sent = self.sock.sendmsg(buffers)
        except (BlockingIOError, InterruptedError):
            return
        except OSError:
            self._fail_locked()
            return
        self.bytes_sent += sent
        self._pending_bytes -= sent
        if not self._pending_bytes:
            # Every byte went (a flood's held frames, usually): nothing to count one by one.
            self.frames_sent += len(pending)
            pending.clear()
            self._head_sent = 0
            if self._blocking:
                self._drained.notify_all()
            return
        sent += self._head_sent
        while pending:
            first = pending[0]
            size = len(first) if first.__class__ is bytes else frame_size(first)
            if sent < size:
                break
            sent -= size
            pending.popleft()
            self.frames_sent += 1
        self._head_sent = sent
        if self._blocking and self._pending_bytes <= self.high_water:
            self._drained.notify_all()


def configure_nodelay(sock: socket.socket, nodelay: bool) -> None:
    """Disable Nagle's algorithm on ``sock`` when the subscriber asked for ``tcp_nodelay``."""
    if nodelay:
        sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)


#: Where ``struct tcp_info`` (Linux, ``<linux/tcp.h>``) keeps ``tcpi_notsent_bytes``, and the
#: length that includes it (Linux 4.6 and later).
_NOTSENT_AT = 144
_TCP_INFO_SIZE = _NOTSENT_AT + 4


def unsent_probe(sock: socket.socket) -> Callable[[], int] | None:
    """A function giving the bytes written to a TCP socket that its kernel has not sent yet
    (``tcpi_notsent_bytes``); None where that cannot be asked.

    They wait because the peer's receive window is full (it is behind, by its whole buffer)
    or for Nagle's algorithm (a segment is not acknowledged yet, which on loopback means the
    peer has not been scheduled to take it): a frame written now would wait behind them in
    the kernel, so holding it back with them delays nothing the peer could read sooner.
    """
    if not sys.platform.startswith("linux") or sock.family not in (
        socket.AF_INET,
        socket.AF_INET6,
    ):
        return None
    level, option = socket.IPPROTO_TCP, socket.TCP_INFO
    try:
        if len(sock.getsockopt(level, option, _TCP_INFO_SIZE)) < _TCP_INFO_SIZE:
            return None
    except OSError:
        return None
    getsockopt = sock.getsockopt
    from_bytes = int.from_bytes

    def unsent() -> int:
        try:
            info = getsockopt(level, option, _TCP_INFO_SIZE)
        except OSError:
            return 0
        return from_bytes(info[_NOTSENT_AT:], "little")

    return unsent


def _limit_unsent(sock: socket.socket, limit: int) -> bool:
    """Whether ``sock``'s kernel now takes no more than ``limit`` bytes it has not sent
    (``TCP_NOTSENT_LOWAT``: the socket is writable, to ``send`` and ``poll``, while fewer
    wait; 0 means the system's default): False where that cannot be asked of it."""
    option = getattr(socket, "TCP_NOTSENT_LOWAT", None)
    if option is None or sock.family not in (socket.AF_INET, socket.AF_INET6):
        return False
    try:
        sock.setsockopt(socket.IPPROTO_TCP, option, limit)
    except OSError:
        return False
    return True
