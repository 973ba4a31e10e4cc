"""rqt_console's data: log entries from ``/rosout_agg``, the rules that filter them, the view.

Pure Python, no threads and no textual: the app feeds `Log.add` batches and reads `Log.shown`.

* `Entry`: one ``rosgraph_msgs/Log`` (time, severity, node, message, topics, location), with a
  repeat count: a record equal to the one before it (same node, severity and text) bumps the
  count instead of taking a row (ros_comm#68's duplicate spam).
* `Rule`: ``include``, ``exclude`` or ``highlight`` on one field — ``severity`` (names, or a
  minimum as ``warn+``), ``node``, ``text``, ``topic`` or ``location`` (regular expressions,
  searched anywhere). Written as ``FIELD:PATTERN``; a bare pattern is on the text.
* `Log`: the entries kept (at most ``limit``; the oldest go first) and the ones shown: no
  include rule or one that matches, and no exclude rule that matches. A new entry is checked
  against the rules once, when it arrives; a change of rules re-checks every entry once. The
  shown rows are a list of entry numbers, so the table draws any row without walking the rest.
"""

from __future__ import annotations

import re
import time
from bisect import bisect_left
from dataclasses import dataclass, field
from enum import Enum
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from collections.abc import Callable, Iterable, Sequence

#: rosgraph_msgs/Log's levels, as rqt_console names them.
SEVERITIES = {1: "Debug", 2: "Info", 4: "Warn", 8: "Error", 16: "Fatal"}
_LEVELS_BY_NAME = {name.lower(): level for level, name in SEVERITIES.items()}
#: How many entries are kept unless said otherwise.
DEFAULT_LIMIT = 100_000
FIELDS = ("severity", "node", "text", "topic", "location")
_FIELD_ALIASES = {"level": "severity", "message": "text", "msg": "text", "topics": "topic"}


@dataclass(slots=True, eq=False)
class Entry:
    """One log record (and how many times in a row it came)."""

    stamp: float
    level: int
    node: str
    message: str
    topics: tuple[str, ...] = ()
    location: str = ""
    count: int = 1

    @property
    def severity(self) -> str:
        """The severity's name as rqt_console shows it (``Warn``), or the number if unknown."""
        return SEVERITIES.get(self.level, str(self.level))

    def repeats(self, other: Entry) -> bool:
        """Whether ``other`` says again what this entry says."""
        return (
            self.message == other.message
            and self.node == other.node
            and self.level == other.level
            and self.location == other.location
        )


def location(file: str, function: str, line: int) -> str:
    """rqt_console's location column: ``file:function:line``, empty when nothing is known."""
    if not (file or function or line):
        return ""
    return f"{file}:{function}:{line}"


class Kind(Enum):
    """What a rule does to the messages it matches: keep only them, drop them, or highlight them."""

    INCLUDE = "include"
    EXCLUDE = "exclude"
    HIGHLIGHT = "highlight"


class RuleError(ValueError):
    """A rule that does not parse; the message says what is wrong."""


@dataclass(frozen=True)
class Rule:
    """One include, exclude or highlight rule on one field of the entries."""

    kind: Kind
    subject: str
    pattern: str
    levels: frozenset[int] = frozenset()
    regex: re.Pattern[str] | None = field(default=None, compare=False)

    @classmethod
    def parse(cls, kind: Kind, text: str) -> Rule:
        """``FIELD:PATTERN`` (or a bare text pattern) as a rule of ``kind``.

        Raises:
            RuleError: an unknown field or severity, or a pattern that is no regular expression.
        """
        name, sep, pattern = text.partition(":")
        name = _FIELD_ALIASES.get(name.strip().lower(), name.strip().lower())
        if not sep or name not in FIELDS:
            if sep and re.fullmatch(r"[a-z]+", name):
                raise RuleError(f"unknown field {name!r}: use one of {', '.join(FIELDS)}")
            name, pattern = "text", text
        pattern = pattern.strip()
        if not pattern:
            raise RuleError(f"empty {name} pattern")
        if name == "severity":
            return cls(kind, name, pattern, _levels(pattern))
        try:
            regex = re.compile(pattern)
        except re.error as error:
            raise RuleError(f"bad regular expression {pattern!r}: {error}") from None
        return cls(kind, name, pattern, regex=regex)

    def matches(self, entry: Entry) -> bool:
        """Whether ``entry`` matches: its severity among ``levels``, or the pattern found in the
        field."""
        if self.subject == "severity":
            return entry.level in self.levels
        regex = self.regex
        assert regex is not None
        if self.subject == "topic":
            return any(regex.search(topic) for topic in entry.topics)
        value = {"node": entry.node, "text": entry.message, "location": entry.location}
        return regex.search(value[self.subject]) is not None

    def __str__(self) -> str:
        return f"{self.kind.value} {self.subject}:{self.pattern}"


def _levels(text: str) -> frozenset[int]:
    """Severities from ``warn,error``, ``warn+`` (warn and above) or ``-info`` (info and
    below)."""
    levels: set[int] = set()
    for word in text.lower().replace(" ", "").split(","):
        bare = word.strip("+-")
        if bare not in _LEVELS_BY_NAME:
            names = ", ".join(name.lower() for name in SEVERITIES.values())
            raise RuleError(f"unknown severity {bare!r}: use {names}, NAME+ or -NAME")
        level = _LEVELS_BY_NAME[bare]
        if word.endswith("+"):
            levels.update(lv for lv in SEVERITIES if lv >= level)
        elif word.startswith("-"):
            levels.update(lv for lv in SEVERITIES if lv <= level)
        else:
            levels.add(level)
    return frozenset(levels)


