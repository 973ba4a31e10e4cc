"""ROS 1's bag format 2.0, record by record: pure functions over bytes, no files.

A bag is the line ``#ROSBAG V2.0``, then records. Every record is a header (a length-prefixed
list of length-prefixed ``name=value`` fields, ``op`` naming the record's kind) and a data part
(length-prefixed bytes); integers are little-endian, times are ``uint32`` seconds and
nanoseconds (ROS wiki Bags/Format/2.0). The kinds:

=========== ===== ===================================== ========================================
record      op    header fields                         data
=========== ===== ===================================== ========================================
bag header  0x03  index_pos u64, conn_count, chunk_count padding: header + data = 4096 bytes
chunk       0x05  compression (none|bz2|lz4), size      connection and message records
index data  0x04  ver=1, conn, count                    count x (time, offset in the chunk)
connection  0x07  conn, topic                           the publisher's connection header
message     0x02  conn, time                            the serialized message
chunk info  0x06  ver=1, chunk_pos u64, start_time,     count x (conn, message count)
                  end_time, count
=========== ===== ===================================== ========================================

Fields are written in sorted order, as ROS 1's C++ writer does. Times are kept as integer
nanoseconds. What this module must not know: files, sockets, messages' contents.
"""

from __future__ import annotations

import struct
from typing import TYPE_CHECKING, NamedTuple

from rosx.bag.errors import BagError, BagFormatError

if TYPE_CHECKING:
    from collections.abc import Iterator, Mapping

MAGIC = b"#ROSBAG V2.0\n"
#: The bag header record's header and data together fill this many bytes.
BAG_HEADER_LENGTH = 4096

OP_MSG_DATA = 0x02
OP_BAG_HEADER = 0x03
OP_INDEX_DATA = 0x04
OP_CHUNK = 0x05
OP_CHUNK_INFO = 0x06
OP_CONNECTION = 0x07

U32 = struct.Struct("<I")
U64 = struct.Struct("<Q")
TIME = struct.Struct("<II")
INDEX_ENTRY = struct.Struct("<III")
_NS = 1_000_000_000


def pack_time(ns: int) -> bytes:
    """A ROS 1 time (seconds, nanoseconds) from integer nanoseconds."""
    return TIME.pack(*divmod(ns, _NS))


def unpack_time(data: bytes) -> int:
    """Integer nanoseconds from a packed ROS 1 time."""
    if len(data) != 8:
        raise BagFormatError(f"Expected a time field of 8 bytes, got {len(data)}")
    secs, nsecs = TIME.unpack(data)
    return int(secs) * _NS + int(nsecs)


def encode_fields(fields: Mapping[str, bytes | str]) -> bytes:
    """``fields`` as a header block: each ``name=value`` with its length, sorted by name."""
    parts = []
    for name in sorted(fields):
        value = fields[name]
        entry = name.encode() + b"=" + (value.encode() if isinstance(value, str) else value)
        parts.append(U32.pack(len(entry)))
        parts.append(entry)
    return b"".join(parts)


def decode_fields(block: bytes | memoryview) -> dict[str, bytes]:
    """The ``name=value`` fields of a header block (values as bytes).

    Raises:
        BagFormatError: a field overruns the block or has no ``=``.
    """
    fields: dict[str, bytes] = {}
    pos, end = 0, len(block)
    while pos < end:
        if pos + 4 > end:
            raise BagFormatError("Error reading header field")
        (size,) = U32.unpack_from(block, pos)
        pos += 4
        if size > end - pos:
            raise BagFormatError(f"Error reading header field: expected {size} bytes")
        entry = bytes(block[pos : pos + size])
        pos += size
        name, eq, value = entry.partition(b"=")
        if not eq:
            raise BagFormatError(f"Error reading header field: no '=' in {entry[:40]!r}")
        fields[name.decode("latin-1")] = value
    return fields


def encode_record(fields: Mapping[str, bytes | str], data: bytes = b"") -> bytes:
    """One record: its header block and its data, each with its length."""
    header = encode_fields(fields)
    return b"".join((U32.pack(len(header)), header, U32.pack(len(data)), data))


def field_u32(fields: Mapping[str, bytes], name: str) -> int:
    """A header's ``uint32`` field."""
    return _number(fields, name, U32)


def field_u64(fields: Mapping[str, bytes], name: str) -> int:
    """A header's ``uint64`` field."""
    return _number(fields, name, U64)


def _number(fields: Mapping[str, bytes], name: str, kind: struct.Struct) -> int:
    value = fields.get(name)
    if value is None:
        raise BagFormatError(f"Required '{name}' field missing")
    if len(value) != kind.size:
        raise BagFormatError(f"Field '{name}' has {len(value)} bytes, expected {kind.size}")
    number: int = kind.unpack(value)[0]
    return number


