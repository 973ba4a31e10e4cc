"""XML-RPC documents, as the XML-RPC specification (xmlrpc.com/spec) defines them.

ROS 1's master, parameter server and every node's Slave API speak XML-RPC. This module turns
Python values into ``methodCall``, ``methodResponse`` and fault documents and back, over bytes,
with no HTTP and no sockets (see `xmlrpc_http` for the HTTP framing).

Types, both ways: ``int`` (``<int>``; ``<i4>`` and ``<i8>`` are read too), ``bool``
(``<boolean>``), ``str`` (``<string>``, and a ``<value>`` with no type element), ``float``
(``<double>``), ``bytes`` (``<base64>``), lists and tuples (``<array>``), dicts with str keys
(``<struct>``), ``xmlrpc.client.DateTime`` (``<dateTime.iso8601>``: its text, kept as sent, as
Python's XML-RPC, and so rospy and rosmaster, keep it, whether or not it is a valid date).
Written only: `datetime.datetime` (as a ``<dateTime.iso8601>``, in Python's format). Read only:
``<nil/>`` (``None``). Encoding refuses ints outside int32 (ROS 1 peers would fault), ``None``
and any other type with `ProtocolError`.

The output keeps to what roscpp's XmlRpc++ can read: no self-closing ``<string/>`` or ``<data/>``,
no whitespace inside the envelope, only ``&``, ``<`` and ``>`` escaped. Decoding uses expat,
refuses any DTD (so no entity expansion), and checks which element may appear inside which.

Hand-written rather than built on `xmlrpc.client`, which costs ~30 ms to import (command-line
tools must start fast) and is slower on the master's large replies.
"""

from __future__ import annotations

import binascii
import sys
from xml.parsers import expat

from rosx.record import Record
from rosx.wire.errors import ProtocolError, UnencodableError

TYPE_CHECKING = False
if TYPE_CHECKING:
    from collections.abc import Callable, Iterable
    from typing import Any, TypeAlias
    from xmlrpc.client import DateTime

    _Parsed: TypeAlias = tuple[list[str], str | None, list[Any]]

_INT_MIN = -(2**31)
_INT_MAX = 2**31 - 1
_PROLOG = '<?xml version="1.0"?>'


class MethodCall(Record):
    """A decoded ``methodCall``: the method's name and its parameters."""

    __match_args__ = ("method", "params")
    __slots__ = __match_args__
    method: str
    params: tuple[Any, ...]

    def __init__(self, method: str, params: tuple[Any, ...]) -> None:
        super().__init__(method=method, params=params)


class MethodResponse(Record):
    """A decoded successful ``methodResponse``: its single value."""

    __match_args__ = ("value",)
    __slots__ = __match_args__
    value: Any

    def __init__(self, value: Any) -> None:
        super().__init__(value=value)


class Fault(Record):
    """A decoded fault ``methodResponse``: the server could not run the call."""

    __match_args__ = ("code", "message")
    __slots__ = __match_args__
    code: int
    message: str

    def __init__(self, code: int, message: str) -> None:
        super().__init__(code=code, message=message)


# -- encoding ---------------------------------------------------------------------------------


def _escape(text: str) -> str:
    if "&" in text:
        text = text.replace("&", "&amp;")
    if "<" in text:
        text = text.replace("<", "&lt;")
    if ">" in text:
        text = text.replace(">", "&gt;")
    return text


