"""``rosbag record``'s splitting, ``--node`` and ``-b`` on a live graph, in this process.

File names are ROS 1's (Debian's C++ recorder, ``-O NAME --split``): ``NAME_0.bag``,
``NAME_1.bag``…; with ``--max-splits N`` the N newest closed files stay beside the one being
written.
"""

from __future__ import annotations

import re
import threading
from collections.abc import Callable
from pathlib import Path
from typing import Any, BinaryIO

import pytest

from rosx.bag.reader import BagReader
from rosx.bag.recorder import Recorder, RecordOptions
from rosx.bag.writer import open_unbuffered
from rosx.msg.codec.classes import get_message_class
from rosx.node import Node
from tests.support.cli import clean_environ, rosx
from tests.support.procs import wait_for

String = get_message_class("std_msgs/String")


def _record(
    node: Node, prefix: Path, /, log: Any = None, opener: Any = open_unbuffered, **options: Any
) -> Recorder:
    recorder = Recorder(
        node,
        RecordOptions(prefix=str(prefix), append_date=False, **options),
        log or (lambda level, text: None),
        opener=opener,
    )
    recorder.start()
    return recorder


def _texts(path: Path) -> list[str]:
    with BagReader(path) as bag:
        return [String().deserialize(d).data for _, _, d in bag.messages()]


def _bags(folder: Path) -> list[str]:
    return sorted((p.name for p in folder.glob("*.bag*")), key=lambda n: (len(n), n))


def test_split_by_size_writes_name_0_name_1_and_loses_nothing(
    make_node: Callable[..., Node], tmp_path: Path
) -> None:
    pub = make_node("talker").advertise("/chatter", String, queue_size=None)
    recorder = _record(
        make_node("record"),
        tmp_path / "NAME.bag",
        topics=["/chatter"],
        split=True,
        max_size=20_000,
        chunk_size=4096,
    )
    wait_for(lambda: pub.get_num_connections() == 1, what="the recorder")
    for i in range(1000):
        pub.publish(String(data=f"{i:04d} " + "x" * 50))
    wait_for(lambda: recorder.written == 1000, what="every message written")
    recorder.stop()
    names = _bags(tmp_path)
    assert len(names) > 2
    assert names == [f"NAME_{i}.bag" for i in range(len(names))]
    got = [text for name in names for text in _texts(tmp_path / name)]
    assert got == [f"{i:04d} " + "x" * 50 for i in range(1000)]
    assert all((tmp_path / n).stat().st_size < 20_000 + 4096 + 8192 for n in names)


def test_split_by_duration_and_max_splits_keep_the_newest_files(
    make_node: Callable[..., Node], tmp_path: Path
) -> None:
    logged: list[str] = []
    pub = make_node("talker").advertise("/chatter", String, queue_size=None)
    recorder = _record(
        make_node("record"),
        tmp_path / "NAME",
        lambda level, text: logged.append(text),
        topics=["/chatter"],
        split=True,
        max_duration=0.2,
        max_splits=2,
    )
    wait_for(lambda: pub.get_num_connections() == 1, what="the recorder")
    sent = 0

    def published_into_file(n: int) -> bool:
        nonlocal sent
        pub.publish(String(data=str(sent)))
        sent += 1
        return f"Recording to '{tmp_path}/NAME_{n}.bag'." in logged

    wait_for(lambda: published_into_file(5), what="the sixth file")
    pub.publish(String(data=str(sent)))
    wait_for(lambda: recorder.written == sent + 1, what="every message written")
    recorder.stop()
    # A message later than a file's 0.2 s (a loaded machine) rolls on to the next file, or
    # past it: the newest file is the last one the recorder said it records to.
    opened = [int(n) for n in re.findall(r"Recording to '.*/NAME_(\d+)\.bag'\.", "\n".join(logged))]
    newest = opened[-1]
    assert opened == list(range(newest + 1)) and newest >= 5
    assert _bags(tmp_path) == [f"NAME_{n}.bag" for n in range(newest - 2, newest + 1)]
    assert f"Closing '{tmp_path}/NAME_0.bag'." in logged
    kept = [int(t) for name in _bags(tmp_path) for t in _texts(tmp_path / name)]
    assert kept == list(range(kept[0], sent + 1))


