"""Field paths into messages, as ``rostopic echo /topic/field[1:3]/x`` selects them.

A path is the part of the name after the topic: fields separated by ``/``, each optionally
followed by an index ``[i]`` or a slice ``[a:b:c]`` (Python semantics, negative numbers allowed).
When a slice selects several messages, the rest of the path applies to each of them and the
result is a list. Errors carry rostopic's texts; rostopic prints them to stderr and then echoes
the whole message (a path it cannot parse) or skips the message (a missing field or element).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from rosx.msg.spec import PRIMITIVE_TYPES, MsgSpec

if TYPE_CHECKING:
    from rosx.msg.store import TypeStore


class FieldPathError(ValueError):
    """A path that cannot be parsed or does not fit the message; ``str()`` is rostopic's text."""


@dataclass(frozen=True)
class Step:
    """One field of a path and what is taken of it: all, one element, or a slice."""

    field: str
    selector: int | slice | None = None


@dataclass(frozen=True)
class FieldPath:
    """A parsed path; ``text`` is as written (rostopic quotes it in its errors)."""

    text: str
    steps: tuple[Step, ...]

    def evaluate(self, msg: object) -> Any:
        """The selected value of ``msg``; `FieldPathError` if a field or element is missing."""
        return self._walk(msg, 0)

    def _walk(self, value: Any, start: int) -> Any:
        for position in range(start, len(self.steps)):
            step = self.steps[position]
            try:
                value = getattr(value, step.field)
            except AttributeError:
                raise FieldPathError(f"no field named {step.field} in {self.text}") from None
            if step.selector is None:
                continue
            try:
                value = value[step.selector]
            except (IndexError, TypeError) as error:
                raise FieldPathError(f"{error}: {self.text}") from None
            if isinstance(value, list):
                return [self._walk(item, position + 1) for item in value]
        return value


def parse_field_path(text: str) -> FieldPath:
    """Parse ``/a/b[2]/c[1:-1]``; an empty path (``''`` or ``/``) selects the whole message."""
    steps: list[Step] = []
    for part in (p for p in text.split("/") if p):
        if "[" not in part:
            steps.append(Step(part))
            continue
        name, rest = part.split("[", 1)
        if not rest.endswith("]"):
            raise FieldPathError(f"missing closing ']' in slice spec '{part}'")
        inside = rest[:-1]
        try:
            selector = _selector(inside)
        except ValueError as error:
            raise FieldPathError(
                f"field '{name}' has invalid slice argument '{inside}': {error}"
            ) from None
        steps.append(Step(name, selector))
    return FieldPath(text, tuple(steps))


def _integer(text: str, what: str) -> int:
    try:
        return int(text)
    except ValueError:
        raise ValueError(f"non-integer {what} '{text}'") from None


def _selector(text: str) -> int | slice:
    if text == "":
        raise ValueError("empty array index")
    parts = text.split(":")
    if len(parts) == 1:
        # rostopic's own wording for a bad single index.
        return _integer(parts[0], "array index step")
    bounds: list[int | None] = [None, None, None]
    for position, what in enumerate(("slice start", "slice stop", "slice step")):
        if position < len(parts) and parts[position] != "":
            bounds[position] = _integer(parts[position], what)
    if len(parts) > 3:
        raise ValueError("too many slice arguments")
    return slice(*bounds)


def field_type(
    lookup: Callable[[str], MsgSpec], msg_type: str, path: FieldPath, *, elements: bool = False
) -> str | None:
    """The declared type of the last field of ``path`` in ``msg_type`` (None for no fields).

    As rostopic's, it ignores indices: ``/data[0]`` of a ``uint8[]`` field is ``uint8[]``;
    with ``elements`` an index selects an element's type (``uint8``), and a field of an array
    not indexed is not found. ``lookup`` finds a message spec by name (e.g. ``TypeStore.msg``);
    the fields of a ``time`` or ``duration`` are ``secs`` and ``nsecs``, both ``int32``.
    """
    found: str | None = None
    for step in path.steps:
        owner = msg_type if found is None else found if elements else found.split("[", 1)[0]
        found = _members(lookup, owner).get(step.field)
        if found is None:
            raise FieldPathError(f"no field named {step.field} in {path.text}")
        if elements and isinstance(step.selector, int) and found.endswith("]"):
            found = found.split("[", 1)[0]
    return found


def _members(lookup: Callable[[str], MsgSpec], type_name: str) -> dict[str, str]:
    """The fields a value of ``type_name`` has, with their types: a message's, a time's or a
    duration's (``secs``, ``nsecs``), none for another primitive or an array."""
    if type_name in ("time", "duration"):
        return {"secs": "int32", "nsecs": "int32"}
    if type_name in PRIMITIVE_TYPES or type_name.endswith("]"):
        return {}
    return {field.name: field.type for field in lookup(type_name).fields}


def find_topic(
    name: str, types: dict[str, str], store: TypeStore | None = None
) -> tuple[str, str] | None:
    """The topic ``name`` denotes, itself or the longest topic it is a field path of.

    As ROS 1's, the path is read up to its first ``[``, and each of its fields must be a field
    of the one before: a topic whose type has no such field (in ``store``: the standard types by
    default) is skipped, as one whose path goes into a primitive or an array not indexed
    (``/pose/x/y``, ``/tf/transforms/header``); one whose type is not known is taken as it is
    (its users then say they cannot load the type, as ROS 1's do).
    """
    if name in types:
        return name, types[name]
    from rosx.msg.store import TypeStore, UnknownTypeError  # noqa: PLC0415 - parsed only for field paths

    store = TypeStore([]) if store is None else store
    for topic in sorted((t for t in types if name.startswith(t + "/")), reverse=True):
        path = name[len(topic) + 1 :].rstrip("/").split("[")[0]
        if not path:
            return topic, types[topic]
        try:
            spec_type = types[topic]
            for part in path.split("/"):
                spec_type = _members(store.msg, spec_type)[part]
        except KeyError:
            continue
        except UnknownTypeError:
            return topic, types[topic]
        return topic, types[topic]
    return None


__all__ = [
    "FieldPath",
    "FieldPathError",
    "Step",
    "field_type",
    "find_topic",
    "parse_field_path",
]
