"""A publisher hands its CPU to subscribers on this machine inside a burst, within a budget.

`rosx.node.slices.Handoff` decides; these tests drive it with a clock they move themselves
and count the yields it makes, then check that a publication asks it exactly when a socket
subscriber on this machine is connected.
"""

from __future__ import annotations

import os
import socket
import subprocess
import sys
import threading
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from rosx.msg.codec.classes import get_message_class
from rosx.node import Node, local, outgoing, publication, slices, unixros
from tests.support.procs import wait_for

Twist = get_message_class("geometry_msgs/Twist")


class Scheduler:
    """A clock moved by hand, and a ``sched_yield`` that counts its calls and takes time."""

    def __init__(self) -> None:
        self.now = 1_000_000_000
        self.yields = 0
        #: How long each yield takes (another thread running meanwhile).
        self.yield_ns = 5_000

    def clock(self) -> int:
        return self.now

    def sched_yield(self) -> int:
        self.yields += 1
        self.now += self.yield_ns
        return 0


@pytest.fixture
def sched(monkeypatch: pytest.MonkeyPatch) -> Scheduler:
    fake = Scheduler()
    # Publications, streams and hand-offs all read this clock.
    for module in (slices, publication, outgoing):
        monkeypatch.setattr(module, "_clock", fake.clock)
    monkeypatch.setattr(slices, "_sched_yield", lambda: fake.sched_yield)
    return fake


def publish_run(handoff: slices.Handoff, sched: Scheduler, count: int, apart_ns: int) -> int:
    """Publish ``count`` messages ``apart_ns`` apart; the yields made."""
    before = sched.yields
    for _ in range(count):
        sched.now += apart_ns
        if handoff.start():
            handoff.give_way()
    return sched.yields - before


def test_a_burst_yields_after_its_2nd_to_16th_message(sched: Scheduler) -> None:
    handoff = slices.Handoff()
    assert publish_run(handoff, sched, 10, 3_000) == 9
    sched.now += 10_000_000
    assert publish_run(handoff, sched, 1, 3_000) == 0  # a lone message: the reader preempts
    sched.now += 10_000_000
    assert publish_run(handoff, sched, 1000, 3_000) == slices.HANDOFF_RUN - 1  # a flood


def test_a_pause_starts_a_new_run(sched: Scheduler) -> None:
    handoff = slices.Handoff()
    assert publish_run(handoff, sched, 40, slices.RUN_GAP_NS) == 0  # 5 kHz: each alone
    assert publish_run(handoff, sched, 40, slices.RUN_GAP_NS - 1) == slices.HANDOFF_RUN - 1


def test_a_pause_while_subscribers_catch_up_is_no_pause(sched: Scheduler) -> None:
    # A publisher kept from the GIL by a callback of its own process goes on with its flood.
    handoff = slices.Handoff()
    behind = [True]
    assert [handoff.start(lambda: not behind[0]) for _ in range(20)].count(True) == 16
    sched.now += 10_000_000
    assert not handoff.start(lambda: not behind[0])
    behind[0] = False
    sched.now += 10_000_000
    assert handoff.start(lambda: not behind[0])


def test_yields_are_paid_from_a_credit(sched: Scheduler) -> None:
    handoff = slices.Handoff()
    sched.yield_ns = 150_000  # a reader that takes its time, short of a slow yield
    yields = []
    for _ in range(100):
        sched.now += 10_000_000
        yields.append(publish_run(handoff, sched, 10, 3_000))
    # 5 ms saved up, then 1/32 of each 10 ms pause: far fewer than 9 a run.
    spent = sum(yields) * sched.yield_ns
    assert spent <= slices.CREDIT_CAP_NS + 100 * (10_000_000 >> 5) + 9 * sched.yield_ns
    assert yields[0] == 9
    assert 0 < max(yields[10:]) <= 3  # 0.3 ms of credit a run: 2 or 3 yields


def test_a_slow_yield_stops_them_for_a_second(sched: Scheduler) -> None:
    handoff = slices.Handoff()
    sched.yield_ns = 1_500_000  # each yield lets another program run a whole slice
    sched.now += 10_000_000
    assert publish_run(handoff, sched, 10, 3_000) == 1
    sched.yield_ns = 5_000
    yields = []
    for _ in range(120):  # 1.2 s of bursts every 10 ms
        sched.now += 10_000_000
        yields.append(publish_run(handoff, sched, 10, 3_000))
    first = next(i for i, n in enumerate(yields) if n)
    assert 90 <= first <= 101
    assert yields[first + 1 :] == [9] * (len(yields) - first - 1)


@pytest.fixture
def given_way(monkeypatch: pytest.MonkeyPatch, sched: Scheduler) -> list[bool]:
    """Each `Handoff.give_way` that publications made meanwhile make: whether it lets the GIL
    go. The clock stands still: every message is published back to back."""
    made: list[bool] = []
    monkeypatch.setattr(slices, "HANDOFF_ENABLED", True)
    monkeypatch.setattr(
        slices.Handoff, "give_way", lambda self, *, release_gil=False: made.append(release_gil)
    )
    return made


