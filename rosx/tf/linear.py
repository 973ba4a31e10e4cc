"""tf2's LinearMath for what the buffer's lookups compose beyond quaternions: rotation matrices.

Each function does the operations of tf2's ``Matrix3x3``/``Transform`` in their order, on
plain floats, so results equal ROS 1's bit for bit: `matrix` (``setRotation``), `rotation`
(``getRotation``), `rpy` (``getRPY``), and `compose` (``Transform::operator*``, which the
fixed-frame lookup uses).
"""

from __future__ import annotations

from math import asin, atan2, cos, inf, pi, sin, sqrt

Matrix = tuple[tuple[float, float, float], tuple[float, float, float], tuple[float, float, float]]
#: (tx, ty, tz, qx, qy, qz, qw)
Transform = tuple[float, float, float, float, float, float, float]


def matrix(qx: float, qy: float, qz: float, qw: float) -> Matrix:
    """``Matrix3x3::setRotation``: the rotation matrix of a quaternion (rows)."""
    d = qx * qx + qy * qy + qz * qz + qw * qw
    s = 2.0 / d if d else inf  # C++ divides by zero into inf, and NaNs follow
    xs, ys, zs = qx * s, qy * s, qz * s
    wx, wy, wz = qw * xs, qw * ys, qw * zs
    xx, xy, xz = qx * xs, qx * ys, qx * zs
    yy, yz, zz = qy * ys, qy * zs, qz * zs
    return (
        (1.0 - (yy + zz), xy - wz, xz + wy),
        (xy + wz, 1.0 - (xx + zz), yz - wx),
        (xz - wy, yz + wx, 1.0 - (xx + yy)),
    )


def rotation(m: Matrix) -> tuple[float, float, float, float]:
    """``Matrix3x3::getRotation``: the quaternion (x, y, z, w) of a rotation matrix."""
    trace = m[0][0] + m[1][1] + m[2][2]
    if trace > 0.0:
        s = sqrt(trace + 1.0)
        w = s * 0.5
        s = 0.5 / s
        return ((m[2][1] - m[1][2]) * s, (m[0][2] - m[2][0]) * s, (m[1][0] - m[0][1]) * s, w)
    i = (2 if m[1][1] < m[2][2] else 1) if m[0][0] < m[1][1] else (2 if m[0][0] < m[2][2] else 0)
    j = (i + 1) % 3
    k = (i + 2) % 3
    temp = [0.0, 0.0, 0.0, 0.0]
    s = sqrt(m[i][i] - m[j][j] - m[k][k] + 1.0)
    temp[i] = s * 0.5
    s = 0.5 / s
    temp[3] = (m[k][j] - m[j][k]) * s
    temp[j] = (m[j][i] + m[i][j]) * s
    temp[k] = (m[k][i] + m[i][k]) * s
    return temp[0], temp[1], temp[2], temp[3]


def multiply(a: Matrix, b: Matrix) -> Matrix:
    """``operator*(Matrix3x3, Matrix3x3)``: ``a · b``, each entry as tf2's ``tdot``."""
    return tuple(  # type: ignore[return-value]
        tuple(b[0][c] * row[0] + b[1][c] * row[1] + b[2][c] * row[2] for c in range(3)) for row in a
    )


def apply(
    m: Matrix, origin: tuple[float, float, float], v: tuple[float, float, float]
) -> tuple[float, float, float]:
    """``Transform::operator()(Vector3)``: ``m · v + origin``."""
    return (
        (m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2]) + origin[0],
        (m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2]) + origin[1],
        (m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]) + origin[2],
    )


def compose(second: Transform, first: Transform) -> Transform:
    """``Transform::operator*``: ``first`` then ``second`` (both as tf2 builds them from
    messages: basis from the quaternion), back to a quaternion as ``transformTF2ToMsg``."""
    m2 = matrix(*second[3:])
    m1 = matrix(*first[3:])
    x, y, z = apply(m2, second[:3], first[:3])
    qx, qy, qz, qw = rotation(multiply(m2, m1))
    return (x, y, z, qx, qy, qz, qw)


def rpy(m: Matrix, tf1: bool = False) -> tuple[float, float, float]:
    """``Matrix3x3::getRPY`` (solution 1): roll, pitch, yaw about fixed X, Y, Z.

    ``tf1``: tf's version, which reads a gimbal-locked matrix's roll from its first row
    (tf2 reads the last): what ``tf_echo`` prints.
    """
    if abs(m[2][0]) >= 1:
        if m[2][0] < 0:
            delta = atan2(m[0][1], m[0][2]) if tf1 else atan2(m[2][1], m[2][2])
            return delta, pi / 2.0, 0.0
        delta = atan2(-m[0][1], -m[0][2]) if tf1 else atan2(m[2][1], m[2][2])
        return delta, -pi / 2.0, 0.0
    pitch = -asin(m[2][0])
    roll = atan2(m[2][1] / cos(pitch), m[2][2] / cos(pitch))
    yaw = atan2(m[1][0] / cos(pitch), m[0][0] / cos(pitch))
    return roll, pitch, yaw


def from_rpy(roll: float, pitch: float, yaw: float) -> tuple[float, float, float, float]:
    """``Quaternion::setRPY``: the quaternion (x, y, z, w) of fixed-axis roll, pitch, yaw."""
    half_yaw, half_pitch, half_roll = yaw * 0.5, pitch * 0.5, roll * 0.5
    cos_yaw, sin_yaw = cos(half_yaw), sin(half_yaw)
    cos_pitch, sin_pitch = cos(half_pitch), sin(half_pitch)
    cos_roll, sin_roll = cos(half_roll), sin(half_roll)
    return (
        sin_roll * cos_pitch * cos_yaw - cos_roll * sin_pitch * sin_yaw,
        cos_roll * sin_pitch * cos_yaw + sin_roll * cos_pitch * sin_yaw,
        cos_roll * cos_pitch * sin_yaw - sin_roll * sin_pitch * cos_yaw,
        cos_roll * cos_pitch * cos_yaw + sin_roll * sin_pitch * sin_yaw,
    )


__all__ = ["Matrix", "apply", "compose", "from_rpy", "matrix", "multiply", "rotation", "rpy"]