def field_op(fields: Mapping[str, bytes]) -> int:
    """A header's ``op`` (the record's kind)."""
    value = fields.get("op")
    if value is None or len(value) != 1:
        raise BagFormatError("Required 'op' field missing")
    return value[0]


# -- the records ------------------------------------------------------------------------------


def bag_header(index_pos: int, conn_count: int, chunk_count: int) -> bytes:
    """The bag header record, padded with spaces to its fixed size."""
    header = encode_fields(
        {
            "op": bytes([OP_BAG_HEADER]),
            "index_pos": U64.pack(index_pos),
            "conn_count": U32.pack(conn_count),
            "chunk_count": U32.pack(chunk_count),
        }
    )
    padding = b" " * (BAG_HEADER_LENGTH - len(header))
    return U32.pack(len(header)) + header + U32.pack(len(padding)) + padding


def connection_record(conn: int, topic: str, header: Mapping[str, str]) -> bytes:
    """A connection record: the publisher's connection header under id ``conn``."""
    fields: dict[str, bytes | str] = {
        "op": bytes([OP_CONNECTION]),
        "conn": U32.pack(conn),
        "topic": topic,
    }
    return encode_record(fields, encode_fields(header))


def message_record(conn: int, time_ns: int, data: bytes) -> bytes:
    """A message data record."""
    fields = {"op": bytes([OP_MSG_DATA]), "conn": U32.pack(conn), "time": pack_time(time_ns)}
    return encode_record(fields, data)


def message_record_head(conn: int, time_ns: int, size: int) -> bytes:
    """A message data record up to its data (to write the data without copying it)."""
    header = encode_fields(
        {"op": bytes([OP_MSG_DATA]), "conn": U32.pack(conn), "time": pack_time(time_ns)}
    )
    return U32.pack(len(header)) + header + U32.pack(size)


def chunk_record_head(compression: str, size: int, data_size: int) -> bytes:
    """A chunk record up to its data: ``size`` uncompressed bytes, ``data_size`` stored."""
    header = encode_fields(
        {"op": bytes([OP_CHUNK]), "compression": compression, "size": U32.pack(size)}
    )
    return U32.pack(len(header)) + header + U32.pack(data_size)


def index_record(conn: int, entries: list[tuple[int, int]]) -> bytes:
    """An index data record: ``(time_ns, offset)`` of each of ``conn``'s messages in a chunk."""
    fields: dict[str, bytes | str] = {
        "op": bytes([OP_INDEX_DATA]),
        "ver": U32.pack(1),
        "conn": U32.pack(conn),
        "count": U32.pack(len(entries)),
    }
    data = b"".join(INDEX_ENTRY.pack(*divmod(t, _NS), offset) for t, offset in entries)
    return encode_record(fields, data)


class ChunkInfo(NamedTuple):
    """Where a chunk is, the times of its first and last messages, and its per-connection
    message counts."""

    pos: int
    start_time: int
    end_time: int
    counts: dict[int, int]


def chunk_info_record(info: ChunkInfo) -> bytes:
    """A chunk info record."""
    fields: dict[str, bytes | str] = {
        "op": bytes([OP_CHUNK_INFO]),
        "ver": U32.pack(1),
        "chunk_pos": U64.pack(info.pos),
        "start_time": pack_time(info.start_time),
        "end_time": pack_time(info.end_time),
        "count": U32.pack(len(info.counts)),
    }
    data = b"".join(U32.pack(c) + U32.pack(n) for c, n in sorted(info.counts.items()))
    return encode_record(fields, data)


def parse_chunk_info(fields: Mapping[str, bytes], data: bytes) -> ChunkInfo:
    """A chunk info record's header and data, read."""
    if field_u32(fields, "ver") != 1:
        raise BagFormatError(f"Unknown chunk info record version: {field_u32(fields, 'ver')}")
    count = field_u32(fields, "count")
    if len(data) < count * 8:
        raise BagFormatError("Chunk info record too short")
    counts = {}
    for i in range(count):
        conn, n = struct.unpack_from("<II", data, i * 8)
        counts[conn] = n
    start = unpack_time(fields.get("start_time", b""))
    end = unpack_time(fields.get("end_time", b""))
    return ChunkInfo(field_u64(fields, "chunk_pos"), start, end, counts)


def parse_index(data: bytes | memoryview, count: int) -> list[tuple[int, int]]:
    """An index data record's entries: ``(time_ns, offset)``."""
    if len(data) < count * 12:
        raise BagFormatError("Index data record too short")
    return [(s * _NS + n, off) for s, n, off in INDEX_ENTRY.iter_unpack(data[: count * 12])]


