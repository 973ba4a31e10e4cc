"""Poses and points in numbers: quaternions to yaw and matrices, poses composed and applied.

A transform is tf's tuple ``(tx, ty, tz, qx, qy, qz, qw)``; points are ``(n, 3)`` (or
``(n, 2)``, on the plane z = 0) float arrays. The view is top-down: whatever a display puts in
the fixed frame is drawn by its x and y.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np  # noqa: TID253 - rviz's model is array work; only rviz imports it

if TYPE_CHECKING:
    import numpy.typing as npt

    Points = npt.NDArray[np.float64]

Transform = tuple[float, float, float, float, float, float, float]
IDENTITY: Transform = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0)


def yaw_of(qx: float, qy: float, qz: float, qw: float) -> float:
    """The heading (rotation about z) of a quaternion, as tf's ``getYaw`` gives it."""
    return math.atan2(2.0 * (qw * qz + qx * qy), 1.0 - 2.0 * (qy * qy + qz * qz))


def quaternion_of_yaw(yaw: float) -> tuple[float, float, float, float]:
    """The quaternion ``(x, y, z, w)`` of a rotation by ``yaw`` about z (tf's ``setRPY(0, 0,
    yaw)``)."""
    return (0.0, 0.0, math.sin(yaw / 2.0), math.cos(yaw / 2.0))


def rotation_matrix(qx: float, qy: float, qz: float, qw: float) -> Points:
    """The 3x3 rotation of a quaternion (normalised first; a zero one is the identity)."""
    norm = math.sqrt(qx * qx + qy * qy + qz * qz + qw * qw)
    if norm < 1e-12:
        return np.eye(3)
    qx, qy, qz, qw = qx / norm, qy / norm, qz / norm, qw / norm
    return np.array(
        [
            [1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy - qz * qw), 2 * (qx * qz + qy * qw)],
            [2 * (qx * qy + qz * qw), 1 - 2 * (qx * qx + qz * qz), 2 * (qy * qz - qx * qw)],
            [2 * (qx * qz - qy * qw), 2 * (qy * qz + qx * qw), 1 - 2 * (qx * qx + qy * qy)],
        ]
    )


def compose(outer: Transform, inner: Transform) -> Transform:
    """``outer ∘ inner``: a point in ``inner``'s child frame, taken to ``outer``'s parent."""
    ox, oy, oz, ax, ay, az, aw = outer
    ix, iy, iz, bx, by, bz, bw = inner
    tx, ty, tz = rotation_matrix(ax, ay, az, aw) @ np.array([ix, iy, iz])
    return (
        float(tx + ox),
        float(ty + oy),
        float(tz + oz),
        aw * bx + ax * bw + ay * bz - az * by,
        aw * by - ax * bz + ay * bw + az * bx,
        aw * bz + ax * by - ay * bx + az * bw,
        aw * bw - ax * bx - ay * by - az * bz,
    )


def apply(transform: Transform, points: Points) -> Points:
    """``points`` (``(n, 3)``, or ``(n, 2)`` on z = 0) moved by ``transform``; ``(n, 3)``.

    Column by column: for a cloud of many points this is several times quicker than a matrix
    product with an inner size of three."""
    tx, ty, tz, qx, qy, qz, qw = transform
    x, y = points[:, 0], points[:, 1]
    flat = points.shape[1] == 2
    z = None if flat else points[:, 2]
    moved = np.empty((len(points), 3), dtype=np.float64)
    if (qx, qy, qz) == (0.0, 0.0, 0.0):
        moved[:, 0] = x + tx
        moved[:, 1] = y + ty
        moved[:, 2] = tz if z is None else z + tz
        return moved
    r = rotation_matrix(qx, qy, qz, qw)
    for row, offset in enumerate((tx, ty, tz)):
        column = r[row, 0] * x + r[row, 1] * y + offset
        if z is not None:
            column += r[row, 2] * z
        moved[:, row] = column
    return moved


def pose_transform(pose: Any) -> Transform:
    """A ``geometry_msgs/Pose`` as a transform."""
    p, q = pose.position, pose.orientation
    return (p.x, p.y, p.z, q.x, q.y, q.z, q.w)


def valid_quaternion(qx: float, qy: float, qz: float, qw: float) -> bool:
    """Whether a quaternion is finite and of length near one (rviz refuses others)."""
    values = (qx, qy, qz, qw)
    if not all(math.isfinite(v) for v in values):
        return False
    return abs(sum(v * v for v in values) - 1.0) < 1e-2


__all__ = [
    "IDENTITY",
    "Transform",
    "apply",
    "compose",
    "pose_transform",
    "quaternion_of_yaw",
    "rotation_matrix",
    "valid_quaternion",
    "yaw_of",
]
