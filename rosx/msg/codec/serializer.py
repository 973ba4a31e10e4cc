"""Generate the ``serialize`` method of a message class: ROS 1 wire format, genpy's bytes.

Implements ROS 1 serialisation (wiki ROS/Message_serialization) as genpy writes it. Consecutive
fixed-size values, through nested messages that are not in arrays, are packed by one
precompiled `struct.Struct`; the uint32 length in front of a string or array joins the run
before it, so a ``Header`` costs one ``pack`` and two writes. Values are taken as genpy takes
them: a string field holds ``str`` (written as UTF-8), ``uint8[]``/``char[]`` hold bytes or a
list/tuple of ints, a fixed ``uint8[N]`` given bytes of another length is padded or cut as
genpy's ``Ns`` packing does, and a fixed array of any other type must have exactly N elements.
Anything that cannot be packed raises, and `rosx.msg.codec.checks` names the field.

A type whose values all have a fixed size (``Twist``, ``Pose``, turtlesim's ``Pose``) also gets
``_frame``: the whole TCPROS frame, length prefix first, from a single ``pack``. Publishing
calls it; a burst's first message runs with the CPU's caches cold (see
`rosx.node.publication`), when each call on the way costs microseconds.
"""

from __future__ import annotations

import struct
from collections.abc import Callable

from rosx.msg.codec.source import Source, python_names
from rosx.msg.codec.wiretypes import BYTE_ARRAY_TYPES, NUMPY_DTYPES, PACK_CHARS, TIME_CHARS
from rosx.msg.spec import Field, MsgSpec

Lookup = Callable[[str], MsgSpec]


def write_serializer(src: Source, spec: MsgSpec, lookup: Lookup, name: str, numpy: bool) -> None:
    """Add ``def name(self, buff[, numpy])`` for ``spec`` to ``src``."""
    body = Source(src.title, {})
    writer = _Writer(src, body, lookup, numpy)
    writer.message(spec, "self", 2)
    writer.flush(2)
    src.add(0, f"def {name}(self, buff{', numpy' if numpy else ''}):")
    if not body.lines:
        src.add(1, "pass")
        return
    src.add(1, "try:")
    src.lines += body.lines
    src.add(1, "except _SerializeErrors as exc:")
    src.add(2, "raise _serialization_error(self, exc) from exc")


def write_framer(src: Source, spec: MsgSpec, lookup: Lookup) -> bool:
    """Add ``def _frame(self)``, the message as one TCPROS frame (uint32 length first) made by a
    single ``pack``, if every value of ``spec`` has a fixed size; whether it did."""
    if not _fixed_size(spec, lookup):
        return False
    body = Source(src.title, {})
    writer = _Writer(src, body, lookup, numpy=False)
    writer.message(spec, "self", 2)
    if not writer.run:  # no fields: the inherited `_frame` does as well
        return False
    fmt = "".join(chars for chars, _ in writer.run)
    writer.run.insert(0, ("I", str(struct.calcsize("<" + fmt))))
    writer.returning = True
    writer.flush(2)
    src.add(0, "def _frame(self):")
    src.add(1, "try:")
    src.lines += body.lines
    src.add(1, "except _SerializeErrors as exc:")
    src.add(2, "raise _serialization_error(self, exc) from exc")
    return True


def _fixed_size(spec: MsgSpec, lookup: Lookup) -> bool:
    """Whether ``spec`` is packed as one run: numbers, times, fixed arrays of numbers or bytes,
    and messages made of those."""
    for field in spec.fields:
        base = field.base_type
        if field.is_array:
            fixed = field.array_len is not None and base in PACK_CHARS
        elif base in PACK_CHARS or base in TIME_CHARS:
            fixed = True
        else:
            fixed = base != "string" and _fixed_size(lookup(base), lookup)
        if not fixed:
            return False
    return True


