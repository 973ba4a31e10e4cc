"""tf2's descriptions of a buffer's frames: ``allFramesAsYAML`` and ``_allFramesAsDot``.

The YAML is what the ``~tf2_frames`` service answers (and view_frames.py reads); the dot text
is what tf2's core writes for tools. Both print numbers with three decimals and the frame
rate as tf2 figures it: the transforms held over the seconds they span.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from rosx.tf import stamps

if TYPE_CHECKING:
    from collections.abc import Sequence

    from rosx.tf.core import FrameInfo


def rate(frame: FrameInfo) -> float:
    """tf2's average rate of ``frame``: transforms held over their span (at least 0.1 ms)."""
    return frame.length / max(stamps.to_sec(frame.newest) - stamps.to_sec(frame.oldest), 0.0001)


def frames_yaml(frames: Sequence[FrameInfo], current_time: float = 0.0) -> str:
    """tf2's ``allFramesAsYAML``: a mapping per frame with data; ``{}`` for no frame at all."""
    if not frames:
        return "{}"
    out = []
    for frame in frames:
        if not frame.parent:
            continue
        newest = stamps.to_sec(frame.newest)
        out.append(
            f"{frame.name}: \n"
            f"  parent: '{frame.parent}'\n"
            f"  broadcaster: '{frame.authority}'\n"
            f"  rate: {rate(frame):.3f}\n"
            f"  most_recent_transform: {newest:.3f}\n"
            f"  oldest_transform: {stamps.to_sec(frame.oldest):.3f}\n"
        )
        if current_time > 0:
            out.append(f"  transform_delay: {current_time - newest:.3f}\n")
        out.append(f"  buffer_length: {stamps.to_sec(frame.newest - frame.oldest):.3f}\n")
    return "".join(out)


def _legend(name: str, current_time: float) -> str:
    recorded = ""
    if current_time > 0:
        recorded = f'"Recorded at time: {current_time:.3f}"[ shape=plaintext ] ;\n '

    return (
        "edge [style=invis];\n"
        ' subgraph cluster_legend { style=bold; color=black; label ="view_frames Result";\n'
        f'{recorded}}}->"{name}";\n'
    )


def frames_dot(frames: Sequence[FrameInfo], current_time: float = 0.0) -> str:
    """tf2's ``_allFramesAsDot``: an edge per frame with data, labelled with its broadcaster,
    rate, newest transform and buffer length, and the legend pointing at the roots."""
    out = ["digraph G {\n"]
    if not frames:
        out.append('"no tf data recieved"')
    for frame in frames:
        if not frame.parent:
            continue
        newest = stamps.to_sec(frame.newest)
        age = f"( {current_time - newest:.3f} sec old)" if current_time > 0 else ""
        out.append(
            f'"{frame.parent}" -> "{frame.name}"[label="Broadcaster: {frame.authority}\\n'
            f"Average rate: {rate(frame):.3f} Hz\\n"
            f"Most recent transform: {newest:.3f} {age}\\n"
            f"Buffer length: {stamps.to_sec(frame.newest - frame.oldest):.3f} sec\\n"
            '"];\n'
        )
    for frame in frames:
        if frame.parent is None:
            if current_time > 0:
                out.append(_legend(frame.name, current_time))
        elif not frame.parent:
            out.append(_legend(frame.name, current_time))
    out.append("}")
    return "".join(out)


__all__ = ["frames_dot", "frames_yaml", "rate"]
