"""rviz's Image: the latest ``sensor_msgs/Image`` of its ``Image Topic``, shown in a pane of
its own (`rosx_commands.rviz.image_pane`), not on the view.

Images become RGB arrays: ``rgb8``, ``rgba8``, ``bgr8``, ``bgra8``, ``mono8``/``8UC1``,
``8UC3`` (as bgr8), and ``mono16``/``16UC1``/``32FC1`` stretched between their own lowest and
highest values (rviz's ``Normalize Range``), or ``Min Value``…``Max Value`` when it is off.
"""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING, Any

import numpy as np  # noqa: TID253 - rviz's model is array work; only rviz imports it

from rosx_commands.rviz.displays.base import Display

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    import numpy.typing as npt

CHANNELS = {"rgb8": 3, "rgba8": 4, "bgr8": 3, "bgra8": 4, "8UC3": 3, "mono8": 1, "8UC1": 1}
WIDE = {"mono16": "u2", "16UC1": "u2", "32FC1": "f4"}


class ImageError(ValueError):
    """An image that cannot be shown; the text is the display's status."""


def to_rgb(
    msg: Any, normalize: bool = True, low: float = 0.0, high: float = 1.0
) -> npt.NDArray[np.uint8]:
    """The image as ``(height, width, 3)`` bytes."""
    height, width, step = int(msg.height), int(msg.width), int(msg.step)
    encoding = str(msg.encoding)
    data = msg.data if isinstance(msg.data, (bytes, bytearray, memoryview)) else bytes(msg.data)
    if encoding in CHANNELS:
        channels, dtype = CHANNELS[encoding], np.dtype(np.uint8)
    elif encoding in WIDE:
        channels = 1
        dtype = np.dtype(WIDE[encoding]).newbyteorder(">" if msg.is_bigendian else "<")
    else:
        raise ImageError(f"Unsupported image encoding [{encoding}]")
    row = width * channels * dtype.itemsize
    if height * width == 0 or step < row or len(data) < step * (height - 1) + row:
        raise ImageError(f"Image data size ({len(data)}) too small for {width}x{height} {encoding}")
    rows = np.frombuffer(data, np.uint8, count=step * (height - 1) + row)
    rows = np.lib.stride_tricks.as_strided(rows, (height, row), (step, 1))
    pixels = np.ascontiguousarray(rows).view(dtype).reshape(height, width, channels)
    if encoding in WIDE:
        values = pixels[..., 0].astype(np.float64)
        finite = np.isfinite(values)
        if normalize and finite.any():
            low, high = float(values[finite].min()), float(values[finite].max())
        span = high - low or 1.0
        grey = np.clip((np.where(finite, values, low) - low) / span, 0.0, 1.0) * 255
        pixels = np.rint(grey).astype(np.uint8)[..., None]
    if pixels.shape[2] == 1:
        return np.repeat(pixels, 3, axis=2)
    if encoding.startswith("bgr") or encoding == "8UC3":
        return np.ascontiguousarray(pixels[..., 2::-1])
    return np.ascontiguousarray(pixels[..., :3])


class Image(Display):
    """rviz's Image display: the latest image of a topic."""

    CLASSES = ("rviz/Image",)
    MESSAGE_TYPE = "sensor_msgs/Image"
    TOPIC_KEY = "Image Topic"

    @override
    def clear(self) -> None:
        self.image: npt.NDArray[np.uint8] | None = None
        if self.topic:
            self.statuses.warn("Image", "No Image received")

    @override
    def take(self, msg: Any, now: float) -> None:
        try:
            self.image = to_rgb(
                msg,
                self.flag("Normalize Range", True),
                self.number("Min Value", 0.0),
                self.number("Max Value", 1.0),
            )
        except ImageError as error:
            self.statuses.error("Image", str(error))
            return
        self.statuses.ok("Image", f"{self.messages} images received")

    @property
    @override
    def summary(self) -> str:
        text = super().summary
        if text == "OK" and self.image is not None:
            height, width = self.image.shape[:2]
            return f"OK ({width}x{height})"
        return text
