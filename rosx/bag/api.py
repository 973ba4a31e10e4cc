"""ROS 1's ``rosbag`` Python API over `rosx.bag`: ``Bag``, its reading and writing, its errors.

What the tutorials' scripts use, with ROS 1's names and results::

    with rosbag.Bag("out.bag", "w") as bag:
        bag.write("/chatter", String(data="hi"))
    for topic, msg, t in rosbag.Bag("out.bag").read_messages(topics=["/chatter"]):
        ...

``read_messages`` yields ``BagMessage(topic, message, timestamp)`` in time order (``raw=True``
gives ``(datatype, data, md5sum, position, pytype)`` instead of the message;
``return_connection_header=True`` adds the connection's header). Times are `Time` values.
"""

from __future__ import annotations

import collections
import io
import os
import time
from pathlib import Path
from typing import TYPE_CHECKING, Any, NamedTuple

from rosx.bag.errors import (
    BagEncryptNotSupportedError,
    BagError,
    BagFormatError,
    BagUnindexedError,
)
from rosx.bag.reader import BagReader
from rosx.bag.types import message_class
from rosx.bag.writer import DEFAULT_CHUNK_THRESHOLD, BagWriter
from rosx.msg.codec.rostime import Time

if TYPE_CHECKING:
    from collections.abc import Callable, Iterable, Iterator

ROSBagException = BagError
ROSBagFormatException = BagFormatError
ROSBagUnindexedException = BagUnindexedError
ROSBagEncryptNotSupportedException = BagEncryptNotSupportedError
ROSBagEncryptException = BagEncryptNotSupportedError

BagMessage = collections.namedtuple("BagMessage", "topic message timestamp")
BagMessageWithConnectionHeader = collections.namedtuple(
    "BagMessageWithConnectionHeader", "topic message timestamp connection_header"
)
TopicTuple = collections.namedtuple(
    "TopicTuple", ["msg_type", "message_count", "connections", "frequency"]
)
TypesAndTopicsTuple = collections.namedtuple("TypesAndTopicsTuple", ["msg_types", "topics"])


class Compression:
    """The chunk compressions a bag may use."""

    NONE = "none"
    BZ2 = "bz2"
    LZ4 = "lz4"


class CompressionTuple(NamedTuple):
    """What `Bag.get_compression_info` returns."""

    compression: str
    uncompressed: int
    compressed: int


def _to_ns(value: Any) -> int | None:
    if value is None:
        return None
    if hasattr(value, "to_nsec"):
        return int(value.to_nsec())
    return int(float(value) * 1e9)


