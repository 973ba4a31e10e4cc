"""What LaserScan and PointCloud2 share, as rviz's ``PointCloudCommon``: clouds kept for the
``Decay Time``, coloured by a ``Color Transformer`` (``Intensity``, ``FlatColor``,
``AxisColor``, ``RGB8``) and counted in the ``Points`` status."""

from __future__ import annotations

import sys
from collections import deque
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np  # noqa: TID253 - rviz's model is array work; only rviz imports it

from rosx_commands.rviz import status
from rosx_commands.rviz.displays.base import Display
from rosx_commands.rviz.geometry import apply
from rosx_commands.rviz.primitives import Layer, Points

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    import numpy.typing as npt

    from rosx_commands.rviz.displays.base import Context
    from rosx_commands.rviz.geometry import Transform

    Floats = npt.NDArray[np.float64]
    Colours = npt.NDArray[np.uint8]


def rainbow(values: Floats) -> Colours:
    """rviz's rainbow (hue from 0 to 5/6) of values in [0, 1], as ``(n, 3)`` bytes."""
    v = np.clip(values, 0.0, 1.0)
    h = v * 5.0 + 1.0
    i = np.floor(h).astype(np.int64)
    f = h - i
    f = np.where(i % 2 == 0, 1.0 - f, f)
    n = 1.0 - f
    one, zero = np.ones_like(n), np.zeros_like(n)
    red = np.select([i <= 1, i == 2, i == 3, i == 4], [n, zero, zero, n], one)
    green = np.select([i <= 1, i == 2, i == 3, i == 4], [zero, n, one, one], n)
    blue = np.select([i <= 1, i == 2, i == 3, i == 4], [one, one, n, zero], zero)
    return np.asarray(np.rint(np.stack([red, green, blue], axis=1) * 255), dtype=np.uint8)


def normalised(values: Floats, low: float | None = None, high: float | None = None) -> Floats:
    """``values`` mapped to [0, 1] between ``low`` and ``high`` (their own bounds if None)."""
    if values.size == 0:
        return values
    low = float(np.min(values)) if low is None else low
    high = float(np.max(values)) if high is None else high
    span = high - low
    if span <= 0:
        return np.zeros_like(values)
    return np.asarray((values - low) / span, dtype=np.float64)


@dataclass
class Cloud:
    """One message's points in its own frame, with what colours them."""

    frame: str
    stamp: int
    received: float
    xyz: Floats
    intensity: Floats | None = None
    rgb: Colours | None = None
    #: The fixed-frame points, with the transform they were made with.
    placed: tuple[Transform, Floats] | None = None


class CloudDisplay(Display):
    """A display of point clouds (see the module docstring)."""

    PREFER = ("Points",)

    @override
    def clear(self) -> None:
        self.clouds: deque[Cloud] = deque()

    def keep(self, cloud: Cloud, now: float) -> None:
        """Add ``cloud``, dropping those older than the decay time (all others when 0)."""
        decay = self.number("Decay Time", 0.0)
        if decay <= 0:
            self.clouds.clear()
        self.clouds.append(cloud)
        self._drop(now, decay)

    def _drop(self, now: float, decay: float) -> bool:
        dropped = False
        while len(self.clouds) > 1 and (decay <= 0 or now - self.clouds[0].received >= decay):
            self.clouds.popleft()
            dropped = True
        return dropped

    @override
    def expire(self, now: float) -> bool:
        decay = self.number("Decay Time", 0.0)
        if decay > 0 and self._drop(now, decay):
            self.version += 1
            return True
        return False

    def colours(self, cloud: Cloud) -> tuple[Colours | None, tuple[int, int, int]]:
        """Per-point colours (None: all ``flat``) by the display's colour transformer."""
        flat = self.colour("Color", (255, 255, 255))
        chosen = str(self.option("Color Transformer", "") or "")
        if not chosen:
            chosen = "RGB8" if cloud.rgb is not None else "Intensity"
            if chosen == "Intensity" and cloud.intensity is None:
                chosen = "FlatColor"
        if chosen == "RGB8" and cloud.rgb is not None:
            return cloud.rgb, flat
        if chosen == "Intensity" and cloud.intensity is not None:
            auto = self.flag("Autocompute Intensity Bounds", True)
            low = None if auto else self.number("Min Intensity", 0.0)
            high = None if auto else self.number("Max Intensity", 4096.0)
            share = normalised(cloud.intensity, low, high)
            if self.flag("Use rainbow", True):
                if self.flag("Invert Rainbow", False):
                    share = 1.0 - share
                return rainbow(share), flat
            lo = np.array(self.colour("Min Color", (0, 0, 0)), dtype=np.float64)
            hi = np.array(self.colour("Max Color", (255, 255, 255)), dtype=np.float64)
            mixed = lo + (hi - lo) * share[:, None]
            return np.asarray(np.rint(mixed), dtype=np.uint8), flat
        if chosen == "AxisColor":
            axis = {"X": 0, "Y": 1, "Z": 2}.get(str(self.option("Axis", "Z")), 2)
            placed = cloud.placed[1] if cloud.placed is not None else cloud.xyz
            auto = self.flag("Autocompute Value Bounds", True)
            low = None if auto else self.number("Min Value", -10.0)
            high = None if auto else self.number("Max Value", 10.0)
            return rainbow(normalised(placed[:, axis], low, high)), flat
        return None, flat

    @override
    def draw(self, context: Context) -> Layer:
        layer = Layer()
        shown = 0
        failed = False
        for cloud in self.clouds:
            answer = context.frames.lookup(cloud.frame, cloud.stamp)
            if isinstance(answer, str):
                self.statuses.error("Transform", answer)
                failed = True
                continue
            if cloud.placed is None or cloud.placed[0] != answer:
                cloud.placed = (answer, apply(answer, cloud.xyz))
            colours, flat = self.colours(cloud)
            xy = cloud.placed[1][:, :2]
            layer.points.append(
                Points(
                    xy,
                    flat,
                    colours,
                    size=max(1, int(self.number("Size (Pixels)", 1))),
                    alpha=self.number("Alpha", 1.0),
                )
            )
            shown += len(xy)
        if not failed:
            self.statuses.ok("Transform", "Transform OK")
        self.statuses.ok("Points", status.showing(shown, len(layer.points)))
        return layer


__all__ = ["Cloud", "CloudDisplay", "normalised", "rainbow"]
