"""Reindexing a bag: its writer never wrote the index (a recorder killed, a disk gone full), or
its bytes were damaged.

`reindex` reads the file's records from the first one after the bag header. Each chunk whose
record is whole is kept as it is stored (under a header written anew: a damaged field name
there would make the bag unreadable again), and its index data records are written anew from its
own connection and message records (those that follow it in the file are not trusted: a
damaged one would make the bag unreadable again). Inside a chunk, the records before a damaged
one are kept, and messages of a connection no record introduced are left out (a damaged
``conn`` field). Where the records themselves cannot be followed, the next chunk is looked for
further on, so one damaged chunk costs that chunk alone; ROS 1's reindex stops there, or fails.
Everything not kept is counted, so the user learns what was lost (ros/ros_comm#1328); the old
index, when there was one, is replaced and not counted. The bag is then written again, index
and header included, and put in place of the original at once.
"""

from __future__ import annotations

import contextlib
import os
from pathlib import Path
from typing import NamedTuple

from rosx.bag import records as rec
from rosx.bag.errors import BagError, BagFormatError, NotABagError


class ReindexReport(NamedTuple):
    """What a reindex kept and dropped."""

    chunks: int
    messages: int
    #: Bytes of the file not kept: damaged or cut short (an old index aside).
    dropped_bytes: int
    #: Messages left out of kept chunks: after a damaged record, or of an unknown connection.
    dropped_messages: int = 0


class _Chunk(NamedTuple):
    """A chunk's entries (connection → ``[(time, offset)…]``), the messages left out, and its
    record written anew (a fresh header, the stored bytes as they are)."""

    entries: dict[int, list[tuple[int, int]]]
    dropped: int
    record: bytes


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
) -> _Chunk:
    """A chunk's index; its connections go to ``connections``.

    Raises:
        BagFormatError: the chunk cannot be decompressed.
    """
    compression = fields.get("compression", b"none").decode("latin-1")
    if compression == "none":
        raw: bytes | memoryview = stored  # its size field is not needed, as ROS 1 ignores it
    else:
        raw = rec.decompress(compression, bytes(stored), rec.field_u32(fields, "size"))
    index: dict[int, list[tuple[int, int]]] = {}
    dropped = 0
    pos = 0
    while pos < len(raw):
        try:
            inner, dpos, ilen = _read_header(raw, pos)
            kind = rec.field_op(inner)
            if kind == rec.OP_CONNECTION:
                conn = rec.field_u32(inner, "conn")
                header = rec.decode_connection_header(bytes(raw[dpos : dpos + ilen]))
                topic = inner.get("topic", b"").decode("utf-8", "replace")
                connections.setdefault(conn, (topic or header.get("topic", ""), header))
            elif kind == rec.OP_MSG_DATA:
                stamp = rec.unpack_time(inner.get("time", b""))
                conn = rec.field_u32(inner, "conn")
                if conn in connections:
                    index.setdefault(conn, []).append((stamp, pos))
                else:
                    dropped += 1
        except BagFormatError:
            dropped += _messages_after(raw, pos)
            break
        pos = dpos + ilen
    head = rec.chunk_record_head(compression, len(raw), len(stored))
    return _Chunk(index, dropped, head + bytes(stored))


def _messages_after(raw: bytes | memoryview, pos: int) -> int:
    """About how many messages the damaged rest of a chunk held (their op fields)."""
    return bytes(raw[pos:]).count(b"op=\x02")


def _record_at(data: memoryview, pos: int) -> bool:
    """Whether a record starts at ``pos`` (or the file ends there)."""
    if pos == len(data):
        return True
    try:
        rec.field_op(_read_header(data, pos)[0])
    except BagFormatError:
        return False
    return True


def _next_chunk(raw: bytes, after: int) -> int | None:
    """Where the next whole chunk record starts after ``after``, found by its ``op`` field."""
    data = memoryview(raw)
    found = raw.find(b"op=\x05", after)
    while found != -1:
        # The op field sits in the record's header, a few dozen bytes after the record starts.
        for start in range(max(after, found - 80), found):
            try:
                fields, _, _ = _read_header(data, start)
                if rec.field_op(fields) == rec.OP_CHUNK and start + 8 < found:
                    return start
            except BagFormatError:
                continue
        found = raw.find(b"op=\x05", found + 1)
    return None