@pytest.mark.parametrize("transport", ["UNIXROS", "TCPROS", "in-process"])
def test_a_publication_gives_way_to_subscribers_on_this_machine_in_a_burst(
    make_node: Callable[..., Node],
    monkeypatch: pytest.MonkeyPatch,
    sched: Scheduler,
    given_way: list[bool],
    transport: str,
) -> None:
    monkeypatch.setattr(local, "ENABLED", transport == "in-process")
    monkeypatch.setattr(unixros, "ENABLED", transport == "UNIXROS")
    talker, listener = make_node("handoff_talker"), make_node("handoff_listener")
    got: list[float] = []
    sub = listener.subscribe("/handoff", Twist, lambda msg: got.append(msg.linear.x))
    pub = talker.advertise("/handoff", Twist, queue_size=100)
    wait_for(lambda: pub.get_num_connections() == 1 and sub.get_num_connections() == 1)
    sched.now += slices.RUN_GAP_NS
    for i in range(20):
        msg = Twist()
        msg.linear.x = float(i)
        pub.publish(msg)
    wait_for(lambda: len(got) == 20)
    assert got == [float(i) for i in range(20)]
    # Only the first 16 of a run are a burst; one of this process needs the GIL let go.
    assert given_way == [transport == "in-process"] * slices.HANDOFF_RUN


@pytest.mark.parametrize("transport", ["UNIXROS", "TCPROS"])
def test_a_flood_held_back_is_one_run_until_a_pause(
    make_node: Callable[..., Node],
    monkeypatch: pytest.MonkeyPatch,
    sched: Scheduler,
    given_way: list[bool],
    transport: str,
) -> None:
    # Over a Unix socket the stream holds the flood's frames back while the reader is stuck
    # in its callback (over TCP it may, when the kernel holds bytes back too), and the
    # hand-off is then only told the time: the runs and bursts are those of every other link.
    monkeypatch.setattr(local, "ENABLED", False)
    monkeypatch.setattr(unixros, "ENABLED", transport == "UNIXROS")
    talker, listener = make_node("flood_talker"), make_node("flood_listener")
    got: list[int] = []
    go_on = threading.Event()

    def stuck(msg: Any) -> None:
        go_on.wait(30)
        got.append(int(msg.linear.x))

    sub = listener.subscribe("/flood", Twist, stuck, queue_size=0)
    pub = talker.advertise("/flood", Twist, queue_size=0)
    wait_for(lambda: pub.get_num_connections() == 1 and sub.get_num_connections() == 1)
    (link,) = talker.publications["/flood"].links
    sent = iter(range(1000))

    def publish(count: int) -> None:
        for _ in range(count):
            sched.now += 1_000  # a Python publisher's pace in a flood
            msg = Twist()
            msg.linear.x = float(next(sent))
            pub.publish(msg)

    sched.now += slices.RUN_GAP_NS
    publish(300)  # 0.3 ms: longer than a pause that ends a run
    assert link.stream.holding or transport == "TCPROS"
    assert len(given_way) == slices.HANDOFF_RUN
    sched.now += slices.RUN_GAP_NS - 1_001  # a short pause: the run goes on
    publish(20)
    assert len(given_way) == slices.HANDOFF_RUN
    sched.now += slices.RUN_GAP_NS  # a pause: a new run, whose first messages are a burst
    publish(20)
    assert len(given_way) == 2 * slices.HANDOFF_RUN
    go_on.set()
    wait_for(lambda: len(got) == 340)
    assert got == list(range(340))


def test_a_subscriber_in_this_process_is_eager_during_a_burst_only(
    make_node: Callable[..., Node],
    monkeypatch: pytest.MonkeyPatch,
    sched: Scheduler,
    given_way: list[bool],
) -> None:
    monkeypatch.setattr(local, "ENABLED", True)
    talker, listener = make_node("eager_talker"), make_node("eager_listener")
    got: list[int] = []
    sub = listener.subscribe("/eager", Twist, lambda msg: got.append(int(msg.linear.x)))
    pub = talker.advertise("/eager", Twist, queue_size=0)
    wait_for(lambda: pub.get_num_connections() == 1 and sub.get_num_connections() == 1)
    receiver = listener.subscriptions["/eager"].receiver
    eager: list[bool] = []
    for i in range(40):
        if i == 30:  # a pause, once the subscriber has caught up: a new burst
            wait_for(lambda: len(got) == 30 and receiver.idle)
            sched.now += slices.RUN_GAP_NS
        msg = Twist()
        msg.linear.x = float(i)
        pub.publish(msg)
        eager.append(receiver.eager)
    wait_for(lambda: len(got) == 40)
    assert got == list(range(40))
    assert eager == [True] * 16 + [False] * 14 + [True] * 10


def test_a_tcp_peer_on_loopback_or_on_our_own_address_is_on_this_machine() -> None:
    with socket.create_server(("127.0.0.1", 0)) as server:
        client = socket.create_connection(server.getsockname())
        accepted, peer = server.accept()
        with client, accepted:
            assert publication._on_this_machine(accepted, peer[0])
            assert not publication._on_this_machine(accepted, "192.0.2.7")
            assert not publication._on_this_machine(accepted, "not an address")


def test_off_in_the_environment() -> None:
    script = "from rosx.node import slices\nprint(slices.HANDOFF_ENABLED)\n"
    done = subprocess.run(
        [sys.executable, "-c", script],
        env=dict(os.environ, ROSX_HANDOFF="0"),
        cwd=Path(__file__).resolve().parents[2],
        capture_output=True,
        text=True,
        check=True,
    )
    assert done.stdout == "False\n"
