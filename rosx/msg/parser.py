"""Parse ROS 1 ``.msg`` and ``.srv`` text into specs.

Implements the message description language of ROS 1 (wiki ROS/msg): one declaration a line,
``#`` comments, constants ``type NAME=value`` (a string constant takes the rest of the line,
comments included), fields ``type name`` with ``T[]`` and ``T[N]`` arrays, ``Header`` meaning
``std_msgs/Header``, and bare message names resolving inside the declaring package. A ``.srv``
splits at the first line starting with ``---``.
"""

from __future__ import annotations

import re

from rosx.msg.spec import (
    CONSTANT_TYPES,
    HEADER_TYPE,
    PRIMITIVE_TYPES,
    Constant,
    Field,
    MsgSpec,
    SrvSpec,
)

_BASE_NAME = re.compile(r"[A-Za-z]\w*\Z")
_RESOURCE_NAME = re.compile(r"[A-Za-z][\w/]*\Z")
_ARRAY_SUFFIX = re.compile(r"\[(\d*)\]\Z")

_INT_BITS = {
    "int8": (True, 8),
    "uint8": (False, 8),
    "int16": (True, 16),
    "uint16": (False, 16),
    "int32": (True, 32),
    "uint32": (False, 32),
    "int64": (True, 64),
    "uint64": (False, 64),
    "byte": (True, 8),
    "char": (False, 8),
}


class InvalidMsgSpecError(ValueError):
    """A definition does not follow the message description language.

    ``line`` is the 1-based line of the offending declaration when known.
    """

    def __init__(self, message: str, line: int | None = None) -> None:
        super().__init__(message)
        self.line = line


def is_valid_type_name(full_name: str) -> bool:
    """True for a legal ``pkg/Type`` name."""
    package, sep, name = full_name.partition("/")
    return bool(sep) and bool(_BASE_NAME.match(package)) and bool(_BASE_NAME.match(name))


def parse_msg(full_name: str, text: str) -> MsgSpec:
    """Parse the text of ``full_name`` (``pkg/Type``) into a `MsgSpec`."""
    package = full_name.partition("/")[0]
    constants: list[Constant] = []
    fields: list[Field] = []
    for number, line in enumerate(text.split("\n"), start=1):
        declaration = line.split("#", 1)[0].strip()
        if not declaration:
            continue
        try:
            if "=" in declaration:
                constants.append(_parse_constant(line))
            else:
                fields.append(_parse_field(line, declaration, package))
        except InvalidMsgSpecError as error:
            raise InvalidMsgSpecError(str(error), number) from None
    names = [f.name for f in fields] + [c.name for c in constants]
    for name in names:
        if names.count(name) > 1:
            raise InvalidMsgSpecError(f"Duplicate field name [{name}] in [{full_name}]")
    return MsgSpec(full_name, tuple(constants), tuple(fields), text)


def parse_srv(full_name: str, text: str) -> SrvSpec:
    """Parse the text of service ``full_name``; the halves become ``…Request``/``…Response``."""
    lines = text.split("\n")
    split = next((i for i, line in enumerate(lines) if line.startswith("---")), len(lines))
    request_text = "".join(line + "\n" for line in lines[:split])
    response_text = "".join(line + "\n" for line in lines[split + 1 :])
    request = parse_msg(full_name + "Request", request_text)
    try:
        response = parse_msg(full_name + "Response", response_text)
    except InvalidMsgSpecError as error:
        line = None if error.line is None else error.line + split + 1
        raise InvalidMsgSpecError(str(error), line) from None
    return SrvSpec(full_name, request, response, text)


def _parse_field(line: str, declaration: str, package: str) -> Field:
    words = declaration.split()
    if len(words) != 2:
        raise InvalidMsgSpecError(f"Invalid declaration: {line}")
    type_text, name = words
    if not _BASE_NAME.match(name):
        raise InvalidMsgSpecError(f"{name} is not a legal message field name")
    base, is_array, array_len = _split_array(type_text)
    if base is None or not _RESOURCE_NAME.match(base):
        raise InvalidMsgSpecError(f"{type_text} is not a legal message field type")
    if base == "Header":
        base = HEADER_TYPE
    elif "/" not in base and base not in PRIMITIVE_TYPES:
        base = f"{package}/{base}"
    elif "/" in base and not is_valid_type_name(base):
        raise InvalidMsgSpecError(f"{type_text} is not a legal message field type")
    return Field(name, base, is_array, array_len)


def _split_array(type_text: str) -> tuple[str | None, bool, int | None]:
    match = _ARRAY_SUFFIX.search(type_text)
    if match is None:
        return (None if "[" in type_text or "]" in type_text else type_text), False, None
    base = type_text[: match.start()]
    if "[" in base or "]" in base:
        return None, False, None  # arrays of arrays do not exist in ROS 1
    size = match.group(1)
    return base, True, int(size) if size else None


def _parse_constant(line: str) -> Constant:
    declaration = line.split("#", 1)[0].strip()
    type_name = declaration.split()[0]
    if type_name not in CONSTANT_TYPES:
        raise InvalidMsgSpecError(f"{type_name} is not a legal constant type")
    if type_name == "string":
        # Everything right of '=' belongs to a string constant, '#' included.
        stripped = line.strip()
        name = stripped[len("string") : stripped.index("=")].strip()
        text = stripped[stripped.index("=") + 1 :].strip()
    else:
        parts = [p.strip() for p in " ".join(declaration.split()[1:]).split("=")]
        if len(parts) != 2:
            raise InvalidMsgSpecError(f"Invalid constant declaration: {line}")
        name, text = parts
    if not _BASE_NAME.match(name):
        raise InvalidMsgSpecError(f"{name} is not a legal constant name")
    return Constant(type_name, name, _constant_value(type_name, text), text)


def _constant_value(type_name: str, text: str) -> bool | int | float | str:
    if type_name == "string":
        return text
    if type_name in ("float32", "float64"):
        try:
            return float(text)
        except ValueError:
            raise InvalidMsgSpecError(f"Invalid constant value: {text}") from None
    if type_name == "bool":
        import ast  # noqa: PLC0415 - bool constants are rare; ast costs a start-up 2 ms

        try:
            return bool(ast.literal_eval(text))
        except (ValueError, SyntaxError):
            raise InvalidMsgSpecError(f"Invalid constant value: {text}") from None
    signed, bits = _INT_BITS[type_name]
    try:
        value = int(text)
    except ValueError:
        raise InvalidMsgSpecError(f"Invalid constant value: {text}") from None
    low, high = (-(1 << (bits - 1)), (1 << (bits - 1)) - 1) if signed else (0, (1 << bits) - 1)
    if not low <= value <= high:
        raise InvalidMsgSpecError(f"cannot coerce [{value}] to {type_name} (out of bounds)")
    return value
