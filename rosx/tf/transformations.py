"""``tf.transformations``: 4x4 homogeneous matrices, quaternions and Euler angles, with numpy.

The module ROS 1's ``tf`` ships (Christoph Gohlke's transformations, 2009 edition): the same
functions, arguments, conventions and results. Quaternions are ``(x, y, z, w)``; matrices act on
column vectors; Euler angles take one of the 24 axis sequences, named ``'sxyz'`` … (``s``:
static axes, ``r``: rotating axes) or given as a tuple ``(first axis, parity, repetition,
frame)``. The functions that read a matrix back (``rotation_from_matrix``, ``scale_from_matrix``
…) find eigenvectors with numpy's LAPACK, so their direction vectors are ROS 1's up to sign
where an eigenvector's sign is arbitrary.

Imported only by scripts (``import tf``), never by rosx's commands: numpy loads with it.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

#: What counts as zero.
_EPS = np.finfo(float).eps * 4.0

#: The axis after each in the cycle x → y → z → x (indexable up to 3).
_NEXT_AXIS = [1, 2, 0, 1]


def _axis_code(axes: str) -> tuple[int, int, int, int]:
    """``(first axis, parity, repetition, frame)`` of an axis string: ``r`` sequences are the
    reversed static ones, in the rotating frame."""
    frame = axes[0] == "r"
    letters = axes[1:][::-1] if frame else axes[1:]
    first, second, third = ("xyz".index(c) for c in letters)
    return first, int(second != _NEXT_AXIS[first]), int(first == third), int(frame)


_AXES2TUPLE = {
    f"{kind}{a}{b}{c}": _axis_code(f"{kind}{a}{b}{c}")
    for kind in "sr"
    for a in "xyz"
    for b in "xyz"
    for c in "xyz"
    if b not in (a, c)
}
_TUPLE2AXES = {code: name for name, code in _AXES2TUPLE.items()}


def _sequence(axes: Any, lower: bool) -> tuple[int, int, int, int, int, int, int]:
    """The axes' code and the indices i, j, k of its three axes.

    Raises:
        KeyError: neither a known name nor a known tuple.
    """
    try:
        code = _AXES2TUPLE[axes.lower() if lower else axes]
    except (AttributeError, KeyError):
        _TUPLE2AXES[axes]  # raises KeyError for an unknown tuple
        code = axes
    first, parity, repetition, frame = code
    i = first
    j = _NEXT_AXIS[i + parity]
    k = _NEXT_AXIS[i - parity + 1]
    return first, parity, repetition, frame, i, j, k


def _floats(data: Any) -> Any:
    return np.asarray(data, dtype=np.float64)


def _eigenvector(matrix: Any, value: float, last: bool, what: str, tolerance: float = 1e-8) -> Any:
    """A (real part of an) eigenvector of ``matrix`` whose eigenvalue is ``value``."""
    values, vectors = np.linalg.eig(matrix)
    found = np.where(abs(np.real(values) - value) < tolerance)[0]
    if not len(found):
        raise ValueError(what)
    return np.real(vectors[:, found[-1] if last else found[0]]).squeeze()


def _dehomogenized(vector: Any) -> Any:
    vector /= vector[3]
    return vector


# -- helpers ----------------------------------------------------------------------------------


def vector_norm(data: Any, axis: Any = None, out: Any = None) -> Any:
    """The Euclidean length of ``data`` (along ``axis``; into ``out`` if given)."""
    data = np.array(data, dtype=np.float64, copy=True)
    if out is None:
        if data.ndim == 1:
            return math.sqrt(np.dot(data, data))
        data *= data
        out = np.atleast_1d(np.sum(data, axis=axis))
        np.sqrt(out, out)
        return out
    data *= data
    np.sum(data, axis=axis, out=out)
    np.sqrt(out, out)
    return None


def unit_vector(data: Any, axis: Any = None, out: Any = None) -> Any:
    """``data`` divided by its length (along ``axis``; into ``out`` if given)."""
    if out is None:
        data = np.array(data, dtype=np.float64, copy=True)
        if data.ndim == 1:
            data /= math.sqrt(np.dot(data, data))
            return data
    else:
        if out is not data:
            out[:] = np.asarray(data)
        data = out
    length = np.atleast_1d(np.sum(data * data, axis))
    np.sqrt(length, length)
    if axis is not None:
        length = np.expand_dims(length, axis)
    data /= length
    return data if out is None else None


def random_vector(size: Any) -> Any:
    """Random doubles in [0, 1)."""
    return np.random.random(size)


def inverse_matrix(matrix: Any) -> Any:
    """The inverse of a square matrix."""
    return np.linalg.inv(matrix)


def concatenate_matrices(*matrices: Any) -> Any:
    """The product of the matrices, left to right."""
    result = np.identity(4)
    for matrix in matrices:
        result = np.dot(result, matrix)
    return result


def is_same_transform(matrix0: Any, matrix1: Any) -> bool:
    """Whether two homogeneous matrices transform alike (after dividing by their [3, 3])."""
    a = np.array(matrix0, dtype=np.float64, copy=True)
    a /= a[3, 3]
    b = np.array(matrix1, dtype=np.float64, copy=True)
    b /= b[3, 3]
    return bool(np.allclose(a, b))


# -- translation, reflection, rotation, scale -------------------------------------------------


def identity_matrix() -> Any:
    """The 4x4 identity."""
    return np.identity(4, dtype=np.float64)


def translation_matrix(direction: Any) -> Any:
    """The matrix translating by ``direction``."""
    m = np.identity(4)
    m[:3, 3] = direction[:3]
    return m


def translation_from_matrix(matrix: Any) -> Any:
    """The translation of a homogeneous matrix."""
    return np.asarray(matrix)[:3, 3].copy()


def reflection_matrix(point: Any, normal: Any) -> Any:
    """The mirror at the plane through ``point`` with ``normal``."""
    n = unit_vector(normal[:3])
    m = np.identity(4)
    m[:3, :3] -= 2.0 * np.outer(n, n)
    m[:3, 3] = (2.0 * np.dot(point[:3], n)) * n
    return m


def reflection_from_matrix(matrix: Any) -> tuple[Any, Any]:
    """A point of the mirror plane and its normal, from a reflection matrix."""
    m = _floats(matrix)
    normal = _eigenvector(
        m[:3, :3], -1.0, False, "no unit eigenvector corresponding to eigenvalue -1"
    )
    point = _eigenvector(m, 1.0, True, "no unit eigenvector corresponding to eigenvalue 1")
    return _dehomogenized(point), normal


def rotation_matrix(angle: float, direction: Any, point: Any = None) -> Any:
    """The rotation by ``angle`` about the axis along ``direction`` (through ``point``)."""
    sina = math.sin(angle)
    cosa = math.cos(angle)
    d = unit_vector(direction[:3])
    r = np.diag([cosa, cosa, cosa]).astype(np.float64)
    r += np.outer(d, d) * (1.0 - cosa)
    d *= sina
    r += np.array(((0.0, -d[2], d[1]), (d[2], 0.0, -d[0]), (-d[1], d[0], 0.0)), dtype=np.float64)
    m = np.identity(4)
    m[:3, :3] = r
    if point is not None:
        p = _floats(point[:3])
        m[:3, 3] = p - np.dot(r, p)
    return m


def rotation_from_matrix(matrix: Any) -> tuple[float, Any, Any]:
    """The angle, axis direction and a point of the axis of a rotation matrix."""
    r = _floats(matrix)
    r33 = r[:3, :3]
    direction = _eigenvector(r33.T, 1.0, True, "no unit eigenvector corresponding to eigenvalue 1")
    point = _eigenvector(r, 1.0, True, "no unit eigenvector corresponding to eigenvalue 1")
    point = _dehomogenized(point)
    cosa = (np.trace(r33) - 1.0) / 2.0
    if abs(direction[2]) > 1e-8:
        sina = (r[1, 0] + (cosa - 1.0) * direction[0] * direction[1]) / direction[2]
    elif abs(direction[1]) > 1e-8:
        sina = (r[0, 2] + (cosa - 1.0) * direction[0] * direction[2]) / direction[1]
    else:
        sina = (r[2, 1] + (cosa - 1.0) * direction[1] * direction[2]) / direction[0]
    return math.atan2(sina, cosa), direction, point


def scale_matrix(factor: float, origin: Any = None, direction: Any = None) -> Any:
    """Scaling by ``factor`` about ``origin``, uniformly or along ``direction``."""
    if direction is None:
        m = np.diag([factor, factor, factor, 1.0]).astype(np.float64)
        if origin is not None:
            m[:3, 3] = origin[:3]
            m[:3, 3] *= 1.0 - factor
        return m
    d = unit_vector(direction[:3])
    shrink = 1.0 - factor
    m = np.identity(4)
    m[:3, :3] -= shrink * np.outer(d, d)
    if origin is not None:
        m[:3, 3] = (shrink * np.dot(origin[:3], d)) * d
    return m


def scale_from_matrix(matrix: Any) -> tuple[float, Any, Any]:
    """The factor, origin and direction (None: uniform) of a scaling matrix."""
    m = _floats(matrix)
    m33 = m[:3, :3]
    factor = np.trace(m33) - 2.0
    values, vectors = np.linalg.eig(m33)
    along = np.where(abs(np.real(values) - factor) < 1e-8)[0]
    if len(along):
        direction = np.real(vectors[:, along[0]]).squeeze()
        direction /= vector_norm(direction)
    else:
        factor = (factor + 2.0) / 3.0
        direction = None
    origin = _eigenvector(m, 1.0, True, "no eigenvector corresponding to eigenvalue 1")
    return factor, _dehomogenized(origin), direction


# -- projection, clipping, shear ---------------------------------------------------------------


def projection_matrix(
    point: Any, normal: Any, direction: Any = None, perspective: Any = None, pseudo: bool = False
) -> Any:
    """Projection onto the plane through ``point`` with ``normal``: from a ``perspective``
    point, along ``direction``, or orthogonal."""
    m = np.identity(4)
    p = _floats(point[:3])
    n = unit_vector(normal[:3])
    if perspective is not None:
        eye = _floats(perspective[:3])
        m[0, 0] = m[1, 1] = m[2, 2] = np.dot(eye - p, n)
        m[:3, :3] -= np.outer(eye, n)
        if pseudo:
            m[:3, :3] -= np.outer(n, n)
            m[:3, 3] = np.dot(p, n) * (eye + n)
        else:
            m[:3, 3] = np.dot(p, n) * eye
        m[3, :3] = -n
        m[3, 3] = np.dot(eye, n)
    elif direction is not None:
        d = _floats(direction[:3])
        scale = np.dot(d, n)
        m[:3, :3] -= np.outer(d, n) / scale
        m[:3, 3] = d * (np.dot(p, n) / scale)
    else:
        m[:3, :3] -= np.outer(n, n)
        m[:3, 3] = np.dot(p, n) * n
    return m


def projection_from_matrix(matrix: Any, pseudo: bool = False) -> tuple[Any, ...]:
    """``projection_matrix``'s arguments (point, normal, direction, perspective, pseudo)."""
    m = _floats(matrix)
    m33 = m[:3, :3]
    values, vectors = np.linalg.eig(m)
    unit = np.where(abs(np.real(values) - 1.0) < 1e-8)[0]
    if not pseudo and len(unit):
        point = _dehomogenized(np.real(vectors[:, unit[-1]]).squeeze())
        direction = _eigenvector(m33, 0.0, False, "no eigenvector corresponding to eigenvalue 0")
        direction /= vector_norm(direction)
        values, vectors = np.linalg.eig(m33.T)
        zero = np.where(abs(np.real(values)) < 1e-8)[0]
        if len(zero):
            normal = np.real(vectors[:, zero[0]]).squeeze()
            normal /= vector_norm(normal)
            return point, normal, direction, None, False
        return point, direction, None, None, False
    nonzero = np.where(abs(np.real(values)) > 1e-8)[0]
    if not len(nonzero):
        raise ValueError("no eigenvector not corresponding to eigenvalue 0")
    point = _dehomogenized(np.real(vectors[:, nonzero[-1]]).squeeze())
    normal = -m[3, :3]
    perspective = m[:3, 3] / np.dot(point[:3], normal)
    if pseudo:
        perspective -= normal
    return point, normal, None, perspective, pseudo