@dataclass(frozen=True)
class Rules:
    """The rules in force, in the order they were added."""

    rules: tuple[Rule, ...] = ()

    def with_rule(self, rule: Rule) -> Rules:
        """These rules with ``rule`` added last (rules are immutable)."""
        return Rules((*self.rules, rule))

    def without(self, kind: Kind | None = None) -> Rules:
        """These rules less those of ``kind`` (all of them when None)."""
        return Rules(tuple(r for r in self.rules if kind is not None and r.kind is not kind))

    def of(self, kind: Kind) -> tuple[Rule, ...]:
        """The rules of ``kind``, in the order added."""
        return tuple(r for r in self.rules if r.kind is kind)

    def shows(self, entry: Entry) -> bool:
        """Whether ``entry`` passes: an include rule matches (or there is none) and no exclude
        rule does."""
        includes = self.of(Kind.INCLUDE)
        if includes and not any(rule.matches(entry) for rule in includes):
            return False
        return not any(rule.matches(entry) for rule in self.of(Kind.EXCLUDE))

    def highlights(self, entry: Entry) -> bool:
        """Whether a highlight rule matches ``entry``."""
        return any(rule.matches(entry) for rule in self.of(Kind.HIGHLIGHT))

    def matcher(self) -> Callable[[Entry], bool]:
        """`shows` as one function, the rules sorted out once (for filtering many entries)."""
        includes, excludes = self.of(Kind.INCLUDE), self.of(Kind.EXCLUDE)
        if not includes and not excludes:
            return lambda _entry: True
        include = [rule.matches for rule in includes]
        exclude = [rule.matches for rule in excludes]

        def shows(entry: Entry) -> bool:
            if include and not any(match(entry) for match in include):
                return False
            return not any(match(entry) for match in exclude)

        return shows


class Log:
    """The entries kept and the numbers of those shown (see the module docstring)."""

    def __init__(self, limit: int = DEFAULT_LIMIT) -> None:
        self.limit = max(1, limit)
        self._entries: list[Entry] = []
        #: The number of the first entry kept (entries are numbered from 0 as they come).
        self._first = 0
        self._shown: list[int] = []
        self.rules = Rules()
        self._shows: Callable[[Entry], bool] = self.rules.matcher()
        #: Entries received in all (repeats included), and dropped for the limit.
        self.received = 0
        self.dropped = 0

    def __len__(self) -> int:
        return len(self._entries)

    @property
    def shown_count(self) -> int:
        """How many entries pass the rules."""
        return len(self._shown)

    def shown(self, row: int) -> Entry:
        """The entry on shown row ``row``."""
        return self._entries[self._shown[row] - self._first]

    def rows(self, start: int, stop: int) -> Sequence[Entry]:
        """The entries on shown rows ``start`` to ``stop`` (excluded)."""
        first = self._first
        return [self._entries[number - first] for number in self._shown[start:stop]]

    def add(self, entries: Iterable[Entry]) -> int:
        """Keep ``entries`` (in order of arrival); the number of rows added to the shown ones
        (repeats of the last entry add none)."""
        kept, shown, shows = self._entries, self._shown, self._shows
        before = len(shown)
        for entry in entries:
            self.received += 1
            if kept and kept[-1].repeats(entry):
                last = kept[-1]
                last.count += entry.count
                last.stamp = entry.stamp
                continue
            kept.append(entry)
            if shows(entry):
                shown.append(self._first + len(kept) - 1)
        if len(kept) > self.limit:
            self._drop(len(kept) - self.limit)
        return len(shown) - before

    def _drop(self, count: int) -> None:
        # Dropping a tenth at a time keeps the cost of the list moves off every batch.
        count = max(count, min(len(self._entries) - 1, self.limit // 10))
        del self._entries[:count]
        self._first += count
        self.dropped += count
        del self._shown[: bisect_left(self._shown, self._first)]

    def set_rules(self, rules: Rules) -> None:
        """Filter every kept entry again under ``rules``."""
        self.rules = rules
        self._shows = shows = rules.matcher()
        first = self._first
        self._shown = [first + i for i, entry in enumerate(self._entries) if shows(entry)]

    def clear(self) -> None:
        """Forget every entry (the rules stay)."""
        self._first += len(self._entries)
        self._entries = []
        self._shown = []


def clock_text(stamp: float) -> str:
    """An entry's time as the table shows it: local ``HH:MM:SS.mmm``."""
    whole, millis = divmod(round(stamp * 1000), 1000)
    return time.strftime("%H:%M:%S", time.localtime(whole)) + f".{millis:03d}"


def stamp_text(stamp: float) -> str:
    """An entry's full time for the details: ``secs.micros (YYYY-MM-DD HH:MM:SS)``."""
    day = time.strftime("%Y-%m-%d %H:%M:%S", time.localtime(int(stamp)))
    return f"{stamp:.6f} ({day})"


def details(entry: Entry) -> str:
    """Every field of ``entry``, one per line, for the details panel."""
    repeated = f" ({entry.count} times)" if entry.count > 1 else ""
    return "\n".join(
        (
            f"Node: {entry.node}",
            f"Time: {stamp_text(entry.stamp)}",
            f"Severity: {entry.severity}{repeated}",
            f"Published Topics: {', '.join(entry.topics)}",
            f"Location: {entry.location}",
            "",
            entry.message,
        )
    )
