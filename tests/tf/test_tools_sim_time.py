"""tf's tools under simulated time, as a robot simulator runs them (``/use_sim_time`` set,
``/clock`` published): tf's static_transform_publisher stamps and paces its /tf in the
simulator's time, as roscpp's does, so a lookup at the simulator's "now" finds it, and
tf_monitor measures delays in that time (ROS 1 prints ~0, not the wall clock's 1.8e9 s)."""

from __future__ import annotations

import re
import subprocess
import sys
import threading
from collections.abc import Iterator

import pytest

from rosx.core import Core
from rosx.msg.codec.classes import get_message_class
from rosx.msg.codec.rostime import Time
from rosx.node import Node
from tests.support.cli import clean_environ
from tests.support.procs import running, wait_for

CLOCK = get_message_class("rosgraph_msgs/Clock")
TF = get_message_class("tf2_msgs/TFMessage")


@pytest.fixture
def sim_time() -> Iterator[tuple[dict[str, str], Node]]:
    """A core with /use_sim_time, and a node publishing /clock from 50 s, 10 ms a tick."""
    with Core(0, {"ROS_IP": "127.0.0.1"}) as core:
        environ = {**clean_environ(), "ROS_MASTER_URI": core.uri, "ROS_IP": "127.0.0.1"}
        node = Node("sim_clock", environ=environ).start()
        node.params.set("/use_sim_time", True)
        clock = node.advertise("/clock", CLOCK, queue_size=1)
        stop = threading.Event()

        def tick() -> None:
            nanos = 50_000_000_000
            while not stop.wait(0.01):
                nanos += 10_000_000
                clock.publish(CLOCK(Time(nanos // 1_000_000_000, nanos % 1_000_000_000)))

        ticker = threading.Thread(target=tick, daemon=True)
        ticker.start()
        try:
            yield environ, node
        finally:
            stop.set()
            ticker.join()
            node.shutdown("test over")


def test_tfs_publisher_and_tf_monitor_keep_the_simulators_time(
    sim_time: tuple[dict[str, str], Node],
) -> None:
    environ, node = sim_time
    stamps: list[float] = []
    node.subscribe(
        "/tf", TF, lambda m: stamps.extend(t.header.stamp.to_sec() for t in m.transforms)
    )
    rosx = [sys.executable, "-m", "rosx_commands"]
    publisher = [
        *rosx,
        "rosrun",
        "tf",
        "static_transform_publisher",
        *["1", "0", "0", "0", "0", "0", "base", "laser", "100"],
    ]
    monitor = [*rosx, "tf_monitor"]
    with (
        running(publisher, environ),
        running(monitor, environ, stdout=subprocess.PIPE, text=True) as watcher,
    ):
        wait_for(lambda: len(stamps) >= 3, what="three transforms on /tf")
        assert watcher.stdout is not None
        delays: list[float] = []
        for line in watcher.stdout:
            assert isinstance(line, str)
            found = re.match(r"Frame: laser published by \S+ Average Delay: (\S+) Max Delay", line)
            if found:
                delays.append(float(found.group(1)))
                break
    # stamped 0.1 s ahead of /clock, which has passed 50 s and not yet 1000
    assert all(50.0 < stamp < 1000.0 for stamp in stamps), stamps
    assert len(delays) == 1 and -1.0 < delays[0] < 1.0, delays