def clip_matrix(
    left: float,
    right: float,
    bottom: float,
    top: float,
    near: float,
    far: float,
    perspective: bool = False,
) -> Any:
    """The matrix to normalized device coordinates of a frustrum (a box if not
    ``perspective``)."""
    if left >= right or bottom >= top or near >= far:
        raise ValueError("invalid frustrum")
    if perspective:
        if near <= _EPS:
            raise ValueError("invalid frustrum: near <= 0")
        t = 2.0 * near
        rows: Any = (
            (-t / (right - left), 0.0, (right + left) / (right - left), 0.0),
            (0.0, -t / (top - bottom), (top + bottom) / (top - bottom), 0.0),
            (0.0, 0.0, -(far + near) / (far - near), t * far / (far - near)),
            (0.0, 0.0, -1.0, 0.0),
        )
    else:
        rows = (
            (2.0 / (right - left), 0.0, 0.0, (right + left) / (left - right)),
            (0.0, 2.0 / (top - bottom), 0.0, (top + bottom) / (bottom - top)),
            (0.0, 0.0, 2.0 / (far - near), (far + near) / (near - far)),
            (0.0, 0.0, 0.0, 1.0),
        )
    return np.array(rows, dtype=np.float64)


def shear_matrix(angle: float, direction: Any, point: Any, normal: Any) -> Any:
    """Shear by ``angle`` along ``direction`` on the plane through ``point`` with
    ``normal`` (orthogonal to ``direction``)."""
    n = unit_vector(normal[:3])
    d = unit_vector(direction[:3])
    if abs(np.dot(n, d)) > 1e-6:
        raise ValueError("direction and normal vectors are not orthogonal")
    slope = math.tan(angle)
    m = np.identity(4)
    m[:3, :3] += slope * np.outer(d, n)
    m[:3, 3] = -slope * np.dot(point[:3], n) * d
    return m


