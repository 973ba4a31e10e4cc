"""The 500x500 trail canvas shrunk to the pond's pixels, without losing thin trails.

A plain box average would fade a 3-pixel trail to a tint once five canvas pixels share one
terminal pixel, and a 1-pixel pen to nothing. `Shrinker` weighs ink instead: in each box, the
pixels that differ from the background ("ink") give the colour, and how much of the box they
cover gives its strength, boosted by `INK_GAIN` so that a trail crossing a box shows at full
colour. Only the bands of rows that changed since the last canvas are recomputed.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np  # noqa: TID253 - the view is array work; only the TUI imports it

if TYPE_CHECKING:
    import numpy.typing as npt

    Image = npt.NDArray[np.uint8]
    Indices = npt.NDArray[np.intp]

#: How many times its share of a box a trail's colour counts (a quarter of a box shows it fully).
INK_GAIN = 4.0


class Shrinker:
    """Shrinks square canvases of ``source`` pixels to ``side`` pixels (any ``side`` ≥ 1)."""

    def __init__(self, side: int, source: int) -> None:
        self.side = side
        self.source = source
        edges = (np.arange(side + 1) * source) // side
        #: Whether every output pixel has at least one source pixel (else nearest sampling).
        self.boxes = side <= source
        self._starts: Indices = edges[:-1].astype(np.intp)
        sizes = np.diff(edges) if self.boxes else np.ones(side, dtype=np.intp)
        self._area = np.outer(sizes, sizes).astype(np.float32)[..., None]
        self._nearest: Indices = ((np.arange(side) * source) // side).astype(np.intp)
        #: The output row holding each source row (for nearest sampling, the first one).
        self.row_of_source: Indices = np.minimum(
            np.searchsorted(edges, np.arange(source), side="right") - 1, side - 1
        ).astype(np.intp)

    def shrink(
        self, canvas: Image, background: tuple[int, int, int], rows: slice | None = None
    ) -> Image:
        """Output rows ``rows`` (all by default) of ``canvas`` shrunk; shape ``(n, side, 3)``."""
        first, stop, _ = (rows or slice(0, self.side)).indices(self.side)
        if not self.boxes:
            picked = canvas[self._nearest[first:stop]]
            return np.ascontiguousarray(picked[:, self._nearest])
        starts = self._starts
        top = int(starts[first])
        bottom = int(starts[stop]) if stop < self.side else self.source
        band = canvas[top:bottom]
        r, g, b = background
        ink = (band[..., 0] != r) | (band[..., 1] != g) | (band[..., 2] != b)
        row_starts = starts[first:stop] - top
        counts = np.add.reduceat(
            np.add.reduceat(ink, row_starts, axis=0, dtype=np.int32), starts, axis=1
        )[..., None].astype(np.float32)
        inked = band * ink[..., None]  # uint8: the ink, and black where there is none
        by_row = np.add.reduceat(inked, row_starts, axis=0, dtype=np.int32)
        sums = np.add.reduceat(by_row, starts, axis=1)
        colour = sums / np.maximum(counts, 1.0)
        alpha = np.minimum(counts * INK_GAIN / self._area[first:stop], 1.0)
        bg = np.asarray(background, dtype=np.float32)
        mixed = bg + (colour - bg) * alpha
        result: Image = np.rint(mixed).astype(np.uint8)
        return result

    def changed_rows(self, old: Image, new: Image) -> slice | None:
        """The band of output rows that differ between two canvases; None if none do."""
        differs = np.flatnonzero(np.any((old != new).reshape(old.shape[0], -1), axis=1))
        if differs.size == 0:
            return None
        first = int(self.row_of_source[differs[0]])
        last = int(self.row_of_source[differs[-1]])
        if not self.boxes:  # several output rows may show one source row
            first = int(np.searchsorted(self._nearest, differs[0]))
            last = int(np.searchsorted(self._nearest, differs[-1], side="right")) - 1
        return slice(first, last + 1)
