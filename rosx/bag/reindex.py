"""Reindexing a bag whose writer never wrote its index (a recorder killed, a disk gone full).

`reindex` scans the file from its first record: each complete chunk is decompressed and read
for its connection and message records; the index data records that follow it are kept when
they are whole and rewritten when not. The scan stops at the first record that is cut short or
damaged, and everything from there on is dropped (ROS 1 once kept such junk, ros/ros_comm#2282)
— and counted, so the user learns what was lost (ros/ros_comm#1328). Then the index is written
and the bag header pointed at it, in place.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import NamedTuple

from rosx.bag import records as rec
from rosx.bag.errors import BagError, BagFormatError


class ReindexReport(NamedTuple):
    """What a reindex kept and dropped."""

    chunks: int
    messages: int
    dropped_bytes: int


def _read_header(data: bytes | memoryview, pos: int) -> tuple[dict[str, bytes], int, int]:
    """The record at ``pos``: its header, where its data starts, its data length."""
    if pos + 4 > len(data):
        raise BagFormatError("record cut short")
    (hlen,) = rec.U32.unpack_from(data, pos)
    if pos + 8 + hlen > len(data):
        raise BagFormatError("record cut short")
    fields = rec.decode_fields(data[pos + 4 : pos + 4 + hlen])
    (dlen,) = rec.U32.unpack_from(data, pos + 4 + hlen)
    start = pos + 8 + hlen
    if start + dlen > len(data):
        raise BagFormatError("record cut short")
    return fields, start, dlen


def _read_chunk(
    fields: dict[str, bytes],
    stored: memoryview,
    connections: dict[int, tuple[str, dict[str, str]]],
) -> dict[int, list[tuple[int, int]]]:
    """A chunk's index (connection → ``[(time, offset)…]``); its connections go to
    ``connections``."""
    raw = rec.decompress(
        fields.get("compression", b"none").decode("latin-1"),
        bytes(stored),
        rec.field_u32(fields, "size"),
    )
    index: dict[int, list[tuple[int, int]]] = {}
    for offset, inner, dpos, ilen in rec.iter_records(raw):
        kind = rec.field_op(inner)
        if kind == rec.OP_CONNECTION:
            conn = rec.field_u32(inner, "conn")
            header = rec.decode_connection_header(raw[dpos : dpos + ilen])
            topic = inner.get("topic", b"").decode("utf-8", "replace")
            connections.setdefault(conn, (topic or header.get("topic", ""), header))
        elif kind == rec.OP_MSG_DATA:
            stamp = rec.unpack_time(inner.get("time", b""))
            index.setdefault(rec.field_u32(inner, "conn"), []).append((stamp, offset))
    return index


def _write_index(
    file: Path,
    good_end: int,
    pending_index: bytes,
    connections: dict[int, tuple[str, dict[str, str]]],
    chunks: list[rec.ChunkInfo],
) -> None:
    """Cut the file after its last good record and write the index there."""
    used = {c for info in chunks for c in info.counts}
    with file.open("r+b") as out:
        out.truncate(good_end)
        out.seek(good_end)
        out.write(pending_index)
        index_pos = out.tell()
        parts = [
            rec.connection_record(conn, topic, header)
            for conn, (topic, header) in sorted(connections.items())
            if conn in used or not chunks
        ]
        parts += [rec.chunk_info_record(info) for info in chunks]
        out.write(b"".join(parts))
        out.seek(len(rec.MAGIC))
        out.write(rec.bag_header(index_pos, len(parts) - len(chunks), len(chunks)))


def reindex(path: str | os.PathLike[str]) -> ReindexReport:
    """Rebuild the index of the bag at ``path`` in place (see the module's docstring).

    Raises:
        OSError: the file cannot be read or written.
        BagError: it does not start as a bag of format 2.0.
    """
    file = Path(path)
    data = memoryview(file.read_bytes())
    if not data:
        raise BagError("empty file")
    if bytes(data[: len(rec.MAGIC)]) != rec.MAGIC:
        raise BagError("This does not appear to be a bag file")
    pos = len(rec.MAGIC) + 8 + rec.BAG_HEADER_LENGTH
    connections: dict[int, tuple[str, dict[str, str]]] = {}
    chunks: list[rec.ChunkInfo] = []
    messages = 0
    good_end = pos
    pending_index = b""
    old_index = False
    while pos < len(data):
        try:
            fields, start, dlen = _read_header(data, pos)
            op = rec.field_op(fields)
            if op != rec.OP_CHUNK:
                old_index = op in (rec.OP_CONNECTION, rec.OP_CHUNK_INFO)
                break
            index = _read_chunk(fields, data[start : start + dlen], connections)
        except BagFormatError:
            break
        chunk_end = start + dlen
        after = chunk_end
        whole = True
        for _ in index:
            try:
                ifields, istart, ilen = _read_header(data, after)
                whole = rec.field_op(ifields) == rec.OP_INDEX_DATA
            except BagFormatError:
                whole = False
            if not whole:
                break
            after = istart + ilen
        stamps = [t for entries in index.values() for t, _ in entries]
        if stamps:
            counts = {conn: len(entries) for conn, entries in index.items()}
            chunks.append(rec.ChunkInfo(pos, min(stamps), max(stamps), counts))
            messages += len(stamps)
        if whole:
            good_end, pending_index = after, b""
        else:
            good_end = chunk_end
            pending_index = b"".join(rec.index_record(c, index[c]) for c in sorted(index))
            break
        pos = after
    dropped = 0 if old_index else len(data) - good_end
    del data
    _write_index(file, good_end, pending_index, connections, chunks)
    return ReindexReport(len(chunks), messages, dropped)


__all__ = ["ReindexReport", "reindex"]
