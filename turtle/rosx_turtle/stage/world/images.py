"""Grey images for floor plans and maps: PGM read and written here, PNG and others via Pillow.

`read_grey` gives an image as a (rows, columns) uint8 array, top row first, as the file stores
it; colour images keep their first channel, as Stage tests the first channel of a pixel (and
map_server averages the channels: `read_channels` gives all of them). PGM (``P2``/``P5``, 8 or
16 bits) needs nothing; other formats load Pillow when first used.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    import numpy as np
    import numpy.typing as npt

_HEADER_FIELD = re.compile(rb"\s*(?:#[^\n]*\n\s*)*(\S+)")


class ImageError(ValueError):
    """An image that cannot be read; the message names the file. ``missing``: the file could
    not be opened at all (else it is not an image rosx reads)."""

    def __init__(self, message: str, *, missing: bool = False) -> None:
        super().__init__(message)
        self.missing = missing


def parse_pgm(data: bytes, name: str = "image") -> npt.NDArray[np.uint8]:
    """The pixels of a binary (P5) or text (P2) PGM file, scaled to 8 bits.

    Raises:
        ImageError: ``data`` is not a PGM image.
    """
    import numpy as np  # numpy only on this path

    fields: list[bytes] = []
    at = 0
    for _ in range(4):
        match = _HEADER_FIELD.match(data, at)
        if match is None:
            raise ImageError(f"{name}: not a PGM image (its header is cut short)")
        fields.append(match.group(1))
        at = match.end()
    magic, *numbers = fields
    if magic not in (b"P2", b"P5") or not all(n.isdigit() for n in numbers):
        raise ImageError(f"{name}: not a PGM image")
    width, height, maxval = (int(n) for n in numbers)
    if not (0 < maxval < 65536) or width <= 0 or height <= 0:
        raise ImageError(f"{name}: a PGM image of {width}x{height} pixels up to {maxval}")
    count = width * height
    if magic == b"P5":
        dtype = np.dtype(">u2") if maxval > 255 else np.dtype(np.uint8)
        body = data[at + 1 : at + 1 + count * dtype.itemsize]
        if len(body) < count * dtype.itemsize:
            raise ImageError(f"{name}: the PGM image is cut short")
        pixels = np.frombuffer(body, dtype=dtype).astype(np.uint32)
    else:
        values = data[at:].split()
        if len(values) < count:
            raise ImageError(f"{name}: the PGM image is cut short")
        pixels = np.array([int(v) for v in values[:count]], dtype=np.uint32)
    if maxval != 255:
        pixels = (pixels * 255 + maxval // 2) // maxval
    return np.minimum(pixels, 255).astype(np.uint8).reshape(height, width)


def format_pgm(pixels: npt.NDArray[np.uint8], comment: str = "") -> bytes:
    """A binary (P5) PGM file of ``pixels``, with an optional comment line."""
    height, width = pixels.shape
    head = b"P5\n" + (f"# {comment}\n".encode() if comment else b"")
    return head + f"{width} {height}\n255\n".encode() + pixels.astype("u1").tobytes()


def read_channels(path: Path) -> npt.NDArray[np.uint8]:
    """The image at ``path`` as (rows, columns, channels) uint8, alpha last if it has one.

    Raises:
        ImageError: the file cannot be read or is not an image.
    """
    try:
        data = path.read_bytes()
    except OSError as exc:
        raise ImageError(f"{path}: {exc.strerror or exc}", missing=True) from None
    if data[:2] in (b"P2", b"P5"):
        return parse_pgm(data, str(path))[:, :, None]
    try:
        from PIL import Image  # noqa: PLC0415 - Pillow only for formats other than PGM
    except ImportError:
        raise ImageError(f"{path}: reading this image needs Pillow (pip install pillow)") from None
    import io  # noqa: PLC0415 - io is not needed at start-up

    import numpy as np  # numpy only on this path

    try:
        with Image.open(io.BytesIO(data)) as image:
            mode = image.mode
            if mode in ("1", "L", "P", "I", "I;16", "F"):
                converted = image.convert("L")
            elif mode in ("LA", "PA"):
                converted = image.convert("LA")
            else:
                converted = image.convert("RGBA" if "A" in mode else "RGB")
            pixels = np.asarray(converted, dtype=np.uint8)
    except (OSError, ValueError):
        raise ImageError(f"{path}: not an image Pillow can read") from None
    return pixels if pixels.ndim == 3 else pixels[:, :, None]


def read_grey(path: Path) -> npt.NDArray[np.uint8]:
    """The first channel of the image at ``path`` (see the module docstring).

    Raises:
        ImageError: the file cannot be read or is not an image.
    """
    return read_channels(path)[:, :, 0]


__all__ = ["ImageError", "format_pgm", "parse_pgm", "read_channels", "read_grey"]
