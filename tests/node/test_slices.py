"""The threads that run a subscription's callbacks ask the kernel for a short time slice.

The kernel shows a thread's slice in ``/proc/self/task/<tid>/sched`` (``se.slice``); where it
does not, or where it ignores the request (Linux before 6.12), the tests skip.
"""

from __future__ import annotations

import os
import subprocess
import sys
import threading
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from rosx.msg.codec.classes import get_message_class
from rosx.node import Node, local, slices
from tests.support.procs import wait_for

Twist = get_message_class("geometry_msgs/Twist")


def slice_of(tid: int) -> int | None:
    """The thread's time slice in nanoseconds, as the kernel shows it."""
    try:
        text = Path(f"/proc/self/task/{tid}/sched").read_text()
    except OSError:
        return None
    for line in text.splitlines():
        name, _, value = line.partition(":")
        if name.strip() == "se.slice":
            return int(value)
    return None


def in_thread(job: Callable[[], Any]) -> Any:
    """Run ``job`` on a thread of its own (a slice or nice value set there stays there)."""
    out: list[Any] = []
    thread = threading.Thread(target=lambda: out.append(job()))
    thread.start()
    thread.join()
    return out[0]


def _supported() -> bool:
    def probe() -> bool:
        return slices.request_short_slice() and slice_of(threading.get_native_id()) == (
            slices.SLICE_NS
        )

    return bool(in_thread(probe))


pytestmark = pytest.mark.skipif(
    not _supported(), reason="this kernel does not take a thread's requested time slice"
)


@pytest.mark.parametrize("in_process", [True, False], ids=["in-process", "socket"])
def test_callbacks_run_on_a_thread_with_a_short_slice(
    make_node: Callable[..., Node], monkeypatch: pytest.MonkeyPatch, in_process: bool
) -> None:
    monkeypatch.setattr(local, "ENABLED", in_process)
    talker, listener = make_node("slice_talker"), make_node("slice_listener")
    threads: list[int] = []
    sub = listener.subscribe("/sliced", Twist, lambda _: threads.append(threading.get_native_id()))
    pub = talker.advertise("/sliced", Twist, queue_size=10)
    wait_for(lambda: pub.get_num_connections() == 1 and sub.get_num_connections() == 1)
    pub.publish(Twist())
    wait_for(lambda: bool(threads))
    assert threads[0] != threading.get_native_id()
    assert slice_of(threads[0]) == slices.SLICE_NS
    assert slice_of(threading.get_native_id()) != slices.SLICE_NS  # the caller's is its own


def test_the_nice_value_stays() -> None:
    def niced() -> tuple[bool, int]:
        tid = threading.get_native_id()
        os.setpriority(os.PRIO_PROCESS, tid, 7)
        accepted = slices.request_short_slice()
        return accepted, os.getpriority(os.PRIO_PROCESS, tid)

    assert in_thread(niced) == (True, 7)


def test_off_in_the_environment() -> None:
    script = (
        "import threading\n"
        "from rosx.node import slices\n"
        "print(slices.request_short_slice())\n"
        "print(open(f'/proc/self/task/{threading.get_native_id()}/sched').read())\n"
    )
    env = dict(os.environ, ROSX_SHORT_SLICE="0")
    done = subprocess.run(
        [sys.executable, "-c", script],
        env=env,
        cwd=Path(__file__).resolve().parents[2],
        capture_output=True,
        text=True,
        check=True,
    )
    first, _, sched = done.stdout.partition("\n")
    assert first == "False"
    assert f"se.slice:{slices.SLICE_NS}\n" not in sched.replace(" ", "")
