"""A node's log file, as rospy writes it when given ``__log:=PATH`` (roslaunch passes one per
node, ``<log folder>/<run_id>/<name>-N.log``).

Each line is rospy's file format, ``[logger][LEVEL] YYYY-MM-DD HH:MM:SS,mmm: text``, with
Python's level names (``WARNING``, ``CRITICAL`` for FATAL): the node's own records under the
``rosout`` logger (``rosout.<name>`` given ``logger_name=``), and rospy's start and stop lines
(``rospy.client``'s ``init_node, name[…], pid[…]``, ``rospy.core``'s ``signal_shutdown […]``).
rospy's other internal lines (XML-RPC server, registration) are not written. A file that cannot
be opened is no log, not an error.
"""

from __future__ import annotations

import threading
import time
from pathlib import Path
from typing import TextIO

from rosx.node.rosout import DEBUG, ERROR, FATAL, INFO, WARN

_LEVEL_NAMES = {DEBUG: "DEBUG", INFO: "INFO", WARN: "WARNING", ERROR: "ERROR", FATAL: "CRITICAL"}


class LogFile:
    """One open log file; lines may come from any thread."""

    def __init__(self, stream: TextIO) -> None:
        self._stream = stream
        self._lock = threading.Lock()

    def write(self, logger: str, level: int, text: str) -> None:
        """Append one record, stamped with the time now."""
        now = time.time()
        stamp = time.strftime("%Y-%m-%d %H:%M:%S", time.localtime(now))
        line = f"[{logger}][{_LEVEL_NAMES.get(level, 'INFO')}] {stamp},{int(now % 1 * 1000):03d}: "
        with self._lock:
            if not self._stream.closed:
                self._stream.write(line + text + "\n")
                self._stream.flush()

    def close(self) -> None:
        """Close the log file; later lines are dropped, not raised on."""
        with self._lock:
            self._stream.close()


def open_log_file(path: str) -> LogFile | None:
    """``path`` opened for appending (its folder made), or None when it cannot be."""
    try:
        file = Path(path).absolute()
        file.parent.mkdir(parents=True, exist_ok=True)
        return LogFile(file.open("a", encoding="utf-8"))
    except OSError:
        return None


__all__ = ["LogFile", "open_log_file"]
