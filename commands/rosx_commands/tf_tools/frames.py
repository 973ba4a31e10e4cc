"""What ``view_frames`` makes of a tree: ``frames.gv``, then ``frames.pdf`` (or the tree as text).

tf2_tools' ``view_frames.py`` asks its buffer's ``~tf2_frames`` service for the frames as YAML
and writes its own Graphviz text (`tf2_dot`); tf's ``view_frames`` writes tf2's
(``allFramesAsDot``). Both then run Graphviz's ``dot`` for the PDF (`render`). Where ROS 1's
scripts then fail (a traceback when ``dot`` is missing; tf's, on Python 3, even when it is
there), rosx's make the PDF, or say that Graphviz is missing and print the tree as text.
"""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from collections.abc import Mapping
    from typing import TextIO

NO_GRAPHVIZ = (
    "Graphviz's dot is not installed, so frames.pdf was not made "
    "(apt install graphviz, or open frames.gv with any Graphviz viewer); the tree:\n"
)


def read_frames_yaml(text: str) -> dict[str, dict[str, Any]]:
    """The ``~tf2_frames`` answer as a mapping, as view_frames.py's ``yaml.safe_load`` reads it."""
    from ruamel.yaml import YAML  # noqa: PLC0415 - a dependency already; only view_frames

    data = YAML(typ="safe", pure=True).load(text) or {}
    return {str(name): dict(values) for name, values in data.items()}


def tf2_dot(frames: Mapping[str, Mapping[str, Any]], now: float) -> str:
    """tf2_tools' ``generate_dot``: an edge per frame, the legend pointing at the root."""
    if not frames:
        return 'digraph G { "No tf data received" }'
    lines = ["digraph G {\n"]
    root = ""
    for name, values in frames.items():
        lines.append(
            f'"{values["parent"]}" -> "{name}"[label=" '
            f"Broadcaster: {values['broadcaster']}\\n"
            f"Average rate: {values['rate']}\\n"
            f"Buffer length: {values['buffer_length']}\\n"
            f"Most recent transform: {values['most_recent_transform']}\\n"
            f"Oldest transform: {values['oldest_transform']}\\n"
            '"];\n'
        )
        if values["parent"] not in frames:
            root = str(values["parent"])
    lines.append("edge [style=invis];\n")
    lines.append(
        ' subgraph cluster_legend { style=bold; color=black; label ="view_frames Result";\n'
    )
    lines.append(f'"Recorded at time: {now}"[ shape=plaintext ] ;\n')
    lines.append(f'}}->"{root}";\n}}')
    return "".join(lines)


def tree_text(parents: Mapping[str, str]) -> str:
    """The tree of ``child -> parent`` links, drawn with box characters from each root."""
    children: dict[str, list[str]] = {}
    for child, parent in parents.items():
        children.setdefault(parent, []).append(child)
    roots = [p for p in children if p not in parents]
    out: list[str] = []

    def draw(frame: str, prefix: str, last: bool, top: bool) -> None:
        out.append(frame if top else f"{prefix}{'└── ' if last else '├── '}{frame}")
        below = children.get(frame, [])
        for i, child in enumerate(below):
            extend = "" if top else prefix + ("    " if last else "│   ")
            draw(child, extend, i == len(below) - 1, False)

    for root in roots:
        draw(root, "", True, True)
    return "".join(line + "\n" for line in out) if out else "(no frames)\n"


def render(dot: str, parents: Mapping[str, str], out: TextIO, folder: Path | None = None) -> bool:
    """Write ``frames.gv`` and make ``frames.pdf`` with Graphviz; without Graphviz, say so and
    print the tree. True when the PDF was made."""
    where = folder or Path.cwd()
    (where / "frames.gv").write_text(dot, encoding="utf-8")
    dot_program = shutil.which("dot")
    if dot_program is not None:
        done = subprocess.run(
            [dot_program, "-Tpdf", "frames.gv", "-o", "frames.pdf"],
            cwd=where,
            capture_output=True,
            text=True,
            check=False,
        )
        if done.returncode == 0:
            return True
        out.write(f"dot failed: {done.stderr.strip()}\n")
    else:
        out.write(NO_GRAPHVIZ)
    out.write(tree_text(parents))
    out.flush()
    return False


def dot_version() -> str | None:
    """The first line ``dot -V`` prints (``dot - graphviz version 2.42.2 (0)``), if any."""
    dot_program = shutil.which("dot")
    if dot_program is None:
        return None
    done = subprocess.run([dot_program, "-V"], capture_output=True, text=True, check=False)
    return (done.stderr or done.stdout).strip() or None


__all__ = ["NO_GRAPHVIZ", "dot_version", "read_frames_yaml", "render", "tf2_dot", "tree_text"]
