"""Which canvas pixels a batch of pen strokes covers: aliased thick lines with square caps.

A stroke of width ``w`` from P0 to P1 covers the pixels whose centres (integer coordinates,
as in Qt's aliased painting) lie in the rectangle running ``w/2`` past each end along the line
and ``w/2`` either side of it, half-open so that a line of width ``w`` along an axis is exactly
``w`` pixels thick. A zero-length stroke is a ``w`` x ``w`` square. This is Qt's default pen
(square cap) drawn without anti-aliasing, which is how turtlesim paints its trails.

All strokes are rasterised together: each is cut into pieces a few pixels long, the pieces are
grouped by the size of their bounding boxes, and every group is tested against one stencil of
pixel offsets in a handful of array operations. The result lists pixels in stroke order, so
assigning colours in that order lets later strokes paint over earlier ones.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np  # noqa: TID253 - rasterising is array work

if TYPE_CHECKING:
    import numpy.typing as npt

    from rosx_turtle.engine.segments import Segments

    F64 = npt.NDArray[np.float64]
    F32 = npt.NDArray[np.float32]
    Ints = npt.NDArray[np.intp]

#: Longest piece a thin stroke is cut into, in pixels (wider pens use pieces as long as wide).
_PIECE = 8.0
#: Stencil sides the pieces' bounding boxes are rounded up to, per axis.
_SIDES = (4, 6, 8, 12, 16, 24, 32, 48, 64, 96, 128, 192, 256, 384, 512)
#: Upper bound on stencil cells tested at once (memory stays in the tens of MB).
_CHUNK_CELLS = 1 << 20
#: Turns the half-open tests ``-h <= s < h`` into one ``|s + _NUDGE| < h``: they differ only
#: for centres within 1e-5 pixel of an edge (about float32's error on a stencil's offsets).
_NUDGE = 1e-5
#: Pixel indices fit in this many bits (canvases up to 2048 x 2048); owners go above them.
_PIXEL_BITS = 22
_PIXEL_MASK = (1 << _PIXEL_BITS) - 1


def stroke_pixels(
    strokes: Segments, size: int, scratch: Scratch | None = None
) -> tuple[Ints, Ints]:
    """The pixels ``strokes`` cover on a ``size`` x ``size`` canvas.

    Returns:
        ``(flat, stroke)``: flat pixel indices (``row * size + column``) and the index of the
        stroke each belongs to, ordered by stroke.
    """
    if not len(strokes):
        return np.zeros(0, np.intp), np.zeros(0, np.intp)
    if size * size > _PIXEL_MASK:
        raise ValueError(f"a {size} x {size} canvas is too large")
    scratch = Scratch() if scratch is None else scratch
    pieces = _Pieces.cut(strokes, size)
    if not len(pieces.owner):  # every stroke is off the canvas
        return np.zeros(0, np.intp), np.zeros(0, np.intp)
    flats: list[Ints] = []
    owners: list[Ints] = []
    for rows, width, height in pieces.groups():
        step = max(1, _CHUNK_CELLS // (width * height))
        for start in range(0, len(rows), step):
            flat, owner = pieces.cover(rows[start : start + step], width, height, size, scratch)
            flats.append(flat)
            owners.append(owner)
    flat = np.concatenate(flats)
    owner = np.concatenate(owners)
    if len(flats) > 1:
        order = np.argsort(owner, kind="stable")  # sorted runs: a merge, not a full sort
        flat, owner = flat[order], owner[order]
    return flat, owner


@dataclass(frozen=True, eq=False)
class _Pieces:
    """Strokes cut into short pieces: each a rectangle (centre, direction, half extents) with
    the pixel box around it."""

    owner: Ints
    cx: F64
    cy: F64
    ux: F32
    uy: F32
    half_length: F32
    half_width: F32
    left: Ints
    top: Ints
    width: Ints
    height: Ints

    @classmethod
    def cut(cls, strokes: Segments, size: int) -> _Pieces:
        dx = strokes.x1 - strokes.x0
        dy = strokes.y1 - strokes.y0
        length = np.hypot(dx, dy)
        point = length == 0
        safe = np.where(point, 1.0, length)
        ux = np.where(point, 1.0, dx / safe)
        uy = np.where(point, 0.0, dy / safe)
        half = strokes.width.astype(np.float64) / 2
        piece = np.maximum(_PIECE, strokes.width)
        count = np.maximum(1, np.ceil(length / piece)).astype(np.intp)

        owner = np.repeat(np.arange(len(strokes), dtype=np.intp), count)
        first = np.cumsum(count) - count
        index = np.arange(len(owner)) - np.repeat(first, count)
        n = count[owner]
        h = half[owner]
        # Square caps: the first piece starts half a width early, the last ends half a width late.
        lo = length[owner] * index / n - np.where(index == 0, h, 0.0)
        hi = length[owner] * (index + 1) / n + np.where(index == n - 1, h, 0.0)

        px, py = ux[owner], uy[owner]
        mid = (lo + hi) / 2
        cx = strokes.x0[owner] + px * mid
        cy = strokes.y0[owner] + py * mid
        a = (hi - lo) / 2
        reach_x = a * np.abs(px) + h * np.abs(py)
        reach_y = a * np.abs(py) + h * np.abs(px)
        left = np.maximum(np.ceil(cx - reach_x), 0)
        right = np.minimum(np.floor(cx + reach_x), size - 1)
        top = np.maximum(np.ceil(cy - reach_y), 0)
        bottom = np.minimum(np.floor(cy + reach_y), size - 1)
        keep = (right >= left) & (bottom >= top)

        def f(values: F64) -> F32:
            return values[keep].astype(np.float32)

        def i(values: F64) -> Ints:
            return values[keep].astype(np.intp)

        return cls(
            owner=owner[keep],
            cx=cx[keep],
            cy=cy[keep],
            ux=f(px),
            uy=f(py),
            half_length=f(a),
            half_width=f(h),
            left=i(left),
            top=i(top),
            width=i(right - left + 1),
            height=i(bottom - top + 1),
        )

    def groups(self) -> list[tuple[Ints, int, int]]:
        """Rows of pieces grouped by the stencil (width, height) that holds them, in order.

        One stencil fits all when that wastes little (a tick's strokes are all alike);
        otherwise pieces are grouped by their box sides rounded up to `_SIDES`.
        """
        width, height = int(self.width.max()), int(self.height.max())
        needed = int(np.dot(self.width, self.height))
        if width * height * len(self.width) <= 2 * needed:
            return [(np.arange(len(self.width)), width, height)]
        sides = np.array(_SIDES)
        wide = np.searchsorted(sides, self.width)
        tall = np.searchsorted(sides, self.height)
        key = wide * (len(sides) + 1) + tall
        found = []
        for k in np.unique(key):
            rows = np.flatnonzero(key == k)
            w, t = divmod(int(k), len(sides) + 1)
            width = int(sides[w]) if w < len(sides) else int(self.width[rows].max())
            height = int(sides[t]) if t < len(sides) else int(self.height[rows].max())
            found.append((rows, width, height))
        return found

    def cover(
        self, rows: Ints, width: int, height: int, size: int, scratch: Scratch
    ) -> tuple[Ints, Ints]:
        """The pixels pieces ``rows`` cover, each tested on a ``width`` x ``height`` stencil."""
        n, cells = len(rows), width * height
        gx_int = np.tile(np.arange(width), height)
        gy_int = np.repeat(np.arange(height), width)
        gx, gy = gx_int.astype(np.float32), gy_int.astype(np.float32)
        ux, uy = self.ux[rows], self.uy[rows]
        left, top = self.left[rows], self.top[rows]
        # The stencil's corner relative to the piece's centre, small numbers: float32 from here.
        ox = left - self.cx[rows]
        oy = top - self.cy[rows]
        along0 = (ox * ux + oy * uy + _NUDGE).astype(np.float32)
        across0 = (oy * ux - ox * uy + _NUDGE).astype(np.float32)
        # (pieces, cells) arrays with contiguous rows, reused from tick to tick.
        along = np.multiply.outer(ux, gx, out=scratch.take("along", (n, cells), np.float32))
        along += np.multiply.outer(uy, gy, out=scratch.take("term", (n, cells), np.float32))
        along += along0[:, None]
        np.abs(along, out=along)
        inside = np.less(
            along, self.half_length[rows, None], out=scratch.take("in", (n, cells), np.bool_)
        )
        across = np.multiply.outer(ux, gy, out=along)
        across -= np.multiply.outer(uy, gx, out=scratch.take("term", (n, cells), np.float32))
        across += across0[:, None]
        np.abs(across, out=across)
        inside &= np.less(
            across, self.half_width[rows, None], out=scratch.take("test", (n, cells), np.bool_)
        )
        # A stencil larger than its piece's box may reach past the canvas's right or bottom edge.
        if (left + width > size).any() or (top + height > size).any():
            inside &= (left[:, None] + gx_int < size) & (top[:, None] + gy_int < size)
        # Owner and pixel packed in one integer, so that one selection picks both.
        keys = np.add.outer(
            (self.owner[rows] << _PIXEL_BITS) + top * size + left,
            gy_int * size + gx_int,
            out=scratch.take("keys", (n, cells), np.intp),
        )[inside]
        return keys & _PIXEL_MASK, keys >> _PIXEL_BITS


class Scratch:
    """Work arrays kept from call to call: at these sizes, fresh memory's page faults cost
    more than the arithmetic done in it. Not for use by two threads at once."""

    def __init__(self) -> None:
        self._arrays: dict[str, npt.NDArray[Any]] = {}

    def take(self, name: str, shape: tuple[int, int], dtype: type[Any]) -> npt.NDArray[Any]:
        """An uninitialised array of ``shape`` and ``dtype`` (the one named ``name`` last time)."""
        count = shape[0] * shape[1]
        array = self._arrays.get(name)
        if array is None or array.dtype != dtype or array.size < count:
            array = self._arrays[name] = np.empty(max(count, 1 << 16), dtype)
        return array[:count].reshape(shape)
