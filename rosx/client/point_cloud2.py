"""``sensor_msgs.point_cloud2``: reading and building ``sensor_msgs/PointCloud2`` messages.

ROS 1 ships this helper beside the generated ``sensor_msgs.msg``; scripts import it as
``from sensor_msgs import point_cloud2`` (`rosx.client.modules` serves it under that name).
The functions and their results are ROS 1's:

* `read_points`: the points as tuples, in row order, of all fields or of ``field_names``;
  ``skip_nans`` leaves out points with a NaN; ``uvs`` reads only those (column, row) points.
* `read_points_list`: the same as named tuples ``Point`` (one attribute per field).
* `create_cloud`: an unorganized cloud (``height`` 1, little-endian, not dense) of ``points``,
  each a sequence of values in the order of ``fields``' offsets; `create_cloud_xyz32` with
  fields ``x``, ``y`` and ``z`` as FLOAT32.
"""

from __future__ import annotations

import math
import struct
import sys
from collections import namedtuple
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from collections.abc import Iterable, Iterator, Sequence

#: PointField's datatype numbers: struct's letter and the size in bytes.
_DATATYPES: dict[int, tuple[str, int]] = {
    1: ("b", 1),  # INT8
    2: ("B", 1),  # UINT8
    3: ("h", 2),  # INT16
    4: ("H", 2),  # UINT16
    5: ("i", 4),  # INT32
    6: ("I", 4),  # UINT32
    7: ("f", 4),  # FLOAT32
    8: ("d", 8),  # FLOAT64
}


def _get_struct_fmt(is_bigendian: bool, fields: Sequence[Any], field_names: Any = None) -> str:
    """The `struct` format of one point: the chosen fields by offset, gaps as pad bytes."""
    fmt = ">" if is_bigendian else "<"
    offset = 0
    for field in sorted(fields, key=lambda f: f.offset):
        if field_names is not None and field.name not in field_names:
            continue
        if offset < field.offset:
            fmt += "x" * (field.offset - offset)
            offset = field.offset
        if field.datatype not in _DATATYPES:
            print(f"Skipping unknown PointField datatype [{field.datatype}]", file=sys.stderr)
            continue
        letter, size = _DATATYPES[field.datatype]
        fmt += field.count * letter
        offset += field.count * size
    return fmt


def _check(cloud: Any) -> None:
    if getattr(cloud, "_type", None) != "sensor_msgs/PointCloud2":
        raise AssertionError("cloud is not a sensor_msgs.msg.PointCloud2")


def read_points(
    cloud: Any,
    field_names: Sequence[str] | None = None,
    skip_nans: bool = False,
    uvs: Iterable[tuple[int, int]] = (),
) -> Iterator[tuple[Any, ...]]:
    """Yield the points of ``cloud`` as tuples (see the module's docstring)."""
    _check(cloud)
    unpack_from = struct.Struct(_get_struct_fmt(cloud.is_bigendian, cloud.fields, field_names))
    data = bytes(cloud.data)
    point_step, row_step = cloud.point_step, cloud.row_step
    isnan = math.isnan
    chosen = list(uvs)
    places = (
        ((u, v) for u, v in chosen)
        if chosen
        else ((u, v) for v in range(cloud.height) for u in range(cloud.width))
    )
    for u, v in places:
        point = unpack_from.unpack_from(data, row_step * v + point_step * u)
        if skip_nans and any(isinstance(x, float) and isnan(x) for x in point):
            continue
        yield point


def read_points_list(
    cloud: Any,
    field_names: Sequence[str] | None = None,
    skip_nans: bool = False,
    uvs: Iterable[tuple[int, int]] = (),
) -> list[Any]:
    """The points of ``cloud`` as named tuples ``Point``, one attribute per field."""
    _check(cloud)
    names = list(field_names) if field_names is not None else [f.name for f in cloud.fields]
    point = namedtuple("Point", names)  # type: ignore[misc]
    return [point._make(p) for p in read_points(cloud, field_names, skip_nans, uvs)]


def create_cloud(header: Any, fields: Sequence[Any], points: Iterable[Sequence[Any]]) -> Any:
    """A ``sensor_msgs/PointCloud2`` of ``points`` (see the module's docstring)."""
    from rosx.msg.codec.classes import get_message_class  # noqa: PLC0415 - message classes load on first use

    layout = struct.Struct(_get_struct_fmt(False, fields))
    rows = list(points)
    buffer = bytearray(layout.size * len(rows))
    offset = 0
    for values in rows:
        layout.pack_into(buffer, offset, *values)
        offset += layout.size
    return get_message_class("sensor_msgs/PointCloud2")(
        header=header,
        height=1,
        width=len(rows),
        is_dense=False,
        is_bigendian=False,
        fields=list(fields),
        point_step=layout.size,
        row_step=layout.size * len(rows),
        data=bytes(buffer),
    )


def create_cloud_xyz32(header: Any, points: Iterable[Sequence[float]]) -> Any:
    """A cloud of ``points`` (x, y, z) as FLOAT32 fields ``x``, ``y``, ``z``."""
    from rosx.msg.codec.classes import get_message_class  # noqa: PLC0415 - message classes load on first use

    field = get_message_class("sensor_msgs/PointField")
    fields = [field(name, offset, 7, 1) for name, offset in (("x", 0), ("y", 4), ("z", 8))]
    return create_cloud(header, fields, points)


__all__ = ["create_cloud", "create_cloud_xyz32", "read_points", "read_points_list"]
