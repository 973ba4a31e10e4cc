"""rviz's ``.rviz`` files read: the displays, the fixed frame, the tools and the 2-D view.

A ``.rviz`` file is YAML. Under ``Visualization Manager``: ``Displays`` (a list of mappings,
each with ``Class`` such as ``rviz/LaserScan``, ``Name``, ``Enabled`` and the display's own
options such as ``Topic``; ``rviz/Group`` holds a ``Displays`` list of its own),
``Global Options`` (``Fixed Frame``, ``Background Color``), ``Tools`` (``Class`` and ``Topic``)
and ``Views`` → ``Current`` (``rviz/TopDownOrtho``: ``X``, ``Y``, ``Scale``, ``Angle``; the
3-D views give a ``Focal Point`` and a ``Distance``). The document is kept as ruamel.yaml's
round-trip tree, so that saving (`rosx_commands.rviz.save`) writes back every key rosx does not
use, as rviz would have written it.

A file that cannot be read or is not such a document raises `ConfigError`, whose text is one
line naming the file as given (and the line where YAML gives one).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

#: rviz's defaults where a config is silent.
DEFAULT_FIXED_FRAME = "map"
DEFAULT_BACKGROUND = (48, 48, 48)
GROUP = "rviz/Group"


class ConfigError(Exception):
    """A config file that cannot be loaded; the text is the one line to print."""


@dataclass
class DisplaySpec:
    """One display of a config: its class, name, whether enabled, and all its keys
    (``options``, the file's own mapping, updated in place when the config is saved)."""

    class_id: str
    name: str
    enabled: bool
    options: Any
    #: The names of the groups holding it, outermost first.
    groups: tuple[str, ...] = ()

    def get(self, key: str, default: Any = None) -> Any:
        """The option ``key`` (``Topic``, ``Color``…), or ``default``."""
        value = self.options.get(key, default) if hasattr(self.options, "get") else default
        return default if value is None else value


@dataclass
class ToolSpec:
    """A tool of the config (``rviz/SetGoal``, ``rviz/SetInitialPose``, ``rviz/PublishPoint``)."""

    class_id: str
    topic: str | None


@dataclass
class ViewSpec:
    """The current view, in rviz's terms: the point looked at, and how far it reaches.

    ``scale`` is rviz's TopDownOrtho ``Scale`` (screen pixels per metre); the 3-D views give
    ``distance`` (metres from the focal point) instead."""

    class_id: str
    x: float = 0.0
    y: float = 0.0
    angle: float = 0.0
    scale: float | None = None
    distance: float | None = None


@dataclass
class RvizConfig:
    """What a ``.rviz`` file says, and its document (``document``) for saving."""

    fixed_frame: str = DEFAULT_FIXED_FRAME
    background: tuple[int, int, int] = DEFAULT_BACKGROUND
    displays: list[DisplaySpec] = field(default_factory=list)
    tools: list[ToolSpec] = field(default_factory=list)
    view: ViewSpec | None = None
    document: Any = None
    source: str | None = None


def yaml() -> Any:
    """ruamel.yaml in round-trip mode, writing block style as rviz does."""
    from ruamel.yaml import YAML  # noqa: PLC0415 - loaded with a config
    from ruamel.yaml.scanner import RoundTripScanner  # noqa: PLC0415 - loaded with a config

    from rosx.msg.text.yamlload import depth_limited  # noqa: PLC0415 - loaded with a config

    loader = YAML(typ="rt")
    loader.Scanner = depth_limited(RoundTripScanner)
    loader.default_flow_style = False
    loader.width = 4096
    return loader


def load_config(path: str) -> RvizConfig:
    """The config in file ``path`` (as the user gave it)."""
    try:
        text = Path(path).read_text(encoding="utf-8")
    except FileNotFoundError:
        raise ConfigError(f"cannot load {path}: no such file") from None
    except IsADirectoryError:
        raise ConfigError(f"cannot load {path}: it is a directory") from None
    except (OSError, UnicodeDecodeError) as error:
        raise ConfigError(
            f"cannot load {path}: {getattr(error, 'strerror', None) or error}"
        ) from None
    config = parse_config(text, path)
    config.source = path
    return config


def parse_config(text: str, name: str) -> RvizConfig:
    """The config in ``text``; ``name`` is how errors name the file."""
    from ruamel.yaml.error import MarkedYAMLError, YAMLError  # noqa: PLC0415 - ruamel loads only on this path

    try:
        document = yaml().load(text)
    except MarkedYAMLError as error:
        mark = error.problem_mark or error.context_mark
        where = f" (line {mark.line + 1})" if mark is not None else ""
        problem = (error.problem or error.context or "invalid YAML").strip()
        raise ConfigError(f"cannot load {name}{where}: {problem}") from None
    except YAMLError as error:
        raise ConfigError(f"cannot load {name}: {str(error).splitlines()[0]}") from None
    except RecursionError:
        raise ConfigError(f"cannot load {name}: nested too deeply") from None
    except (ValueError, LookupError, TypeError, OverflowError) as error:
        # ruamel's round-trip constructor fails so on some scalars (``-_``, ``._``).
        raise ConfigError(f"cannot load {name}: invalid value ({error})") from None
    if not isinstance(document, dict) or not isinstance(
        document.get("Visualization Manager"), dict
    ):
        raise ConfigError(f"cannot load {name}: not an rviz config (no 'Visualization Manager')")
    manager = document["Visualization Manager"]
    config = RvizConfig(document=document)
    options = manager.get("Global Options")
    if isinstance(options, dict):
        frame = options.get("Fixed Frame")
        if isinstance(frame, str) and frame.strip("/"):
            config.fixed_frame = frame.lstrip("/")
        config.background = parse_color(options.get("Background Color"), DEFAULT_BACKGROUND)
    config.displays = _displays(
        manager.get("Displays"), name, (), True, _key_line(manager, "Displays")
    )
    config.tools = _tools(manager.get("Tools"))
    views = manager.get("Views")
    if isinstance(views, dict) and isinstance(views.get("Current"), dict):
        config.view = _view(views["Current"])
    return config


def _line(node: Any) -> str:
    line = getattr(getattr(node, "lc", None), "line", None)
    return f" (line {line + 1})" if isinstance(line, int) else ""


def _key_line(mapping: Any, key: str) -> str:
    try:
        line = mapping.lc.key(key)[0]
    except (AttributeError, KeyError, TypeError):
        return ""
    return f" (line {line + 1})"


def _displays(
    items: Any, name: str, groups: tuple[str, ...], enabled: bool, where: str = ""
) -> list[DisplaySpec]:
    if items is None:
        return []
    if not isinstance(items, list):
        raise ConfigError(f"cannot load {name}{where}: 'Displays' is not a list")
    found: list[DisplaySpec] = []
    for item in items:
        if not isinstance(item, dict) or not isinstance(item.get("Class"), str):
            raise ConfigError(f"cannot load {name}{_line(item)}: a display without a 'Class'")
        on = enabled and _truth(item.get("Enabled", item.get("Value", True)))
        title = str(item.get("Name") or item["Class"].rsplit("/", 1)[-1])
        if item["Class"] == GROUP:
            inner = _displays(
                item.get("Displays"), name, (*groups, title), on, _key_line(item, "Displays")
            )
            found.extend(inner)
            continue
        found.append(DisplaySpec(item["Class"], title, on, item, groups))
    return found


def _truth(value: Any) -> bool:
    if isinstance(value, str):
        return value.strip().lower() in ("true", "1", "yes", "on")
    return bool(value)


def _tools(items: Any) -> list[ToolSpec]:
    if not isinstance(items, list):
        return []
    tools = []
    for item in items:
        if isinstance(item, dict) and isinstance(item.get("Class"), str):
            topic = item.get("Topic")
            tools.append(ToolSpec(item["Class"], str(topic) if topic else None))
    return tools


def _number(value: Any, default: float | None) -> float | None:
    try:
        return float(value)
    except (TypeError, ValueError):
        return default


def _view(current: Any) -> ViewSpec:
    view = ViewSpec(str(current.get("Class", "")))
    focal = current.get("Focal Point")
    if isinstance(focal, dict):
        view.x = _number(focal.get("X"), 0.0) or 0.0
        view.y = _number(focal.get("Y"), 0.0) or 0.0
    else:
        view.x = _number(current.get("X"), 0.0) or 0.0
        view.y = _number(current.get("Y"), 0.0) or 0.0
    view.angle = _number(current.get("Angle"), 0.0) or 0.0
    view.scale = _number(current.get("Scale"), None)
    view.distance = _number(current.get("Distance"), None)
    if view.scale is not None and view.scale <= 0:
        view.scale = None
    if view.distance is not None and view.distance <= 0:
        view.distance = None
    return view


def parse_color(value: Any, default: tuple[int, int, int]) -> tuple[int, int, int]:
    """rviz's ``"R; G; B"`` colour text as a tuple (``default`` for anything else)."""
    if not isinstance(value, str):
        return default
    parts = [part.strip() for part in value.split(";")]
    try:
        red, green, blue = (max(0, min(255, int(float(part)))) for part in parts[:3])
    except (ValueError, OverflowError):  # OverflowError: an infinite component
        return default
    return (red, green, blue)


def format_color(rgb: tuple[int, int, int]) -> str:
    """A colour as rviz writes it: ``"R; G; B"``."""
    return "; ".join(str(part) for part in rgb)


__all__ = [
    "DEFAULT_BACKGROUND",
    "DEFAULT_FIXED_FRAME",
    "ConfigError",
    "DisplaySpec",
    "RvizConfig",
    "ToolSpec",
    "ViewSpec",
    "format_color",
    "load_config",
    "parse_color",
    "parse_config",
    "yaml",
]
