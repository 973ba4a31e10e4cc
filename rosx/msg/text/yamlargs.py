"""Message values from YAML arguments, as ``rostopic pub`` and ``rosservice call`` read them.

Each command-line word is one YAML document (`load_args`). The loaded values fill a message as
genpy's ``fill_message_args`` does (`fill_message_args`):

* one dict fills fields by name, in any depth (``{linear: {x: 2.0}}``); fields not named keep
  their values; a key given without a value sets the empty string;
* otherwise the values are positional, one per field in declaration order, nested messages as
  lists or dicts; too many or too few is an error that lists what was given and expected;
* ``now`` in place of a ``time`` (or ``duration``) sets the current time, ``auto`` in place of a
  ``Header`` sets a header stamped now (``seq`` 0, empty ``frame_id``); any other word in place of
  a message or time is an error; an integer for a time means nanoseconds (through a float);
* values are set as loaded, not converted: an ``int`` stays an ``int`` in a ``float64`` field
  (the codec writes it as a float), a wrong type is found when the message is serialised;
* arrays take a list, fixed-size ones of their exact length; ``uint8[]``/``char[]`` take the
  value as given (a list of numbers or a string).

Errors are genpy's ``MessageException`` (and ``ValueError`` for a value where a message or list
is needed), with its texts; `publish_error_text` and `call_error_text` add what rostopic and
rosservice print around them. A key like ``x:5`` (YAML needs a space after the colon) gets a
one-line explanation.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING, Any

from rosx.msg.codec.introspect import field_types, is_message
from rosx.msg.codec.message import MessageException
from rosx.msg.codec.rostime import Duration, Time, TVal
from rosx.msg.spec import HEADER_TYPE, PRIMITIVE_TYPES
from rosx.msg.text.yamlload import load

if TYPE_CHECKING:
    from rosx.msg.store import TypeStore

#: Reads the current (ROS) time; injected so that ``now`` is testable.
Clock = Callable[[], Time]

#: The field names of `Time`/`Duration` in the order positional values fill them.
_TIME_SLOTS = ["secs", "nsecs"]

#: Finds the class of a message type by name.
_ClassOf = Callable[[str], Any]


def load_args(words: Sequence[str], *, empty_is_string: bool = False) -> list[Any]:
    """Each word loaded as one YAML document (`YAMLLoadError` for the first invalid one).

    ``empty_is_string`` is rosservice's rule: an empty word is the empty string, not null.
    """
    return [load("''" if empty_is_string and word == "" else word) for word in words]


def substitution_keys(now: Time, store: TypeStore | None = None) -> dict[str, object]:
    """The words that stand for values: ``now`` (a time) and ``auto`` (a header stamped now)."""
    # Classes come with the code generator, which loading arguments alone does not need.
    from rosx.msg.codec.classes import get_message_class  # noqa: PLC0415 - message classes load on first use

    header = get_message_class(HEADER_TYPE, store)(stamp=now)
    return {"now": now, "auto": header}


def fill_message_args(
    msg: object,
    args: list[Any] | None,
    *,
    clock: Clock | None = None,
    keys: dict[str, object] | None = None,
    store: TypeStore | None = None,
) -> None:
    """Fill ``msg`` from loaded YAML values ``args``, in place.

    ``clock`` gives the time for ``now``/``auto`` (read once; wall-clock time by default, as
    ``rostopic pub`` without ``--use-rostime``); ``keys`` replaces the default substitutions.
    ``store`` is where the classes of array elements are looked up.

    Raises:
        MessageException: too many or too few values, an unknown field or key word, an array of
            the wrong kind or length.
        ValueError: a scalar where a message or a list of values is needed.
    """
    if keys is None:
        now = clock() if clock is not None else Time.from_nsec(time.time_ns())
        keys = substitution_keys(now, store)
    from rosx.msg.codec.classes import get_message_class  # noqa: PLC0415 - as in substitution_keys

    filler = _Filler(keys, lambda name: get_message_class(name, store))
    values = [] if args is None else args
    if len(values) == 1 and type(values[0]) is dict:
        filler.fill(msg, values[0], "")
    else:
        filler.fill(msg, values, "")


def printable_args(msg: object) -> str:
    """The field names ``msg`` takes, nested ones dotted: ``linear.x linear.y … angular.z``."""
    names: list[str] = []
    _collect_names(msg, "", names)
    return " ".join(names)


def publish_error_text(error: Exception, msg: object) -> str:
    """What ``rostopic pub`` prints (after ``ERROR: ``) when filling ``msg`` failed."""
    return f"{error}\n\nArgs are: [{printable_args(msg)}]"


def call_error_text(error: Exception, args: object, request: object) -> str:
    """What ``rosservice call`` prints (after ``ERROR: ``) when filling ``request`` failed."""
    if isinstance(args, list | tuple):
        given = "\n".join(f" * {a} (type {type(a).__name__})" for a in args)
    else:
        given = f" * {args} (type {type(args).__name__})"
    return (
        f"Incompatible arguments to call service:\n{error}\nProvided arguments are:\n{given}"
        f"\n\nService arguments are: [{printable_args(request)}]"
    )


def _collect_names(msg: object, prefix: str, names: list[str]) -> None:
    for name in _slots(msg):
        value = getattr(msg, name)
        if is_message(value):
            _collect_names(value, f"{prefix}{name}.", names)
        else:
            names.append(prefix + name)


def _slots(msg: object) -> list[str]:
    if isinstance(msg, TVal):
        return list(_TIME_SLOTS)
    return list(getattr(msg, "__slots__", ()))


def _slot_type(msg: object, name: str) -> str:
    if isinstance(msg, TVal):
        return "int32"
    return dict(field_types(msg))[name]


def _colon_hint(key: object, value: object) -> str:
    """Explain ``{x:5}``: without a space after the colon YAML reads ``x:5`` as one key."""
    if value is not None or not isinstance(key, str) or ":" not in key:
        return ""
    name, _, rest = key.partition(":")
    return f": YAML needs a space after the colon, write {{{name}: {rest}}}"


class _Filler:
    def __init__(self, keys: dict[str, object], message_class: _ClassOf) -> None:
        self.keys = keys
        self.message_class = message_class

    def fill(self, msg: object, args: Any, prefix: str) -> None:
        if not (is_message(msg) or isinstance(msg, TVal)):
            raise ValueError(f"msg must be a Message instance: {msg}")
        slots = _slots(msg)
        if type(args) is dict:
            for name, value in args.items():
                if name not in slots:
                    hint = _colon_hint(name, value)
                    raise MessageException(f"No field name [{prefix}{name}]{hint}")
                self.fill_field(msg, name, "" if value is None else value, prefix)
        elif type(args) is list:
            if len(args) != len(slots):
                which = "Too many" if len(args) > len(slots) else "Not enough"
                raise MessageException(
                    f"{which} arguments:\n * Given: {args}\n * Expected: {slots}"
                )
            for name, value in zip(slots, args, strict=True):
                self.fill_field(msg, name, value, prefix)
        else:
            raise ValueError(f"invalid msg_args type: {args}")

    def fill_field(self, msg: object, name: str, value: Any, prefix: str) -> None:
        field_type = _slot_type(msg, name)
        base, _, size_text = field_type.partition("[")
        current = getattr(msg, name)
        if not size_text and (base not in PRIMITIVE_TYPES or base in ("time", "duration")):
            self._fill_nested(msg, name, current, value, prefix)
        elif size_text and base not in ("uint8", "char"):
            size = int(size_text[:-1]) if size_text[:-1] else None
            setattr(msg, name, self._array(base, size, value, f"{prefix}{name}", prefix))
        else:
            setattr(msg, name, value)

    def _fill_nested(self, msg: object, name: str, current: Any, value: Any, prefix: str) -> None:
        if type(value) is str:
            if value not in self.keys:
                raise MessageException(f"No key named [{value}]")
            setattr(msg, name, self.keys[value])
        elif isinstance(current, TVal) and type(value) is int:
            setattr(msg, name, _time_from_nanoseconds(type(current), value))
        else:
            self.fill(current, value, f"{prefix}{name}.")

    def _array(self, base: str, size: int | None, value: Any, label: str, prefix: str) -> Any:
        if type(value) not in (list, tuple):
            raise MessageException(
                f"Field [{label}] must be a list or tuple instead of: {type(value).__name__}"
            )
        if size is not None and len(value) != size:
            raise MessageException(
                f"Field [{label}] has incorrect number of elements: {len(value)} != {size}"
            )
        if base in PRIMITIVE_TYPES and base not in ("time", "duration"):
            return value
        element_class: Callable[[], Any]
        if base in ("time", "duration"):
            element_class = Time if base == "time" else Duration
        else:
            element_class = self.message_class(base)
        elements = []
        for item in value:
            element = element_class()
            if isinstance(element, TVal) and type(item) is int:
                element = _time_from_nanoseconds(type(element), item)
            else:
                # As genpy: errors inside elements are named after the enclosing message.
                self.fill(element, item, prefix)
            elements.append(element)
        return elements


def _time_from_nanoseconds(kind: type[TVal], nanoseconds: int) -> TVal:
    # genpy goes through float seconds, losing precision past ~2**53 ns, and so do we.
    try:
        return kind.from_sec(nanoseconds / 1e9)
    except TypeError as error:
        raise ValueError(str(error)) from None


__all__ = [
    "Clock",
    "call_error_text",
    "fill_message_args",
    "load_args",
    "printable_args",
    "publish_error_text",
    "substitution_keys",
]
