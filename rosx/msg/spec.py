"""The parsed form of ROS 1 message, service and action definitions.

A `MsgSpec` is what a `.msg` file says once its type names are resolved: constants, then fields,
each field type fully qualified (``geometry_msgs/Vector3``, ``std_msgs/Header``) unless it is a
built-in. Services are a request and a response spec under one name; actions the seven messages
genaction makes of an ``.action`` file (`ACTION_SUFFIXES`). These are plain values; the
parser builds them, the type store holds them, and the codec, md5 and YAML code read them.
"""

from __future__ import annotations

from rosx.record import Record

#: Built-in field types of ROS 1 messages. ``char`` and ``byte`` are the deprecated aliases of
#: ``uint8`` and ``int8``; they keep their own names in definitions and md5 texts.
PRIMITIVE_TYPES = frozenset(
    {
        "bool",
        "int8",
        "uint8",
        "int16",
        "uint16",
        "int32",
        "uint32",
        "int64",
        "uint64",
        "float32",
        "float64",
        "string",
        "char",
        "byte",
        "time",
        "duration",
    }
)

#: Types a constant may have (every primitive but time and duration).
CONSTANT_TYPES = PRIMITIVE_TYPES - {"time", "duration"}

HEADER_TYPE = "std_msgs/Header"


class Field(Record):
    """One field: ``base_type`` is a primitive or a full ``pkg/Type`` name.

    ``is_array`` marks ``T[]`` and ``T[N]``; ``array_len`` is N for fixed-size arrays and
    None for variable-length ones (and for scalars).
    """

    __match_args__ = ("name", "base_type", "is_array", "array_len")
    __slots__ = __match_args__
    name: str
    base_type: str
    is_array: bool
    array_len: int | None

    def __init__(
        self, name: str, base_type: str, is_array: bool = False, array_len: int | None = None
    ) -> None:
        super().__init__(name=name, base_type=base_type, is_array=is_array, array_len=array_len)

    @property
    def type(self) -> str:
        """The type as ROS 1 writes it in resolved form, e.g. ``float64[9]``, ``pkg/T[]``."""
        if not self.is_array:
            return self.base_type
        return f"{self.base_type}[{'' if self.array_len is None else self.array_len}]"

    @property
    def is_builtin(self) -> bool:
        """Whether the field's base type is a primitive (``int32``, ``string``, ``time``...), not
        a message."""
        return self.base_type in PRIMITIVE_TYPES


class Constant(Record):
    """A constant: ``text`` is the value as written (what rosmsg shows and md5 hashes)."""

    __match_args__ = ("type", "name", "value", "text")
    __slots__ = __match_args__
    type: str
    name: str
    value: bool | int | float | str
    text: str

    def __init__(self, type: str, name: str, value: bool | int | float | str, text: str) -> None:
        super().__init__(type=type, name=name, value=value, text=text)


class MsgSpec(Record):
    """A message type. ``text`` is its definition text (what ``rosmsg show -r`` prints)."""

    __match_args__ = ("full_name", "constants", "fields", "text")
    __slots__ = __match_args__
    full_name: str
    constants: tuple[Constant, ...]
    fields: tuple[Field, ...]
    text: str

    def __init__(
        self,
        full_name: str,
        constants: tuple[Constant, ...],
        fields: tuple[Field, ...],
        text: str,
    ) -> None:
        super().__init__(full_name=full_name, constants=constants, fields=fields, text=text)

    @property
    def package(self) -> str:
        """The package part of ``pkg/Name``."""
        return self.full_name.partition("/")[0]

    @property
    def short_name(self) -> str:
        """The name without its package (``Pose`` of ``turtlesim/Pose``)."""
        return self.full_name.partition("/")[2]

    @property
    def has_header(self) -> bool:
        """ROS 1's rule: the first field is ``Header header``."""
        return (
            bool(self.fields)
            and self.fields[0].name == "header"
            and not self.fields[0].is_array
            and self.fields[0].base_type == HEADER_TYPE
        )


class SrvSpec(Record):
    """A service type: ``request`` and ``response`` are named ``pkg/TypeRequest``/``…Response``."""

    __match_args__ = ("full_name", "request", "response", "text")
    __slots__ = __match_args__
    full_name: str
    request: MsgSpec
    response: MsgSpec
    text: str

    def __init__(self, full_name: str, request: MsgSpec, response: MsgSpec, text: str) -> None:
        super().__init__(full_name=full_name, request=request, response=response, text=text)

    @property
    def package(self) -> str:
        """The package part of ``pkg/Name``."""
        return self.full_name.partition("/")[0]

    @property
    def short_name(self) -> str:
        """The name without its package (``AddTwoInts`` of ``rospy_tutorials/AddTwoInts``)."""
        return self.full_name.partition("/")[2]


#: The messages of an action ``X``, by the suffix of their names (``XAction``, ``XActionGoal`` …),
#: in the order genaction lists them.
ACTION_SUFFIXES = (
    "Action",
    "ActionGoal",
    "ActionResult",
    "ActionFeedback",
    "Goal",
    "Result",
    "Feedback",
)


class ActionSpec(Record):
    """An action type: ``messages`` are its seven messages, in the order of `ACTION_SUFFIXES`."""

    __match_args__ = ("full_name", "messages", "text")
    __slots__ = __match_args__
    full_name: str
    messages: tuple[MsgSpec, ...]
    text: str

    def __init__(self, full_name: str, messages: tuple[MsgSpec, ...], text: str) -> None:
        super().__init__(full_name=full_name, messages=messages, text=text)

    @property
    def package(self) -> str:
        """The package part of ``pkg/Name``."""
        return self.full_name.partition("/")[0]

    @property
    def short_name(self) -> str:
        """The name without its package (``Fibonacci`` of ``actionlib_tutorials/Fibonacci``)."""
        return self.full_name.partition("/")[2]

    def message(self, suffix: str) -> MsgSpec:
        """The message named ``<action><suffix>`` (``suffix`` one of `ACTION_SUFFIXES`)."""
        return self.messages[ACTION_SUFFIXES.index(suffix)]
