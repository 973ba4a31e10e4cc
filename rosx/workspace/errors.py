"""The error of a workspace build."""

from __future__ import annotations


class BuildError(Exception):
    """The workspace cannot be built; ``str()`` says what is wrong and where."""


__all__ = ["BuildError"]