def _dump(value: object, append: Callable[[str], None]) -> None:
    # Ordered by how often ROS's replies hold each type; bool before int, as bool is an int.
    if isinstance(value, str):
        append(f"<value><string>{_escape(value)}</string></value>")
    elif isinstance(value, (list, tuple)):
        append("<value><array><data>")
        for item in value:
            _dump(item, append)
        append("</data></array></value>")
    elif isinstance(value, bool):
        append(
            "<value><boolean>1</boolean></value>"
            if value
            else "<value><boolean>0</boolean></value>"
        )
    elif isinstance(value, int):
        if not _INT_MIN <= value <= _INT_MAX:
            raise UnencodableError(
                f"int {value} is outside XML-RPC's 32-bit range, which ROS 1 peers refuse; "
                "send it as a double or a string",
                "<class 'OverflowError'>:int exceeds XML-RPC limits",
            )
        append(f"<value><int>{int.__repr__(value)}</int></value>")
    elif isinstance(value, dict):
        append("<value><struct>")
        for key, item in value.items():
            if not isinstance(key, str):
                raise UnencodableError(
                    f"XML-RPC struct keys must be strings, not {key!r}",
                    "<class 'TypeError'>:dictionary key must be string",
                )
            append(f"<member><name>{_escape(key)}</name>")
            _dump(item, append)
            append("</member>")
        append("</struct></value>")
    elif isinstance(value, float):
        append(f"<value><double>{float.__repr__(value)}</double></value>")
    elif isinstance(value, (bytes, bytearray, memoryview)):
        encoded = binascii.b2a_base64(value, newline=False).decode("ascii")
        append(f"<value><base64>{encoded}</base64></value>")
    elif value is None:
        raise UnencodableError(
            "XML-RPC cannot carry None (nil); ROS 1 peers refuse it",
            "<class 'TypeError'>:cannot marshal None unless allow_none is enabled",
        )
    else:
        text = _date_time_text(value)
        if text is None:
            raise UnencodableError(
                f"XML-RPC cannot carry a value of type {type(value).__name__}",
                f"<class 'TypeError'>:cannot marshal {type(value)} objects",
            )
        append(f"<value><dateTime.iso8601>{_escape(text)}</dateTime.iso8601></value>")


def _date_time_text(value: object) -> str | None:
    """The ``<dateTime.iso8601>`` text of a ``DateTime`` or ``datetime``, else None."""
    # Either class is only ever held once its module is loaded: look, never import.
    client = sys.modules.get("xmlrpc.client")
    if client is not None and isinstance(value, client.DateTime):
        return str(value.value)
    clock = sys.modules.get("datetime")
    if clock is not None and isinstance(value, clock.datetime):
        return (
            f"{value.year:04d}{value.month:02d}{value.day:02d}"
            f"T{value.hour:02d}:{value.minute:02d}:{value.second:02d}"
        )
    return None


def encode_value(value: object) -> str:
    """The ``<value>`` element for `value` (the building block of the documents below)."""
    parts: list[str] = []
    _dump(value, parts.append)
    return "".join(parts)


def encode_call(method: str, params: Iterable[object]) -> bytes:
    """A ``methodCall`` document calling `method` with `params`."""
    parts = [f"{_PROLOG}<methodCall><methodName>{_escape(method)}</methodName><params>"]
    append = parts.append
    for param in params:
        append("<param>")
        _dump(param, append)
        append("</param>")
    append("</params></methodCall>")
    return "".join(parts).encode()


def encode_response(value: object) -> bytes:
    """A successful ``methodResponse`` document carrying `value`."""
    parts = [f"{_PROLOG}<methodResponse><params><param>"]
    _dump(value, parts.append)
    parts.append("</param></params></methodResponse>")
    return "".join(parts).encode()


def encode_fault(code: int, message: str) -> bytes:
    """A fault ``methodResponse`` document with ``faultCode`` `code` and ``faultString``."""
    fault = encode_value({"faultCode": code, "faultString": message})
    return f"{_PROLOG}<methodResponse><fault>{fault}</fault></methodResponse>".encode()


# -- decoding ---------------------------------------------------------------------------------
#
# The decoder (after the rewrite described at _SHORTCUTS) is a table-driven state machine over
# expat's events. Values go on one stack; the marks stack remembers where each open array,
# struct, member, param and fault began on it, so closing one gathers what lies above its mark.
# ``typed`` tells whether the innermost open <value> already holds a typed element (if not, its
# text is a string). A text longer than expat's buffer arrives in pieces; the pieces after the
# first collect in ``spill``. The handlers are closures over local state because expat calls
# them for every element, and cell access is the cheapest state Python offers there.

# What opening an element does (besides checking that its parent allows it).
_VALUE, _SCALAR, _CONTAINER, _HOLDER, _NAME, _PLAIN, _TOP, _TOP_HOLDER = range(8)

