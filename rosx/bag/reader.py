"""Reading bags of ROS 1's format 2.0: the index, chunk by chunk, messages in time order.

`BagReader` opens a file, checks it is a bag, and reads what its index holds: the connections
(topic and publisher's connection header) and the chunk infos (where each chunk is, its first
and last times, its message counts). Chunk headers (compression, sizes) and the per-chunk index
records are read only when asked for, so ``rosbag info`` of a large bag reads a few bytes per
chunk; `BagReader.messages` merges the chunks' entries in time order, decompressing one chunk at
a time. A bag whose index was never written (its recorder was killed) is refused as unindexed,
as ROS 1 refuses it; `rosx.bag.reindex` repairs it.

``rosbags.rosbag1.Reader`` reads the same files, but normalises type names to ROS 2's form,
does not expose chunk compression or sizes, and reads every index record on opening; this
reader keeps ROS 1's names and reads lazily.
"""

from __future__ import annotations

import heapq
import os
from pathlib import Path
from typing import TYPE_CHECKING, BinaryIO, NamedTuple

from rosx.bag import records as rec
from rosx.bag.errors import (
    BagEncryptNotSupportedError,
    BagError,
    BagFormatError,
    BagUnindexedError,
    NotABagError,
)

if TYPE_CHECKING:
    from collections.abc import Collection, Iterator

    from rosx.bag.records import ChunkInfo


class Connection(NamedTuple):
    """One publisher's connection to a topic, as recorded: its id, topic and header."""

    id: int
    topic: str
    header: dict[str, str]

    @property
    def type(self) -> str:
        """The message type (``geometry_msgs/Twist``)."""
        return self.header.get("type", "")

    @property
    def md5sum(self) -> str:
        """The type's md5sum."""
        return self.header.get("md5sum", "")

    @property
    def message_definition(self) -> str:
        """The type's full definition, as the publisher sent it."""
        return self.header.get("message_definition", "")

    @property
    def callerid(self) -> str:
        """The publishing node, when recorded."""
        return self.header.get("callerid", "")

    @property
    def latching(self) -> bool:
        """Whether the publisher latched."""
        return self.header.get("latching", "0") == "1"


class ChunkHeader(NamedTuple):
    """A chunk's compression, uncompressed size, and where and how long its stored data is."""

    compression: str
    size: int
    data_pos: int
    data_size: int


