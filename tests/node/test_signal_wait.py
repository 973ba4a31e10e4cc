"""A signal that the kernel hands to a thread other than the main one still stops a program.

Python runs signal handlers in the main thread only; a main thread asleep in an untimed wait
would never run one that another thread took, and Ctrl-C would do nothing (it happened to
``rosx rosbridge`` one time in five). ``pthread_kill`` gives the signal to a chosen thread.
"""

from __future__ import annotations

import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest

from rosx.node import Node
from rosx.signals import install_signal_handlers, stop_on_signals, wait

pytestmark = pytest.mark.skipif(
    not Path("/proc/self/task").is_dir(), reason="needs Linux's /proc to see the main thread asleep"
)

#: Long enough for any machine; a wait that missed the handler returns False after it.
PATIENCE = 30.0


def _signal_from_another_thread(signum: int) -> None:
    """Once the main thread is asleep in a wait, a new thread signals itself."""

    def send() -> None:
        deadline = time.monotonic() + PATIENCE
        while not _main_thread_asleep_in_a_wait():
            if time.monotonic() > deadline:
                return
            time.sleep(0.001)
        signal.pthread_kill(threading.get_ident(), signum)

    threading.Thread(target=send, daemon=True).start()


def _main_thread_asleep_in_a_wait() -> bool:
    main = threading.main_thread()
    frame = sys._current_frames().get(main.ident or 0)
    stat = Path(f"/proc/self/task/{main.native_id}/stat").read_text()
    state = stat.rpartition(")")[2].split()[0]
    return frame is not None and frame.f_code.co_name == "wait" and state == "S"


def test_the_main_thread_waiting_runs_a_handler_another_thread_took() -> None:
    with stop_on_signals([signal.SIGUSR1]) as stop:
        assert threading.current_thread() is threading.main_thread()
        _signal_from_another_thread(signal.SIGUSR1)
        assert wait(stop, PATIENCE)


def test_a_node_waiting_for_shutdown_shuts_down_on_such_a_signal(master: str) -> None:
    before = signal.getsignal(signal.SIGUSR2)
    node = Node("/waiting", master_uri=master).start()
    try:
        install_signal_handlers(node.shutdown, [signal.SIGUSR2])
        _signal_from_another_thread(signal.SIGUSR2)
        assert node.wait_for_shutdown(PATIENCE)
        assert node.shutdown_reason == f"signal-{signal.SIGUSR2}"
    finally:
        signal.signal(signal.SIGUSR2, before)
        node.shutdown("test over")


# The main thread takes the event's own lock, as its wait does at times, and a signal's handler
# runs there, between two bytecodes: setting the event in the handler would wait forever.
HANDLER_UNDER_THE_LOCK = """
import os, signal
from rosx.signals import stop_on_signals, wait
with stop_on_signals([signal.SIGUSR1]) as stop:
    with stop._cond:
        os.kill(os.getpid(), signal.SIGUSR1)
        print("handled", flush=True)
    print("stopped", wait(stop, 30), flush=True)
"""


def test_a_handler_that_runs_while_the_main_thread_holds_the_events_lock_still_stops_it() -> None:
    done = subprocess.run(
        [sys.executable, "-c", HANDLER_UNDER_THE_LOCK],
        capture_output=True, text=True, timeout=PATIENCE, check=False,
    )  # fmt: skip
    assert (done.stdout, done.returncode) == ("handled\nstopped True\n", 0)


def test_a_timed_wait_still_times_out() -> None:
    assert not wait(threading.Event(), 0.05)
    assert wait(_set(), 0.0)
    assert wait(_set())


def _set() -> threading.Event:
    event = threading.Event()
    event.set()
    return event