def shear_from_matrix(matrix: Any) -> tuple[float, Any, Any, Any]:
    """The angle, direction, plane point and plane normal of a shear matrix.

    A shear's matrix is defective (its eigenvalues are all 1, its unit eigenvectors span only
    the plane), so LAPACK may give two of them nearly parallel, and a normal crossed from them
    is then wrong (0.439 read for a shear of 0.5). `shear_matrix` adds ``tan(angle) *
    direction ⊗ normal`` to the identity: the normal is that product's first right singular
    vector, and a point of the plane the fixed point of the whole matrix with the largest
    ``w``, both found stably.
    """
    m = _floats(matrix)
    m33 = m[:3, :3]
    values = np.linalg.eigvals(m33)
    if np.count_nonzero(abs(np.real(values) - 1.0) < 1e-4) < 2:
        raise ValueError(f"No two linear independent eigenvectors found {values}")
    sheared = m33 - np.identity(3)
    normal = np.linalg.svd(sheared)[2][0]
    direction = np.dot(sheared, normal)
    slope = vector_norm(direction)
    direction /= slope
    _, singular, rows = np.linalg.svd(m - np.identity(4))
    fixed = rows[singular < 1e-8 * max(1.0, singular[0])]
    if not len(fixed):
        raise ValueError("no eigenvector corresponding to eigenvalue 1")
    point = np.dot(fixed[:, 3], fixed)  # the fixed points' projection of (0, 0, 0, 1)
    return math.atan(slope), direction, _dehomogenized(point), normal


