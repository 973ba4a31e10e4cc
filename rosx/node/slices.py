"""Short time slices for callback threads, and publishers that give way to them in a burst,
so that a message is handled as it arrives.

Linux's fair scheduler (EEVDF, since 6.6) lets a thread that wakes up preempt the running one
only when it asks for a shorter time slice; since Linux 6.12 a thread may ask for one, without
privileges, with ``sched_setattr`` (its ``sched_runtime``; the kernel's "latency-sensitive
tasks" knob). Without it a subscriber's reader thread woken by a message waits for the thread
running on its CPU to block or use up its slice (0.75 ms times 1 + log2 of the CPUs, at most 3 ms),
which is common: schedulers put a thread woken through a socket on the waker's CPU, and virtual
machines pack threads onto few CPUs. With it the callback runs as soon as the message lands:
on a two-CPU virtual machine, publish → callback at 1 kHz between two processes took 7 µs
instead of 11-13 µs.

`request_short_slice` asks, for the calling thread, for `SLICE_NS` (0.5 ms: shorter than the
kernel's default anywhere) and keeps the thread's policy and nice value. The share of CPU a
thread gets does not change, only how soon it runs when woken and how long it runs before
another thread of its CPU may. Nothing happens off Linux, on kernels that ignore the field,
on architectures whose system call number is not listed here, for threads under real-time
policies, or with ``ROSX_SHORT_SLICE=0`` in the environment.

A short slice is not enough inside a burst. A reader thread that has just run is owed no CPU
time when the next message wakes it, so it waits until the publisher (whose CPU it was woken
on) has published the whole burst and gone to sleep: per message, a burst of ten Twists took
40-50 µs. `Handoff` is the publisher's side. A run is a series of messages published less
than `RUN_GAP_NS` apart; its first `HANDOFF_RUN` messages are a burst, the rest a flood.

* After each burst message but the first (whose reader preempts the publisher anyway), once it
  is written to a subscriber on this machine, the publishing thread yields its CPU
  (``sched_yield``): the reader takes the message now and the publisher carries on where it
  was. The GIL is kept, so no other thread of the publisher's process runs meanwhile, unless
  a subscriber is in this process: its local thread needs the GIL.
* A subscriber in this process is told it is in a burst (`Receiver.eager`): its local thread
  then sleeps on its pipe at once, not on the condition that batches a flood, so the
  publisher's write to the pipe wakes it on the publisher's CPU.
* A flood keeps its batches: no yield, no pipe.
* Time spent in yields is paid from a credit that grows by 1/32 of the time between runs
  (at most `CREDIT_CAP_NS`), so they never cost the publisher more than about 3 % of its
  time. On a busy machine a yield may hand the CPU to another program for a whole slice,
  which delays the reader too; a yield that long (`SLOW_YIELD_NS`) stops them for about a
  second.

``ROSX_HANDOFF=0`` turns hand-offs off.
"""

from __future__ import annotations

import contextlib
import functools
import os
import struct
import sys
import time
from collections.abc import Callable
from typing import cast

SLICE_NS = 500_000

#: ``sched_setattr``'s number per architecture (``uname -m``).
_SYSCALLS = {"x86_64": 314, "aarch64": 274, "arm64": 274, "riscv64": 274}

#: struct sched_attr as of Linux 4.1 (SCHED_ATTR_SIZE_VER0): size, policy, flags, nice,
#: priority, runtime, deadline, period.
_ATTR = struct.Struct("=IIQiIQQQ")

#: Whether to ask at all (``ROSX_SHORT_SLICE=0`` says no); only Linux is ever asked.
ENABLED = os.environ.get("ROSX_SHORT_SLICE", "1") != "0"


@functools.cache
def _setattr() -> Callable[[bytes], int] | None:
    """``sched_setattr`` for the calling thread, loaded on first use (ctypes costs start-up)."""
    number = None
    if ENABLED and sys.platform.startswith("linux"):
        number = _SYSCALLS.get(os.uname().machine)
    if number is None:
        return None
    import ctypes  # noqa: PLC0415 - ctypes is not needed at start-up

    try:
        syscall = ctypes.CDLL(None, use_errno=True).syscall
    except (OSError, AttributeError):
        return None
    return lambda attr: int(syscall(number, 0, attr, 0))


