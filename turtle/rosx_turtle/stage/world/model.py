"""The world as the simulator needs it, built from a parsed world file (`Entity` tree).

`build` turns the tree into a `World`: the floor plans and plain obstacles (`Block`), the robots
(`Robot`, Stage's ``position`` models) with their lasers (`Laser`, Stage's ``ranger`` with one
``sensor``, or Stage 3's ``laser``), the world's ``resolution`` and ``interval_sim``. Values
are SI (metres, radians, seconds); poses are ``(x, y, yaw)`` in the world. Stage's defaults
apply where a property is missing.

What rosx reads and ignores on purpose (``window``, the ``gui_*`` look, ``mass``...) passes
silently; anything else it does not simulate (a camera, an unknown property) is listed in
`World.ignored` with ``file:line``, for one warning. No I/O here: bitmaps are named, not read.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from rosx_turtle.stage.world.worldfile import WorldFileError

if TYPE_CHECKING:
    from rosx_turtle.stage.world.worldfile import Entity, Value

Pose = tuple[float, float, float]

#: World properties read, and those accepted without effect.
#: The most beams a laser may cast (real ones cast up to a few thousand); each beam is traced
#: through the grid at every scan.
MAX_SAMPLES = 100_000
#: The longest step or update interval, in seconds: simulated time counts in int64 nanoseconds,
#: which a step of 9e12 ms overflows at once.
MAX_INTERVAL = 3600.0
_WORLD_PROPS = {"resolution", "interval_sim"}
_WORLD_QUIET = {
    "interval_real", "quit_time", "threads", "paused", "speedup", "show_clock",
    "show_clock_interval", "name", "log", "update_interval",
}  # fmt: skip
#: Entities read as a whole and ignored (the GUI's).
_QUIET_ENTITIES = {"window", "gui"}
_MODEL_PROPS = {
    "pose", "size", "origin", "color", "name", "bitmap", "boundary", "obstacle_return",
    "ranger_return", "laser_return", "update_interval",
}  # fmt: skip
_MODEL_QUIET = {
    "gui_nose", "gui_grid", "gui_outline", "gui_move", "gui_boundary", "fiducial_return",
    "fiducial_key", "blob_return", "gripper_return", "visual_return", "mass", "map_resolution",
    "say", "alwayson", "stack_children", "ctrl", "color_rgba", "watts", "watts_give",
    "watts_take", "give_watts", "take_watts", "stall", "block", "blocks", "points", "point",
    "polygons", "polygon", "joules", "joules_capacity", "kjoules", "fiducial_id",
}  # fmt: skip
_POSITION_PROPS = {"drive", "localization", "localization_origin"}
_POSITION_QUIET = {
    "odom_error", "velocity_bounds", "acceleration_bounds", "wheelbase", "velocity",
    "enforce_velocity_bounds", "enforce_acceleration_bounds", "odom",
}  # fmt: skip
_SENSOR_PROPS = {"pose", "size", "range", "fov", "samples", "color", "noise"}
_LASER3_PROPS = {"range_min", "range_max", "fov", "samples", "resolution"}
_DRIVES = ("diff", "omni")
_LOCALIZATIONS = ("gps", "odom")


@dataclass(frozen=True)
class Block:
    """A static obstacle: a box, or a bitmap stretched over ``size`` (a floor plan).

    ``pose`` is the model's; ``origin`` shifts its body (x, y, yaw) in its own frame.
    ``ranger_return`` below zero hides it from lasers; ``obstacle_return`` 0 lets robots
    through. ``bitmap`` is the file name as written (resolved against ``base``'s folder).
    """

    name: str
    pose: Pose
    size: tuple[float, float]
    origin: Pose = (0.0, 0.0, 0.0)
    bitmap: str | None = None
    base: str = ""
    boundary: bool = False
    color: str = "red"
    ranger_return: float = 1.0
    obstacle_return: bool = True


@dataclass(frozen=True)
class Laser:
    """A laser on a robot: ``pose`` in the robot's frame; angles from -fov/2 to +fov/2."""

    name: str
    pose: Pose
    fov: float
    samples: int
    range_min: float
    range_max: float
    interval: float  # seconds between scans
    height: float = 0.1

    @property
    def angle_increment(self) -> float:
        """The angle between two beams (stage_ros: fov / (samples - 1))."""
        return self.fov / (self.samples - 1) if self.samples > 1 else 0.0


@dataclass(frozen=True)
class Robot:
    """A Stage ``position`` model: a box ``size`` whose centre is ``origin`` in its frame."""

    name: str
    token: str
    pose: Pose
    size: tuple[float, float, float]
    origin: Pose = (0.0, 0.0, 0.0)
    drive: str = "diff"
    localization: str = "gps"
    localization_origin: Pose | None = None
    color: str = "red"
    lasers: tuple[Laser, ...] = ()
    interval: float = 0.1
    ranger_return: float = 1.0


@dataclass(frozen=True)
class World:
    """Everything the engine simulates, and what was ignored (``file:line what``)."""

    resolution: float = 0.02
    interval_sim: float = 0.1
    blocks: tuple[Block, ...] = ()
    robots: tuple[Robot, ...] = ()
    ignored: tuple[str, ...] = field(default=())


class _Reader:
    def __init__(self) -> None:
        self.ignored: list[str] = []
        self.count: dict[str, int] = {}

    def ignore(self, where: object, what: str) -> None:
        self.ignored.append(f"{where} {what}")

    def check(self, entity: Entity, known: set[str], quiet: set[str]) -> None:
        for name, value in entity.props.items():
            if name not in known and name not in quiet:
                self.ignore(value.where, f"unknown property '{name}' of {entity.declared}")

    def token(self, entity: Entity) -> str:
        """Stage's model name: ``name`` if given, else ``<type>:<n>`` counting per type."""
        index = self.count.get(entity.declared, 0)
        self.count[entity.declared] = index + 1
        return f"{entity.declared}:{index}"


def _numbers(value: Value, count: int, name: str) -> tuple[float, ...]:
    items = value.items[:count]
    # Finite ones: Stage reads "nan" and "inf" as numbers, and a pose or size of either has
    # no place in a grid.
    if len(items) < count or not all(isinstance(i, float) and math.isfinite(i) for i in items):
        raise WorldFileError(f"{value.where}: '{name}' needs {count} numbers")
    return tuple(float(item) for item in items)


def _number(entity: Entity, name: str, default: float) -> float:
    value = entity.props.get(name)
    return default if value is None else _numbers(value, 1, name)[0]


def _text(entity: Entity, name: str, default: str) -> str:
    value = entity.props.get(name)
    if value is None:
        return default
    if not value.items:
        raise WorldFileError(f"{value.where}: '{name}' has no value")
    return str(value.items[0]) if isinstance(value.items[0], str) else f"{value.items[0]:g}"


def _pose(entity: Entity, name: str = "pose") -> Pose:
    value = entity.props.get(name)
    if value is None:
        return (0.0, 0.0, 0.0)
    if len(value.items) == 3:  # Stage 3's [x y a]
        x, y, a = _numbers(value, 3, name)
    else:
        x, y, _z, a = _numbers(value, 4, name)
    return (x, y, math.radians(a))


def _size(entity: Entity, default: tuple[float, float, float]) -> tuple[float, float, float]:
    value = entity.props.get("size")
    if value is None:
        return default
    if len(value.items) == 2:
        x, y = _numbers(value, 2, "size")
        return (x, y, default[2])
    x, y, z = _numbers(value, 3, "size")
    return (x, y, z)


def _interval(entity: Entity, default: float) -> float:
    interval = _number(entity, "update_interval", default * 1000.0) / 1000.0
    if interval > MAX_INTERVAL:
        where = entity.props["update_interval"].where
        raise WorldFileError(f"{where}: update_interval of more than {MAX_INTERVAL:g} s")
    return interval


def build(root: Entity) -> World:
    """The `World` of a parsed world file.

    Raises:
        WorldFileError: a value has the wrong shape (the message names ``file:line``).
    """
    reader = _Reader()
    reader.check(root, _WORLD_PROPS, _WORLD_QUIET)
    resolution = _number(root, "resolution", 0.02)
    interval = _number(root, "interval_sim", 100.0) / 1000.0
    if resolution <= 0 or interval <= 0:
        raise WorldFileError(f"{root.where}: resolution and interval_sim must be positive")
    if interval > MAX_INTERVAL:
        raise WorldFileError(f"{root.where}: interval_sim of more than {MAX_INTERVAL:g} s")
    blocks: list[Block] = []
    robots: list[Robot] = []
    for entity in root.children:
        _top_model(reader, entity, blocks, robots)
    ignored = tuple(dict.fromkeys(reader.ignored))  # a define's line once, not per instance
    return World(resolution, interval, tuple(blocks), tuple(robots), ignored)


def _top_model(reader: _Reader, entity: Entity, blocks: list[Block], robots: list[Robot]) -> None:
    if entity.kind in _QUIET_ENTITIES:
        return
    if entity.kind == "model":
        reader.check(entity, _MODEL_PROPS, _MODEL_QUIET)
        blocks.append(_block(reader, entity, (0.0, 0.0, 0.0), ""))
        for child in entity.children:  # obstacles inside obstacles: placed in the parent
            _nested_block(reader, child, blocks, entity)
    elif entity.kind == "position":
        robots.append(_robot(reader, entity))
    else:
        reader.ignore(entity.where, f"{entity.declared} (a {entity.kind}: not simulated)")


def _nested_block(reader: _Reader, entity: Entity, blocks: list[Block], parent: Entity) -> None:
    if entity.kind != "model":
        reader.ignore(entity.where, f"{entity.declared} (a {entity.kind} inside a model)")
        return
    reader.check(entity, _MODEL_PROPS, _MODEL_QUIET)
    px, py, pa = _pose(parent)
    x, y, a = _pose(entity)
    world = (
        px + x * math.cos(pa) - y * math.sin(pa),
        py + x * math.sin(pa) + y * math.cos(pa),
        pa + a,
    )
    blocks.append(_block(reader, entity, world, "", placed=True))


def _block(
    reader: _Reader, entity: Entity, pose: Pose, base: str, *, placed: bool = False
) -> Block:
    size = _size(entity, (0.1, 0.1, 0.1))
    bitmap = _text(entity, "bitmap", "") or None
    returns = _number(entity, "ranger_return", _number(entity, "laser_return", 1.0))
    return Block(
        name=_text(entity, "name", "") or reader.token(entity),
        pose=pose if placed else _pose(entity),
        size=(size[0], size[1]),
        origin=_pose(entity, "origin"),
        bitmap=bitmap,
        base=entity.props["bitmap"].where.file if bitmap else base,
        boundary=_number(entity, "boundary", 0.0) != 0,
        color=_text(entity, "color", "red"),
        ranger_return=returns if returns > 0 else -1.0,
        obstacle_return=_number(entity, "obstacle_return", 1.0) != 0,
    )


def _robot(reader: _Reader, entity: Entity) -> Robot:
    reader.check(entity, _MODEL_PROPS | _POSITION_PROPS, _MODEL_QUIET | _POSITION_QUIET)
    token = reader.token(entity)
    drive = _text(entity, "drive", "diff")
    if drive not in _DRIVES:
        reader.ignore(entity.props["drive"].where, f'drive "{drive}" (moved as "diff")')
        drive = "diff"
    localization = _text(entity, "localization", "gps")
    if localization not in _LOCALIZATIONS:
        where = entity.props["localization"].where
        raise WorldFileError(f'{where}: localization "{localization}" is not "gps" or "odom"')
    origin = entity.props.get("localization_origin")
    size = _size(entity, (0.4, 0.4, 1.0))
    lasers: list[Laser] = []
    for child in entity.children:
        if child.kind in ("ranger", "laser"):
            lasers.append(_laser(reader, child, size[2]))
        elif child.kind != "model":
            reader.ignore(child.where, f"{child.declared} (a {child.kind}: not simulated)")
        else:
            reader.check(child, _MODEL_PROPS, _MODEL_QUIET)  # a body part: drawn as the body
    interval = _interval(entity, 0.1)
    return Robot(
        name=_text(entity, "name", ""),
        token=token,
        pose=_pose(entity),
        size=size,
        origin=_pose(entity, "origin"),
        drive=drive,
        localization=localization,
        localization_origin=None if origin is None else _pose(entity, "localization_origin"),
        color=_text(entity, "color", "red"),
        lasers=tuple(lasers),
        interval=interval,
        ranger_return=_number(entity, "ranger_return", 1.0),
    )


def _laser(reader: _Reader, entity: Entity, body_height: float) -> Laser:
    interval = _interval(entity, 0.1)
    if entity.kind == "laser":  # Stage 3's laser model
        reader.check(entity, _MODEL_PROPS | _LASER3_PROPS, _MODEL_QUIET)
        source = entity
        low, high = _number(entity, "range_min", 0.0), _number(entity, "range_max", 8.0)
        fov_default, samples_default = 180.0, 361.0
    else:
        reader.check(entity, _MODEL_PROPS, _MODEL_QUIET)
        sensors = [child for child in entity.children if child.kind == "sensor"]
        for child in entity.children:
            if child.kind != "sensor" or child is not sensors[0]:
                what = "a second sensor" if child.kind == "sensor" else child.declared
                reader.ignore(child.where, f"{what} (stage_ros reads a ranger's first sensor)")
        source = sensors[0] if sensors else entity
        if sensors:
            reader.check(source, _SENSOR_PROPS, set())
        value = source.props.get("range")
        low, high = (0.0, 5.0) if value is None else _numbers(value, 2, "range")
        fov_default, samples_default = math.degrees(0.1), 1.0
    fov = math.radians(_number(source, "fov", fov_default))
    samples = int(_number(source, "samples", samples_default))
    if samples < 1 or high <= low or fov < 0:
        raise WorldFileError(
            f"{source.where}: a laser needs samples >= 1, range min < max and fov >= 0"
        )
    if samples > MAX_SAMPLES:
        raise WorldFileError(f"{source.where}: a laser of more than {MAX_SAMPLES} samples")
    x, y, a = _pose(entity)
    return Laser(
        name=_text(entity, "name", "") or entity.declared,
        pose=(x, y, a),
        fov=fov,
        samples=samples,
        range_min=low,
        range_max=high,
        interval=interval,
        height=body_height,
    )


__all__ = ["Block", "Laser", "Pose", "Robot", "World", "build"]
