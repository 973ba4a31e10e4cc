"""Recording and playing on a live graph: rosx publishers, the recorder and the player in one
process, on the test's master."""

from __future__ import annotations

import itertools
import threading
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from rosx.bag.player import Player, PlayOptions
from rosx.bag.reader import BagReader
from rosx.bag.recorder import Recorder, RecordOptions
from rosx.msg.codec.classes import get_message_class
from rosx.msg.codec.rostime import Time
from rosx.node import Node, local
from tests.support.frames import HeldRead
from tests.support.procs import wait_for

String = get_message_class("std_msgs/String")


def _record(node: Node, path: Path, **options: Any) -> Recorder:
    recorder = Recorder(
        node,
        RecordOptions(prefix=str(path), append_date=False, **options),
        lambda level, text: None,
    )
    recorder.start()
    return recorder


def test_record_all_picks_up_late_topics_and_loses_nothing(
    make_node: Callable[..., Node], tmp_path: Path
) -> None:
    talker = make_node("talker")
    early = talker.advertise("/early", String, queue_size=None)
    recorder = _record(make_node("record"), tmp_path / "all", record_all=True)
    wait_for(lambda: early.get_num_connections() == 1, what="the recorder on /early")
    late = talker.advertise("/late", String, queue_size=None)
    wait_for(lambda: late.get_num_connections() == 1, what="the recorder on /late")
    assert Path(f"{tmp_path}/all.bag.active").exists()
    for i in range(2000):
        early.publish(String(data=f"e{i}"))
        late.publish(String(data=f"l{i}"))
    wait_for(lambda: recorder.written + len(recorder._queue) >= 4000, what="every message queued")
    recorder.stop()
    assert not Path(f"{tmp_path}/all.bag.active").exists()
    with BagReader(tmp_path / "all.bag") as bag:
        by_topic: dict[str, list[str]] = {}
        for conn, _, data in bag.messages():
            by_topic.setdefault(conn.topic, []).append(String().deserialize(data).data)
        headers = {c.topic: c.header for c in bag.connections.values()}
    assert by_topic["/early"] == [f"e{i}" for i in range(2000)]
    assert by_topic["/late"] == [f"l{i}" for i in range(2000)]
    assert headers["/late"]["callerid"] == "/talker"
    assert headers["/late"]["md5sum"] == String._md5sum


def test_limit_stops_after_n_messages_per_topic(
    make_node: Callable[..., Node], tmp_path: Path
) -> None:
    talker = make_node("talker")
    pub = talker.advertise("/chatter", String, queue_size=None)
    recorder = _record(make_node("record"), tmp_path / "limited", topics=["/chatter"], limit=5)
    wait_for(lambda: pub.get_num_connections() == 1, what="the recorder")
    for i in range(20):
        pub.publish(String(data=str(i)))
    wait_for(lambda: recorder.stopping, what="the recorder to stop by itself")
    recorder.stop()
    with BagReader(tmp_path / "limited.bag") as bag:
        assert [String().deserialize(d).data for _, _, d in bag.messages()] == list("01234")


@pytest.mark.parametrize("rate", [1.0, 4.0])
def test_play_delivers_every_message_with_the_recorded_spacing(
    make_node: Callable[..., Node], tmp_path: Path, rate: float
) -> None:
    from rosx.bag.writer import BagWriter

    path = tmp_path / "spaced.bag"
    header = {
        "type": String._type,
        "md5sum": String._md5sum,
        "message_definition": String._full_text,
        "topic": "/chatter",
        "latching": "1",
    }
    with BagWriter(path) as writer:
        conn = writer.add_connection("/chatter", header)
        for i in range(20):
            buff = bytearray()
            String(data=str(i)).serialize(_Sink(buff))
            writer.write(conn, 10**9 + i * 20_000_000, bytes(buff))
    got: list[str] = []
    done = threading.Event()

    def heard(msg: Any) -> None:
        got.append(msg.data)
        if len(got) == 20:
            done.set()

    make_node("listener").subscribe("/played", String, heard)
    player_node = make_node("play", remappings={"/chatter": "/played"})
    with BagReader(path) as bag:
        player = Player(player_node, [bag], PlayOptions(rate=rate))
        player.timing = []
        player.advertise()
        wait_for(
            lambda: player._publishers["/chatter"].get_num_connections() == 1, what="a subscriber"
        )
        player.run()
    assert done.wait(5)
    assert got == [str(i) for i in range(20)]
    assert player_node.publications["/played"].latching
    due = [d for d, _ in player.timing]
    spacing = [b - a for a, b in itertools.pairwise(due)]
    assert all(abs(s - 0.02 / rate) < 1e-6 for s in spacing)


class _Sink:
    def __init__(self, buff: bytearray) -> None:
        self.buff = buff

    def write(self, data: bytes) -> None:
        self.buff += data


def _wait_for_time(recorder: Recorder, seconds: float) -> None:
    wait_for(lambda: recorder.node.clock.now().to_sec() == seconds, what=f"time {seconds}")


def _wait_for_count(recorder: Recorder, count: int) -> None:
    wait_for(lambda: recorder.written + len(recorder._queue) >= count, what=f"{count} messages")


