"""rosbridge's ``png`` compression: a message's JSON text as the pixels of a PNG image.

The text's UTF-8 bytes, padded with newlines, fill an RGB image about as wide as high; its PNG,
in base64, is the ``data`` of a ``{"op": "png"}`` frame (ROSBRIDGE_PROTOCOL.md, 3.1.2), which
roslibjs decodes by drawing the image on a canvas. Pillow is imported when a client asks.
"""

from __future__ import annotations

import base64
import io
import json
import math


def png_frame(text: str) -> str:
    """The ``png`` frame carrying ``text``."""
    from PIL import Image  # noqa: PLC0415 - only png subscriptions pay for Pillow

    data = text.encode()
    pixels = max(1, math.ceil(len(data) / 3))
    width = max(1, math.isqrt(pixels))
    height = math.ceil(pixels / width)
    padded = data + b"\n" * (width * height * 3 - len(data))
    buff = io.BytesIO()
    Image.frombytes("RGB", (width, height), padded).save(buff, "png")
    return json.dumps({"op": "png", "data": base64.b64encode(buff.getvalue()).decode("ascii")})


def png_text(data: str) -> str:
    """The text a ``png`` frame's ``data`` carries (the inverse of `png_frame`)."""
    from PIL import Image  # noqa: PLC0415 - only png subscriptions pay for Pillow

    image = Image.open(io.BytesIO(base64.b64decode(data)))
    return image.tobytes().decode().rstrip("\n")


__all__ = ["png_frame", "png_text"]
