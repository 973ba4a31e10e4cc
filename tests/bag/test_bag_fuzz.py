"""Bags under fuzz: what is written reads back, and damaged bytes give `BagError`, nothing else.

Random bags (connections, times, payloads, compression, chunk sizes) are written with
`BagWriter` and read back whole; then their bytes are damaged (bits flipped, bytes replaced,
lengths set to huge values, the file cut) and opened, read, summarised and reindexed: each step
either works or raises `BagError` with one line of text; never another exception, never a hang.
The named bombs (record, chunk and index lengths of 4 GiB, a bz2 chunk that expands a
thousandfold) stay within `MEMORY_BOUND`.
"""

from __future__ import annotations

import bz2
import shutil
import struct
import tempfile
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given
from hypothesis import strategies as st

from rosx.bag import records as rec
from rosx.bag.errors import BagError
from rosx.bag.info import summarize
from rosx.bag.reader import BagReader
from rosx.bag.reindex import reindex
from rosx.bag.writer import BagWriter
from tests.support.fuzz import MEMORY_BOUND, fuzz_settings, no_hang, peak_allocation

pytestmark = pytest.mark.fuzz

_TOPICS = st.sampled_from(["/a", "/b/c", "/chatter", "/x"])
_HEADERS = st.fixed_dictionaries(
    {"type": st.sampled_from(["std_msgs/String", "pkg/T"]), "md5sum": st.just("0" * 32)},
    optional={
        "callerid": st.text(max_size=8),
        "latching": st.sampled_from(["0", "1"]),
        "message_definition": st.text(max_size=40),
    },
)


@st.composite
def bags(draw: st.DrawFn) -> dict[str, Any]:
    """A bag's content: connections, then messages ``(connection, time_ns, data)``."""
    connections = draw(st.lists(st.tuples(_TOPICS, _HEADERS), min_size=1, max_size=4))
    messages = draw(
        st.lists(
            st.tuples(
                st.integers(0, len(connections) - 1),
                st.integers(0, 2**32 * 10**9 - 1),
                st.binary(max_size=300),
            ),
            max_size=30,
        )
    )
    return {
        "connections": connections,
        "messages": messages,
        "compression": draw(st.sampled_from(rec.COMPRESSIONS)),
        "threshold": draw(st.integers(64, 4096)),
    }


def _write(path: Path, bag: dict[str, Any]) -> list[int]:
    """Write ``bag`` to ``path``; the connection ids of its connections."""
    with BagWriter(path, compression=bag["compression"], chunk_threshold=bag["threshold"]) as out:
        ids = [out.add_connection(topic, header) for topic, header in bag["connections"]]
        for which, stamp, data in bag["messages"]:
            out.write(ids[which], stamp, data)
    return ids


@pytest.fixture(scope="module")
def folder() -> Any:
    with tempfile.TemporaryDirectory() as name:
        yield Path(name)


@fuzz_settings(60)
@given(bag=bags())
def test_what_is_written_reads_back(folder: Path, bag: dict[str, Any]) -> None:
    path = folder / "round.bag"
    ids = _write(path, bag)
    with BagReader(path) as reader:
        read = [(c.id, c.topic, stamp, data) for c, stamp, data in reader.messages()]
        assert reader.message_count() == len(bag["messages"])
        # Connections are recorded with their first message, as ROS 1's writer does.
        used = {ids[which]: bag["connections"][which] for which, _, _ in bag["messages"]}
        assert {c.id: (c.topic, c.header) for c in reader.connections.values()} == used
    written = [
        (ids[which], bag["connections"][which][0], stamp, data)
        for which, stamp, data in bag["messages"]
    ]
    # Time order; equal times in the order written.
    assert read == sorted(written, key=lambda m: m[2])


def _read_all(path: Path) -> None:
    """Everything a user does with a bag: open, summarise, read every message."""
    try:
        with no_hang(), BagReader(path) as reader:
            summarize(reader, str(path))
            for _ in reader.messages():
                pass
    except BagError as error:
        _one_line(error)


def _reindex(path: Path) -> None:
    try:
        with no_hang():
            reindex(path)
    except BagError as error:
        _one_line(error)
        return
    _read_all(path)


def _one_line(error: BagError) -> None:
    text = str(error)
    assert text
    assert "\n" not in text


@st.composite
def damage(draw: st.DrawFn, data: bytes) -> bytes:
    """``data`` with some of its bytes damaged."""
    out = bytearray(data)
    for _ in range(draw(st.integers(1, 4))):
        at = draw(st.integers(0, len(out) - 1))
        kind = draw(st.sampled_from(["flip", "byte", "length", "cut", "insert"]))
        if kind == "flip":
            out[at] ^= 1 << draw(st.integers(0, 7))
        elif kind == "byte":
            out[at] = draw(st.integers(0, 255))
        elif kind == "length":
            value = draw(st.sampled_from([0, 1, 0x7FFFFFFF, 0xFFFFFFFF, len(out)]))
            out[at : at + 4] = struct.pack("<I", value)
        elif kind == "cut":
            del out[at:]
            if not out:
                break
        else:
            out[at:at] = draw(st.binary(min_size=1, max_size=16))
    return bytes(out)


