"""Frames into the fixed frame: what every display asks tf, and rviz's words when it cannot.

rviz transforms each message from its ``header.frame_id`` at its ``header.stamp`` into the
fixed frame. `FixedFrame` asks a tf2 buffer core (`rosx.tf.core.BufferCore`, through its
public ``lookup``) the same, with one difference a terminal needs: when tf has not yet got the
message's time (or has already dropped it), the latest transform serves instead of the message
waiting or being thrown away, so a slow terminal still draws. A frame tf does not connect to
the fixed frame gives rviz's status text, ``No transform from [F] to [FIXED]``.

Answers are kept until tf changes (the core's ``version``), so many displays asking about
the same frames in one frame drawn cost one lookup each.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from rosx_commands.rviz.geometry import IDENTITY
from rosx_commands.rviz.status import no_transform

if TYPE_CHECKING:
    from rosx.tf.core import BufferCore
    from rosx_commands.rviz.geometry import Transform


def clean(frame: str) -> str:
    """A frame id as tf2 keeps it (rviz strips the leading slash of ROS 1's old names)."""
    return frame[1:] if frame.startswith("/") else frame


class FixedFrame:
    """Transforms into ``fixed`` from ``core``'s frames (see the module docstring)."""

    def __init__(self, core: BufferCore, fixed: str) -> None:
        self.core = core
        self.fixed = clean(fixed)
        self._version = -1
        self._answers: dict[tuple[str, int], Transform | str] = {}

    def set_fixed(self, fixed: str) -> None:
        """Make ``fixed`` the fixed frame (a leading slash dropped); cached answers are
        forgotten."""
        self.fixed = clean(fixed)
        self._answers.clear()

    @property
    def version(self) -> int:
        """Changes whenever tf got a transform (what cached drawings depend on)."""
        return self.core.version

    def lookup(self, frame: str, stamp: int = 0) -> Transform | str:
        """The transform taking data in ``frame`` at ``stamp`` (ns; 0 the latest) into the
        fixed frame, or rviz's text saying why there is none."""
        from rosx.tf.exceptions import ExtrapolationException, TransformException  # noqa: PLC0415 - tf code loads only when used

        frame = clean(frame)
        if frame == self.fixed:
            return IDENTITY
        if self._version != self.core.version:
            self._version = self.core.version
            self._answers.clear()
        key = (frame, stamp)
        found = self._answers.get(key)
        if found is not None:
            return found
        answer: Transform | str
        try:
            answer = self.core.lookup(self.fixed, frame, stamp)[1] if frame else ""
        except ExtrapolationException:
            try:
                answer = self.core.lookup(self.fixed, frame, 0)[1]
            except TransformException:
                answer = ""
        except TransformException:
            answer = ""
        if answer == "":
            answer = no_transform(frame, self.fixed)
        self._answers[key] = answer
        return answer

    def frames(self) -> list[str]:
        """Every frame tf knows."""
        return self.core.frame_names()

    def parent(self, frame: str) -> str | None:
        """``frame``'s parent in tf's tree, or None for a root or an unknown frame."""
        return self.core.parent_of(frame)

    def exists(self, frame: str) -> bool:
        """Whether tf has heard of ``frame`` (a leading slash ignored)."""
        return self.core.frame_exists(clean(frame))


__all__ = ["FixedFrame", "clean"]