# -- composing and decomposing ----------------------------------------------------------------


def decompose_matrix(matrix: Any) -> tuple[Any, Any, Any, Any, Any]:
    """Scale, shear, static-xyz Euler angles, translation and perspective of a matrix.

    Raises:
        ValueError: the matrix is degenerate.
    """
    m = np.array(matrix, dtype=np.float64, copy=True).T
    if abs(m[3, 3]) < _EPS:
        raise ValueError("M[3, 3] is zero")
    m /= m[3, 3]
    p = m.copy()
    p[:, 3] = 0, 0, 0, 1
    if not np.linalg.det(p):
        raise ValueError("Matrix is singular")
    scale = np.zeros((3,), dtype=np.float64)
    shear: Any = [0, 0, 0]
    angles = [0.0, 0.0, 0.0]
    if any(abs(m[:3, 3]) > _EPS):
        perspective = np.dot(m[:, 3], np.linalg.inv(p.T))
        m[:, 3] = 0, 0, 0, 1
    else:
        perspective = np.array((0, 0, 0, 1), dtype=np.float64)
    translate = m[3, :3].copy()
    m[3, :3] = 0
    row = m[:3, :3].copy()
    scale[0] = vector_norm(row[0])
    row[0] /= scale[0]
    shear[0] = np.dot(row[0], row[1])
    row[1] -= row[0] * shear[0]
    scale[1] = vector_norm(row[1])
    row[1] /= scale[1]
    shear[0] /= scale[1]
    shear[1] = np.dot(row[0], row[2])
    row[2] -= row[0] * shear[1]
    shear[2] = np.dot(row[1], row[2])
    row[2] -= row[1] * shear[2]
    scale[2] = vector_norm(row[2])
    row[2] /= scale[2]
    shear[1:] /= scale[2]
    if np.dot(row[0], np.cross(row[1], row[2])) < 0:
        scale *= -1
        row *= -1
    angles[1] = math.asin(-row[0, 2])
    if math.cos(angles[1]):
        angles[0] = math.atan2(row[1, 2], row[2, 2])
        angles[2] = math.atan2(row[0, 1], row[0, 0])
    else:
        angles[0] = math.atan2(-row[2, 1], row[1, 1])
        angles[2] = 0.0
    return scale, shear, angles, translate, perspective


