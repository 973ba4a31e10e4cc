"""Bags: ROS 1's format 2.0 read and written, recorded from topics and played back to them.

Format code, with no I/O beyond files: `records` (the records as bytes), `reader`
(`BagReader`: index, chunks, messages in time order), `writer` (`BagWriter`: incremental
writing, chunk by chunk), `reindex` (a bag whose writer never closed it), `info` (ROS 1's
``rosbag info`` text and YAML). Shells over the node runtime: `recorder` (raw subscriptions
into a writer) and `player` (raw publications from a reader). `api` is the ``rosbag`` Python
API of ROS 1 (``rosbag.Bag``) for users' scripts, importable as ``rosbag`` from `SHIM_DIR`.

This package imports `rosx.msg`, `rosx.node` and `rosx.names`, nothing above them. Importing it
loads none of its modules.
"""

from __future__ import annotations

from pathlib import Path

#: The import-path entry holding the ``rosbag`` module of users' scripts (see
#: `rosx.client.script`; the commands put it on the path beside the client's).
SHIM_DIR = Path(__file__).resolve().parent / "shim"

__all__ = ["SHIM_DIR"]
