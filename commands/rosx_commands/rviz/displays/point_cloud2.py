"""rviz's PointCloud2: a ``sensor_msgs/PointCloud2`` projected on the plane.

The fields ``x``, ``y``, ``z`` (and ``rgb``/``rgba``, ``intensity`` or the ``Channel Name``)
are read as one numpy view of the data (rows padded to ``row_step`` allowed, either byte
order); points with a coordinate that is not finite are dropped, as rviz drops them.
"""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING, Any

import numpy as np  # noqa: TID253 - rviz's model is array work; only rviz imports it

from rosx.tf.stamps import nanos
from rosx_commands.rviz.displays.clouds import Cloud, CloudDisplay
from rosx_commands.rviz.frames import clean

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    import numpy.typing as npt

#: sensor_msgs/PointField's datatypes as numpy's.
DATATYPES = {1: "i1", 2: "u1", 3: "i2", 4: "u2", 5: "i4", 6: "u4", 7: "f4", 8: "f8"}


class CloudError(ValueError):
    """A cloud whose fields cannot be read; the text is rviz's status."""


def cloud_arrays(
    msg: Any, channel: str = "intensity"
) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64] | None, npt.NDArray[np.uint8] | None]:
    """The finite points (``(n, 3)``), the ``channel`` values and the ``rgb`` colours."""
    fields = {f.name: f for f in msg.fields if f.datatype in DATATYPES}
    if not {"x", "y", "z"} <= fields.keys():
        raise CloudError("PointCloud2 message has no x, y and z fields")
    order = ">" if msg.is_bigendian else "<"
    step, width, height = int(msg.point_step), int(msg.width), int(msg.height)
    wanted = [name for name in ("x", "y", "z", channel, "rgb", "rgba") if name in fields]
    wanted = list(dict.fromkeys(wanted))
    dtype = np.dtype(
        {
            "names": wanted,
            "formats": [order + DATATYPES[fields[name].datatype] for name in wanted],
            "offsets": [int(fields[name].offset) for name in wanted],
            "itemsize": step,
        }
    )
    data = msg.data if isinstance(msg.data, (bytes, bytearray, memoryview)) else bytes(msg.data)
    row_step = int(msg.row_step) or width * step
    if step <= 0 or len(data) < row_step * (height - 1) + width * step:
        raise CloudError(
            f"Data size ({len(data)} bytes) does not match width ({width}) times height "
            f"({height}) times point_step ({step}).  Dropping message."
        )
    if row_step == width * step:
        points = np.frombuffer(data, dtype, count=width * height)
    else:  # rows padded: keep each row's points, then read them as one array
        raw = np.frombuffer(data, np.uint8)
        kept = [raw[r * row_step : r * row_step + width * step] for r in range(height)]
        points = np.frombuffer(np.concatenate(kept).tobytes(), dtype)
    xyz = np.column_stack([points["x"], points["y"], points["z"]]).astype(np.float64)
    finite = np.isfinite(xyz).all(axis=1)
    xyz = xyz[finite]
    values = points[channel].astype(np.float64)[finite] if channel in fields else None
    rgb = None
    colour_field = "rgb" if "rgb" in fields else "rgba" if "rgba" in fields else None
    if colour_field is not None:
        packed = np.ascontiguousarray(points[colour_field][finite]).view(np.uint32)
        rgb = np.stack([(packed >> 16) & 0xFF, (packed >> 8) & 0xFF, packed & 0xFF], axis=1)
        rgb = rgb.astype(np.uint8)
    return xyz, values, rgb


class PointCloud2(CloudDisplay):
    """rviz's PointCloud2 display: the points of the latest clouds."""

    CLASSES = ("rviz/PointCloud2",)
    MESSAGE_TYPE = "sensor_msgs/PointCloud2"

    @override
    def take(self, msg: Any, now: float) -> None:
        channel = str(self.option("Channel Name", "intensity") or "intensity")
        try:
            xyz, values, rgb = cloud_arrays(msg, channel)
        except CloudError as error:
            self.statuses.error("Message", str(error))
            return
        self.statuses.delete("Message")
        header = msg.header
        self.keep(Cloud(clean(header.frame_id), nanos(header.stamp), now, xyz, values, rgb), now)