def compose_matrix(
    scale: Any = None,
    shear: Any = None,
    angles: Any = None,
    translate: Any = None,
    perspective: Any = None,
) -> Any:
    """The matrix of ``decompose_matrix``'s parts (each optional)."""
    m = np.identity(4)
    if perspective is not None:
        part = np.identity(4)
        part[3, :] = perspective[:4]
        m = np.dot(m, part)
    if translate is not None:
        part = np.identity(4)
        part[:3, 3] = translate[:3]
        m = np.dot(m, part)
    if angles is not None:
        m = np.dot(m, euler_matrix(angles[0], angles[1], angles[2], "sxyz"))
    if shear is not None:
        part = np.identity(4)
        part[1, 2] = shear[2]
        part[0, 2] = shear[1]
        part[0, 1] = shear[0]
        m = np.dot(m, part)
    if scale is not None:
        part = np.identity(4)
        part[0, 0], part[1, 1], part[2, 2] = scale[0], scale[1], scale[2]
        m = np.dot(m, part)
    m /= m[3, 3]
    return m


def orthogonalization_matrix(lengths: Any, angles: Any) -> Any:
    """The orthogonalization matrix of a crystallographic cell (angles in degrees)."""
    a, b, c = lengths
    radians = np.radians(angles)
    sina, sinb, _ = np.sin(radians)
    cosa, cosb, cosg = np.cos(radians)
    co = (cosa * cosb - cosg) / (sina * sinb)
    return np.array(
        (
            (a * sinb * math.sqrt(1.0 - co * co), 0.0, 0.0, 0.0),
            (-a * sinb * co, b * sina, 0.0, 0.0),
            (a * cosb, b * cosa, c, 0.0),
            (0.0, 0.0, 0.0, 1.0),
        ),
        dtype=np.float64,
    )


def superimposition_matrix(v0: Any, v1: Any, scaling: bool = False, usesvd: bool = True) -> Any:
    """The rotation, translation (and uniform scale) moving the points ``v0`` onto ``v1``
    (shape (3, n) or (4, n), n ≥ 3): Kabsch's SVD or Horn's quaternion method."""
    a = _floats(v0)[:3]
    b = _floats(v1)[:3]
    if a.shape != b.shape or a.shape[1] < 3:
        raise ValueError("Vector sets are of wrong shape or type.")
    ta = np.mean(a, axis=1)
    tb = np.mean(b, axis=1)
    a = a - ta.reshape(3, 1)
    b = b - tb.reshape(3, 1)
    if usesvd:
        u, s, vh = np.linalg.svd(np.dot(b, a.T))
        r = np.dot(u, vh)
        if np.linalg.det(r) < 0.0:
            r -= np.outer(u[:, 2], vh[2, :] * 2.0)
            s[-1] *= -1.0
        m = np.identity(4)
        m[:3, :3] = r
    else:
        xx, yy, zz = np.sum(a * b, axis=1)
        xy, yz, zx = np.sum(a * np.roll(b, -1, axis=0), axis=1)
        xz, yx, zy = np.sum(a * np.roll(b, -2, axis=0), axis=1)
        n = (
            (xx + yy + zz, yz - zy, zx - xz, xy - yx),
            (yz - zy, xx - yy - zz, xy + yx, zx + xz),
            (zx - xz, xy + yx, -xx + yy - zz, yz + zy),
            (xy - yx, zx + xz, yz + zy, -xx - yy + zz),
        )
        values, vectors = np.linalg.eig(n)
        q = vectors[:, np.argmax(values)]
        q /= vector_norm(q)
        m = quaternion_matrix(np.roll(q, -1))
    if scaling:
        a *= a
        b *= b
        m[:3, :3] *= math.sqrt(np.sum(b) / np.sum(a))
    m[:3, 3] = tb
    shift = np.identity(4)
    shift[:3, 3] = -ta
    return np.dot(m, shift)


# -- Euler angles ------------------------------------------------------------------------------


def euler_matrix(ai: float, aj: float, ak: float, axes: Any = "sxyz") -> Any:
    """The rotation matrix of Euler angles ``ai``, ``aj``, ``ak`` about ``axes``."""
    _, parity, repetition, frame, i, j, k = _sequence(axes, lower=False)
    if frame:
        ai, ak = ak, ai
    if parity:
        ai, aj, ak = -ai, -aj, -ak
    si, sj, sk = math.sin(ai), math.sin(aj), math.sin(ak)
    ci, cj, ck = math.cos(ai), math.cos(aj), math.cos(ak)
    cc, cs = ci * ck, ci * sk
    sc, ss = si * ck, si * sk
    m = np.identity(4)
    if repetition:
        m[i, i] = cj
        m[i, j] = sj * si
        m[i, k] = sj * ci
        m[j, i] = sj * sk
        m[j, j] = -cj * ss + cc
        m[j, k] = -cj * cs - sc
        m[k, i] = -sj * ck
        m[k, j] = cj * sc + cs
        m[k, k] = cj * cc - ss
    else:
        m[i, i] = cj * ck
        m[i, j] = sj * sc - cs
        m[i, k] = sj * cc + ss
        m[j, i] = cj * sk
        m[j, j] = sj * ss + cc
        m[j, k] = sj * cs - sc
        m[k, i] = -sj
        m[k, j] = cj * si
        m[k, k] = cj * ci
    return m


