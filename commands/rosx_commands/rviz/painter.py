"""Layers to pixels: the picture of a view (numpy, no terminal).

`Painter.paint` fills the background, lays the images (maps) sampled at each pixel, then
draws polygons, segments and points in the order of the displays, blending by alpha. The
background and images are kept between pictures of the same view (`Painter` remembers them
by the view and the images' versions), so a picture where only a scan moved costs the copy
of that and the scan's pixels. Labels are not drawn: their places come back with the picture,
for the terminal to write as text (`rosx_commands.rviz.cells`) or a PNG to print.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np  # noqa: TID253 - rviz's model is array work; only rviz imports it

if TYPE_CHECKING:
    from collections.abc import Sequence

    import numpy.typing as npt

    from rosx_commands.rviz.primitives import RGB, Layer, Points, Polygon, Segments
    from rosx_commands.rviz.primitives import Image as PictureImage
    from rosx_commands.rviz.view import View

    Image = npt.NDArray[np.uint8]
    Floats = npt.NDArray[np.float64]


@dataclass
class PlacedLabel:
    """A label at picture coordinates (column and row of pixels)."""

    column: float
    row: float
    text: str
    colour: RGB
    centred: bool = False


@dataclass
class Picture:
    """The pixels of a view, top row first, and the labels to write over them."""

    pixels: Image
    labels: list[PlacedLabel] = field(default_factory=list)


def _blend(
    image: Image,
    rows: npt.NDArray[np.intp],
    cols: npt.NDArray[np.intp],
    colours: npt.NDArray[np.float64] | RGB,
    alpha: float | Floats,
) -> None:
    """Paint pixels (``rows``, ``cols``) with ``colours`` at ``alpha``."""
    if rows.size == 0:
        return
    paint = np.asarray(colours, dtype=np.float64)
    if np.ndim(alpha) == 0 and float(alpha) >= 1.0:
        image[rows, cols] = np.broadcast_to(paint, (rows.size, 3)).astype(np.uint8)
        return
    a = np.clip(np.asarray(alpha, dtype=np.float64), 0.0, 1.0)
    a = a[:, None] if a.ndim == 1 else a
    under = image[rows, cols].astype(np.float64)
    image[rows, cols] = np.rint(under + (paint - under) * a).astype(np.uint8)


def clip_segments(ends: Floats, width: int, height: int) -> tuple[Floats, npt.NDArray[np.bool_]]:
    """Segments (``(n, 2, 2)`` picture coordinates) cut to the picture (Liang-Barsky), and
    which of them show at all (the others' rows are meaningless)."""
    low, high = np.zeros(len(ends)), np.ones(len(ends))
    keep: npt.NDArray[np.bool_] = np.asarray(np.isfinite(ends).all(axis=(1, 2)))
    ends = np.where(keep[:, None, None], ends, 0.0)
    x0, y0 = ends[:, 0, 0], ends[:, 0, 1]
    dx, dy = ends[:, 1, 0] - x0, ends[:, 1, 1] - y0
    for p, q in ((-dx, x0), (dx, width - x0), (-dy, y0), (dy, height - y0)):
        parallel = np.abs(p) < 1e-12
        keep &= ~(parallel & (q < 0))
        with np.errstate(divide="ignore", invalid="ignore"):
            r = np.where(parallel, 0.0, q / np.where(parallel, 1.0, p))
        low = np.where(~parallel & (p < 0), np.maximum(low, r), low)
        high = np.where(~parallel & (p > 0), np.minimum(high, r), high)
    keep &= low <= high
    start = np.stack([x0 + low * dx, y0 + low * dy], axis=1)
    stop = np.stack([x0 + high * dx, y0 + high * dy], axis=1)
    return np.stack([start, stop], axis=1), keep


class Painter:
    """Pictures of layers (see the module docstring)."""

    def __init__(self) -> None:
        self._base_key: object = None
        self._base: Image | None = None

    def paint(
        self, view: View, layers: list[Layer], background: RGB, thickness: int = 1
    ) -> Picture:
        """The picture of ``layers`` as ``view`` sees them over ``background``; points and
        lines ``thickness`` times as thick (a larger picture of the same view)."""
        images = [image for layer in layers for image in layer.images]
        key = (view.key, background, tuple((id(image), image.version) for image in images))
        if key != self._base_key or self._base is None:
            self._base = self._background(view, images, background)
            self._base_key = key
        pixels = self._base.copy()
        labels: list[PlacedLabel] = []
        for layer in layers:
            for polygon in layer.polygons:
                self._polygon(pixels, view, polygon)
            for segments in layer.segments:
                self._segments(pixels, view, segments, thickness)
            for points in layer.points:
                self._points(pixels, view, points, thickness)
            for label in layer.labels:
                col, row = view.to_pixels(np.array([label.x]), np.array([label.y]))
                labels.append(
                    PlacedLabel(
                        float(col[0]), float(row[0]), label.text, label.colour, label.centred
                    )
                )
        return Picture(pixels, labels)

    @staticmethod
    def _background(view: View, images: Sequence[PictureImage], background: RGB) -> Image:
        width, height = view.width, view.height
        pixels = np.empty((height, width, 3), dtype=np.uint8)
        pixels[:] = background
        if not images:
            return pixels
        cols, rows = np.meshgrid(np.arange(width) + 0.5, np.arange(height) + 0.5)
        x, y = view.to_world(cols.ravel(), rows.ravel())
        flat = pixels.reshape(-1, 3)
        every_row, every_col = np.divmod(np.arange(width * height), width)
        for image in images:
            colours, alphas = image.sample(x, y, 1.0 / view.pixels_per_metre)
            shown = alphas > 0
            _blend(
                pixels,
                every_row[shown],
                every_col[shown],
                colours[shown].astype(np.float64),
                alphas[shown],
            )
        return flat.reshape(height, width, 3)

    @staticmethod
    def _points(pixels: Image, view: View, points: Points, thickness: int = 1) -> None:
        if len(points.xy) == 0:
            return
        col, row = view.to_pixels(points.xy[:, 0], points.xy[:, 1])
        colours = points.colours
        near = (col > -64) & (col < view.width + 64) & (row > -64) & (row < view.height + 64)
        if not near.all():  # also drops points that are not finite
            col, row = col[near], row[near]
            colours = None if colours is None else colours[near]
        cols = np.floor(col).astype(np.intp)
        rows = np.floor(row).astype(np.intp)
        size = max(points.size * thickness, round(points.metres * view.pixels_per_metre), 1)
        size = min(size, 64 * thickness)
        if size > 1:
            offsets = np.arange(size) - (size - 1) // 2
            dr, dc = np.meshgrid(offsets, offsets)
            rows = (rows[:, None] + dr.ravel()[None, :]).ravel()
            cols = (cols[:, None] + dc.ravel()[None, :]).ravel()
            if colours is not None:
                colours = np.repeat(colours, size * size, axis=0)
        height, width = pixels.shape[:2]
        inside = (rows >= 0) & (rows < height) & (cols >= 0) & (cols < width)
        paint = points.colour if colours is None else colours[inside].astype(np.float64)
        _blend(pixels, rows[inside], cols[inside], paint, points.alpha)

    @staticmethod
    def _segments(pixels: Image, view: View, segments: Segments, thickness: int = 1) -> None:
        ends = segments.ends
        if len(ends) == 0:
            return
        col, row = view.to_pixels(ends[..., 0].ravel(), ends[..., 1].ravel())
        picture = np.stack([col, row], axis=1).reshape(-1, 2, 2)
        height, width = pixels.shape[:2]
        clipped, keep = clip_segments(picture, width, height)
        keep_index = np.flatnonzero(keep)
        clipped = clipped[keep]
        if len(clipped) == 0:
            return
        delta = clipped[:, 1] - clipped[:, 0]
        counts = np.ceil(np.abs(delta).max(axis=1)).astype(np.intp) + 1
        first = np.repeat(np.cumsum(counts) - counts, counts)
        step = np.arange(counts.sum()) - first
        share = step / np.repeat(np.maximum(counts - 1, 1), counts)
        owner = np.repeat(np.arange(len(clipped)), counts)
        xs = clipped[owner, 0, 0] + delta[owner, 0] * share
        ys = clipped[owner, 0, 1] + delta[owner, 1] * share
        cols = np.floor(xs).astype(np.intp)
        rows = np.floor(ys).astype(np.intp)
        if thickness > 1:  # a square brush
            offsets = np.arange(thickness) - (thickness - 1) // 2
            dr, dc = np.meshgrid(offsets, offsets)
            rows = (rows[:, None] + dr.ravel()[None, :]).ravel()
            cols = (cols[:, None] + dc.ravel()[None, :]).ravel()
            owner = np.repeat(owner, thickness * thickness)
        cols = np.clip(cols, 0, width - 1)
        rows = np.clip(rows, 0, height - 1)
        if segments.colours is not None:
            paint: npt.NDArray[np.float64] | RGB = segments.colours[keep_index[owner]].astype(
                np.float64
            )
        else:
            paint = segments.colour
        _blend(pixels, rows, cols, paint, segments.alpha)

    @staticmethod
    def _polygon(pixels: Image, view: View, polygon: Polygon) -> None:
        corners = polygon.corners
        if len(corners) < 3:
            return
        col, row = view.to_pixels(corners[:, 0], corners[:, 1])
        height, width = pixels.shape[:2]
        left, right = max(0, int(np.floor(col.min()))), min(width, int(np.ceil(col.max())) + 1)
        top, bottom = max(0, int(np.floor(row.min()))), min(height, int(np.ceil(row.max())) + 1)
        if left >= right or top >= bottom:
            return
        grid_c, grid_r = np.meshgrid(np.arange(left, right) + 0.5, np.arange(top, bottom) + 0.5)
        pc, pr = grid_c.ravel(), grid_r.ravel()
        x0, y0 = col, row
        x1, y1 = np.roll(col, -1), np.roll(row, -1)
        crosses = ((y0[None, :] > pr[:, None]) != (y1[None, :] > pr[:, None])) & (
            pc[:, None]
            < (x1 - x0)[None, :]
            * (pr[:, None] - y0[None, :])
            / np.where(y1 - y0 == 0, 1e-12, y1 - y0)[None, :]
            + x0[None, :]
        )
        inside = np.count_nonzero(crosses, axis=1) % 2 == 1
        if not inside.any():  # smaller than a pixel: one pixel where it is
            cx, cy = int(np.floor(col.mean())), int(np.floor(row.mean()))
            if 0 <= cx < width and 0 <= cy < height:
                _blend(pixels, np.array([cy]), np.array([cx]), polygon.colour, polygon.alpha)
            return
        rows = np.floor(pr[inside]).astype(np.intp)
        cols = np.floor(pc[inside]).astype(np.intp)
        _blend(pixels, rows, cols, polygon.colour, polygon.alpha)


__all__ = ["Painter", "Picture", "PlacedLabel", "clip_segments"]
