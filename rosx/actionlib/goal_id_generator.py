"""Goal ids a server makes up for goals sent without one (``actionlib.goal_id_generator``).

An id is ``<name>-<n>-<secs>.<nsecs>``: the node's name, a number counting the ids of the whole
process from 1 (shared by every generator, safe across threads), and the time it was made.
"""

from __future__ import annotations

import itertools
import threading
from typing import Any

from rosx.actionlib.protocol import msgs
from rosx.client import lifecycle, timing

_count = itertools.count(1)
_count_lock = threading.Lock()


class GoalIDGenerator:
    """Makes unique `GoalID`s named after ``name`` (the node's name by default)."""

    def __init__(self, name: str | None = None) -> None:
        self.name = ""
        self.set_name(name if name is not None else lifecycle.get_name())

    def set_name(self, name: str) -> None:
        """Name the ids after ``name`` (normally a fully qualified node name)."""
        self.name = name

    def generate_ID(self) -> Any:  # noqa: N802 - actionlib's name
        """A new ``actionlib_msgs/GoalID``, stamped now."""
        now = timing.Time.now()
        with _count_lock:
            number = next(_count)
        return msgs().GoalID(id=f"{self.name}-{number}-{now.secs}.{now.nsecs}", stamp=now)


__all__ = ["GoalIDGenerator"]