def euler_from_matrix(matrix: Any, axes: Any = "sxyz") -> tuple[float, float, float]:
    """Euler angles about ``axes`` of a rotation matrix (one of the triplets giving it)."""
    _, parity, repetition, frame, i, j, k = _sequence(axes, lower=True)
    m = _floats(matrix)[:3, :3]
    if repetition:
        sy = math.sqrt(m[i, j] * m[i, j] + m[i, k] * m[i, k])
        if sy > _EPS:
            ax = math.atan2(m[i, j], m[i, k])
            ay = math.atan2(sy, m[i, i])
            az = math.atan2(m[j, i], -m[k, i])
        else:
            ax = math.atan2(-m[j, k], m[j, j])
            ay = math.atan2(sy, m[i, i])
            az = 0.0
    else:
        cy = math.sqrt(m[i, i] * m[i, i] + m[j, i] * m[j, i])
        if cy > _EPS:
            ax = math.atan2(m[k, j], m[k, k])
            ay = math.atan2(-m[k, i], cy)
            az = math.atan2(m[j, i], m[i, i])
        else:
            ax = math.atan2(-m[j, k], m[j, j])
            ay = math.atan2(-m[k, i], cy)
            az = 0.0
    if parity:
        ax, ay, az = -ax, -ay, -az
    if frame:
        ax, az = az, ax
    return ax, ay, az


def euler_from_quaternion(quaternion: Any, axes: Any = "sxyz") -> tuple[float, float, float]:
    """Euler angles about ``axes`` of a quaternion."""
    return euler_from_matrix(quaternion_matrix(quaternion), axes)


def quaternion_from_euler(ai: float, aj: float, ak: float, axes: Any = "sxyz") -> Any:
    """The quaternion (x, y, z, w) of Euler angles about ``axes``."""
    _, parity, repetition, frame, i, j, k = _sequence(axes, lower=True)
    if frame:
        ai, ak = ak, ai
    if parity:
        aj = -aj
    ai /= 2.0
    aj /= 2.0
    ak /= 2.0
    ci, si = math.cos(ai), math.sin(ai)
    cj, sj = math.cos(aj), math.sin(aj)
    ck, sk = math.cos(ak), math.sin(ak)
    cc, cs = ci * ck, ci * sk
    sc, ss = si * ck, si * sk
    q = np.empty((4,), dtype=np.float64)
    if repetition:
        q[i] = cj * (cs + sc)
        q[j] = sj * (cc + ss)
        q[k] = sj * (cs - sc)
        q[3] = cj * (cc - ss)
    else:
        q[i] = cj * sc - sj * cs
        q[j] = cj * ss + sj * cc
        q[k] = cj * cs - sj * sc
        q[3] = cj * cc + sj * ss
    if parity:
        q[j] *= -1
    return q


# -- quaternions -------------------------------------------------------------------------------


def quaternion_about_axis(angle: float, axis: Any) -> Any:
    """The quaternion of a rotation by ``angle`` about ``axis``."""
    q = np.zeros((4,), dtype=np.float64)
    q[:3] = axis[:3]
    length = vector_norm(q)
    if length > _EPS:
        q *= math.sin(angle / 2.0) / length
    q[3] = math.cos(angle / 2.0)
    return q


def quaternion_matrix(quaternion: Any) -> Any:
    """The homogeneous rotation matrix of a quaternion (the identity for a null one)."""
    q = np.array(quaternion[:4], dtype=np.float64, copy=True)
    nq = np.dot(q, q)
    if nq < _EPS:
        return np.identity(4)
    q *= math.sqrt(2.0 / nq)
    o = np.outer(q, q)
    return np.array(
        (
            (1.0 - o[1, 1] - o[2, 2], o[0, 1] - o[2, 3], o[0, 2] + o[1, 3], 0.0),
            (o[0, 1] + o[2, 3], 1.0 - o[0, 0] - o[2, 2], o[1, 2] - o[0, 3], 0.0),
            (o[0, 2] - o[1, 3], o[1, 2] + o[0, 3], 1.0 - o[0, 0] - o[1, 1], 0.0),
            (0.0, 0.0, 0.0, 1.0),
        ),
        dtype=np.float64,
    )


