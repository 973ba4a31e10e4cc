"""The 2-D view: rviz's TopDownOrtho over the fixed frame, as pixels of a terminal picture.

The view looks straight down on the fixed frame's xy plane, x to the right and y up (rotated
by ``angle`` as TopDownOrtho's ``Angle``), centred on ``(x, y)``, at ``scale`` pixels a metre.
Pixels are square: a terminal cell shows two, one above the other (half blocks). Without a
config's view it starts on the fixed frame's origin showing `DEFAULT_REACH` metres each way
along the shorter side. rviz's ``Scale`` counts screen pixels; `SCREEN_PIXELS` of them make
one of ours (a cell about 8 pixels wide), so a view saved here looks alike in rviz.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np  # noqa: TID253 - rviz's model is array work; only rviz imports it

if TYPE_CHECKING:
    import numpy.typing as npt

    from rosx_commands.rviz.config import ViewSpec

    Floats = npt.NDArray[np.float64]

#: Metres from the centre to the nearer edge of a view nobody set (rviz users see ±3 m).
DEFAULT_REACH = 5.0
#: rviz's screen pixels per pixel of the terminal picture.
SCREEN_PIXELS = 8.0
#: A 3-D view's visible half-height per metre of distance (rviz's 45° field of view).
ORBIT_REACH = math.tan(math.pi / 8)
#: How far each zoom step goes, and its bounds (pixels a metre).
ZOOM_STEP = 1.25
MIN_SCALE, MAX_SCALE = 1e-3, 1e4


class View:
    """Where the picture looks (see the module docstring)."""

    def __init__(
        self, x: float = 0.0, y: float = 0.0, scale: float | None = None, angle: float = 0.0
    ) -> None:
        self.x, self.y, self.angle = x, y, angle
        self.scale = scale
        self.reach = DEFAULT_REACH
        self.width = self.height = 0
        #: Whether the user moved it (a saved config then gets a TopDownOrtho view).
        self.moved = False

    @classmethod
    def from_spec(cls, spec: ViewSpec | None) -> View:
        """The view a config's ``Views/Current`` gives (the default one for None)."""
        view = cls()
        if spec is None:
            return view
        view.x, view.y, view.angle = spec.x, spec.y, spec.angle
        if spec.scale is not None and "Ortho" in spec.class_id:
            view.scale = spec.scale / SCREEN_PIXELS
        elif spec.distance is not None:
            view.reach = max(spec.distance * ORBIT_REACH, 0.5)
        return view

    def resize(self, width: int, height: int) -> None:
        """Draw ``width`` by ``height`` pixels; the first size fixes a scale not yet set."""
        self.width, self.height = max(1, width), max(1, height)
        if self.scale is None:
            self.scale = min(self.width, self.height) / 2.0 / self.reach

    @property
    def pixels_per_metre(self) -> float:
        """The scale in pixels per metre (1.0 until the first `resize` sets it)."""
        return self.scale or 1.0

    @property
    def key(self) -> tuple[float, float, float, float, int, int]:
        """Everything a picture of this view depends on."""
        return (self.x, self.y, self.pixels_per_metre, self.angle, self.width, self.height)

    def to_pixels(self, x: Floats, y: Floats) -> tuple[Floats, Floats]:
        """Picture coordinates (column, row; row 0 at the top; pixel centres at .5) of
        fixed-frame points."""
        dx, dy = x - self.x, y - self.y
        if self.angle:
            c, s = math.cos(-self.angle), math.sin(-self.angle)
            dx, dy = c * dx - s * dy, s * dx + c * dy
        scale = self.pixels_per_metre
        return self.width / 2.0 + dx * scale, self.height / 2.0 - dy * scale

    def to_world(self, column: Floats, row: Floats) -> tuple[Floats, Floats]:
        """Fixed-frame points at picture coordinates (the inverse of `to_pixels`)."""
        scale = self.pixels_per_metre
        dx = (column - self.width / 2.0) / scale
        dy = (self.height / 2.0 - row) / scale
        if self.angle:
            c, s = math.cos(self.angle), math.sin(self.angle)
            dx, dy = c * dx - s * dy, s * dx + c * dy
        return self.x + dx, self.y + dy

    def point_at(self, column: float, row: float) -> tuple[float, float]:
        """The fixed-frame point under the centre of pixel (``column``, ``row``)."""
        x, y = self.to_world(np.array([column + 0.5]), np.array([row + 0.5]))
        return float(x[0]), float(y[0])

    def zoom(self, steps: float, about: tuple[float, float] | None = None) -> None:
        """Zoom in (``steps`` > 0) or out, keeping the point at picture coordinates
        ``about`` (the centre by default) where it is."""
        if about is not None:
            fx, fy = self.to_world(np.array([about[0]]), np.array([about[1]]))
        scale = self.pixels_per_metre * ZOOM_STEP**steps
        self.scale = min(MAX_SCALE, max(MIN_SCALE, scale))
        if about is not None:
            nx, ny = self.to_world(np.array([about[0]]), np.array([about[1]]))
            self.x += float(fx[0] - nx[0])
            self.y += float(fy[0] - ny[0])
        self.moved = True

    def pan(self, columns: float, rows: float) -> None:
        """Move what is shown by ``columns`` right and ``rows`` down, in pixels (the scene
        follows the mouse: the centre moves the other way)."""
        scale = self.pixels_per_metre
        dx, dy = -columns / scale, rows / scale
        if self.angle:
            c, s = math.cos(self.angle), math.sin(self.angle)
            dx, dy = c * dx - s * dy, s * dx + c * dy
        self.x += dx
        self.y += dy
        self.moved = True

    def centre_on(self, x: float, y: float) -> None:
        """Look at fixed-frame point ``x``, ``y`` (Follow uses it), keeping zoom and angle."""
        self.x, self.y = x, y

    def reset(self) -> None:
        """Back to the fixed frame's origin at the default reach."""
        self.x = self.y = self.angle = 0.0
        self.reach = DEFAULT_REACH
        self.scale = min(self.width, self.height) / 2.0 / self.reach if self.width else None
        self.moved = True

    @property
    def rviz_scale(self) -> float:
        """TopDownOrtho's ``Scale`` for this view (rviz's screen pixels a metre)."""
        return self.pixels_per_metre * SCREEN_PIXELS


__all__ = ["DEFAULT_REACH", "SCREEN_PIXELS", "View"]
