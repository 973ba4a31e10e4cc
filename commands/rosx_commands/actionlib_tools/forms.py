"""What axclient and axserver show and read, without a screen: an action's message types, a
message as YAML text and back, and the words and colours of a goal's status.

A message is shown as ``rostopic echo`` prints it (ROS 1's tools show it in genpy's YAML) and
read back from YAML as ``rostopic pub`` reads its argument: a mapping of field names, where a
field left out keeps its default.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, NamedTuple

if TYPE_CHECKING:
    from rosx.msg.codec.message import Message


class ActionTypes(NamedTuple):
    """An action's name (``pkg/Name``) and the classes of its ``XAction``, ``XGoal``,
    ``XFeedback`` and ``XResult``."""

    name: str
    action: type[Message]
    goal: type[Message]
    feedback: type[Message]
    result: type[Message]


class FormError(ValueError):
    """A text is not a message of the type wanted; the message says why, in one line."""


def action_types(action_type: str) -> ActionTypes:
    """The types of the action ``action_type`` (``pkg/NameAction``; ``pkg/Name`` also does).

    Raises:
        FormError: a type cannot be loaded (ROS 1's ``Could not load message for: …``).
    """
    from rosx.msg.codec.classes import get_message_class  # noqa: PLC0415 - the type store
    from rosx.msg.store import UnknownTypeError  # noqa: PLC0415 - as the classes

    name = action_type[: -len("Action")] if action_type.endswith("Action") else action_type
    classes = []
    for part in ("Action", "Goal", "Feedback", "Result"):
        try:
            classes.append(get_message_class(name + part))
        except (UnknownTypeError, ValueError):
            raise FormError(f"Could not load message for: {name + part}") from None
    return ActionTypes(name, *classes)


def to_yaml(msg: object) -> str:
    """``msg`` as the text of the editor: ``rostopic echo``'s YAML."""
    from rosx.msg.text.echo import format_message  # noqa: PLC0415 - the text forms

    return format_message(msg)


def from_yaml(cls: type[Message], text: str) -> Message:
    """A ``cls`` message filled from the YAML ``text`` (empty text: the default message).

    Raises:
        FormError: the text is not YAML, not a mapping, or does not fit ``cls``.
    """
    from rosx.msg.codec.message import serialize_frame  # noqa: PLC0415 - the codec
    from rosx.msg.text.yamlargs import fill_message_args  # noqa: PLC0415 - the text forms
    from rosx.msg.text.yamlload import YAMLLoadError, load  # noqa: PLC0415 - as above

    try:
        values = {} if not text.strip() else load(text)
    except YAMLLoadError as error:
        raise FormError(str(error).splitlines()[0]) from None
    if not isinstance(values, dict):
        raise FormError("yaml string does not contain a dictionary")
    msg = cls()
    try:
        fill_message_args(msg, [values])
        serialize_frame(msg)  # a value the wire cannot carry is refused now
    except Exception as error:  # the filler's and the codec's refusals, each one line
        raise FormError(
            str(error).splitlines()[0] if str(error) else type(error).__name__
        ) from None
    return msg


#: Each goal status: its word and the colour ROS 1's axclient paints it (as a rich colour).
STATUS_LOOK = {
    0: ("PENDING", "rgb(255,174,59)"),
    1: ("ACTIVE", "rgb(0,255,0)"),
    2: ("PREEMPTED", "rgb(255,252,16)"),
    3: ("SUCCEEDED", "rgb(38,250,253)"),
    4: ("ABORTED", "rgb(200,0,0)"),
    5: ("REJECTED", "rgb(253,38,159)"),
    6: ("PREEMPTING", "rgb(253,38,159)"),
    7: ("RECALLING", "rgb(230,38,253)"),
    8: ("RECALLED", "rgb(230,38,253)"),
    9: ("LOST", "rgb(255,0,0)"),
}


def status_look(status: int) -> tuple[str, str]:
    """The word and colour of a goal status number."""
    return STATUS_LOOK.get(status, (f"NO_SUCH_STATE_{status}", "rgb(255,0,0)"))


__all__ = [
    "STATUS_LOOK",
    "ActionTypes",
    "FormError",
    "action_types",
    "from_yaml",
    "status_look",
    "to_yaml",
]
