"""Loading a world file from disk: the I/O around `worldfile.parse`, `model.build` and
`grid.rasterise` (includes and bitmaps are found next to the file that names them)."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from rosx_turtle.stage.world.images import ImageError, read_grey
from rosx_turtle.stage.world.model import build
from rosx_turtle.stage.world.worldfile import WorldFileError, parse

if TYPE_CHECKING:
    import numpy as np
    import numpy.typing as npt

    from rosx_turtle.stage.engine.grid import Grid
    from rosx_turtle.stage.world.model import Block, World


#: The most cells a world's occupancy grid may have (5 bytes each): a 100 m square at 2 cm.
MAX_CELLS = 25_000_000


def _include(name: str, including: str) -> tuple[str, str]:
    path = Path(including).parent / name
    return path.read_text(encoding="utf-8", errors="replace"), str(path)


def bitmap_path(block: Block) -> Path:
    """Where a block's bitmap is: relative to the world file that named it."""
    return Path(block.base).parent / (block.bitmap or "")


def read_world(path: Path) -> World:
    """The world described by the file at ``path``.

    Raises:
        WorldFileError: the file cannot be read or is not a world file (``file:line:`` first).
    """
    try:
        text = path.read_text(encoding="utf-8", errors="replace")
    except OSError as exc:
        raise WorldFileError(f"The world file {path} does not exist.") from exc
    return build(parse(text, str(path), _include))


def load_world(path: Path) -> tuple[World, Grid]:
    """The world at ``path`` and its occupancy grid, bitmaps read.

    Raises:
        WorldFileError: the world file or one of its bitmaps cannot be read.
    """
    from rosx_turtle.stage.engine.grid import grid_shape, rasterise  # noqa: PLC0415 - numpy

    world = read_world(path)
    rows, cols = grid_shape(world)
    if rows * cols > MAX_CELLS:
        raise WorldFileError(
            f"{path}:1: the world's grid would be {cols} x {rows} cells at resolution "
            f"{world.resolution:g}: more than {MAX_CELLS} (a coarser resolution?)"
        )

    def bitmap(block: Block) -> npt.NDArray[np.uint8]:
        try:
            return read_grey(bitmap_path(block))
        except ImageError as exc:
            where = f"{block.base}"
            raise WorldFileError(f"{where}: bitmap of {block.name}: {exc}") from None

    return world, rasterise(world, bitmap)


__all__ = ["bitmap_path", "load_world", "read_world"]
