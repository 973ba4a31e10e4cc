"""Bags: ROS 1's format 2.0 read and written, recorded from topics and played back to them.

Format code, with no I/O beyond files: `records` (the records as bytes), `reader`
(`BagReader`: index, chunks, messages in time order), `writer` (`BagWriter`: incremental
writing, chunk by chunk), `reindex` (a bag whose writer never closed it), `info` (ROS 1's
``rosbag info`` text and YAML). Shells over the node runtime: `recorder` (raw subscriptions
into a writer) and `player` (raw publications from a reader). `api` is the ``rosbag`` Python
API of ROS 1 (``rosbag.Bag``) for users' scripts.

This package imports `rosx.msg`, `rosx.node` and `rosx.names`, nothing above them.
"""

from __future__ import annotations

from rosx.bag.errors import BagError, BagFormatError, BagUnindexedError
from rosx.bag.reader import BagReader, Connection
from rosx.bag.writer import BagWriter

__all__ = [
    "BagError",
    "BagFormatError",
    "BagReader",
    "BagUnindexedError",
    "BagWriter",
    "Connection",
]