def quaternion_from_matrix(matrix: Any) -> Any:
    """The quaternion of a rotation matrix."""
    q = np.empty((4,), dtype=np.float64)
    m = _floats(matrix)[:4, :4]
    t = np.trace(m)
    if t > m[3, 3]:
        q[3] = t
        q[2] = m[1, 0] - m[0, 1]
        q[1] = m[0, 2] - m[2, 0]
        q[0] = m[2, 1] - m[1, 2]
    else:
        i, j, k = 0, 1, 2
        if m[1, 1] > m[0, 0]:
            i, j, k = 1, 2, 0
        if m[2, 2] > m[i, i]:
            i, j, k = 2, 0, 1
        t = m[i, i] - (m[j, j] + m[k, k]) + m[3, 3]
        q[i] = t
        q[j] = m[i, j] + m[j, i]
        q[k] = m[k, i] + m[i, k]
        q[3] = m[k, j] - m[j, k]
    q *= 0.5 / math.sqrt(t * m[3, 3])
    return q


def quaternion_multiply(quaternion1: Any, quaternion0: Any) -> Any:
    """``quaternion1 · quaternion0``."""
    x0, y0, z0, w0 = quaternion0
    x1, y1, z1, w1 = quaternion1
    return np.array(
        (
            x1 * w0 + y1 * z0 - z1 * y0 + w1 * x0,
            -x1 * z0 + y1 * w0 + z1 * x0 + w1 * y0,
            x1 * y0 - y1 * x0 + z1 * w0 + w1 * z0,
            -x1 * x0 - y1 * y0 - z1 * z0 + w1 * w0,
        ),
        dtype=np.float64,
    )


def quaternion_conjugate(quaternion: Any) -> Any:
    """The conjugate (x, y, z negated)."""
    return np.array(
        (-quaternion[0], -quaternion[1], -quaternion[2], quaternion[3]), dtype=np.float64
    )


def quaternion_inverse(quaternion: Any) -> Any:
    """The inverse: the conjugate over the squared length."""
    return quaternion_conjugate(quaternion) / np.dot(quaternion, quaternion)


def quaternion_slerp(
    quat0: Any, quat1: Any, fraction: float, spin: int = 0, shortestpath: bool = True
) -> Any:
    """The spherical linear interpolation from ``quat0`` (0) to ``quat1`` (1)."""
    q0 = unit_vector(quat0[:4])
    q1 = unit_vector(quat1[:4])
    if fraction == 0.0:
        return q0
    if fraction == 1.0:
        return q1
    d = np.dot(q0, q1)
    if abs(abs(d) - 1.0) < _EPS:
        return q0
    if shortestpath and d < 0.0:
        d = -d
        q1 *= -1.0
    angle = math.acos(d) + spin * math.pi
    if abs(angle) < _EPS:
        return q0
    isin = 1.0 / math.sin(angle)
    q0 *= math.sin((1.0 - fraction) * angle) * isin
    q1 *= math.sin(fraction * angle) * isin
    q0 += q1
    return q0


def random_quaternion(rand: Any = None) -> Any:
    """A uniformly random unit quaternion (from three uniform numbers in [0, 1), if given)."""
    if rand is None:
        rand = np.random.rand(3)
    else:
        assert len(rand) == 3
    r1 = np.sqrt(1.0 - rand[0])
    r2 = np.sqrt(rand[0])
    t1 = math.pi * 2.0 * rand[1]
    t2 = math.pi * 2.0 * rand[2]
    return np.array(
        (np.sin(t1) * r1, np.cos(t1) * r1, np.sin(t2) * r2, np.cos(t2) * r2), dtype=np.float64
    )


def random_rotation_matrix(rand: Any = None) -> Any:
    """A uniformly random rotation matrix."""
    return quaternion_matrix(random_quaternion(rand))


# -- the arcball --------------------------------------------------------------------------------


def arcball_map_to_sphere(point: Any, center: Any, radius: float) -> Any:
    """Window coordinates on the unit sphere."""
    v = np.array(
        ((point[0] - center[0]) / radius, (center[1] - point[1]) / radius, 0.0), dtype=np.float64
    )
    n = v[0] * v[0] + v[1] * v[1]
    if n > 1.0:
        v /= math.sqrt(n)
    else:
        v[2] = math.sqrt(1.0 - n)
    return v


def arcball_constrain_to_axis(point: Any, axis: Any) -> Any:
    """The sphere point perpendicular to ``axis`` nearest ``point``."""
    v = np.array(point, dtype=np.float64, copy=True)
    a = np.array(axis, dtype=np.float64, copy=True)
    v -= a * np.dot(a, v)
    n = vector_norm(v)
    if n > _EPS:
        if v[2] < 0.0:
            v *= -1.0
        v /= n
        return v
    if a[2] == 1.0:
        return np.array([1, 0, 0], dtype=np.float64)
    return unit_vector([-a[1], a[0], 0])


