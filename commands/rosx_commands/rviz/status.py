"""A display's statuses as rviz keeps them: named entries, each with a level and a text.

rviz shows, under each display, a "Status" list: one entry per concern ("Topic", "Transform",
"Points", "Message"…), each Ok, Warn or Error with a text in rviz's words, and the display's
own level is the worst of them. `StatusList` is that list; `summary` is the one line the
Displays panel shows: the worst problem if there is one, else the most telling Ok text.
"""

from __future__ import annotations

from enum import IntEnum


class Level(IntEnum):
    """rviz's ``StatusProperty::Level``."""

    OK = 0
    WARN = 1
    ERROR = 2


#: The texts rviz and rosx give the usual cases.
OK = "OK"
NO_MESSAGES = "No messages received"
UNSUPPORTED = "unsupported"
DISABLED = "disabled"


def no_transform(frame: str, fixed: str) -> str:
    """rviz's words for a frame tf cannot put into the fixed frame."""
    return f"No transform from [{frame}] to [{fixed}]"


def received(count: int) -> str:
    """rviz's count of messages on a display's topic."""
    return f"{count} messages received"


def showing(points: int, messages: int) -> str:
    """rviz's count of points a cloud or scan display draws."""
    return f"Showing [{points}] points from [{messages}] messages"


class StatusList:
    """The named statuses of one display, in the order they were first set."""

    def __init__(self) -> None:
        self.entries: dict[str, tuple[Level, str]] = {}

    def set(self, name: str, level: Level, text: str) -> None:
        """Set status ``name``; a new name goes last, an existing one keeps its place."""
        self.entries[name] = (level, text)

    def ok(self, name: str, text: str) -> None:
        """Set status ``name`` to OK with ``text``."""
        self.set(name, Level.OK, text)

    def warn(self, name: str, text: str) -> None:
        """Set status ``name`` to Warn with ``text``."""
        self.set(name, Level.WARN, text)

    def error(self, name: str, text: str) -> None:
        """Set status ``name`` to Error with ``text``."""
        self.set(name, Level.ERROR, text)

    def delete(self, name: str) -> None:
        """Remove status ``name``, if it is set."""
        self.entries.pop(name, None)

    def clear(self) -> None:
        """Remove every status."""
        self.entries.clear()

    @property
    def level(self) -> Level:
        """The worst level of the entries (OK when there are none)."""
        return max((level for level, _ in self.entries.values()), default=Level.OK)

    def summary(self, prefer: tuple[str, ...] = ()) -> str:
        """One line: the first entry at the worst level when something is wrong; otherwise
        the text of the first of ``prefer`` that is set, else ``OK``."""
        level = self.level
        if level > Level.OK:
            return next(text for lvl, text in self.entries.values() if lvl == level)
        for name in prefer:
            entry = self.entries.get(name)
            if entry is not None:
                return entry[1]
        return OK


__all__ = [
    "DISABLED",
    "NO_MESSAGES",
    "OK",
    "UNSUPPORTED",
    "Level",
    "StatusList",
    "no_transform",
    "received",
    "showing",
]
