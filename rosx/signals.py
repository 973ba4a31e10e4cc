"""Signals: the one place rosx installs handlers for them.

Python runs a signal handler in the main thread only, between two bytecodes, so every helper
here installs nothing when called from another thread, and a handler never waits for a lock
(it hands long work to a thread, or sets a flag the program polls). Between two bytecodes the
main thread may hold any lock, an event's own among them while it waits on that event: a
handler that took it would wait forever, and one that raised there could leave it held (the
exception may come between the lock's acquiring and the ``with`` that releases it). So a
handler that may run while the program waits sets no event itself and raises nothing: it hands
such work to `soon`. (Python's own SIGINT handler raises `KeyboardInterrupt` anywhere; the
tools that let it, as ROS 1's do, exit after it.)

- `handling`: while a block runs, a function of rosx's takes the given signals; the previous
  handlers come back after. How the tools stop on Ctrl-C and SIGTERM (``rosbag record/play``,
  roscore, rostopic, turtlesim's programs, roslaunch's process monitor).
- `stop_on_signals`: the usual case of it, an event that SIGINT or SIGTERM sets.
- `install_signal_handlers`: for the rest of the process, rospy's way: the nodes shut down with
  the reason ``signal-N``, then the handler that was installed before runs (for SIGINT that is
  Python's, which raises `KeyboardInterrupt`; rospy keeps it from the program).
- `interrupt_on_sigint`: SIGINT raises `KeyboardInterrupt` even in a process that started with it
  ignored, as ROS 1's tools stop on ``kill -INT``.
- `soon`: a handler's work that takes locks (setting an event, shutting a node down), done on
  a thread of its own.
- `wait`: how the main thread waits for an event while other threads run. The kernel may hand a
  signal to any thread; one that lands on another thread only marks Python's handler as due,
  and a main thread asleep in an untimed wait never wakes to run it (Ctrl-C then does
  nothing). The main thread therefore waits in slices, as rospy's ``spin`` does.
"""

from __future__ import annotations

import contextlib
import signal

TYPE_CHECKING = False  # not typing's: every tool imports this module at start-up
if TYPE_CHECKING:
    import threading
    from collections.abc import Callable, Iterable, Iterator
    from types import FrameType
    from typing import Any

#: What stops a program: Ctrl-C and ``kill``.
STOP_SIGNALS = (signal.SIGINT, signal.SIGTERM)


def _main_thread() -> bool:
    import threading  # noqa: PLC0415 - asked only when a handler is installed, not at start-up

    return threading.current_thread() is threading.main_thread()


@contextlib.contextmanager
def handling(signals: Iterable[int], handler: Callable[[int], object]) -> Iterator[bool]:
    """While the block runs, each of ``signals`` calls ``handler(signum)`` (which may raise, in
    the main thread); yields whether the handlers were installed (not outside the main
    thread, where nothing changes)."""
    if not _main_thread():
        yield False
        return
    previous: dict[int, Any] = {}

    def on_signal(signum: int, frame: FrameType | None) -> None:
        handler(signum)

    try:
        for signum in signals:
            previous[signum] = signal.signal(signum, on_signal)
        yield True
    finally:
        for signum, old in previous.items():
            if old is not None:  # None: a handler installed from C, which cannot be put back
                signal.signal(signum, old)


@contextlib.contextmanager
def stop_on_signals(signals: Iterable[int] = STOP_SIGNALS) -> Iterator[threading.Event]:
    """An event that each of ``signals`` sets while the block runs (main thread only)."""
    import threading  # noqa: PLC0415 - as in `_main_thread`

    stop = threading.Event()
    with handling(signals, lambda signum: soon(stop.set)):
        yield stop


def soon(work: Callable[[], object]) -> None:
    """Run ``work`` now on a thread of its own: what a signal handler does that takes a lock
    (see the module's notes). The thread is started without `threading`'s own locks."""
    import _thread  # noqa: PLC0415 - as in `_main_thread`

    _thread.start_new_thread(work, ())


def install_signal_handlers(
    shutdown: Callable[[str], object],
    signals: Iterable[int] = STOP_SIGNALS,
    *,
    quiet: bool = False,
) -> None:
    """From now on, each of ``signals`` calls ``shutdown("signal-N")``, then the handler
    installed before (``quiet``: keeping its `KeyboardInterrupt` from the program, as rospy
    does). ``shutdown`` must not wait: it hands the shutdown to a thread. Installing again
    replaces the handlers installed here and chains to the ones before them. Main thread only;
    elsewhere nothing changes."""
    if not _main_thread():
        return
    for signum in signals:
        previous = signal.getsignal(signum)
        previous = getattr(previous, "chained", previous)  # ours: chain to what it chained

        def handler(sig: int, frame: FrameType | None, previous: Any = previous) -> None:
            shutdown(f"signal-{sig}")
            if callable(previous):
                if quiet:
                    with contextlib.suppress(KeyboardInterrupt):
                        previous(sig, frame)
                else:
                    previous(sig, frame)

        handler.chained = previous  # type: ignore[attr-defined]
        signal.signal(signum, handler)


#: The longest the main thread sleeps in `wait` before it looks for a due signal handler.
WAIT_SLICE = 0.2


def wait(event: threading.Event, timeout: float | None = None) -> bool:
    """``event.wait(timeout)``, in slices of `WAIT_SLICE` in the main thread, so a signal that
    the kernel gave another thread still reaches its handler there (see the module's notes)."""
    if not _main_thread():
        return event.wait(timeout)
    import time  # noqa: PLC0415 - as in `_main_thread`

    deadline = None if timeout is None else time.monotonic() + timeout
    while True:
        left = WAIT_SLICE if deadline is None else min(WAIT_SLICE, deadline - time.monotonic())
        if event.wait(max(left, 0.0)) or left <= 0:
            return event.is_set()


def interrupt_on_sigint() -> None:
    """Make SIGINT raise `KeyboardInterrupt` even when this process started with it ignored.

    A POSIX shell starts ``cmd &`` with SIGINT ignored, and Python then installs no handler of
    its own; ROS 1's tools install theirs and stop on ``kill -INT``, so rosx's do too.
    """
    if signal.getsignal(signal.SIGINT) is signal.SIG_IGN:
        signal.signal(signal.SIGINT, signal.default_int_handler)


__all__ = [
    "STOP_SIGNALS",
    "handling",
    "install_signal_handlers",
    "interrupt_on_sigint",
    "soon",
    "stop_on_signals",
    "wait",
]