def arcball_nearest_axis(point: Any, axes: Any) -> Any:
    """The axis whose arc is nearest ``point``."""
    p = _floats(point)
    nearest = None
    best = -1.0
    for axis in axes:
        t = np.dot(arcball_constrain_to_axis(p, axis), p)
        if t > best:
            nearest = axis
            best = t
    return nearest


class Arcball:
    """A virtual trackball: drags of the pointer as rotations."""

    def __init__(self, initial: Any = None) -> None:
        """Start at ``initial`` (a quaternion or rotation matrix; the identity if None)."""
        self._axis: Any = None
        self._axes: Any = None
        self._radius = 1.0
        self._center = [0.0, 0.0]
        self._vdown = np.array([0, 0, 1], dtype=np.float64)
        self._constrain = False
        if initial is None:
            self._qdown = np.array([0, 0, 0, 1], dtype=np.float64)
        else:
            start = np.array(initial, dtype=np.float64)
            if start.shape == (4, 4):
                self._qdown = quaternion_from_matrix(start)
            elif start.shape == (4,):
                start /= vector_norm(start)
                self._qdown = start
            else:
                raise ValueError("initial not a quaternion or matrix.")
        self._qnow = self._qpre = self._qdown

    def place(self, center: Any, radius: float) -> None:
        """Put the ball at window coordinates ``center`` with ``radius``."""
        self._radius = float(radius)
        self._center[0] = center[0]
        self._center[1] = center[1]

    def setaxes(self, *axes: Any) -> None:
        """The axes rotations may be constrained to."""
        self._axes = None if axes is None else [unit_vector(axis) for axis in axes]

    def setconstrain(self, constrain: Any) -> None:
        """Constrain rotations to the nearest axis, or not."""
        self._constrain = constrain == True  # noqa: E712 - an array's truth, as ROS 1's

    def getconstrain(self) -> bool:
        """Whether rotations are constrained to an axis."""
        return self._constrain

    def down(self, point: Any) -> None:
        """The pointer went down at window coordinates ``point``."""
        self._vdown = arcball_map_to_sphere(point, self._center, self._radius)
        self._qdown = self._qpre = self._qnow
        if self._constrain and self._axes is not None:
            self._axis = arcball_nearest_axis(self._vdown, self._axes)
            self._vdown = arcball_constrain_to_axis(self._vdown, self._axis)
        else:
            self._axis = None

    def drag(self, point: Any) -> None:
        """The pointer moved to ``point`` while down."""
        vnow = arcball_map_to_sphere(point, self._center, self._radius)
        if self._axis is not None:
            vnow = arcball_constrain_to_axis(vnow, self._axis)
        self._qpre = self._qnow
        t = np.cross(self._vdown, vnow)
        if np.dot(t, t) < _EPS:
            self._qnow = self._qdown
        else:
            q = [t[0], t[1], t[2], np.dot(self._vdown, vnow)]
            self._qnow = quaternion_multiply(q, self._qdown)

    def next(self, acceleration: float = 0.0) -> None:
        """Keep rotating as the last drag did."""
        q = quaternion_slerp(self._qpre, self._qnow, 2.0 + acceleration, False)
        self._qpre, self._qnow = self._qnow, q

    def matrix(self) -> Any:
        """The current rotation matrix."""
        return quaternion_matrix(self._qnow)


__all__ = [
    "Arcball",
    "arcball_constrain_to_axis",
    "arcball_map_to_sphere",
    "arcball_nearest_axis",
    "clip_matrix",
    "compose_matrix",
    "concatenate_matrices",
    "decompose_matrix",
    "euler_from_matrix",
    "euler_from_quaternion",
    "euler_matrix",
    "identity_matrix",
    "inverse_matrix",
    "is_same_transform",
    "orthogonalization_matrix",
    "projection_from_matrix",
    "projection_matrix",
    "quaternion_about_axis",
    "quaternion_conjugate",
    "quaternion_from_euler",
    "quaternion_from_matrix",
    "quaternion_inverse",
    "quaternion_matrix",
    "quaternion_multiply",
    "quaternion_slerp",
    "random_quaternion",
    "random_rotation_matrix",
    "random_vector",
    "reflection_from_matrix",
    "reflection_matrix",
    "rotation_from_matrix",
    "rotation_matrix",
    "scale_from_matrix",
    "scale_matrix",
    "shear_from_matrix",
    "shear_matrix",
    "superimposition_matrix",
    "translation_from_matrix",
    "translation_matrix",
    "unit_vector",
    "vector_norm",
]