_SCALARS = ("string", "int", "i4", "i8", "boolean", "double", "base64", "dateTime.iso8601", "nil")

#: For each element, the elements it may contain and what opening each of them does;
#: "" is the document itself.
_CHILDREN: dict[str, dict[str, int]] = {
    "": {"methodCall": _PLAIN, "methodResponse": _PLAIN},
    "methodCall": {"methodName": _TOP, "params": _TOP},
    "methodResponse": {"params": _TOP, "fault": _TOP_HOLDER},
    "params": {"param": _HOLDER},
    "param": {"value": _VALUE},
    "fault": {"value": _VALUE},
    "value": {**dict.fromkeys(_SCALARS, _SCALAR), "array": _CONTAINER, "struct": _CONTAINER},
    "array": {"data": _PLAIN, "value": _VALUE},  # <value> directly inside: see _SHORTCUTS
    "data": {"value": _VALUE},
    "struct": {"member": _HOLDER},
    "member": {"name": _NAME, "value": _VALUE},
    **{leaf: {} for leaf in (*_SCALARS, "methodName", "name")},
}


def _refuse_doctype(*_: object) -> None:
    raise ProtocolError("XML-RPC documents must not contain a DTD (<!DOCTYPE ...>)")


def _date_time(text: str) -> DateTime:
    # The value class rospy hands its users; rare, and costly to import at start-up.
    from xmlrpc.client import DateTime  # noqa: PLC0415 - xmlrpc is not needed at start-up

    return DateTime(text.strip())


def _scalar(tag: str, text: str) -> object:
    """The value of a scalar element other than <string>, from its text."""
    try:
        if tag in {"int", "i4", "i8"}:
            return int(text)
        if tag == "double":
            return float(text)
        if tag == "boolean":
            flag = text.strip()
            if flag in {"0", "1"}:
                return flag == "1"
        elif tag == "base64":
            return binascii.a2b_base64(text.encode("ascii"))
        elif tag == "dateTime.iso8601":
            return _date_time(text)
        elif tag == "nil":
            return None
    except (ValueError, UnicodeEncodeError):  # binascii.Error is a ValueError
        pass
    raise ProtocolError(f"XML-RPC: <{tag}> holds {text!r}")


def _parse_document(data: bytes) -> _Parsed:  # noqa: PLR0915 -- one state machine
    """Parse a document into its top-level elements, method name (calls) and values."""
    stack: list[Any] = []
    marks: list[int] = []
    open_tags = [""]
    tops: list[str] = []
    method: str | None = None
    text = ""
    spill: list[str] = []
    typed = False
    push = stack.append

    def start(tag: str, _attrs: object) -> None:
        nonlocal text, spill, typed
        parent = open_tags[-1]
        action = _CHILDREN[parent].get(tag)
        if action is None:
            where = f"inside <{parent}>" if parent else "as the document element"
            raise ProtocolError(f"XML-RPC: <{tag}> is not allowed {where}")
        open_tags.append(tag)
        text = ""
        if spill:
            spill = []
        if action == _VALUE:
            typed = False
        elif action in (_SCALAR, _CONTAINER):
            if typed:
                raise ProtocolError("XML-RPC: a <value> holds more than one value")
            if action == _CONTAINER:
                marks.append(len(stack))
        elif action == _NAME:
            if len(stack) != marks[-1]:
                raise ProtocolError("XML-RPC: a struct <member> must start with its <name>")
        elif action == _HOLDER:
            marks.append(len(stack))
        elif action != _PLAIN:
            tops.append(tag)
            if action == _TOP_HOLDER:
                marks.append(len(stack))

    def chars(data: str) -> None:
        nonlocal text
        if text:
            spill.append(data)
        else:
            text = data

    def end(tag: str) -> None:
        nonlocal typed, method
        open_tags.pop()
        if tag == "value":
            if not typed:
                push(text + "".join(spill) if spill else text)
                typed = True
        elif tag == "string":
            push(text + "".join(spill) if spill else text)
            typed = True
        elif tag == "array":
            mark = marks.pop()
            items = stack[mark:]
            del stack[mark:]
            push(items)
            typed = True
        elif tag == "name":
            push(text + "".join(spill) if spill else text)
        elif tag == "member":
            if len(stack) - marks.pop() != 2:
                raise ProtocolError("XML-RPC: a struct <member> needs one <name> and one <value>")
        elif tag == "struct":
            mark = marks.pop()
            items = stack[mark:]
            del stack[mark:]
            push(dict(zip(items[::2], items[1::2], strict=True)))
            typed = True
        elif tag == "param" or tag == "fault":  # noqa: PLR1714 -- interned strings compare faster
            if len(stack) - marks.pop() != 1:
                raise ProtocolError(f"XML-RPC: a <{tag}> needs exactly one <value>")
        elif tag == "methodName":
            if method is not None:
                raise ProtocolError("XML-RPC: a <methodCall> names more than one method")
            method = text + "".join(spill) if spill else text
        elif _CHILDREN[tag]:
            return  # data, params and the document element: nothing to build
        else:
            push(_scalar(tag, text + "".join(spill) if spill else text))
            typed = True

    parser = expat.ParserCreate()
    parser.buffer_text = True
    parser.buffer_size = 1 << 16
    parser.ordered_attributes = True
    parser.StartDoctypeDeclHandler = _refuse_doctype
    parser.StartElementHandler = start
    parser.EndElementHandler = end
    parser.CharacterDataHandler = chars
    try:
        parser.Parse(data, True)
    except expat.ExpatError as exc:
        raise ProtocolError(f"malformed XML-RPC document: {exc}") from None
    return tops, method, stack