class _Rebuild:
    """The bag being rebuilt: the chunks kept (with their new index records), where the next
    goes in the new file, and what was dropped."""

    def __init__(self) -> None:
        self.connections: dict[int, tuple[str, dict[str, str]]] = {}
        self.chunks: list[rec.ChunkInfo] = []
        self.body: list[bytes | memoryview] = []
        self.at = len(rec.MAGIC) + 8 + rec.BAG_HEADER_LENGTH
        self.messages = self.dropped_messages = self.dropped_bytes = 0

    def keep(self, chunk: _Chunk) -> None:
        """Keep a chunk, followed by index records made from it."""
        self.dropped_messages += chunk.dropped
        stamps = [t for entries in chunk.entries.values() for t, _ in entries]
        if stamps:
            counts = {conn: len(entries) for conn, entries in chunk.entries.items()}
            self.chunks.append(rec.ChunkInfo(self.at, min(stamps), max(stamps), counts))
            self.messages += len(stamps)
        index = b"".join(rec.index_record(c, chunk.entries[c]) for c in sorted(chunk.entries))
        self.body += [chunk.record, index]
        self.at += len(chunk.record) + len(index)

    def report(self) -> ReindexReport:
        return ReindexReport(
            len(self.chunks), self.messages, self.dropped_bytes, self.dropped_messages
        )


def _scan(raw: bytes, rebuild: _Rebuild) -> None:
    """Follow the records of the bag in ``raw``, keeping its chunks in ``rebuild``."""
    data = memoryview(raw)
    pos = len(rec.MAGIC) + 8 + rec.BAG_HEADER_LENGTH
    while pos < len(data):
        try:
            fields, start, dlen = _read_header(data, pos)
            op = rec.field_op(fields)
        except BagFormatError:
            following = _next_chunk(raw, pos + 1)
            end = len(data) if following is None else following
            rebuild.dropped_bytes += end - pos
            pos = end
            continue
        end = start + dlen
        if op in (rec.OP_CONNECTION, rec.OP_CHUNK_INFO):
            return  # the old index: rebuilt
        if op == rec.OP_INDEX_DATA:
            # Rebuilt with its chunk. Its data length and its count both say where it ends:
            # the one a record follows wins, should the other be damaged.
            ends = [end]
            with contextlib.suppress(BagFormatError):
                ends.append(start + rec.INDEX_ENTRY.size * rec.field_u32(fields, "count"))
            end = next((e for e in ends if _record_at(data, e)), end)
        elif op != rec.OP_CHUNK:
            rebuild.dropped_bytes += end - pos
        else:
            try:
                rebuild.keep(_read_chunk(fields, data[start:end], rebuild.connections))
            except BagFormatError:
                rebuild.dropped_bytes += end - pos
        pos = end


def reindex(path: str | os.PathLike[str]) -> ReindexReport:
    """Rebuild the bag at ``path`` with an index (see the module's docstring).

    Raises:
        OSError: the file cannot be read or written.
        BagError: it does not start as a bag of format 2.0.
    """
    file = Path(path)
    raw = file.read_bytes()
    if not raw:
        raise NotABagError("empty file")
    if not raw.startswith(rec.MAGIC):
        raise NotABagError("This does not appear to be a bag file")
    rebuild = _Rebuild()
    rebuild.connections.update(_indexed_connections(file))
    _scan(raw, rebuild)
    _write(file, rebuild.at, rebuild.body, rebuild.connections, rebuild.chunks)
    return rebuild.report()


def _indexed_connections(file: Path) -> dict[int, tuple[str, dict[str, str]]]:
    """The connections the bag's old index lists, if it has one that reads: a chunk is the
    only place a connection's record is written, so its messages in later chunks would be
    lost with it."""
    from rosx.bag.reader import BagReader  # noqa: PLC0415 - reindexing reads the file itself

    try:
        with BagReader(file, allow_unindexed=True) as bag:
            return {c.id: (c.topic, dict(c.header)) for c in bag.connections.values()}
    except (BagError, OSError):
        return {}


def _write(
    file: Path,
    index_pos: int,
    body: list[bytes | memoryview],
    connections: dict[int, tuple[str, dict[str, str]]],
    chunks: list[rec.ChunkInfo],
) -> None:
    """Write the bag anew beside ``file`` and put it in its place."""
    used = {c for info in chunks for c in info.counts}
    records = [
        rec.connection_record(conn, topic, header)
        for conn, (topic, header) in sorted(connections.items())
        if conn in used or not chunks
    ]
    records += [rec.chunk_info_record(info) for info in chunks]
    header = rec.bag_header(index_pos, len(records) - len(chunks), len(chunks))
    partial = file.with_name(file.name + ".reindexing")
    with partial.open("wb") as out:
        out.write(rec.MAGIC + header)
        for part in body:
            out.write(part)
        out.write(b"".join(records))
    partial.replace(file)


__all__ = ["ReindexReport", "reindex"]