class BagReader:
    """An open bag file (see the module's docstring). Use it as a context manager."""

    def __init__(self, path: str | os.PathLike[str], *, allow_unindexed: bool = False) -> None:
        """Open ``path`` and read its index.

        Raises:
            OSError: the file cannot be opened.
            BagError: it is not a bag (`NotABagError`), or a damaged one (`BagFormatError`),
                or an unindexed one (`BagUnindexedError`, unless ``allow_unindexed``).
        """
        self.path = os.fspath(path)
        self.file: BinaryIO = Path(self.path).open("rb")  # noqa: SIM115 - closed by close()
        try:
            self.size = os.fstat(self.file.fileno()).st_size
            self.connections: dict[int, Connection] = {}
            self.chunks: list[ChunkInfo] = []
            self._headers: dict[int, ChunkHeader] = {}
            self._cache: tuple[int, bytes] = (-1, b"")
            self.indexed = self._open(allow_unindexed)
        except BaseException:
            self.file.close()
            raise

    # -- opening -----------------------------------------------------------------------------

    def _open(self, allow_unindexed: bool) -> bool:
        magic = self.file.readline(64)
        if not magic:
            raise NotABagError("empty file")
        if not magic.startswith(b"#ROSBAG V"):
            raise NotABagError("This does not appear to be a bag file")
        if magic != rec.MAGIC:
            version = magic[9:].strip().decode("latin-1")
            raise BagError(f"bag format version {version} is not supported (rosx reads 2.0)")
        self.version = 200
        try:
            fields, _ = self._read_record_header(rec.OP_BAG_HEADER)
            self.index_pos = rec.field_u64(fields, "index_pos")
            self.conn_count = rec.field_u32(fields, "conn_count")
            self.chunk_count = rec.field_u32(fields, "chunk_count")
        except BagFormatError:
            if allow_unindexed:
                self.index_pos = 0
                return False
            raise BagUnindexedError from None
        if fields.get("encryptor"):
            raise BagEncryptNotSupportedError(
                f"bag is encrypted with {fields['encryptor'].decode('latin-1')}, "
                "which rosx cannot decrypt"
            )
        if self.index_pos == 0 or self.index_pos > self.size:
            if allow_unindexed:
                return False
            raise BagUnindexedError
        try:
            self._read_index()
        except BagFormatError:
            if allow_unindexed:
                self.connections.clear()
                self.chunks.clear()
                return False
            raise BagUnindexedError from None
        return True

    def _read_index(self) -> None:
        self.file.seek(self.index_pos)
        for _ in range(self.conn_count):
            fields, data = self._read_record(rec.OP_CONNECTION)
            conn = rec.field_u32(fields, "conn")
            header = rec.decode_connection_header(data)
            topic = fields.get("topic", b"").decode("utf-8", "replace") or header.get("topic", "")
            self.connections[conn] = Connection(conn, topic, header)
        for _ in range(self.chunk_count):
            fields, data = self._read_record(rec.OP_CHUNK_INFO)
            self.chunks.append(rec.parse_chunk_info(fields, data))

    def _read_record_header(self, op: int | None = None) -> tuple[dict[str, bytes], int]:
        """The header of the record at the file's position, and its data length."""
        head = self.file.read(4)
        if len(head) < 4:
            raise BagFormatError("Unexpected end of file reading a record header")
        (hlen,) = rec.U32.unpack(head)
        if hlen > self.size:
            raise BagFormatError(f"Record header length {hlen} is past the end of the file")
        block = self.file.read(hlen + 4)
        if len(block) < hlen + 4:
            raise BagFormatError("Unexpected end of file reading a record header")
        fields = rec.decode_fields(block[:hlen])
        if op is not None and rec.field_op(fields) != op:
            raise BagFormatError(f"Expected op {op:#04x}, found {rec.field_op(fields):#04x}")
        (dlen,) = rec.U32.unpack(block[hlen:])
        return fields, dlen

    def _read_record(self, op: int | None = None) -> tuple[dict[str, bytes], bytes]:
        fields, dlen = self._read_record_header(op)
        self._check_within(dlen)
        data = self.file.read(dlen)
        if len(data) < dlen:
            raise BagFormatError("Unexpected end of file reading a record's data")
        return fields, data

    def _check_within(self, length: int) -> None:
        """Refuse a length that runs past the end of the file before reading it (a read
        allocates what it is asked for, 4 GiB for a damaged length)."""
        if length > self.size - self.file.tell():
            raise BagFormatError("Unexpected end of file reading a record's data")

    # -- chunks ------------------------------------------------------------------------------

    def chunk_header(self, index: int) -> ChunkHeader:
        """The header of chunk ``index`` (of `chunks`)."""
        header = self._headers.get(index)
        if header is None:
            self.file.seek(self.chunks[index].pos)
            fields, dlen = self._read_record_header(rec.OP_CHUNK)
            compression = fields.get("compression", b"none").decode("latin-1")
            size = rec.field_u32(fields, "size")
            header = ChunkHeader(compression, size, self.file.tell(), dlen)
            self._headers[index] = header
        return header

    def chunk_index(self, index: int) -> dict[int, list[tuple[int, int]]]:
        """Chunk ``index``'s index records: connection id → ``[(time_ns, offset)…]``."""
        header = self.chunk_header(index)
        self.file.seek(header.data_pos + header.data_size)
        entries: dict[int, list[tuple[int, int]]] = {}
        for _ in range(len(self.chunks[index].counts)):
            # ``count`` entries follow the header, whatever its data length says (as ROS 1
            # reads them: a damaged length loses nothing).
            fields, _ = self._read_record_header(rec.OP_INDEX_DATA)
            count = rec.field_u32(fields, "count")
            self._check_within(count * rec.INDEX_ENTRY.size)
            data = self.file.read(count * rec.INDEX_ENTRY.size)
            entries[rec.field_u32(fields, "conn")] = rec.parse_index(data, count)
        return entries

    def chunk_data(self, index: int) -> bytes:
        """Chunk ``index``'s records, decompressed (the last one read is kept)."""
        if self._cache[0] == index:
            return self._cache[1]
        header = self.chunk_header(index)
        self.file.seek(header.data_pos)
        self._check_within(header.data_size)
        stored = self.file.read(header.data_size)
        if len(stored) < header.data_size:
            raise BagFormatError("Unexpected end of file reading a chunk")
        data = rec.decompress(header.compression, stored, header.size)
        self._cache = (index, data)
        return data

    # -- messages ----------------------------------------------------------------------------

    @property
    def start_time(self) -> int | None:
        """The time of the first chunk's first message, in ns (ROS 1's ``start``)."""
        return self.chunks[0].start_time if self.chunks else None

    @property
    def end_time(self) -> int | None:
        """The time of the last chunk's last message, in ns."""
        return self.chunks[-1].end_time if self.chunks else None

    def message_count(self, conns: Collection[int] | None = None) -> int:
        """Messages of ``conns`` (all connections if None), from the chunk infos."""
        return sum(
            n for info in self.chunks for c, n in info.counts.items() if conns is None or c in conns
        )

    def entries(
        self,
        conns: Collection[int] | None = None,
        start: int | None = None,
        end: int | None = None,
    ) -> Iterator[tuple[int, int, int, int]]:
        """``(time_ns, chunk, offset, conn)`` of each message of ``conns`` with
        ``start <= time <= end``, in time order (ties in file order)."""
        order = sorted(range(len(self.chunks)), key=lambda i: (self.chunks[i].start_time, i))
        heap: list[tuple[int, int, int, int]] = []
        next_chunk = 0
        while True:
            while next_chunk < len(order) and (
                not heap or self.chunks[order[next_chunk]].start_time <= heap[0][0]
            ):
                index = order[next_chunk]
                next_chunk += 1
                info = self.chunks[index]
                if (end is not None and info.start_time > end) or (
                    start is not None and info.end_time < start
                ):
                    continue
                if conns is not None and not any(c in conns for c in info.counts):
                    continue
                for conn, items in self.chunk_index(index).items():
                    if conns is not None and conn not in conns:
                        continue
                    for time_ns, offset in items:
                        if (start is None or time_ns >= start) and (end is None or time_ns <= end):
                            heapq.heappush(heap, (time_ns, index, offset, conn))
            if not heap:
                return
            yield heapq.heappop(heap)

    def span(
        self,
        conns: Collection[int] | None = None,
        start: int | None = None,
        end: int | None = None,
    ) -> tuple[int, int] | None:
        """The times (ns) of the first and the last message of ``conns`` with
        ``start <= time <= end``, or None if there is none; from the index records of the
        chunks at either end alone."""
        low = -1 if start is None else start
        high = 2**64 if end is None else end
        chunks = [
            i
            for i, info in enumerate(self.chunks)
            if info.start_time <= high
            and info.end_time >= low
            and (conns is None or any(c in conns for c in info.counts))
        ]

        def times(index: int) -> list[int]:
            return [
                time_ns
                for conn, items in self.chunk_index(index).items()
                if conns is None or conn in conns
                for time_ns, _ in items
                if low <= time_ns <= high
            ]

        first = high + 1
        for i in sorted(chunks, key=lambda i: self.chunks[i].start_time):
            if self.chunks[i].start_time >= first:
                break
            first = min([first, *times(i)])
        if first > high:
            return None
        last = first
        for i in sorted(chunks, key=lambda i: self.chunks[i].end_time, reverse=True):
            if self.chunks[i].end_time <= last:
                break
            last = max([last, *times(i)])
        return first, last

    def read_message(self, chunk: int, offset: int) -> tuple[int, int, bytes]:
        """The message record at ``offset`` in chunk ``chunk``: ``(conn, time_ns, data)``."""
        data = self.chunk_data(chunk)
        for _, fields, pos, dlen in rec.iter_records(data, offset):
            if rec.field_op(fields) == rec.OP_CONNECTION:
                continue
            if rec.field_op(fields) != rec.OP_MSG_DATA:
                raise BagFormatError("Expected to find message data")
            time_ns = rec.unpack_time(fields.get("time", b""))
            return rec.field_u32(fields, "conn"), time_ns, data[pos : pos + dlen]
        raise BagFormatError("Expected to find message data")

    def messages(
        self,
        conns: Collection[int] | None = None,
        start: int | None = None,
        end: int | None = None,
    ) -> Iterator[tuple[Connection, int, bytes]]:
        """``(connection, time_ns, serialized bytes)`` of each message, in time order."""
        for _, chunk, offset, _ in self.entries(conns, start, end):
            conn, time_ns, data = self.read_message(chunk, offset)
            connection = self.connections.get(conn)
            if connection is None:
                raise BagFormatError(f"Message on unknown connection {conn}")
            yield connection, time_ns, data

    def topic_connections(self, topics: Collection[str] | None = None) -> list[Connection]:
        """The connections of ``topics`` (all if None)."""
        return [c for c in self.connections.values() if topics is None or c.topic in topics]

    # -- closing -----------------------------------------------------------------------------

    def close(self) -> None:
        """Close the file."""
        self._cache = (-1, b"")
        self.file.close()

    def __enter__(self) -> BagReader:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


__all__ = ["BagReader", "ChunkHeader", "Connection"]
