"""Editing bags: copying messages into a new bag, compressed or not, filtered or not; checking
what a bag's types have become; where an edited bag's original is kept.

What ``rosbag compress/decompress/filter/reindex/check`` do to files, without their options and
words (`rosx_commands.rosbag.tools` has those):

- `copy_messages`: every message a predicate keeps, from a reader to a writer, each connection
  added once, in time order;
- `recompress`: a whole bag written again with another chunk compression;
- `uncompressed_size` and `data_size`: ROS 1's measures of the work, for progress lines;
- `backup_path`: ``NAME.orig.bag``, where a bag edited in place keeps its original;
- `bag_file_problem`: why a file cannot be a bag (empty, another format), before reindexing;
- `changed_types`: the recorded types whose md5 sum differs from this system's.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from rosx.bag.reader import BagReader

if TYPE_CHECKING:
    from collections.abc import Callable

    from rosx.bag.reader import Connection
    from rosx.bag.writer import BagWriter

#: What a bag file starts with (format 2.0 and older).
BAG_MAGIC = b"#ROSBAG V"


def copy_messages(
    source: BagReader, target: BagWriter, keep: Callable[[Connection, int, bytes], bool]
) -> None:
    """Write every message of ``source`` that ``keep(connection, stamp, data)`` accepts to
    ``target``, in time order; each connection is added to ``target`` once, when first kept."""
    ids: dict[int, int] = {}
    for conn, stamp, data in source.messages():
        if not keep(conn, stamp, data):
            continue
        if conn.id not in ids:
            ids[conn.id] = target.add_connection(conn.topic, conn.header)
        target.write(ids[conn.id], stamp, data)


def recompress(source: str, out: str, compression: str) -> None:
    """Write the bag at ``source`` again at ``out`` with chunks compressed as ``compression``
    (``none``, ``bz2`` or ``lz4``).

    Raises:
        BagError: ``source`` cannot be read.
        OSError: a file cannot be read or written.
    """
    from rosx.bag.writer import BagWriter  # noqa: PLC0415 - lz4 and bz2 only when writing

    with BagReader(source) as bag, BagWriter(out, compression=compression) as writer:
        copy_messages(bag, writer, lambda *_: True)


def uncompressed_size(path: str) -> int:
    """ROS 1's measure of a bag to copy: its chunks' uncompressed sizes (or the file's size)."""
    with BagReader(path) as bag:
        if not bag.chunks:
            return bag.size
        return sum(bag.chunk_header(i).size for i in range(len(bag.chunks)))


def data_size(path: str) -> int:
    """ROS 1's measure of a bag to reindex: the file up to its index (all of it if none)."""
    with BagReader(path, allow_unindexed=True) as bag:
        return bag.index_pos or bag.size


def backup_path(path: str) -> Path:
    """Where a bag edited in place keeps its original: ``NAME.orig.bag`` beside it."""
    named = Path(path)
    return named.with_name(f"{named.stem}.orig{named.suffix}")


def bag_file_problem(path: str) -> str | None:
    """Why the file at ``path`` cannot be a bag (unreadable, empty, another format), or None.

    Only the first bytes are read: a bag whose writer never closed it still qualifies.
    """
    try:
        with Path(path).open("rb") as file:
            head = file.read(len(BAG_MAGIC) + 4)
    except OSError as exc:
        return str(exc)
    if not head:
        return "empty file"
    if not head.startswith(BAG_MAGIC):
        return "This does not appear to be a bag file"
    return None


def changed_types(
    bag: BagReader, current_md5: Callable[[str], str | None]
) -> list[tuple[str, str]]:
    """The recorded ``(type, md5sum)`` pairs whose type has another md5 sum here, in the
    bag's connection order; ``current_md5`` gives this system's sum, or None for a type it does
    not know (that one plays with the definition the bag recorded). Every message is read, so
    a damaged chunk raises here.

    Raises:
        BagError: a chunk or record cannot be read.
    """
    changed: list[tuple[str, str]] = []
    for conn in bag.connections.values():
        current = current_md5(conn.type)
        if (
            current is not None
            and current != conn.md5sum
            and (conn.type, conn.md5sum) not in changed
        ):
            changed.append((conn.type, conn.md5sum))
    for _ in bag.messages():
        pass  # every chunk decompresses, every record parses
    return changed


__all__ = [
    "backup_path",
    "bag_file_problem",
    "changed_types",
    "copy_messages",
    "data_size",
    "recompress",
    "uncompressed_size",
]