def test_node_records_what_that_node_subscribes_to(
    make_node: Callable[..., Node], tmp_path: Path
) -> None:
    listener = make_node("listener")
    listener.subscribe("/heard", String, lambda msg: None)
    talker = make_node("talker")
    heard = talker.advertise("/heard", String, queue_size=None)
    other = talker.advertise("/other", String, queue_size=None)
    recorder = _record(make_node("record"), tmp_path / "node", node="/listener")
    wait_for(lambda: heard.get_num_connections() == 2, what="the recorder on /heard")
    heard.publish(String(data="yes"))
    other.publish(String(data="no"))
    wait_for(lambda: recorder.written == 1, what="the message written")
    recorder.stop()
    assert other.get_num_connections() == 0
    with BagReader(tmp_path / "node.bag") as bag:
        assert [c.topic for c in bag.connections.values()] == ["/heard"]
    assert _texts(tmp_path / "node.bag") == ["yes"]


class _Gate:
    """A file whose writes wait until the gate opens (a disk that stalls)."""

    def __init__(self) -> None:
        self.armed = threading.Event()
        self.open = threading.Event()
        self.waiting = threading.Event()

    def opener(self, path: str, mode: str) -> BinaryIO:
        raw = open_unbuffered(path, mode)
        write = raw.write
        gate = self

        class Stalling:
            def __getattr__(self, name: str) -> Any:
                return getattr(raw, name)

            def write(self, data: Any) -> int:
                if gate.armed.is_set():
                    gate.waiting.set()
                    gate.open.wait(30)
                return write(data)

        return Stalling()  # type: ignore[return-value]


def test_a_full_buffer_drops_the_oldest_messages_with_ros1s_warning(
    make_node: Callable[..., Node], tmp_path: Path
) -> None:
    logged: list[tuple[str, str]] = []
    gate = _Gate()
    pub = make_node("talker").advertise("/chatter", String, queue_size=None)
    recorder = _record(
        make_node("record"),
        tmp_path / "b",
        lambda level, text: logged.append((level, text)),
        topics=["/chatter"],
        buffer_size=100_000,
        chunk_size=1,
        opener=gate.opener,
    )
    wait_for(lambda: pub.get_num_connections() == 1, what="the recorder")
    gate.armed.set()
    pub.publish(String(data="first " + "x" * 5000))
    wait_for(gate.waiting.is_set, what="the writer to stall")
    for i in range(100):
        pub.publish(String(data=f"{i:03d} " + "y" * 5000))
    wait_for(lambda: recorder.dropped > 0 and len(recorder._queue) > 0, what="drops")
    gate.open.set()
    wait_for(lambda: recorder.written + recorder.dropped == 101, what="the rest written")
    recorder.stop()
    warnings = [text for level, text in logged if level == "WARN"]
    assert warnings == ["rosbag record buffer exceeded.  Dropping oldest queued message."]
    got = _texts(tmp_path / "b.bag")
    assert got[0].startswith("first ")
    assert len(got) == 101 - recorder.dropped
    assert got[-1] == "099 " + "y" * 5000
    assert [t[:3] for t in got[1:]] == [f"{i:03d}" for i in range(100 - len(got) + 1, 100)]


