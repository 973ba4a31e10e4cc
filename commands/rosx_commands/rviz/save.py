"""Saving the displays to a ``.rviz`` file rviz itself reads.

The document a config was loaded from is written back with what changed here: each display's
``Enabled`` (and ``Value``, the same flag in rviz's tree), the fixed frame, and, when the view
was moved, a ``rviz/TopDownOrtho`` current view (``X``, ``Y``, ``Scale``, ``Angle``, ``Target
Frame``). Every other key, including displays and panels rosx does not draw, is kept as it
was. Without a loaded document, a new one is made in rviz's layout (``Panels``,
``Visualization Manager`` with ``Displays``, ``Global Options``, ``Tools``, ``Views``).
"""

from __future__ import annotations

import io
from pathlib import Path
from typing import TYPE_CHECKING, Any

from rosx_commands.rviz.config import format_color, yaml

if TYPE_CHECKING:
    from rosx_commands.rviz.config import RvizConfig
    from rosx_commands.rviz.manager import Manager
    from rosx_commands.rviz.tools import Tool
    from rosx_commands.rviz.view import View


def new_document(background: tuple[int, int, int], tools: tuple[Tool, ...]) -> Any:
    """An empty config in rviz's layout."""
    from ruamel.yaml.comments import CommentedMap, CommentedSeq  # noqa: PLC0415 - ruamel loads only on this path

    document = CommentedMap()
    panels = CommentedSeq()
    panels.append(CommentedMap([("Class", "rviz/Displays"), ("Name", "Displays")]))
    panels.append(CommentedMap([("Class", "rviz/Views"), ("Name", "Views")]))
    document["Panels"] = panels
    manager = CommentedMap()
    manager["Class"] = ""
    manager["Displays"] = CommentedSeq()
    manager["Enabled"] = True
    manager["Global Options"] = CommentedMap(
        [("Background Color", format_color(background)), ("Fixed Frame", "map"), ("Frame Rate", 30)]
    )
    manager["Name"] = "root"
    tool_list = CommentedSeq()
    tool_list.append(CommentedMap([("Class", "rviz/MoveCamera")]))
    for tool in tools:
        tool_list.append(CommentedMap([("Class", tool.class_id), ("Topic", tool.topic)]))
    manager["Tools"] = tool_list
    manager["Value"] = True
    manager["Views"] = CommentedMap([("Current", CommentedMap()), ("Saved", None)])
    document["Visualization Manager"] = manager
    return document


def _view_map(view: View, target: str | None) -> Any:
    from ruamel.yaml.comments import CommentedMap  # noqa: PLC0415 - ruamel loads only on this path

    return CommentedMap(
        [
            ("Angle", round(view.angle, 6)),
            ("Class", "rviz/TopDownOrtho"),
            ("Enable Stereo Rendering", CommentedMap(
                [("Stereo Eye Separation", 0.06), ("Stereo Focal Distance", 1),
                 ("Swap Stereo Eyes", False), ("Value", False)]
            )),
            ("Invert Z Axis", False),
            ("Name", "Current View"),
            ("Near Clip Distance", 0.01),
            ("Scale", round(view.rviz_scale, 6)),
            ("Target Frame", target or "<Fixed Frame>"),
            ("X", round(view.x, 6)),
            ("Y", round(view.y, 6)),
        ]
    )  # fmt: skip


def config_text(
    config: RvizConfig,
    manager: Manager,
    view: View,
    tools: tuple[Tool, ...],
    target: str | None = None,
) -> str:
    """The config as it is now, as YAML text."""
    from ruamel.yaml.comments import CommentedMap  # noqa: PLC0415 - ruamel loads only on this path

    document = config.document
    if document is None:
        document = config.document = new_document(config.background, tools)
    root = document["Visualization Manager"]
    displays = root.setdefault("Displays", [])
    with manager.lock:
        for display in manager.displays:
            options = display.spec.options
            if not isinstance(options, dict):
                continue
            if "Class" not in options:  # added here: put it in the file
                options["Class"] = display.class_id
                options["Name"] = display.name
                if display.topic:
                    options[display.TOPIC_KEY] = display.topic
                displays.append(options)
            options["Enabled"] = display.enabled
            options["Value"] = display.enabled
        fixed = manager.fixed_frame
    options = root.setdefault("Global Options", CommentedMap())
    options["Fixed Frame"] = fixed
    views = root.setdefault("Views", CommentedMap())
    current = views.get("Current") if isinstance(views, dict) else None
    if (
        view.moved
        or not isinstance(current, dict)
        or "Ortho" in str(current.get("Class", ""))
        or not current
    ):
        views["Current"] = _view_map(view, target)
    stream = io.StringIO()
    yaml().dump(document, stream)
    return stream.getvalue()


def save_config(
    path: Path,
    config: RvizConfig,
    manager: Manager,
    view: View,
    tools: tuple[Tool, ...],
    target: str | None = None,
) -> None:
    """Write the config to ``path`` (its folder made if needed)."""
    text = config_text(config, manager, view, tools, target)
    path.parent.mkdir(parents=True, exist_ok=True)
    Path(path).write_text(text, encoding="utf-8")


__all__ = ["config_text", "new_document", "save_config"]
