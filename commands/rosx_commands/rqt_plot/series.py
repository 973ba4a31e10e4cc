"""What ``rosx rqt_plot`` plots: series of numbers over time, kept in fixed-size ring buffers.

A `Series` is one ``TOPIC/FIELD`` (``/turtle1/pose/x``, ``/scan/ranges[0]``) and its samples.
Its buffer never grows: once full, each new sample replaces the oldest, so a plot left open
for hours costs what it cost after a minute (rqt_plot#1). Samples are written twice, at ``i``
and ``i + capacity``, so the samples in time order are always one contiguous slice: no copy
of the buffer to draw it. Writers (the subscriptions' threads) and the reader (the UI) share
one lock per series.

`expand_args` reads rqt_plot's command line shorthand; `envelope` thins a window of samples
to what a plot of some columns can show (min and max per column), so drawing costs the
width of the screen, not the rate of the topic.
"""

from __future__ import annotations

import threading
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from collections.abc import Iterable

    import numpy as np
    from numpy.typing import NDArray

#: Samples kept per series: one hour at 25 Hz, 100 s at 1 kHz.
CAPACITY = 100_000


class SeriesError(ValueError):
    """A series that cannot be plotted; ``str()`` says why."""


def expand_args(args: Iterable[str]) -> list[str]:
    """rqt_plot's ways to name several fields at once: ``/a/x,/b/y`` and ``/pose/x:y:theta``.

    The fields after a colon share the topic (and parent fields) of the first one.
    """
    names: list[str] = []
    for arg in args:
        for part in (p for p in arg.split(",") if p):
            if ":" not in part:
                names.append(part)
                continue
            first, *more = part.split(":")
            if "/" not in first.strip("/"):
                raise SeriesError(f"{part} must contain a topic and field name")
            names.append(first)
            parent = first[: first.rfind("/")]
            names.extend(f"{parent}/{field}" for field in more if field)
    return names


class Series:
    """One plotted field: its name, its colour and its last `CAPACITY` samples."""

    def __init__(self, name: str, style: str = "white", capacity: int = CAPACITY) -> None:
        import numpy as np  # numpy only on this path

        self.name = name
        self.style = style
        self.capacity = capacity
        self.status = ""  # why nothing arrives, when something is wrong
        self._times = np.zeros(2 * capacity)
        self._values = np.zeros(2 * capacity)
        self._head = 0
        self._count = 0
        self.received = 0  # samples ever appended (the UI redraws when it moves)
        self._lock = threading.Lock()

    def __len__(self) -> int:
        return self._count

    def append(self, time: float, value: float) -> None:
        """Add one sample; the oldest goes once the buffer is full."""
        with self._lock:
            head, capacity = self._head, self.capacity
            self._times[head] = self._times[head + capacity] = time
            self._values[head] = self._values[head + capacity] = value
            self._head = (head + 1) % capacity
            self._count = min(self._count + 1, capacity)
            self.received += 1

    def clear(self) -> None:
        """Drop every sample (the series stays, counting as changed)."""
        with self._lock:
            self._head = self._count = 0
            self.received += 1

    @property
    def latest(self) -> float | None:
        """The newest value, or None if there is none."""
        with self._lock:
            if not self._count:
                return None
            return float(self._values[(self._head - 1) % self.capacity])

    def window(self, start: float, end: float) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """Copies of the times and values of the samples between ``start`` and ``end``."""
        import numpy as np  # numpy only on this path

        with self._lock:
            last = self._head + self.capacity
            times = self._times[last - self._count : last]
            values = self._values[last - self._count : last]
            first = np.searchsorted(times, start, side="left")
            stop = np.searchsorted(times, end, side="right")
            return times[first:stop].copy(), values[first:stop].copy()

    def all(self) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """Copies of every sample kept, oldest first."""
        return self.window(float("-inf"), float("inf"))


def envelope(
    times: NDArray[np.float64],
    values: NDArray[np.float64],
    start: float,
    end: float,
    columns: int,
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """At most two points per column (the smallest and the largest value in it), in time order;
    fewer samples than that are returned as they are."""
    import numpy as np  # numpy only on this path

    if len(times) <= 2 * columns or end <= start:
        return times, values
    bins = ((times - start) * (columns / (end - start))).astype(np.int64)
    starts = np.concatenate(([0], np.flatnonzero(np.diff(bins)) + 1))
    lows = np.minimum.reduceat(values, starts)
    highs = np.maximum.reduceat(values, starts)
    xs = np.repeat(times[starts], 2)
    ys = np.empty(2 * len(starts))
    ys[0::2], ys[1::2] = lows, highs
    return xs, ys