@pytest.mark.parametrize("repeat", [True, False])
def test_repeat_latched_starts_each_new_file_with_the_latched_messages(
    make_node: Callable[..., Node], tmp_path: Path, repeat: bool
) -> None:
    talker = make_node("talker")
    latched = talker.advertise("/map", String, queue_size=None, latch=True)
    chatter = talker.advertise("/chatter", String, queue_size=None)
    recorder = _record(
        make_node("record"),
        tmp_path / "NAME",
        topics=["/map", "/chatter"],
        split=True,
        max_size=10_000,
        chunk_size=2048,
        repeat_latched=repeat,
    )
    wait_for(lambda: chatter.get_num_connections() == 1, what="the recorder on /chatter")
    wait_for(lambda: latched.get_num_connections() == 1, what="the recorder on /map")
    latched.publish(String(data="map 1"))
    latched.publish(String(data="map 2"))
    wait_for(lambda: recorder.written == 2, what="the latched messages written")
    for i in range(400):
        chatter.publish(String(data=f"{i:04d} " + "x" * 50))
    wait_for(lambda: recorder.written == 402, what="every message written")
    recorder.stop()
    names = _bags(tmp_path)
    assert len(names) > 2
    maps = [[t for t in _texts(tmp_path / n) if t.startswith("map")] for n in names]
    # Each later file holds the publisher's last latched message once, still latched.
    copies = [["map 2"] if repeat else [] for _ in names[1:]]
    assert maps == [["map 1", "map 2"], *copies]
    for name in names[1:] if repeat else []:
        with BagReader(tmp_path / name) as bag:
            headers = [c.header for c in bag.connections.values() if c.topic == "/map"]
        assert [h.get("latching") for h in headers] == ["1"]
    chatter_texts = [t for n in names for t in _texts(tmp_path / n) if not t.startswith("map")]
    assert chatter_texts == [f"{i:04d} " + "x" * 50 for i in range(400)]


def test_publish_announces_each_new_file_on_begin_write(
    make_node: Callable[..., Node], tmp_path: Path
) -> None:
    announced: list[str] = []
    make_node("listener", namespace="/lab").subscribe(
        "/lab/begin_write", String, lambda msg: announced.append(msg.data)
    )
    chatter = make_node("talker").advertise("/chatter", String, queue_size=None)
    recorder = _record(
        make_node("record", namespace="/lab"),
        tmp_path / "NAME",
        topics=["/chatter"],
        split=True,
        max_size=10_000,
        chunk_size=2048,
        publish=True,
    )
    # The first file's name is latched: a subscriber connecting later still gets it.
    wait_for(lambda: announced == [f"{tmp_path}/NAME_0.bag"], what="the first file announced")
    wait_for(lambda: chatter.get_num_connections() == 1, what="the recorder on /chatter")
    for i in range(400):
        chatter.publish(String(data=f"{i:04d} " + "x" * 50))
    wait_for(lambda: recorder.written == 400, what="every message written")
    wait_for(lambda: len(announced) == len(_bags(tmp_path)), what="every file announced")
    recorder.stop()
    names = _bags(tmp_path)
    assert len(names) > 2
    assert announced == [f"{tmp_path}/{name}" for name in names]


def test_named_topics_are_subscribed_in_sorted_order_then_the_file_opens(
    make_node: Callable[..., Node], tmp_path: Path
) -> None:
    """ROS 1's C++ recorder logs ``Subscribing to`` for each named topic, sorted, once each
    and as given, before ``Recording to``."""
    logged: list[str] = []
    recorder = _record(
        make_node("record"),
        tmp_path / "order",
        lambda level, text: logged.append(f"{level} {text}"),
        topics=["/zeta", "/alpha", "/zeta", "beta"],
    )
    recorder.stop()
    assert logged == [
        "INFO Subscribing to /alpha",
        "INFO Subscribing to /zeta",
        "INFO Subscribing to beta",
        f"INFO Recording to '{tmp_path}/order.bag'.",
        f"INFO Closing '{tmp_path}/order.bag'.",
    ]


def test_a_topic_the_master_refuses_is_one_error_line_and_leaves_no_file(
    master: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)
    done = rosx(
        "rosbag", "record", "-O", "x", "bad name", environ=clean_environ(ROS_MASTER_URI=master)
    )
    assert (done.status, done.err) == (1, "ERROR: parameter [topic] contains illegal chars\n")
    assert list(tmp_path.iterdir()) == []


def test_a_bag_that_cannot_be_created_is_ros1s_error_line(master: str, tmp_path: Path) -> None:
    target = tmp_path / "no such folder" / "x"
    done = rosx(
        "rosbag", "record", "-O", str(target), "/scan", environ=clean_environ(ROS_MASTER_URI=master)
    )
    assert done.status == 1  # ROS 1's exits 0 (README.md)
    said = f"Error writing: Error opening file: {target}.bag.active"
    assert re.fullmatch(rf"\[ERROR\] \[\d+\.\d{{9}}\]: {re.escape(said)}\n", done.err)
