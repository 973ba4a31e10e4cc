"""actionlib's exception (``actionlib.exceptions``)."""

from __future__ import annotations


class ActionException(Exception):  # noqa: N818 - actionlib's name
    """An action type or an action's use is wrong (``Type is not an action spec: …``)."""


__all__ = ["ActionException"]