def _time(ns: int) -> Time:
    return Time(ns // 1_000_000_000, ns % 1_000_000_000)


class Bag:
    """A bag file opened for reading (``'r'``), writing (``'w'``) or appending (``'a'``)."""

    def __init__(
        self,
        f: str | os.PathLike[str],
        mode: str = "r",
        compression: str = Compression.NONE,
        chunk_threshold: int = DEFAULT_CHUNK_THRESHOLD,
        allow_unindexed: bool = False,
        options: dict[str, Any] | None = None,
        skip_index: bool = False,
    ) -> None:
        if options:
            compression = options.get("compression", compression)
            chunk_threshold = options.get("chunk_threshold", chunk_threshold)
        if mode not in ("r", "w", "a"):
            raise ValueError(f"mode {mode!r} is invalid; must be 'r', 'w', or 'a'")
        if compression not in (Compression.NONE, Compression.BZ2, Compression.LZ4):
            raise ROSBagException(f"unsupported compression type: {compression}")
        self._filename = os.fspath(f)
        self._mode = mode
        self._compression = compression
        self._reader: BagReader | None = None
        self._writer: BagWriter | None = None
        if mode == "r":
            self._reader = BagReader(self._filename)
        else:
            exists = mode == "a" and Path(self._filename).exists()
            self._writer = BagWriter(
                self._filename,
                "a" if exists else "w",
                compression=compression,
                chunk_threshold=chunk_threshold,
            )

    # -- properties --------------------------------------------------------------------------

    @property
    def filename(self) -> str:
        """The path the bag was opened with."""
        return self._filename

    @property
    def mode(self) -> str:
        """``'r'``, ``'w'`` or ``'a'``."""
        return self._mode

    @property
    def compression(self) -> str:
        """The compression of chunks written from now on."""
        return self._compression

    @property
    def size(self) -> int:
        """The file's size in bytes."""
        if self._writer is not None:
            return self._writer.size
        return self._read().size

    def _read(self) -> BagReader:
        if self._reader is None:
            raise ValueError("bag is not open for reading")
        return self._reader

    # -- writing -----------------------------------------------------------------------------

    def write(
        self,
        topic: str,
        msg: Any,
        t: Any = None,
        raw: bool = False,
        connection_header: dict[str, str] | None = None,
    ) -> None:
        """Add ``msg`` on ``topic`` at time ``t`` (now if None).

        With ``raw``, ``msg`` is ``(datatype, data, md5sum, position, pytype)`` or
        ``(datatype, data, md5sum)`` as `read_messages` returns it.
        """
        if self._writer is None:
            raise ValueError("bag is not open for writing")
        if not topic:
            raise ValueError("topic is not specified")
        if msg is None:
            raise ValueError("msg is not specified")
        stamp = time.time_ns() if t is None else _to_ns(t)
        assert stamp is not None
        if raw:
            datatype, data, md5sum = msg[0], msg[1], msg[2]
            pytype = msg[4] if len(msg) > 4 else None
            definition = getattr(pytype, "_full_text", "") if pytype is not None else ""
        else:
            datatype, md5sum = msg._type, msg._md5sum
            definition = msg._full_text
            buff = io.BytesIO()
            msg.serialize(buff)
            data = buff.getvalue()
        header = {
            "topic": topic,
            "type": datatype,
            "md5sum": md5sum,
            "message_definition": definition,
        }
        if connection_header:
            header.update(connection_header)
        conn = self._writer.add_connection(topic, header)
        self._writer.write(conn, stamp, bytes(data))

    def flush(self) -> None:
        """Write the open chunk to the file."""
        if self._writer is not None:
            self._writer.flush()

    # -- reading -----------------------------------------------------------------------------

    def _connection_ids(
        self,
        topics: Iterable[str] | str | None,
        connection_filter: Callable[..., bool] | None = None,
    ) -> set[int]:
        bag = self._read()
        if isinstance(topics, str):
            topics = [topics]
        chosen = set(topics) if topics else None
        ids = set()
        for conn in bag.connections.values():
            if chosen is not None and conn.topic not in chosen:
                continue
            if connection_filter is not None and not connection_filter(
                conn.topic, conn.type, conn.md5sum, conn.message_definition, conn.header
            ):
                continue
            ids.add(conn.id)
        return ids

    def read_messages(
        self,
        topics: Iterable[str] | str | None = None,
        start_time: Any = None,
        end_time: Any = None,
        connection_filter: Callable[..., bool] | None = None,
        raw: bool = False,
        return_connection_header: bool = False,
    ) -> Iterator[Any]:
        """Messages of ``topics`` between the times (inclusive), in time order."""
        bag = self._read()
        ids = self._connection_ids(topics, connection_filter)
        for conn, stamp, data in bag.messages(ids, _to_ns(start_time), _to_ns(end_time)):
            cls = message_class(conn)
            message: Any = (
                (conn.type, data, conn.md5sum, 0, cls) if raw else cls().deserialize(data)
            )
            if return_connection_header:
                yield BagMessageWithConnectionHeader(conn.topic, message, _time(stamp), conn.header)
            else:
                yield BagMessage(conn.topic, message, _time(stamp))

    def get_message_count(self, topic_filters: Iterable[str] | str | None = None) -> int:
        """Messages on ``topic_filters`` (all topics if None)."""
        return self._read().message_count(self._connection_ids(topic_filters))

    def get_start_time(self) -> float:
        """The time of the first message, in seconds."""
        start = self._read().start_time
        if start is None:
            raise ROSBagException("Bag contains no message")
        return start / 1e9

    def get_end_time(self) -> float:
        """The time of the last message, in seconds."""
        end = self._read().end_time
        if end is None:
            raise ROSBagException("Bag contains no message")
        return end / 1e9

    def get_type_and_topic_info(
        self, topic_filters: Iterable[str] | str | None = None
    ) -> TypesAndTopicsTuple:
        """Each type's md5sum, and each topic's type, count, connections, median frequency."""
        from rosx.bag.info import _median_frequency  # noqa: PLC0415 - bag code loads only for bags

        bag = self._read()
        ids = self._connection_ids(topic_filters)
        conns = [bag.connections[i] for i in sorted(ids)]
        types = {c.type: c.md5sum for c in sorted(conns, key=lambda c: c.type)}
        topics = {}
        for topic in sorted({c.topic for c in conns}):
            mine = [c for c in conns if c.topic == topic]
            chosen = {c.id for c in mine}
            topics[topic] = TopicTuple(
                mine[0].type,
                bag.message_count(chosen),
                len(mine),
                _median_frequency(bag, chosen),
            )
        return TypesAndTopicsTuple(types, topics)

    def get_compression_info(self) -> CompressionTuple:
        """The main compression and the uncompressed and stored sizes of the chunks."""
        bag = self._read()
        headers = [bag.chunk_header(i) for i in range(len(bag.chunks))]
        kinds = collections.Counter(h.compression for h in headers)
        main = kinds.most_common(1)[0][0] if kinds else Compression.NONE
        return CompressionTuple(
            main, sum(h.size for h in headers), sum(h.data_size for h in headers)
        )

    # -- closing -----------------------------------------------------------------------------

    def close(self) -> None:
        """Finish writing (the index) and close the file."""
        if self._writer is not None:
            self._writer.close()
        if self._reader is not None:
            self._reader.close()

    def __enter__(self) -> Bag:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def __iter__(self) -> Iterator[Any]:
        return self.read_messages()

    def __str__(self) -> str:
        from rosx.bag.info import format_text, summarize  # noqa: PLC0415 - bag code loads only for bags

        return format_text(summarize(self._read(), self._filename))


__all__ = [
    "Bag",
    "BagMessage",
    "Compression",
    "ROSBagEncryptException",
    "ROSBagEncryptNotSupportedException",
    "ROSBagException",
    "ROSBagFormatException",
    "ROSBagUnindexedException",
    "TopicTuple",
    "TypesAndTopicsTuple",
]
