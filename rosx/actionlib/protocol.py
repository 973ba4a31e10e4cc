"""What every part of actionlib shares: the messages of ``actionlib_msgs``, the five topics of an
action, and the message types an action's ``XAction`` class implies.

An action named ``ns`` is five topics under it (wiki actionlib/DetailedDescription): ``ns/goal``
(``XActionGoal``) and ``ns/cancel`` (``actionlib_msgs/GoalID``) from clients to the server,
``ns/status`` (``actionlib_msgs/GoalStatusArray``), ``ns/feedback`` (``XActionFeedback``) and
``ns/result`` (``XActionResult``) back.
"""

from __future__ import annotations

from functools import cache
from typing import TYPE_CHECKING, Any, NamedTuple

from rosx.actionlib.exceptions import ActionException
from rosx.client import names

if TYPE_CHECKING:
    from rosx.msg.codec.message import Message


class ActionTypes(NamedTuple):
    """The message classes of one action."""

    action: type[Message]
    goal: type[Message]
    result: type[Message]
    feedback: type[Message]
    result_type: type[Message]


def action_types(spec: Any) -> ActionTypes:
    """The classes ``XActionGoal``, ``XActionResult``, ``XActionFeedback`` and ``XResult`` of the
    ``XAction`` class ``spec``.

    Raises:
        ActionException: ``spec`` is not an action's class (ROS 1's text).
    """
    try:
        sample = spec()
        return ActionTypes(
            spec,
            type(sample.action_goal),
            type(sample.action_result),
            type(sample.action_feedback),
            type(sample.action_result.result),
        )
    except (AttributeError, TypeError):
        raise ActionException(f"Type is not an action spec: {spec}") from None


class _Msgs(NamedTuple):
    GoalID: type[Message]
    GoalStatus: type[Message]
    GoalStatusArray: type[Message]


@cache
def msgs() -> _Msgs:
    """``actionlib_msgs``' classes (GoalID, GoalStatus, GoalStatusArray), loaded on first use."""
    from rosx.msg.codec.classes import get_message_class  # noqa: PLC0415 - the type store

    return _Msgs(*(get_message_class(f"actionlib_msgs/{n}") for n in _Msgs._fields))


def topic(ns: str, name: str) -> str:
    """The topic ``name`` (``goal``, ``status``…) of the action at ``ns``, remapped as rospy's
    actionlib names it."""
    return names.remap_name(ns) + "/" + name


def seconds_of(timeout: Any) -> float:
    """A timeout given as a `Duration`, a number of seconds or None, in seconds (0 and None:
    no limit, as actionlib's ``Duration()`` default)."""
    if timeout is None:
        return 0.0
    to_sec = getattr(timeout, "to_sec", None)
    return float(to_sec() if to_sec is not None else timeout)


__all__ = ["ActionTypes", "action_types", "msgs", "seconds_of", "topic"]
