"""A started simulator and what it printed, for the node tests."""

from __future__ import annotations

import io
from dataclasses import dataclass

from rosx_turtle.node import TurtlesimNode


@dataclass
class Sim:
    """A started simulator and what it printed."""

    node: TurtlesimNode
    out: io.StringIO
    err: io.StringIO

    def lines(self) -> list[str]:
        return self.out.getvalue().splitlines()

    def errors(self) -> list[str]:
        return self.err.getvalue().splitlines()
