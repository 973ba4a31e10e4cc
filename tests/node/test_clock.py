"""The node runtime's clock: the wall clock, or ``/clock`` once told to follow it."""

from __future__ import annotations

import sys
import threading

import pytest

from rosx.msg.codec.rostime import Time
from rosx.node.clock import Clock, Rate
from rosx.node.errors import NodeShutdownError, TimeMovedBackwardsError
from tests.support.procs import wait_for


def test_a_clock_reads_the_wall_until_it_follows_simulated_time() -> None:
    clock = Clock()
    assert clock.is_wallclock and clock.now().to_sec() > 1e9
    clock.use_sim_time()
    assert not clock.is_wallclock and clock.now() == Time(0, 0)
    clock.set(Time(12, 500_000_000))
    assert clock.now() == Time(12, 500_000_000) and clock.seconds() == 12.5


def test_a_simulated_sleep_ends_on_shutdown_and_on_time_going_back() -> None:
    clock = Clock()
    clock.use_sim_time()
    shutdown = threading.Event()
    shutdown.set()
    with pytest.raises(NodeShutdownError):
        clock.sleep(1.0, shutdown=shutdown)  # no /clock yet, and the node is gone
    clock.set(Time(30, 0))
    rate = Rate(0.5, clock=clock)
    outcome: list[TimeMovedBackwardsError] = []

    def sleep() -> None:
        try:
            rate.sleep()
        except TimeMovedBackwardsError as error:
            outcome.append(error)

    sleeper = threading.Thread(target=sleep)
    sleeper.start()
    wait_for(lambda: _waiting(sleeper), what="the sleep to begin")
    clock.set(Time(10, 0))
    sleeper.join(10)
    assert outcome and outcome[0].jump == pytest.approx(20.0)


def _waiting(thread: threading.Thread) -> bool:
    frame = sys._current_frames().get(thread.ident or 0)
    return frame is not None and frame.f_code.co_name == "wait"