def request_short_slice() -> bool:
    """Ask for a short time slice for the calling thread; whether the kernel accepted the
    request (a kernel older than 6.12 accepts it and ignores it)."""
    call = _setattr()
    if call is None:
        return False
    try:
        policy = os.sched_getscheduler(0)
        if policy not in (os.SCHED_OTHER, os.SCHED_BATCH):
            return False
        nice = os.getpriority(os.PRIO_PROCESS, 0)  # Linux: the calling thread's
    except OSError:
        return False
    attr = _ATTR.pack(_ATTR.size, policy, 0, nice, 0, SLICE_NS, 0, 0)
    with contextlib.suppress(OSError):
        return call(attr) == 0
    return False


#: Messages of a run (published less than `RUN_GAP_NS` apart) after which the publisher stops
#: handing off.
HANDOFF_RUN = 16

#: A pause between two messages that starts a new run.
RUN_GAP_NS = 200_000

#: At most this much time in yields is saved up (a shift: 1/32 of the time between runs).
CREDIT_CAP_NS = 5_000_000
_CREDIT_SHIFT = 5

#: A yield that takes longer than this (a reader handles a message in a few µs) leaves the
#: credit at minus `SLOW_PENALTY_NS`: no yields until about a second of pauses has passed.
SLOW_YIELD_NS = 200_000
SLOW_PENALTY_NS = 1_000_000_000 >> _CREDIT_SHIFT

#: Whether publishers hand off (``ROSX_HANDOFF=0`` says no); only on Linux, whose scheduler
#: this was measured on.
HANDOFF_ENABLED = sys.platform.startswith("linux") and os.environ.get("ROSX_HANDOFF", "1") != "0"

_clock = time.perf_counter_ns

#: ``sched_yield`` that lets the GIL go (for a subscriber thread of the publisher's process).
_YIELD_LETTING_GIL_GO = os.sched_yield if hasattr(os, "sched_yield") else None


@functools.cache
def _sched_yield() -> Callable[[], int] | None:
    """``sched_yield`` called with the GIL held (so no other thread of this process takes the
    GIL meanwhile), loaded on first use."""
    import ctypes  # noqa: PLC0415 - ctypes is not needed at start-up

    try:
        call = ctypes.PyDLL(None).sched_yield
    except (OSError, AttributeError):
        return None
    call.argtypes, call.restype = [], ctypes.c_int
    return cast("Callable[[], int]", call)


class Handoff:
    """One publication's hand-offs to its readers during a burst (see the module's docstring).

    The publishing thread calls `start` before a message goes out and `give_way` once it is
    written to every socket subscriber. Several threads publishing at once may blur a run's
    count; nothing worse.
    """

    __slots__ = ("_credit", "_run", "last")

    def __init__(self) -> None:
        #: When the last message was counted, or the readers last had the CPU: a publisher
        #: that knows its run goes on past `HANDOFF_RUN` (a stream holding a flood's frames,
        #: `rosx.node.outgoing`) sets it instead of calling `start`.
        self.last = _clock() - RUN_GAP_NS  # the first message starts a run
        self._run = 0
        self._credit = CREDIT_CAP_NS

    def start(self, caught_up: Callable[[], bool] | None = None, now: int = 0) -> bool:
        """Count a message about to be published; whether it is one of the first
        `HANDOFF_RUN` of its run (a burst so far, not a flood). A pause starts a new run only
        if the subscribers have ``caught_up``: a publisher kept from the GIL by a callback of
        its own process has not paused, its flood goes on. ``now`` is the message's time
        (`time.perf_counter_ns`) if the caller has read it."""
        now = now or _clock()
        gap = now - self.last
        self.last = now
        if gap >= RUN_GAP_NS and (caught_up is None or caught_up()):
            self._run = 1
            self._credit = min(CREDIT_CAP_NS, self._credit + (gap >> _CREDIT_SHIFT))
            return True
        run = self._run + 1
        self._run = run
        return run <= HANDOFF_RUN

    def give_way(self, *, release_gil: bool = False) -> None:
        """Yield the CPU if the message just written is the 2nd to `HANDOFF_RUN`-th of its run
        and the credit allows."""
        if not 1 < self._run <= HANDOFF_RUN or self._credit <= 0:
            return
        call = _YIELD_LETTING_GIL_GO if release_gil else _sched_yield()
        if call is None:
            return
        before = _clock()
        call()
        after = _clock()
        took = after - before
        # Longer than a reader takes: the CPU went to another program, or the callback is
        # slow. Either way the yields stop for a while.
        self._credit = -SLOW_PENALTY_NS if took > SLOW_YIELD_NS else self._credit - took
        self.last = after  # the time the readers took is not a pause of the publisher's