@fuzz_settings(120)
@given(bag=bags(), data=st.data())
def test_damaged_bags_are_read_or_refused(folder: Path, bag: dict[str, Any], data: Any) -> None:
    path = folder / "damaged.bag"
    _write(path, bag)
    path.write_bytes(data.draw(damage(path.read_bytes())))
    _read_all(path)
    _reindex(path)


@fuzz_settings(60)
@given(tail=st.binary(max_size=5000))
def test_random_bytes_after_the_magic_line_are_refused(folder: Path, tail: bytes) -> None:
    path = folder / "random.bag"
    path.write_bytes(rec.MAGIC + tail)
    _read_all(path)
    _reindex(path)


# -- bombs: small files whose lengths ask for gigabytes -----------------------------------------


def _bag_with(records: bytes, index: bytes = b"", conn_count: int = 0, chunks: int = 0) -> bytes:
    start = len(rec.MAGIC) + 8 + rec.BAG_HEADER_LENGTH
    header = rec.bag_header(start + len(records), conn_count, chunks)
    return rec.MAGIC + header + records + index


def _u32_record(fields: Mapping[str, bytes | str], data_length: int) -> bytes:
    header = rec.encode_fields(fields)
    return rec.U32.pack(len(header)) + header + rec.U32.pack(data_length)


_CONN: dict[str, bytes | str] = {
    "op": bytes([rec.OP_CONNECTION]),
    "conn": rec.U32.pack(0),
    "topic": "/t",
}
_CHUNK_INFO: dict[str, bytes | str] = {
    "op": bytes([rec.OP_CHUNK_INFO]),
    "ver": rec.U32.pack(1),
    "chunk_pos": rec.U64.pack(len(rec.MAGIC) + 8 + rec.BAG_HEADER_LENGTH),
    "start_time": rec.pack_time(0),
    "end_time": rec.pack_time(0),
    "count": rec.U32.pack(1),
}


def _chunk(compression: str, size: int, stored: bytes) -> bytes:
    return rec.chunk_record_head(compression, size, len(stored)) + stored


_BZ2_BOMB = bz2.compress(b"\0" * (512 << 20))  # 512 MiB of zeros in a few hundred bytes

BOMBS = {
    # The index's connection record says its data is 4 GiB long.
    "connection data length": _bag_with(b"", _u32_record(_CONN, 0xFFFFFFFF), conn_count=1),
    # The index promises four billion connections and chunks.
    "record counts": _bag_with(b"", b"", conn_count=0xFFFFFFFF, chunks=0xFFFFFFFF),
    # A chunk info whose data says 4 GiB, after a chunk that is fine.
    "chunk info data length": _bag_with(
        _chunk("none", 0, b""), _u32_record(_CHUNK_INFO, 0xFFFFFFFF), chunks=1
    ),
    # A chunk that says it holds 4 GiB of records, and stores none.
    "chunk size": _bag_with(
        _chunk("none", 0xFFFFFFFF, b""),
        rec.chunk_info_record(rec.ChunkInfo(len(rec.MAGIC) + 8 + 4096, 0, 0, {0: 1})),
        chunks=1,
    ),
    # A chunk whose stored bytes are said to be 4 GiB long.
    "chunk data length": _bag_with(
        rec.chunk_record_head("bz2", 100, 0xFFFFFFFF),
        rec.chunk_info_record(rec.ChunkInfo(len(rec.MAGIC) + 8 + 4096, 0, 0, {0: 1})),
        chunks=1,
    ),
    # A bz2 chunk of a few hundred bytes that decompresses to 512 MiB.
    "bz2 bomb": _bag_with(
        _chunk("bz2", 512 << 20, _BZ2_BOMB),
        rec.chunk_info_record(rec.ChunkInfo(len(rec.MAGIC) + 8 + 4096, 0, 0, {0: 1})),
        chunks=1,
    ),
    # An index data record that counts four billion entries.
    "index count": _bag_with(
        _chunk("none", 0, b"")
        + rec.encode_record(
            {
                "op": bytes([rec.OP_INDEX_DATA]),
                "ver": rec.U32.pack(1),
                "conn": rec.U32.pack(0),
                "count": rec.U32.pack(0xFFFFFFFF),
            },
            b"\0" * 12,
        ),
        rec.chunk_info_record(rec.ChunkInfo(len(rec.MAGIC) + 8 + 4096, 0, 0, {0: 1})),
        chunks=1,
    ),
}


@pytest.mark.parametrize("name", sorted(BOMBS))
def test_small_bags_with_huge_lengths_stay_small(folder: Path, name: str) -> None:
    path = folder / "bomb.bag"
    assert len(BOMBS[name]) < 5 << 10
    path.write_bytes(BOMBS[name])
    assert peak_allocation(lambda: _read_all(path)) < MEMORY_BOUND
    copy = folder / "bomb-reindexed.bag"
    shutil.copyfile(path, copy)
    assert peak_allocation(lambda: _reindex(copy)) < MEMORY_BOUND
    _read_all(path)  # and nothing but BagError
    _reindex(copy)
