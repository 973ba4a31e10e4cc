"""The few KDL frame operations ``tf2_geometry_msgs`` transforms messages with.

ROS 1's ``tf2_geometry_msgs`` builds ``PyKDL.Frame`` objects from the transform and the message
and multiplies them; these functions do KDL's arithmetic (its quaternion-to-matrix formula, its
matrix products, its ``GetQuaternion``) on plain floats, so transformed points and poses come
out as ROS 1's do, without PyKDL.
"""

from __future__ import annotations

from math import sqrt

#: Row-major 3x3 rotation, as KDL's ``Rotation.data``.
Rotation = tuple[float, float, float, float, float, float, float, float, float]
Vector = tuple[float, float, float]


def rotation(x: float, y: float, z: float, w: float) -> Rotation:
    """``KDL::Rotation::Quaternion``."""
    x2, y2, z2, w2 = x * x, y * y, z * z, w * w
    return (
        w2 + x2 - y2 - z2,
        2 * x * y - 2 * w * z,
        2 * x * z + 2 * w * y,
        2 * x * y + 2 * w * z,
        w2 - x2 + y2 - z2,
        2 * y * z - 2 * w * x,
        2 * x * z - 2 * w * y,
        2 * y * z + 2 * w * x,
        w2 - x2 - y2 + z2,
    )


def rotate(m: Rotation, v: Vector) -> Vector:
    """``KDL::Rotation * Vector``."""
    return (
        m[0] * v[0] + m[1] * v[1] + m[2] * v[2],
        m[3] * v[0] + m[4] * v[1] + m[5] * v[2],
        m[6] * v[0] + m[7] * v[1] + m[8] * v[2],
    )


def apply(m: Rotation, p: Vector, v: Vector) -> Vector:
    """``KDL::Frame * Vector``: ``m · v + p``."""
    r = rotate(m, v)
    return (r[0] + p[0], r[1] + p[1], r[2] + p[2])


def multiply(a: Rotation, b: Rotation) -> Rotation:
    """``KDL::Rotation * Rotation``."""
    return (
        a[0] * b[0] + a[1] * b[3] + a[2] * b[6],
        a[0] * b[1] + a[1] * b[4] + a[2] * b[7],
        a[0] * b[2] + a[1] * b[5] + a[2] * b[8],
        a[3] * b[0] + a[4] * b[3] + a[5] * b[6],
        a[3] * b[1] + a[4] * b[4] + a[5] * b[7],
        a[3] * b[2] + a[4] * b[5] + a[5] * b[8],
        a[6] * b[0] + a[7] * b[3] + a[8] * b[6],
        a[6] * b[1] + a[7] * b[4] + a[8] * b[7],
        a[6] * b[2] + a[7] * b[5] + a[8] * b[8],
    )


def quaternion(m: Rotation) -> tuple[float, float, float, float]:
    """``KDL::Rotation::GetQuaternion``: (x, y, z, w)."""
    trace = m[0] + m[4] + m[8]
    if trace > 1e-12:
        s = 0.5 / sqrt(trace + 1.0)
        return ((m[7] - m[5]) * s, (m[2] - m[6]) * s, (m[3] - m[1]) * s, 0.25 / s)
    if m[0] > m[4] and m[0] > m[8]:
        s = 2.0 * sqrt(1.0 + m[0] - m[4] - m[8])
        return (0.25 * s, (m[1] + m[3]) / s, (m[2] + m[6]) / s, (m[7] - m[5]) / s)
    if m[4] > m[8]:
        s = 2.0 * sqrt(1.0 + m[4] - m[0] - m[8])
        return ((m[1] + m[3]) / s, 0.25 * s, (m[5] + m[7]) / s, (m[2] - m[6]) / s)
    s = 2.0 * sqrt(1.0 + m[8] - m[0] - m[4])
    return ((m[2] + m[6]) / s, (m[5] + m[7]) / s, 0.25 * s, (m[3] - m[1]) / s)


__all__ = ["Rotation", "Vector", "apply", "multiply", "quaternion", "rotate", "rotation"]
