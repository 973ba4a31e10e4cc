"""`Turtles`: the state of every turtle as parallel numpy arrays, one row per turtle.

Rows are sorted by name, the order turtlesim updates its turtles in (a ``std::map``), so the
same inputs give the same warnings and the same trails in the same order. A `Turtles` value is
never changed in place: the engine's functions return new values (arrays shared where nothing
changed), so a reader holding one sees a consistent picture.

Positions are in turtlesim's internal frame (see `rosx_turtle.engine.constants`): ``x`` as in
the world, ``y`` measured down from the top edge. `world_y` gives the published y.
"""

from __future__ import annotations

import bisect
from dataclasses import dataclass, replace
from functools import cached_property
from typing import TYPE_CHECKING, Any

import numpy as np  # noqa: TID253 - the engine is numpy through and through

from rosx_turtle.engine.constants import DEFAULT_PEN, DEFAULT_PEN_WIDTH, WORLD_SIZE

if TYPE_CHECKING:
    from collections.abc import Sequence

    import numpy.typing as npt

    F64 = npt.NDArray[np.float64]
    U8 = npt.NDArray[np.uint8]
    I32 = npt.NDArray[np.int32]
    Bools = npt.NDArray[np.bool_]

#: The per-turtle arrays of `Turtles`, in order.
ARRAYS = (
    "x",
    "y",
    "theta",
    "vx",
    "vy",
    "w",
    "last_command",
    "pen_on",
    "pen_rgb",
    "pen_width",
    "sprite",
)
_DTYPES: dict[str, Any] = {
    "x": np.float64,
    "y": np.float64,
    "theta": np.float64,
    "vx": np.float64,
    "vy": np.float64,
    "w": np.float64,
    "last_command": np.float64,
    "pen_on": np.bool_,
    "pen_rgb": np.uint8,
    "pen_width": np.int32,
    "sprite": np.int32,
}


@dataclass(frozen=True, eq=False)
class Turtles:
    """Every turtle's state (one row each, sorted by name).

    Attributes:
        names: The turtles' names, sorted.
        x: Position in metres from the left edge.
        y: Position in metres from the **top** edge (turtlesim's internal frame).
        theta: Heading in radians, counter-clockwise from +x (in [-PI, PI) after a tick).
        vx, vy, w: The last command: forward and sideways speed (m/s), turn rate (rad/s).
        last_command: Wall-clock time (s) the last command arrived; 0 for never.
        pen_on: Whether the turtle draws its trail.
        pen_rgb: The pen's colour, shape (n, 3).
        pen_width: The pen's width in pixels (1 or more).
        sprite: Which of the sprites the turtle is drawn with.
    """

    names: tuple[str, ...]
    x: F64
    y: F64
    theta: F64
    vx: F64
    vy: F64
    w: F64
    last_command: F64
    pen_on: Bools
    pen_rgb: U8
    pen_width: I32
    sprite: I32

    @cached_property
    def _rows(self) -> dict[str, int]:
        return {name: row for row, name in enumerate(self.names)}

    @classmethod
    def empty(cls) -> Turtles:
        """No turtles."""
        arrays = {
            name: np.zeros((0, 3) if name == "pen_rgb" else 0, dtype)
            for name, dtype in _DTYPES.items()
        }
        return cls(names=(), **arrays)

    @classmethod
    def create(
        cls,
        names: Sequence[str],
        x: npt.ArrayLike,
        y: npt.ArrayLike,
        theta: npt.ArrayLike,
        sprite: npt.ArrayLike = 0,
    ) -> Turtles:
        """Turtles at rest with the default pen, at internal positions ``x``, ``y``.

        Raises:
            ValueError: a name appears twice.
        """
        count = len(names)
        if len(set(names)) != count:
            raise ValueError("turtle names must be unique")
        order = sorted(range(count), key=names.__getitem__)

        def column(values: npt.ArrayLike, dtype: Any) -> Any:
            return np.broadcast_to(np.asarray(values, dtype), (count,))[order].copy()

        return cls(
            names=tuple(names[i] for i in order),
            x=column(x, np.float64),
            y=column(y, np.float64),
            theta=column(theta, np.float64),
            vx=np.zeros(count),
            vy=np.zeros(count),
            w=np.zeros(count),
            last_command=np.zeros(count),
            pen_on=np.ones(count, np.bool_),
            pen_rgb=np.tile(np.array(DEFAULT_PEN, np.uint8), (count, 1)),
            pen_width=np.full(count, DEFAULT_PEN_WIDTH, np.int32),
            sprite=column(sprite, np.int32),
        )

    def __len__(self) -> int:
        return len(self.names)

    def __contains__(self, name: object) -> bool:
        return name in self._rows

    def row(self, name: str) -> int | None:
        """The row of turtle ``name``, or None."""
        return self._rows.get(name)

    def rows(self, names: Sequence[str]) -> npt.NDArray[np.intp]:
        """The rows of ``names`` (each must exist)."""
        return np.fromiter((self._rows[n] for n in names), np.intp, count=len(names))

    @property
    def world_y(self) -> F64:
        """y in the world frame (up from the bottom edge), as the pose reports it."""
        return WORLD_SIZE - self.y

    def evolve(self, **arrays: Any) -> Turtles:
        """A copy with some arrays replaced (same names and rows)."""
        copy = replace(self, **arrays)
        if "_rows" in self.__dict__:  # the same names: share the index instead of rebuilding it
            copy.__dict__["_rows"] = self.__dict__["_rows"]
        return copy

    def with_turtle(self, name: str, x: float, y: float, theta: float, sprite: int) -> Turtles:
        """A copy with one more turtle, at rest with the default pen (``name`` must be new)."""
        if name in self._rows:
            raise ValueError(f"turtle [{name}] exists")
        at = bisect.bisect(self.names, name)
        new = Turtles.create([name], [x], [y], [theta], [sprite])
        arrays = {
            key: np.concatenate((old[:at], getattr(new, key), old[at:]))
            for key in ARRAYS
            for old in (getattr(self, key),)
        }
        return Turtles(names=(*self.names[:at], name, *self.names[at:]), **arrays)

    def without(self, name: str) -> Turtles:
        """A copy without turtle ``name`` (which must exist)."""
        at = self._rows[name]
        arrays = {key: np.delete(getattr(self, key), at, axis=0) for key in ARRAYS}
        return Turtles(names=self.names[:at] + self.names[at + 1 :], **arrays)
