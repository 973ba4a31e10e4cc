"""A plot feed for tests: a fixed clock, samples appended by the test, no network."""

from __future__ import annotations

import math

from rosx_commands.rqt_plot.series import Series, SeriesError

#: Names this feed refuses, with the reason (as a live feed words it).
REFUSED = {"/turtle1/pose": "/turtle1/pose is a topic (turtlesim/Pose): name a numeric field of it"}


class StaticFeed:
    """Every series attaches at once; ``now`` moves only when the test says so."""

    def __init__(self, now: float = 10.0) -> None:
        self.time = now
        self.attached: list[str] = []
        self.detached: list[str] = []
        self.closed = False

    def now(self) -> float:
        return self.time

    def attach(self, series: Series) -> bool:
        if series.name in REFUSED:
            raise SeriesError(REFUSED[series.name])
        self.attached.append(series.name)
        return True

    def detach(self, series: Series) -> None:
        self.detached.append(series.name)

    def close(self) -> None:
        self.closed = True


def fill(series: Series, phase: float, until: float = 10.0, rate: float = 20.0) -> None:
    """A sine of period 2π s from 0 to ``until`` seconds, ``rate`` samples a second."""
    for i in range(int(until * rate) + 1):
        t = i / rate
        series.append(t, math.sin(t + phase))
