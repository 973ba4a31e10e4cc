"""Writing bags of ROS 1's format 2.0 incrementally: every chunk reaches the disk when it closes.

`BagWriter` writes the magic and a bag header with no index first, then one chunk at a time:
the chunk (its connection and message records, compressed as asked), followed at once by its
index data records, and flushed to the file. `BagWriter.close` writes the index (every
connection record, every chunk info) and rewrites the bag header to point at it. So at any
moment the file holds every closed chunk complete: a writer that is killed leaves a bag that
`rosx.bag.reindex` restores whole but for the chunk it had open, and one that closes leaves a
bag ROS 1 opens. ROS 1's writer keeps the same layout; ``rosbags.rosbag1.Writer`` writes the
file only on close and cannot append, hence this writer.

A connection's record is written in the chunk of its first message and again in the index, as
ROS 1 does. Mode ``'a'`` reopens an indexed bag, drops its index and goes on after its last
chunk.

A write that fails (a full disk: ``ENOSPC``) cuts the file back to the end of the last complete
chunk, drops the messages of the chunk that did not fit and raises the `OSError`; the writer then
takes no more messages, and `BagWriter.close` still writes the index of the chunks on disk (the
last chunks give way to it if cutting the partial one did not free enough room), so the bag
opens with everything written before the failure. Files are written unbuffered, so nothing
half-written stays in a buffer to be retried later.
"""

from __future__ import annotations

import contextlib
import io
import os
import threading
from pathlib import Path
from typing import TYPE_CHECKING, BinaryIO, Protocol

from rosx.bag import records as rec
from rosx.bag.errors import BagError
from rosx.bag.records import ChunkInfo

if TYPE_CHECKING:
    from collections.abc import Mapping

#: ROS 1's default chunk size (``rosbag record --chunksize``, in bytes).
DEFAULT_CHUNK_THRESHOLD = 768 * 1024


class Opener(Protocol):
    """How a writer opens its file: ``opener(path, mode)`` (``'wb'`` or ``'r+b'``), unbuffered."""

    def __call__(self, path: str, mode: str, /) -> BinaryIO:
        """Open ``path`` in ``mode`` (``'wb'`` or ``'r+b'``) without buffering."""


def open_unbuffered(path: str, mode: str) -> BinaryIO:
    """The file at ``path`` opened in ``mode`` with no buffering (the default `Opener`)."""
    return io.FileIO(path, mode)


