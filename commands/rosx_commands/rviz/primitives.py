"""What displays draw, in the fixed frame: points, line segments, filled polygons, labels and
images, each with rviz's colour and alpha. `Layer` is one display's drawing; the painter
(`rosx_commands.rviz.painter`) turns layers into pixels.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Protocol

if TYPE_CHECKING:
    import numpy as np
    import numpy.typing as npt

    Floats = npt.NDArray[np.float64]
    Colours = npt.NDArray[np.uint8]

RGB = tuple[int, int, int]


@dataclass
class Points:
    """``xy`` (``(n, 2)`` metres) drawn ``size`` pixels wide, or ``metres`` wide when that is
    more, each in ``colour`` or in its row of ``colours`` (``(n, 3)``)."""

    xy: Floats
    colour: RGB = (255, 255, 255)
    colours: Colours | None = None
    size: int = 1
    alpha: float = 1.0
    metres: float = 0.0


@dataclass
class Segments:
    """Line segments ``(n, 2, 2)``: each from ``[i, 0]`` to ``[i, 1]``."""

    ends: Floats
    colour: RGB = (255, 255, 255)
    colours: Colours | None = None
    alpha: float = 1.0


@dataclass
class Polygon:
    """A filled polygon (``(k, 2)`` corners, in order)."""

    corners: Floats
    colour: RGB = (255, 255, 255)
    alpha: float = 1.0

    def __post_init__(self) -> None:
        self.corners = self.corners[:, :2]


@dataclass
class Label:
    """Text at a point (drawn in terminal cells, left-aligned, or centred)."""

    x: float
    y: float
    text: str
    colour: RGB = (255, 255, 255)
    centred: bool = False


class Image(Protocol):
    """A picture laid on the plane (a map): its colours at fixed-frame points."""

    version: int

    def sample(self, x: Floats, y: Floats, metres_per_pixel: float) -> tuple[Colours, Floats]:
        """Colours (``(n, 3)``) and alphas (``(n,)``, 0 where it shows nothing) at the
        points, as seen at ``metres_per_pixel``."""
        ...


@dataclass
class Layer:
    """One display's drawing."""

    images: list[Image] = field(default_factory=list)
    polygons: list[Polygon] = field(default_factory=list)
    segments: list[Segments] = field(default_factory=list)
    points: list[Points] = field(default_factory=list)
    labels: list[Label] = field(default_factory=list)

    def extend(self, other: Layer) -> Layer:
        """Add ``other``'s drawing to this one (drawn after it); this layer."""
        self.images += other.images
        self.polygons += other.polygons
        self.segments += other.segments
        self.points += other.points
        self.labels += other.labels
        return self


__all__ = ["RGB", "Image", "Label", "Layer", "Points", "Polygon", "Segments"]