class _Writer:
    def __init__(self, src: Source, body: Source, lookup: Lookup, numpy: bool) -> None:
        self.src = src
        self.body = body
        self.lookup = lookup
        self.numpy = numpy
        self.run: list[tuple[str, str]] = []  # (struct characters, argument expression)
        #: Whether the last run is returned (`write_framer`) rather than written.
        self.returning = False

    def add(self, depth: int, line: str) -> None:
        self.body.add(depth, line)

    def flush(self, depth: int) -> None:
        if not self.run:
            return
        fmt = "".join(chars for chars, _ in self.run)
        args = ", ".join(arg for _, arg in self.run)
        packed = f"{self.src.struct(fmt)}.pack({args})"
        self.add(depth, f"return {packed}" if self.returning else f"buff.write({packed})")
        self.run = []

    def message(self, spec: MsgSpec, obj: str, depth: int) -> None:
        for field, attr in zip(spec.fields, python_names(spec), strict=True):
            self.field(field, f"{obj}.{attr}", depth)

    def field(self, field: Field, expr: str, depth: int) -> None:
        if field.is_array:
            self.array(field, expr, depth)
        else:
            self.scalar(field.base_type, expr, depth)

    def scalar(self, base: str, expr: str, depth: int) -> None:
        if base in PACK_CHARS:
            self.run.append((PACK_CHARS[base], expr))
        elif base in TIME_CHARS:
            chars = TIME_CHARS[base]
            self.run += [(chars, f"{expr}.secs"), (chars, f"{expr}.nsecs")]
        elif base == "string":
            encoded = self.src.local("b")
            self.add(depth, f"{encoded} = {expr}.encode()")
            self.run.append(("I", f"len({encoded})"))
            self.flush(depth)
            self.add(depth, f"buff.write({encoded})")
        else:
            value = self.src.local("m")
            self.add(depth, f"{value} = {expr}")
            self.message(self.lookup(base), value, depth)

    def array(self, field: Field, expr: str, depth: int) -> None:
        base, size = field.base_type, field.array_len
        value = self.src.local("a")
        self.add(depth, f"{value} = {expr}")
        if base in BYTE_ARRAY_TYPES:
            self.byte_array(value, size, depth)
        elif base in PACK_CHARS:
            if self.numpy:
                self.numpy_array(base, value, size, depth)
            else:
                self.number_array(base, value, size, depth)
        else:
            self.each_element(base, value, size, depth)

    def byte_array(self, value: str, size: int | None, depth: int) -> None:
        if size is None:
            self.add(depth, f"if {value}.__class__ is not bytes: {value} = _as_bytes({value})")
            self.run.append(("I", f"len({value})"))
            self.flush(depth)
            self.add(depth, f"buff.write({value})")
        else:
            self.add(
                depth,
                f"if {value}.__class__ is not bytes: {value} = _as_fixed_bytes({value}, {size})",
            )
            self.run.append((f"{size}s", value))

    def number_array(self, base: str, value: str, size: int | None, depth: int) -> None:
        chars = PACK_CHARS[base]
        if size is not None:
            self.run.append((f"{size}{chars}", f"*{value}"))
            return
        count = self.src.local("n")
        self.add(depth, f"{count} = len({value})")
        self.run.append(("I", count))
        self.flush(depth)
        self.add(depth, f"if {count}: buff.write(_array_struct('{chars}', {count}).pack(*{value}))")

    def numpy_array(self, base: str, value: str, size: int | None, depth: int) -> None:
        if size is None:
            self.run.append(("I", f"len({value})"))
        else:
            self.add(depth, f"_check_length({value}, {size})")
        self.flush(depth)
        self.add(depth, f"buff.write(numpy.asarray({value}, {NUMPY_DTYPES[base]!r}).tobytes())")

    def each_element(self, base: str, value: str, size: int | None, depth: int) -> None:
        if size is None:
            self.run.append(("I", f"len({value})"))
        else:
            self.add(depth, f"_check_length({value}, {size})")
        self.flush(depth)
        element = self.src.local("e")
        self.add(depth, f"for {element} in {value}:")
        before = len(self.body.lines)
        if base == "string" or base in TIME_CHARS:
            self.scalar(base, element, depth + 1)
        else:
            self.message(self.lookup(base), element, depth + 1)
        self.flush(depth + 1)
        if len(self.body.lines) == before:  # elements with no fields (std_msgs/Empty)
            self.add(depth + 1, "pass")
