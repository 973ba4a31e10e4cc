"""Messages straight to rosbridge's JSON text, with no dictionaries on the way.

`rosx.bridge.convert.json_values` builds a message's JSON values as dictionaries, and
``json.dumps`` then walks them; for a small message that walk (and the encoder ``json.dumps``
makes on each call with options) costs several times the rest of a message's way through the
bridge. Here each message class gets one generated function, made once from its `MsgSpec`,
that writes the text in one f-string: nested messages' fields inline, arrays through a few
helpers. The text is the one ``json.dumps(json_values(msg), separators=(",", ":"),
allow_nan=False)`` gives, character for character (ASCII, fields in declaration order, NaN and
±inf as ``null``, byte arrays in base64); tests compare the two.

A value the generated code does not expect (an integer in a float field, a numpy scalar that is
not a float, None) raises `TypeError` or `AttributeError`; the caller then falls back to the
general path, which says what is wrong.
"""

from __future__ import annotations

import binascii
import json.encoder
from typing import TYPE_CHECKING, Any

from rosx.msg.codec.classes import get_message_class
from rosx.msg.codec.source import Source, python_name
from rosx.msg.codec.wiretypes import BYTE_ARRAY_TYPES

if TYPE_CHECKING:
    from collections.abc import Callable

    from rosx.msg.codec.message import Message
    from rosx.msg.spec import Field

_FLOATS = frozenset({"float32", "float64"})
_TIMES = frozenset({"time", "duration"})
#: A JSON string of ASCII text (what ``json.dumps`` writes with ``ensure_ascii``).
_string = json.encoder.encode_basestring_ascii
_float = float.__repr__
_int = int.__repr__


def _floats(values: Any) -> str:
    text = ",".join(map(_float, values))
    if "n" in text:  # only "nan" and "inf" hold an n: JSON has no such numbers
        text = ",".join([_float(v) if v - v == 0.0 else "null" for v in values])
    return text


def _ints(values: Any) -> str:
    return ",".join(map(_int, values))


def _bools(values: Any) -> str:
    return ",".join(["true" if v else "false" for v in values])


def _strings(values: Any) -> str:
    return ",".join(map(_string, values))


def _times(values: Any) -> str:
    return ",".join([f'{{"secs":{_int(t.secs)},"nsecs":{_int(t.nsecs)}}}' for t in values])


def _base64(values: Any) -> str:
    data = values if type(values) is bytes else bytes(values)
    return binascii.b2a_base64(data, newline=False).decode("ascii")


_HELPERS: dict[str, Any] = {
    "_float": _float,
    "_int": _int,
    "_string": _string,
    "_floats": _floats,
    "_ints": _ints,
    "_bools": _bools,
    "_strings": _strings,
    "_times": _times,
    "_base64": _base64,
    "_null": "null",
    "_true": "true",
    "_false": "false",
}
_ARRAY_HELPERS = {
    "float32": "_floats",
    "float64": "_floats",
    "bool": "_bools",
    "string": "_strings",
    "time": "_times",
    "duration": "_times",
}

_encoders: dict[type, Callable[[Any], str]] = {}


def json_text(msg: Message) -> str:
    """``msg`` as rosbridge's JSON text (see the module docstring).

    Raises:
        TypeError, AttributeError: a value of an unexpected kind (use the general path).
    """
    cls = type(msg)
    encode = _encoders.get(cls)
    if encode is None:
        encode = encoder(cls)
    return encode(msg)


def encoder(cls: type[Message]) -> Callable[[Any], str]:
    """The generated encoder of ``cls`` (made once)."""
    encode = _encoders.get(cls)
    if encode is None:
        encode = _encoders[cls] = _Writer(cls).compile()
    return encode


class _Writer:
    """The source of one class's encoder: statements that name nested messages, then one
    f-string of literal text and expressions."""

    def __init__(self, cls: type[Message]) -> None:
        self.cls = cls
        self.src = Source(f"json text of {cls._type}", _HELPERS)
        self.statements: list[str] = []
        self.parts: list[str] = []

    def compile(self) -> Callable[[Any], str]:
        self.message(self.cls, "m")
        body = "".join(self.parts)
        self.src.add(0, "def encode(m):")
        for statement in self.statements:
            self.src.add(1, statement)
        self.src.add(1, f"return f'{body}'")
        encode: Callable[[Any], str] = self.src.compile()["encode"]
        return encode

    def text(self, literal: str) -> None:
        self.parts.append(literal.replace("{", "{{").replace("}", "}}").replace("'", "\\'"))

    def value(self, expression: str) -> None:
        self.parts.append("{" + expression + "}")

    def message(self, cls: type[Message], obj: str) -> None:
        spec = cls._spec
        assert spec is not None, f"{cls._type} has no definition"
        self.text("{")
        for index, field in enumerate(spec.fields):
            self.text(("," if index else "") + json.dumps(field.name) + ":")
            self.field(field, f"{obj}.{python_name(field.name)}")
        self.text("}")

    def local(self, expression: str) -> str:
        name = self.src.local("v")
        self.statements.append(f"{name} = {expression}")
        return name

    def field(self, field: Field, access: str) -> None:
        base = field.base_type
        if field.is_array:
            if base in BYTE_ARRAY_TYPES:
                self.text('"')
                self.value(f"_base64({access})")
                self.text('"')
                return
            helper = _ARRAY_HELPERS.get(base)
            if helper is None and field.is_builtin:
                helper = "_ints"
            if helper is None:
                nested = self.src.bind(encoder(get_message_class(base)), "enc")
                self.text("[")
                self.value(f'",".join(map({nested}, {access}))')
                self.text("]")
                return
            self.text("[")
            self.value(f"{helper}({access})")
            self.text("]")
        elif base in _FLOATS:
            name = self.src.local("f")
            self.value(f"(_float({name}) if ({name} := {access}) - {name} == 0.0 else _null)")
        elif base == "bool":
            self.value(f"(_true if {access} else _false)")
        elif base == "string":
            self.value(f"_string({access})")
        elif base in _TIMES:
            stamp = self.local(access)
            self.text('{"secs":')
            self.value(f"_int({stamp}.secs)")
            self.text(',"nsecs":')
            self.value(f"_int({stamp}.nsecs)")
            self.text("}")
        elif field.is_builtin:
            self.value(f"_int({access})")
        else:
            self.message(get_message_class(base), self.local(access))


__all__ = ["encoder", "json_text"]