def iter_records(
    buffer: bytes | memoryview, start: int = 0
) -> Iterator[tuple[int, dict[str, bytes], int, int]]:
    """Every record of ``buffer`` (a chunk's data): ``(offset, header, data_pos, data_len)``.

    Raises:
        BagFormatError: a record runs past the end of the buffer.
    """
    pos, end = start, len(buffer)
    while pos < end:
        offset = pos
        if pos + 4 > end:
            raise BagFormatError("Record header length overruns the chunk")
        (hlen,) = U32.unpack_from(buffer, pos)
        pos += 4
        if hlen > end - pos - 4:
            raise BagFormatError("Record header overruns the chunk")
        fields = decode_fields(buffer[pos : pos + hlen])
        pos += hlen
        (dlen,) = U32.unpack_from(buffer, pos)
        pos += 4
        if dlen > end - pos:
            raise BagFormatError("Record data overruns the chunk")
        yield offset, fields, pos, dlen
        pos += dlen


def decode_connection_header(data: bytes) -> dict[str, str]:
    """A connection record's data: the publisher's connection header, as text."""
    return {k: v.decode("utf-8", "replace") for k, v in decode_fields(data).items()}


# -- compression ------------------------------------------------------------------------------

COMPRESSIONS = ("none", "bz2", "lz4")


def compress(compression: str, data: bytes) -> bytes:
    """A chunk's records, compressed as ``compression`` says."""
    if compression == "none":
        return data
    if compression == "bz2":
        import bz2  # noqa: PLC0415 - only bags that use it pay for it

        return bz2.compress(data)
    if compression == "lz4":
        import lz4.frame  # noqa: PLC0415 - lz4 loads only on this path

        # ROS 1's roslz4 reads only frames laid out as it writes them: 1 MiB independent
        # blocks, a content checksum and no content size (lz4's defaults differ).
        out: bytes = lz4.frame.compress(
            data,
            block_size=lz4.frame.BLOCKSIZE_MAX1MB,
            block_linked=False,
            content_checksum=True,
            store_size=False,
        )
        return out
    raise BagError(f"Unknown compression type: {compression}")


#: What a chunk may say it holds whatever it stores: records up to the chunk threshold plus one
#: message (a chunk over ROS 1's 768 KiB threshold holds a single large message).
CHUNK_FLOOR = 64 << 20
#: Beyond `CHUNK_FLOOR`, how many times its stored bytes a compressed chunk may expand to. Real
#: data compresses a few times (lz4 cannot pass 255); a chunk claiming more is a bomb, which
#: a few hundred bytes of bz2 can make of half a gigabyte of zeros.
MAX_RATIO = 1000


def decompress(compression: str, data: bytes, size: int) -> bytes:
    """A chunk's records from its stored bytes.

    Never produces more than ``size`` bytes, and refuses a ``size`` beyond `CHUNK_FLOOR` that
    is more than `MAX_RATIO` times the stored bytes, so a small file cannot make its reader
    allocate gigabytes.

    Raises:
        BagFormatError: unknown compression, a ``size`` out of proportion to the stored bytes,
            or bytes that do not decompress to ``size``.
    """
    if compression == "none":
        return data  # the stored bytes are the records, whatever the size field says (ROS 1)
    if compression in ("bz2", "lz4"):
        if size > CHUNK_FLOOR and size > MAX_RATIO * len(data):
            raise BagFormatError(
                f"Chunk says it holds {size} bytes in {len(data)} bytes of {compression}: "
                "too many to be true"
            )
        out = _decompress(compression, data, size)
    else:
        raise BagFormatError(f"Unknown compression type: {compression}")
    if len(out) != size:
        raise BagFormatError(f"Chunk is {len(out)} bytes, its header says {size}")
    return out


def _decompress(compression: str, data: bytes, size: int) -> bytes:
    # One stream (one frame) per chunk, as ROS 1 writes them; one byte over `size` is enough
    # to know the header is wrong.
    try:
        if compression == "bz2":
            import bz2  # noqa: PLC0415 - only bags that use it pay for it

            return bz2.BZ2Decompressor().decompress(data, max_length=size + 1)
        import lz4.frame  # noqa: PLC0415 - lz4 loads only on this path

        out: bytes = lz4.frame.LZ4FrameDecompressor().decompress(data, max_length=size + 1)
        return out
    except (OSError, ValueError, EOFError, RuntimeError) as exc:
        raise BagFormatError(f"Error decompressing {compression} chunk: {exc}") from None
