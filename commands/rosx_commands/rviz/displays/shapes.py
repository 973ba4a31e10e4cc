"""Shapes rviz draws in 3-D, seen from above: arrows, axes, and the outline of boxes, spheres
and cylinders (the convex hull of their corners or rims, projected on the plane).

Each takes the transform of the shape's frame into the fixed frame, composed with the shape's
pose, and gives a `Layer`. Small shapes keep a few pixels (``minimum``, metres) so that they
show when zoomed out.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np  # noqa: TID253 - rviz's model is array work; only rviz imports it

from rosx_commands.rviz.geometry import apply
from rosx_commands.rviz.primitives import Layer, Polygon, Segments

if TYPE_CHECKING:
    import numpy.typing as npt

    from rosx_commands.rviz.geometry import Transform
    from rosx_commands.rviz.primitives import RGB

    Floats = npt.NDArray[np.float64]

X_COLOUR, Y_COLOUR = (255, 0, 0), (0, 255, 0)


def hull(points: Floats) -> Floats:
    """The convex hull of ``(n, 2)`` points, counter-clockwise (Andrew's monotone chain)."""
    unique = np.unique(np.round(points, 9), axis=0)
    if len(unique) < 3:
        return unique
    pts = unique[np.lexsort((unique[:, 1], unique[:, 0]))]

    def half(seq: Floats) -> list[Floats]:
        chain: list[Floats] = []
        for p in seq:
            while len(chain) >= 2:
                (ax, ay), (bx, by) = chain[-2], chain[-1]
                if (bx - ax) * (p[1] - ay) - (by - ay) * (p[0] - ax) > 1e-12:
                    break
                chain.pop()
            chain.append(p)
        return chain

    lower, upper = half(pts), half(pts[::-1])
    return np.array(lower[:-1] + upper[:-1])


def arrow(
    pose: Transform,
    length: float,
    head_length: float,
    head_radius: float,
    colour: RGB,
    alpha: float = 1.0,
    minimum: float = 0.0,
) -> Layer:
    """An arrow along the x axis of ``pose``: a shaft of ``length - head_length`` and a head
    (a triangle twice ``head_radius`` wide) reaching ``length``."""
    if 0.0 < length < minimum:
        scale = minimum / length
        length, head_length, head_radius = length * scale, head_length * scale, head_radius * scale
    base = max(0.0, length - head_length)
    ends = apply(
        pose,
        np.array(
            [[0.0, 0.0, 0.0], [base, 0.0, 0.0], [length, 0.0, 0.0],
             [base, head_radius, 0.0], [base, -head_radius, 0.0]]
        ),
    )[:, :2]  # fmt: skip
    layer = Layer(segments=[Segments(np.array([[ends[0], ends[1]]]), colour, alpha=alpha)])
    layer.polygons.append(Polygon(np.array([ends[2], ends[3], ends[4]]), colour, alpha))
    return layer


def flat_arrow(pose: Transform, length: float, colour: RGB, alpha: float = 1.0) -> Layer:
    """rviz's "Arrow (Flat)": a line and two barbs, a third of its length."""
    barb = length / 3.0
    ends = apply(
        pose,
        np.array(
            [[0.0, 0.0, 0.0], [length, 0.0, 0.0],
             [length - barb * math.cos(0.5), barb * math.sin(0.5), 0.0],
             [length - barb * math.cos(0.5), -barb * math.sin(0.5), 0.0]]
        ),
    )[:, :2]  # fmt: skip
    lines = np.array([[ends[0], ends[1]], [ends[1], ends[2]], [ends[1], ends[3]]])
    return Layer(segments=[Segments(lines, colour, alpha=alpha)])


def axes(pose: Transform, length: float, alpha: float = 1.0) -> Layer:
    """The x (red) and y (green) axes of ``pose``, ``length`` long."""
    ends = apply(pose, np.array([[0.0, 0.0, 0.0], [length, 0.0, 0.0], [0.0, length, 0.0]]))
    xy = ends[:, :2]
    return Layer(
        segments=[
            Segments(np.array([[xy[0], xy[1]]]), X_COLOUR, alpha=alpha),
            Segments(np.array([[xy[0], xy[2]]]), Y_COLOUR, alpha=alpha),
        ]
    )


def box(pose: Transform, size: tuple[float, float, float]) -> Floats:
    """The outline of a box of ``size`` centred on ``pose``, seen from above."""
    sx, sy, sz = (abs(v) / 2.0 for v in size)
    corners = np.array([[x, y, z] for x in (-sx, sx) for y in (-sy, sy) for z in (-sz, sz)])
    return hull(apply(pose, corners)[:, :2])


def ellipsoid(pose: Transform, size: tuple[float, float, float], steps: int = 24) -> Floats:
    """The outline of an ellipsoid with diameters ``size`` on ``pose``, seen from above."""
    a = np.linspace(0.0, math.tau, steps, endpoint=False)
    rx, ry, rz = (abs(v) / 2.0 for v in size)
    c, s = np.cos(a), np.sin(a)
    zero = np.zeros_like(a)
    rims = np.concatenate(
        [np.stack([rx * c, ry * s, zero], 1), np.stack([rx * c, zero, rz * s], 1),
         np.stack([zero, ry * c, rz * s], 1)]
    )  # fmt: skip
    return hull(apply(pose, rims)[:, :2])


def cylinder(pose: Transform, size: tuple[float, float, float], steps: int = 24) -> Floats:
    """The outline of a cylinder (diameters x and y, height z, along z) seen from above."""
    a = np.linspace(0.0, math.tau, steps, endpoint=False)
    rx, ry, h = abs(size[0]) / 2.0, abs(size[1]) / 2.0, abs(size[2]) / 2.0
    rims = np.concatenate(
        [np.stack([rx * np.cos(a), ry * np.sin(a), np.full_like(a, z)], 1) for z in (-h, h)]
    )
    return hull(apply(pose, rims)[:, :2])


__all__ = ["arrow", "axes", "box", "cylinder", "ellipsoid", "flat_arrow", "hull"]
