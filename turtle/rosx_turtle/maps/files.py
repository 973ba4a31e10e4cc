"""map_server's file conventions, without I/O: the YAML description, pixels → occupancy, and
what map_saver writes.

The YAML names ``image`` (relative to the YAML's folder), ``resolution`` (m/pixel),
``origin`` ([x, y, yaw] of the lower-left pixel), ``negate``, ``occupied_thresh``,
``free_thresh`` and optionally ``mode`` (``trinary``, the default, ``scale`` or ``raw``).
A pixel's channels are averaged (alpha left out, except in trinary mode); with
``p = (255 - average) / 255`` (after ``negate``), ``p > occupied_thresh`` is 100,
``p < free_thresh`` is 0, and in between -1 (trinary, or a transparent pixel) or a value
scaled from 1 to 99; ``raw`` keeps the average. The grid's first row is the image's last.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    import numpy as np
    import numpy.typing as npt

MODES = ("trinary", "scale", "raw")


class MapFileError(ValueError):
    """A map description map_server refuses, with its ROS_ERROR text."""


@dataclass(frozen=True)
class MapSpec:
    """A map's description, as its YAML gives it."""

    image: str
    resolution: float
    origin: tuple[float, float, float]
    negate: bool = False
    occupied_thresh: float = 0.65
    free_thresh: float = 0.196
    mode: str = "trinary"


def _number(doc: dict[str, Any], key: str, message: str) -> float:
    value = doc.get(key)
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise MapFileError(message)
    return float(value)


def _yaml_error(exc: Exception) -> str:
    """A YAML error on one line, where it is as yaml-cpp says it (``yaml-cpp: error at line L,
    column C: PROBLEM``)."""
    mark = getattr(exc, "problem_mark", None)
    problem = " ".join(str(getattr(exc, "problem", None) or exc).split())
    if mark is None:
        return f"yaml-cpp: error: {problem}"
    return f"yaml-cpp: error at line {mark.line + 1}, column {mark.column + 1}: {problem}"


def parse_map_yaml(text: str) -> MapSpec:
    """The map described by ``text``.

    Raises:
        MapFileError: a tag is missing or invalid (map_server's words).
    """
    from ruamel.yaml import YAML  # noqa: PLC0415 - only to read a map
    from ruamel.yaml.error import YAMLError  # noqa: PLC0415 - ruamel loads only on this path

    try:
        doc = YAML(typ="safe", pure=True).load(text)
    except YAMLError as exc:
        raise MapFileError(f"map_server exception: {_yaml_error(exc)}") from None
    if not isinstance(doc, dict):
        raise MapFileError("The map does not contain a resolution tag or it is invalid.")
    resolution = _number(
        doc, "resolution", "The map does not contain a resolution tag or it is invalid."
    )
    negate = _number(doc, "negate", "The map does not contain a negate tag or it is invalid.")
    occupied = _number(
        doc, "occupied_thresh", "The map does not contain an occupied_thresh tag or it is invalid."
    )
    free = _number(
        doc, "free_thresh", "The map does not contain a free_thresh tag or it is invalid."
    )
    mode = doc.get("mode", "trinary")
    if mode not in MODES:
        raise MapFileError(f'Invalid mode tag "{mode}".')
    origin = doc.get("origin")
    if (
        not isinstance(origin, list)
        or len(origin) < 3
        or not all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in origin[:3])
    ):
        raise MapFileError("The map does not contain an origin tag or it is invalid.")
    image = doc.get("image")
    if not isinstance(image, str):
        raise MapFileError("The map does not contain an image tag or it is invalid.")
    if not image:
        raise MapFileError("The image tag cannot be an empty string.")
    return MapSpec(
        image,
        resolution,
        (float(origin[0]), float(origin[1]), float(origin[2])),
        bool(negate),
        occupied,
        free,
        mode,
    )


def occupancy(pixels: npt.NDArray[np.uint8], spec: MapSpec) -> npt.NDArray[np.int8]:
    """The OccupancyGrid data of an image ``pixels`` (rows, columns, channels), as rows from
    the bottom of the image up (see the module docstring)."""
    import numpy as np  # numpy only on this path

    channels = pixels.shape[2]
    alpha_last = channels in (2, 4)
    averaged = channels - 1 if alpha_last and spec.mode != "trinary" else channels
    colour = pixels[:, :, :averaged].astype(np.float64).sum(axis=2) / averaged
    opaque = pixels[:, :, -1] >= 1 if channels > 1 else np.ones(colour.shape, dtype=np.bool_)
    if spec.negate:
        colour = 255 - colour
    if spec.mode == "raw":
        value = colour.astype(np.uint8).astype(np.int8)
    else:
        occ = (255 - colour) / 255.0
        between = (occ - spec.free_thresh) / (spec.occupied_thresh - spec.free_thresh)
        scaled = (1 + 98 * between).astype(np.int64)
        unknown = (spec.mode == "trinary") | ~opaque
        value = np.where(
            occ > spec.occupied_thresh,
            100,
            np.where(occ < spec.free_thresh, 0, np.where(unknown, -1, scaled)),
        ).astype(np.int8)
    flipped: npt.NDArray[np.int8] = value[::-1]
    return flipped


def saved_pgm(
    data: npt.NDArray[np.int8],
    width: int,
    height: int,
    resolution: float,
    occupied: int = 65,
    free: int = 25,
) -> bytes:
    """map_saver's image of an OccupancyGrid: free 254, occupied 0, unknown 205."""
    import numpy as np  # numpy only on this path

    grid = data.reshape(height, width)[::-1].astype(np.int16)
    pixels = np.where((grid >= 0) & (grid <= free), 254, np.where(grid >= occupied, 0, 205)).astype(
        np.uint8
    )
    head = f"P5\n# CREATOR: map_saver.cpp {resolution:.3f} m/pix\n{width} {height}\n255\n"
    return head.encode() + pixels.tobytes()


def saved_yaml(image: str, resolution: float, x: float, y: float, yaw: float) -> str:
    """map_saver's description of the image it wrote."""
    return (
        f"image: {image}\nresolution: {resolution:f}\norigin: [{x:f}, {y:f}, {yaw:f}]\n"
        "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n\n"
    )


__all__ = [
    "MODES",
    "MapFileError",
    "MapSpec",
    "occupancy",
    "parse_map_yaml",
    "saved_pgm",
    "saved_yaml",
]
