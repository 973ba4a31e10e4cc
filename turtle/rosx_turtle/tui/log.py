"""turtlesim's log lines for the screen: `ScreenConsole` hands them to a feed, not to stdout.

While the pond is drawn, printing would scribble over it; the node's records still go to
``/rosout`` as always, and the screen shows the latest one in a `LogLine`.
"""

from __future__ import annotations

import io
import sys
from dataclasses import dataclass
from typing import TYPE_CHECKING

from rosx_turtle.console import SEVERITIES, Console

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    from collections.abc import Callable, Mapping


@dataclass(frozen=True)
class LogRecord:
    """One log record: rosconsole's severity (``" WARN"``...) and the message."""

    level: int
    severity: str
    message: str

    def __str__(self) -> str:
        return f"[{self.severity}] {self.message}"


class ScreenConsole(Console):
    """A console that offers each record to ``offer`` (quickly, from the node's threads)."""

    def __init__(
        self, offer: Callable[[LogRecord], object], environ: Mapping[str, str] | None = None
    ) -> None:
        super().__init__(io.StringIO(), io.StringIO(), environ or {})
        self.offer = offer

    @override
    def print(
        self, level: int, message: str, *, node: str = "", sim_nanos: int | None = None
    ) -> None:
        self.offer(LogRecord(level, SEVERITIES.get(level, " INFO"), message))