def test_under_sim_time_without_a_clock_it_says_so(
    make_node: Callable[..., Node], tmp_path: Path
) -> None:
    """A /use_sim_time left true by a simulator that has gone: nothing can be stamped, and
    rosbag record says why in ROS 1's words instead of writing an empty bag in silence."""
    setter = make_node("simulator")
    setter.params.set("/use_sim_time", True)
    lines: list[tuple[str, str]] = []
    try:
        recorder = Recorder(
            make_node("record"),
            RecordOptions(prefix=str(tmp_path / "sim"), append_date=False, topics=["/chatter"]),
            lambda level, text: lines.append((level, text)),
        )
        recorder.start()
        warning = (
            "WARN",
            "/use_sim_time set to true and no clock published.  Still waiting for valid time...",
        )
        wait_for(lambda: warning in lines, what="the warning")
        recorder.stop()
    finally:
        setter.params.delete("/use_sim_time")  # the master is the module's
    assert lines.count(warning) == 1


def test_under_sim_time_messages_carry_the_clocks_time(
    make_node: Callable[..., Node], tmp_path: Path
) -> None:
    """As ROS 1's rosbag record (roscpp's time): with /use_sim_time, messages carry the time on
    /clock, and --duration is simulated seconds."""
    talker = make_node("simulator")
    talker.params.set("/use_sim_time", True)
    try:
        clock = talker.advertise("/clock", get_message_class("rosgraph_msgs/Clock"), queue_size=10)
        pub = talker.advertise("/chatter", String, queue_size=None)
        recorder = _record(
            make_node("record"), tmp_path / "sim", topics=["/chatter"], max_duration=1.5
        )
        wait_for(lambda: pub.get_num_connections() == 1, what="the recorder")
        wait_for(lambda: clock.get_num_connections() == 1, what="the recorder on /clock")
        for count, seconds in enumerate((1000, 1001), 1):
            clock.publish(get_message_class("rosgraph_msgs/Clock")(clock=Time.from_sec(seconds)))
            _wait_for_time(recorder, seconds)
            pub.publish(String(data=f"at {seconds}"))
            _wait_for_count(recorder, count)  # recorded before the clock moves on
        # --duration 1.5 in simulated time: at 1002 the recording ends, whatever the wall.
        clock.publish(get_message_class("rosgraph_msgs/Clock")(clock=Time.from_sec(1002)))
        _wait_for_time(recorder, 1002)
        wait_for(lambda: recorder.stopping, what="the recorder to stop by itself")
        recorder.stop()
    finally:
        talker.params.delete("/use_sim_time")  # the master is the module's
    with BagReader(tmp_path / "sim.bag") as bag:
        seen = [(String().deserialize(d).data, t) for _, t, d in bag.messages()]
    assert seen == [("at 1000", 1000 * 10**9), ("at 1001", 1001 * 10**9)]


def test_a_stop_keeps_what_a_connection_was_reading_when_it_came(
    make_node: Callable[..., Node], tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Messages a connection's thread has just read when the recording stops are counted only
    when that read returns: the stop waits for the connection to end before it looks."""
    monkeypatch.setattr(local, "ENABLED", False)  # the recorder reads a socket
    pub = make_node("held_talker").advertise("/held", String, queue_size=None)
    node = make_node("record")
    recorder = _record(node, tmp_path / "held", topics=["/held"])
    wait_for(lambda: pub.get_num_connections() == 1, what="the recorder on /held")
    stream: Any = next(iter(recorder._subscribers["/held"].subscription.streams.values()))
    held = HeldRead(stream.sock, armed=False)
    stream.sock = held
    # A second callback on the topic: the thread's quick loop for one callback keeps the
    # socket it began with; with two, each read takes the stream's socket, the wrapped one.
    node.subscribe("/held", None, lambda raw: None)
    sent: list[str] = []

    def publish(text: str) -> None:
        sent.append(text)
        pub.publish(String(data=text))

    def queued() -> int:
        return recorder.written + len(recorder._queue)

    try:
        # The thread may be waiting in a read that began before the swap: a first message
        # ends it, a second one the read after it, which began unarmed too (or armed: then
        # the second message is held with the rest).
        publish("m0")
        wait_for(lambda: queued() == 1, what="m0 queued")
        held.armed.set()
        publish("m1")
        wait_for(held.entered.is_set, what="a read begun armed")
        for i in range(2, 7):
            publish(f"m{i}")
        wait_for(lambda: pub.delivered_to() == {"/record"}, what="the messages sent")
        held.published.set()
        assert held.taken.wait(10), "the thread did not read through the wrapped socket"
        stopping = threading.Thread(target=recorder.stop)
        stopping.start()
        assert held.shut.wait(10), "the recorder did not stop reading"
        held.go.set()  # the read returns: its messages are counted now
        stopping.join(60)
        assert not stopping.is_alive()
    finally:
        held.release()
    with BagReader(tmp_path / "held.bag") as bag:
        recorded = [String().deserialize(data).data for _, _, data in bag.messages()]
    assert recorded == sent
