"""A small bag of many chunks, and where its records are: what the corrupt-bag tests damage."""

from __future__ import annotations

import io
from pathlib import Path

from rosx.bag import records as rec
from rosx.bag.reader import BagReader
from rosx.bag.writer import BagWriter
from rosx.msg.codec.classes import get_message_class

#: Messages in `sample_bag`: two topics, one message each per 10 ms.
MESSAGES = 60


def _header(type_name: str, topic: str) -> dict[str, str]:
    cls = get_message_class(type_name)
    return {
        "callerid": "/talker",
        "latching": "0",
        "md5sum": cls._md5sum,
        "message_definition": cls._full_text,
        "topic": topic,
        "type": type_name,
    }


def sample_bag(path: Path, compression: str = "none") -> None:
    """Write `MESSAGES` messages of ``/chatter`` and ``/cmd`` in a dozen small chunks."""
    string = get_message_class("std_msgs/String")
    twist = get_message_class("geometry_msgs/Twist")
    with BagWriter(path, compression=compression, chunk_threshold=400) as bag:
        chatter = bag.add_connection("/chatter", _header("std_msgs/String", "/chatter"))
        cmd = bag.add_connection("/cmd", _header("geometry_msgs/Twist", "/cmd"))
        for i in range(MESSAGES // 2):
            buffer = io.BytesIO()
            string(data=f"hello {i}").serialize(buffer)
            bag.write(chatter, 1_000_000_000 + i * 10_000_000, buffer.getvalue())
            buffer = io.BytesIO()
            message = twist()
            message.linear.x = float(i)
            message.serialize(buffer)
            bag.write(cmd, 1_000_000_000 + i * 10_000_000 + 5, buffer.getvalue())


def record_ends(data: bytes) -> list[int]:
    """Where each top-level record of a whole bag ends (the bag header's end first)."""
    ends = []
    pos = len(rec.MAGIC)
    while pos < len(data):
        (header,) = rec.U32.unpack_from(data, pos)
        (length,) = rec.U32.unpack_from(data, pos + 4 + header)
        pos += 8 + header + length
        ends.append(pos)
    return ends


def chunk_spans(path: Path) -> list[tuple[int, int, int]]:
    """Each chunk of a whole bag: where its record starts and ends, and its messages."""
    with BagReader(path) as bag:
        spans = []
        for index, info in enumerate(bag.chunks):
            header = bag.chunk_header(index)
            spans.append((info.pos, header.data_pos + header.data_size, sum(info.counts.values())))
    return spans