# Most values in ROS's replies are strings and arrays, and expat calls back for every element, so
# a document parses faster once the wrappers that encoders write around them are dropped:
# <value><string>x</string></value> means <value>x</value>, and <value><array><data>...</data>
# </array></value> is read as <value><array>...</array></value>. A document written any other
# way (whitespace between those tags, say) no longer parses after the rewrite and is parsed as
# sent; one with CDATA sections, whose text the rewrite could change, is always parsed as sent.
_SHORTCUTS = (
    (b"<value><string>", b"<value>"),
    (b"</string></value>", b"</value>"),
    (b"<value><array><data>", b"<value><array>"),
    (b"</data></array></value>", b"</array></value>"),
)


def _parse(body: bytes | bytearray | memoryview) -> _Parsed:
    data = bytes(body)
    if b"<![CDATA[" not in data:
        short = data
        for long_form, short_form in _SHORTCUTS:
            short = short.replace(long_form, short_form)
        if len(short) != len(data):
            try:
                return _parse_document(short)
            except ProtocolError:
                pass  # refused or not: the document as sent decides, and words the refusal
    return _parse_document(data)


def decode_call(body: bytes | bytearray | memoryview) -> MethodCall:
    """Decode a ``methodCall`` document.

    Raises:
        ProtocolError: the bytes are not well-formed XML or not a valid ``methodCall``.
    """
    tops, method, values = _parse(body)
    if method is None or tops not in (["methodName"], ["methodName", "params"]):
        raise ProtocolError(
            "XML-RPC: expected a <methodCall> holding a <methodName>, then optional <params>"
        )
    return MethodCall(method, tuple(values))


def decode_response(body: bytes | bytearray | memoryview) -> MethodResponse | Fault:
    """Decode a ``methodResponse`` document: its value, or the fault it reports.

    Raises:
        ProtocolError: the bytes are not well-formed XML, not a ``methodResponse`` holding exactly
            one value, or a fault without an int ``faultCode`` and a string ``faultString``.
    """
    tops, _, values = _parse(body)
    if tops == ["params"] and len(values) == 1:
        return MethodResponse(values[0])
    if tops == ["fault"]:
        fault = values[0]
        if (
            isinstance(fault, dict)
            and type(fault.get("faultCode")) is int
            and isinstance(fault.get("faultString"), str)
        ):
            return Fault(fault["faultCode"], fault["faultString"])
        raise ProtocolError("XML-RPC: a <fault> must be a struct of faultCode and faultString")
    raise ProtocolError("XML-RPC: expected a <methodResponse> holding one <param> or a <fault>")