class BagWriter:
    """A bag being written (see the module's docstring); every method is thread-safe."""

    def __init__(
        self,
        path: str | os.PathLike[str],
        mode: str = "w",
        *,
        compression: str = "none",
        chunk_threshold: int = DEFAULT_CHUNK_THRESHOLD,
        opener: Opener = open_unbuffered,
    ) -> None:
        """Create (``'w'``) or reopen (``'a'``) the bag at ``path``, opened with ``opener``.

        Raises:
            OSError: the file cannot be created, opened or written.
            BagError: ``'a'`` on a file that is not an indexed bag; unknown compression.
        """
        if compression not in rec.COMPRESSIONS:
            raise BagError(f"Unknown compression type: {compression}")
        self.path = os.fspath(path)
        self.compression = compression
        self.chunk_threshold = chunk_threshold
        self._lock = threading.RLock()
        self.connections: dict[int, tuple[str, dict[str, str]]] = {}
        self._conn_ids: dict[tuple[str, tuple[tuple[str, str], ...]], int] = {}
        self._written_conns: set[int] = set()
        self.chunks: list[ChunkInfo] = []
        self._buffer = bytearray()
        self._index: dict[int, list[tuple[int, int]]] = {}
        self._times: tuple[int, int] = (0, 0)
        self.closed = False
        #: The error that stopped writing (a full disk), if any.
        self.failed: OSError | None = None
        self._opener = opener
        if mode == "w":
            self.file: BinaryIO = opener(self.path, "wb")
            try:
                self._write_all(rec.MAGIC + rec.bag_header(0, 0, 0))
            except OSError:
                self.file.close()
                Path(self.path).unlink(missing_ok=True)
                raise
        elif mode == "a":
            self._reopen()
        else:
            raise ValueError(f"mode {mode!r} is not 'w' or 'a'")

    def _reopen(self) -> None:
        from rosx.bag.reader import BagReader  # noqa: PLC0415 - bag code loads only for bags

        with BagReader(self.path) as bag:
            end = bag.index_pos
            for conn in bag.connections.values():
                key = (conn.topic, tuple(sorted(conn.header.items())))
                self.connections[conn.id] = (conn.topic, dict(conn.header))
                self._conn_ids[key] = conn.id
                self._written_conns.add(conn.id)
            self.chunks = list(bag.chunks)
        self.file = self._opener(self.path, "r+b")
        self.file.seek(len(rec.MAGIC))
        self._write_all(rec.bag_header(0, 0, 0))  # unindexed until closed again
        self.file.truncate(end)
        self.file.seek(end)

    def _write_all(self, data: bytes) -> None:
        view = memoryview(data)
        while view:
            written = self.file.write(view)
            if not written:
                raise OSError(f"wrote nothing of {len(view)} bytes")
            view = view[written:]

    # -- writing ------------------------------------------------------------------------------

    def add_connection(self, topic: str, header: Mapping[str, str]) -> int:
        """The id of the connection of ``topic`` with publisher header ``header`` (new ids
        numbered from 0, a header seen before gets its id again)."""
        items = tuple(sorted(header.items()))
        key = (topic, items)
        with self._lock:
            conn = self._conn_ids.get(key)
            if conn is None:
                conn = max(self.connections, default=-1) + 1
                self._conn_ids[key] = conn
                self.connections[conn] = (topic, dict(items))
            return conn

    def write(self, conn: int, time_ns: int, data: bytes | memoryview) -> None:
        """Add one message of connection ``conn`` received at ``time_ns``."""
        with self._lock:
            if self.closed:
                raise BagError("Tried to write to a closed bag")
            if self.failed is not None:
                raise self.failed
            buffer = self._buffer
            if conn not in self._written_conns:
                topic, header = self.connections[conn]
                buffer += rec.connection_record(conn, topic, header)
                self._written_conns.add(conn)
            offset = len(buffer)
            buffer += rec.message_record_head(conn, time_ns, len(data))
            buffer += data
            entries = self._index.get(conn)
            if entries is None:
                self._index[conn] = [(time_ns, offset)]
                if len(self._index) == 1:
                    self._times = (time_ns, time_ns)
            else:
                entries.append((time_ns, offset))
            first, last = self._times
            if time_ns < first:
                self._times = (time_ns, last)
            elif time_ns > last:
                self._times = (first, time_ns)
            if len(buffer) >= self.chunk_threshold:
                self._flush_chunk()

    def flush(self) -> None:
        """Close the open chunk now: it reaches the file with its index records."""
        with self._lock:
            if not self.closed and self.failed is None:
                self._flush_chunk()

    def _flush_chunk(self) -> None:
        if not self._index:
            return
        raw = bytes(self._buffer)
        stored = rec.compress(self.compression, raw)
        pos = self.file.tell()
        parts = [rec.chunk_record_head(self.compression, len(raw), len(stored)), stored]
        parts += [rec.index_record(conn, self._index[conn]) for conn in sorted(self._index)]
        try:
            self._write_all(b"".join(parts))
        except OSError as error:
            self._drop_chunk(pos, error)
            raise
        counts = {conn: len(entries) for conn, entries in self._index.items()}
        self.chunks.append(ChunkInfo(pos, self._times[0], self._times[1], counts))
        self._buffer = bytearray()
        self._index = {}

    def _drop_chunk(self, pos: int, error: OSError) -> None:
        """Cut the file back to ``pos`` (the end of the last complete chunk) and forget the
        chunk that did not fit: its messages, and the connections first written in it."""
        self.failed = error
        in_chunks = {conn for info in self.chunks for conn in info.counts}
        self._written_conns &= in_chunks
        self._buffer = bytearray()
        self._index = {}
        self.file.truncate(pos)
        self.file.seek(pos)

    @property
    def size(self) -> int:
        """Bytes written so far, the open chunk included (uncompressed)."""
        with self._lock:
            return (self.file.tell() if not self.closed else 0) + len(self._buffer)

    @property
    def message_count(self) -> int:
        """Messages written so far."""
        with self._lock:
            done = sum(n for info in self.chunks for n in info.counts.values())
            return done + sum(len(e) for e in self._index.values())

    def close(self) -> None:
        """Write the last chunk and the index, and close the file (idempotent).

        Raises:
            OSError: the last chunk did not fit (the bag is closed with the chunks before it).
        """
        with self._lock:
            if self.closed:
                return
            failed_before = self.failed
            try:
                if self.failed is None:
                    with contextlib.suppress(OSError):  # kept in self.failed, raised below
                        self._flush_chunk()
                self._write_index()
            finally:
                self.closed = True
                self.file.close()
            if self.failed is not None and self.failed is not failed_before:
                raise self.failed

    def _write_index(self) -> None:
        """The index after the last chunk, and the header pointing at it. Where the index does
        not fit (a full disk), the last chunks give way to it, so the bag always opens."""
        while True:
            index_pos = self.file.tell()
            parts = [
                rec.connection_record(conn, topic, header)
                for conn, (topic, header) in sorted(self.connections.items())
                if conn in self._written_conns
            ]
            parts += [rec.chunk_info_record(info) for info in self.chunks]
            try:
                self._write_all(b"".join(parts))
                break
            except OSError as error:
                if not self.chunks:
                    raise
                self._drop_chunk(self.chunks.pop().pos, self.failed or error)
        self.file.truncate()
        self.file.seek(len(rec.MAGIC))
        conn_count = len(self._written_conns)
        self._write_all(rec.bag_header(index_pos, conn_count, len(self.chunks)))

    def __enter__(self) -> BagWriter:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


__all__ = ["DEFAULT_CHUNK_THRESHOLD", "BagWriter", "Opener", "open_unbuffered"]
