"""Bag files as bytes: what rosx writes reads back, reads in rosbags too, and survives a kill."""

from __future__ import annotations

import io
import shutil
from pathlib import Path

import pytest

from rosx.bag import records as rec
from rosx.bag.errors import BagError, BagUnindexedError
from rosx.bag.reader import BagReader
from rosx.bag.reindex import reindex
from rosx.bag.writer import BagWriter
from rosx.msg.codec.classes import get_message_class

Twist = get_message_class("geometry_msgs/Twist")
String = get_message_class("std_msgs/String")


def _serialized(msg: object) -> bytes:
    buff = io.BytesIO()
    msg.serialize(buff)  # type: ignore[attr-defined]
    return buff.getvalue()


def _header(cls: type) -> dict[str, str]:
    return {
        "callerid": "/talker",
        "latching": "0",
        "md5sum": cls._md5sum,  # type: ignore[attr-defined]
        "message_definition": cls._full_text,  # type: ignore[attr-defined]
        "topic": "/x",
        "type": cls._type,  # type: ignore[attr-defined]
    }


def _write(path: Path, count: int, compression: str = "none", threshold: int = 2000) -> None:
    with BagWriter(path, compression=compression, chunk_threshold=threshold) as bag:
        twist = bag.add_connection("/cmd_vel", _header(Twist))
        chat = bag.add_connection("/chatter", _header(String))
        for i in range(count):
            msg = Twist()
            msg.linear.x = float(i)
            bag.write(twist, 1_000_000_000 + i * 10_000_000, _serialized(msg))
            bag.write(chat, 1_000_000_000 + i * 10_000_000 + 5, _serialized(String(data=f"m{i}")))


@pytest.mark.parametrize("compression", ["none", "bz2", "lz4"])
def test_written_bags_read_back_in_time_order(tmp_path: Path, compression: str) -> None:
    path = tmp_path / "a.bag"
    _write(path, 100, compression)
    with BagReader(path) as bag:
        assert bag.message_count() == 200
        assert len(bag.chunks) > 1
        assert {bag.chunk_header(i).compression for i in range(len(bag.chunks))} == {compression}
        seen = list(bag.messages())
    assert [t for _, t, _ in seen] == sorted(t for _, t, _ in seen)
    twists = [Twist().deserialize(d).linear.x for c, _, d in seen if c.topic == "/cmd_vel"]
    assert twists == [float(i) for i in range(100)]
    assert seen[0][0].header["callerid"] == "/talker"


@pytest.mark.parametrize("compression", ["none", "bz2", "lz4"])
def test_rosbags_reads_what_rosx_writes(tmp_path: Path, compression: str) -> None:
    from rosbags.rosbag1 import Reader

    path = tmp_path / "a.bag"
    _write(path, 50, compression)
    with Reader(path) as reader:
        assert reader.message_count == 100
        assert sorted(c.topic for c in reader.connections) == ["/chatter", "/cmd_vel"]
        assert len(list(reader.messages())) == 100


def test_header_record_fills_4096_bytes(tmp_path: Path) -> None:
    path = tmp_path / "a.bag"
    _write(path, 1)
    data = path.read_bytes()
    assert data.startswith(b"#ROSBAG V2.0\n")
    (hlen,) = rec.U32.unpack_from(data, 13)
    (dlen,) = rec.U32.unpack_from(data, 17 + hlen)
    assert hlen + dlen == 4096


def test_time_windows_select_messages(tmp_path: Path) -> None:
    path = tmp_path / "a.bag"
    _write(path, 100)
    with BagReader(path) as bag:
        ids = {c.id for c in bag.topic_connections(["/cmd_vel"])}
        times = [t for _, t, _ in bag.messages(ids, 1_100_000_000, 1_200_000_000)]
    assert times == [1_000_000_000 + i * 10_000_000 for i in range(10, 21)]


def test_a_killed_writer_leaves_chunks_that_reindex_restores(tmp_path: Path) -> None:
    live = tmp_path / "live.bag.active"
    writer = BagWriter(live, chunk_threshold=1500)
    conn = writer.add_connection("/chatter", _header(String))
    for i in range(200):
        writer.write(conn, 1_000_000_000 + i, _serialized(String(data=f"message {i}")))
    written = sum(n for info in writer.chunks for n in info.counts.values())
    killed = tmp_path / "killed.bag.active"
    shutil.copy(live, killed)  # what a SIGKILL leaves: flushed chunks, no index
    writer.close()
    with pytest.raises(BagUnindexedError):
        BagReader(killed)
    report = reindex(killed)
    assert report.messages == written > 0
    assert report.dropped_bytes == 0
    with BagReader(killed) as bag:
        texts = [String().deserialize(d).data for _, _, d in bag.messages()]
    assert texts == [f"message {i}" for i in range(written)]


def test_reindex_drops_a_chunk_cut_short_and_says_how_much(tmp_path: Path) -> None:
    path = tmp_path / "a.bag"
    _write(path, 100, threshold=3000)
    with BagReader(path) as bag:
        cut = bag.chunks[2].pos + 100
        kept = sum(sum(info.counts.values()) for info in bag.chunks[:2])
    data = path.read_bytes()[:cut]
    path.write_bytes(data)
    report = reindex(path)
    assert (report.chunks, report.messages, report.dropped_bytes) == (2, kept, 100)
    with BagReader(path) as bag:
        assert bag.message_count() == kept == len(list(bag.messages()))


def test_append_mode_continues_a_closed_bag(tmp_path: Path) -> None:
    path = tmp_path / "a.bag"
    _write(path, 10)
    with BagWriter(path, "a") as bag:
        conn = bag.add_connection("/cmd_vel", _header(Twist))
        bag.write(conn, 5_000_000_000, _serialized(Twist()))
    with BagReader(path) as bag:
        assert bag.message_count() == 21
        assert len(bag.connections) == 2


@pytest.mark.parametrize(
    ("content", "message"),
    [
        (b"", "empty file"),
        (b"hello\n", "This does not appear to be a bag file"),
    ],
)
def test_bad_files_are_refused_with_ros1s_words(
    tmp_path: Path, content: bytes, message: str
) -> None:
    path = tmp_path / "bad.bag"
    path.write_bytes(content)
    with pytest.raises(BagError, match=message):
        BagReader(path)


def test_truncated_bags_are_unindexed(tmp_path: Path) -> None:
    path = tmp_path / "a.bag"
    _write(path, 10)
    for size in (20, 5000):
        cut = tmp_path / f"cut{size}.bag"
        cut.write_bytes(path.read_bytes()[:size])
        with pytest.raises(BagUnindexedError):
            BagReader(cut)


def test_roslz4_frame_layout() -> None:
    frame = rec.compress("lz4", b"x" * 100_000)
    # magic, then FLG: version 01, independent blocks, content checksum, no content size
    assert frame[:4] == b"\x04\x22\x4d\x18"
    assert frame[4] == 0x64
    assert rec.decompress("lz4", frame, 100_000) == b"x" * 100_000
