"""Generate the ``deserialize`` method of a message class: ROS 1 wire format in, genpy's values out.

Implements ROS 1 deserialisation (wiki ROS/Message_serialization) with the values genpy gives
on Python 3: ``bool`` fields as bools, strings decoded from UTF-8, ``uint8[]``/``char[]`` (and
their fixed forms) as bytes, other numeric arrays as tuples (bool arrays as lists of bools),
arrays of strings, times and messages as lists, time and duration as `Time`/`Duration`. Only
the message's own (not nested) time and duration fields are canonicalised, as genpy does. As
in genpy, ``deserialize`` fills the nested messages and times the instance already holds; array
elements are always new.

Runs of fixed-size values, through nested messages, are unpacked by one precompiled struct with
``unpack_from`` (no slicing); offsets are constants until the first variable-length field. A
string or byte array that runs past the end of the data is an error (genpy would silently
return a short value). Trailing bytes are ignored, as genpy ignores them.
"""

from __future__ import annotations

import struct
from collections.abc import Callable

from rosx.msg.codec.source import Source, python_names
from rosx.msg.codec.wiretypes import (
    BYTE_ARRAY_TYPES,
    NUMPY_DTYPES,
    SIZES,
    TIME_CHARS,
    UNPACK_CHARS,
)
from rosx.msg.spec import Field, MsgSpec

Lookup = Callable[[str], MsgSpec]
ClassOf = Callable[[str], type]

_NSEC_PER_SEC = 1_000_000_000


class _Item:
    """One entry of a run: the struct characters ``chars`` unpack into ``target``, one value
    (``count`` 0) or ``count`` values gathered into a tuple (a list when ``as_list``)."""

    __slots__ = ("as_list", "chars", "count", "target")

    def __init__(self, chars: str, target: str, count: int = 0, as_list: bool = False) -> None:
        self.chars = chars
        self.target = target
        self.count = count
        self.as_list = as_list


def write_deserializer(
    src: Source,
    spec: MsgSpec,
    lookup: Lookup,
    class_of: ClassOf,
    name: str,
    *,
    numpy: bool,
    lossy: bool,
    reuse: bool,
) -> None:
    """Add ``def name(self, data[, numpy])`` for ``spec`` to ``src``.

    ``lossy`` decodes invalid UTF-8 with replacement characters instead of raising. ``reuse``
    fills the nested messages and times ``self`` already holds, as genpy does (which saves
    their allocation when the message was just constructed); without it, every nested value is
    new, which also serves instances made without ``__init__``.
    """
    body = Source(src.title, {})
    reader = _Reader(src, body, lookup, class_of, numpy=numpy, lossy=lossy, reuse=reuse)
    reader.message(spec, "self", 2, root=True)
    reader.flush(2)
    src.add(0, f"def {name}(self, data{', numpy' if numpy else ''}):")
    src.add(1, "try:")
    if reader.uses_length:
        src.add(2, "L = len(data)")
    src.lines += body.lines
    for line in reader.final:
        src.add(2, line)
    src.add(2, "return self")
    src.add(1, "except _StructError as exc:")
    src.add(2, "raise _deserialization_error(self, data, exc) from None")
    if reader.reuses:  # a field was never set: start from new values
        src.add(1, "except AttributeError:")
        src.add(2, f"return _deserialize_unset(self, data{', numpy' if numpy else ''})")
    if reader.decodes and not lossy:
        src.add(1, "except UnicodeDecodeError as exc:")
        src.add(2, f"return _decode_lossily(self, data, exc{', numpy' if numpy else ''})")


class _Reader:
    def __init__(
        self,
        src: Source,
        body: Source,
        lookup: Lookup,
        class_of: ClassOf,
        *,
        numpy: bool,
        lossy: bool,
        reuse: bool,
    ) -> None:
        self.src = src
        self.body = body
        self.lookup = lookup
        self.class_of = class_of
        self.numpy = numpy
        self.errors = ", 'replace'" if lossy else ""
        self.reuse = reuse
        self.reuses = False
        self.run: list[_Item] = []
        self.dynamic = False  # False: offsets are constants; True: relative to local p
        self.delta = 0
        self.final: list[str] = []
        self.uses_length = False
        self.decodes = False

    # -- offsets ---------------------------------------------------------------------------

    def offset(self) -> str:
        if not self.dynamic:
            return str(self.delta)
        return f"p + {self.delta}" if self.delta else "p"

    def settle(self, depth: int) -> None:
        """Make the local ``p`` hold the current offset."""
        if not self.dynamic:
            self.add(depth, f"p = {self.delta}")
        elif self.delta:
            self.add(depth, f"p += {self.delta}")
        self.dynamic, self.delta = True, 0

    def add(self, depth: int, line: str) -> None:
        self.body.add(depth, line)

    def flush(self, depth: int) -> None:
        if not self.run:
            return
        fmt = "".join(item.chars for item in self.run)
        unpack = f"{self.src.struct(fmt)}.unpack_from(data, {self.offset()})"
        if all(item.count == 0 for item in self.run):
            targets = ", ".join(item.target for item in self.run)
            self.add(depth, f"{targets}, = {unpack}")
        else:
            values = self.src.local("r")
            self.add(depth, f"{values} = {unpack}")
            index = 0
            for item in self.run:
                if item.count == 0:
                    self.add(depth, f"{item.target} = {values}[{index}]")
                    index += 1
                    continue
                part = f"{values}[{index}:{index + item.count}]"
                self.add(depth, f"{item.target} = {'list(' + part + ')' if item.as_list else part}")
                index += item.count
        self.delta += struct.calcsize("<" + fmt)
        self.run = []

    def count(self, depth: int) -> str:
        """Queue the uint32 count of a variable-length field; flush; return its local."""
        count = self.src.local("n")
        self.run.append(_Item("I", count))
        self.flush(depth)
        return count

    # -- fields ----------------------------------------------------------------------------

    def message(self, spec: MsgSpec, obj: str, depth: int, *, root: bool = False) -> None:
        for field, attr in zip(spec.fields, python_names(spec), strict=True):
            self.field(field, f"{obj}.{attr}", depth, root)

    def field(self, field: Field, target: str, depth: int, root: bool) -> None:
        if field.is_array:
            self.array(field, target, depth)
            return
        base = field.base_type
        if base in UNPACK_CHARS:
            self.run.append(_Item(UNPACK_CHARS[base], target))
        elif base in TIME_CHARS:
            value = self.new_time(base, target, depth)
            if root:  # genpy canonicalises the message's own time fields only
                low = "" if base == "time" else "0 <= "
                self.final.append(f"if not {low}{value}.nsecs < {_NSEC_PER_SEC}: {value}.canon()")
        elif base == "string":
            self.take(self.count(depth), target, depth, text=True)
        else:
            self.new_message(base, target, depth)

    def new_time(self, base: str, target: str, depth: int) -> str:
        value = self.src.local("t")
        self.fresh(value, target, "_Time" if base == "time" else "_Duration", depth)
        chars = TIME_CHARS[base]
        self.run += [_Item(chars, f"{value}.secs"), _Item(chars, f"{value}.nsecs")]
        return value

    def new_message(self, base: str, target: str, depth: int) -> None:
        value = self.src.local("m")
        self.fresh(value, target, self.src.bind(self.class_of(base), "C"), depth)
        self.message(self.lookup(base), value, depth)

    def fresh(self, value: str, target: str, cls: str, depth: int) -> None:
        """Bind ``value`` to the ``cls`` instance stored at ``target``: reused or new."""
        if self.reuse:
            self.reuses = True
            self.add(depth, f"{value} = {target}")
            self.add(depth, f"if {value}.__class__ is not {cls}: {value} = {target} = _new({cls})")
        else:
            self.add(depth, f"{value} = {target} = _new({cls})")

    def take(self, count: str, target: str, depth: int, *, text: bool) -> None:
        """Read ``count`` bytes at the current offset as a str (``text``) or bytes."""
        self.uses_length = True
        self.add(depth, f"p = {self.offset()} + {count}")
        self.add(depth, "if p > L: _short(L, p)")
        chunk = f"data[p - {count}:p]"
        if text:
            self.decodes = True
            self.add(depth, f"{target} = str({chunk}, 'utf-8'{self.errors})")
        else:
            self.add(depth, f"{target} = bytes({chunk})")
        self.dynamic, self.delta = True, 0

    # -- arrays ----------------------------------------------------------------------------

    def array(self, field: Field, target: str, depth: int) -> None:
        base, size = field.base_type, field.array_len
        if base in BYTE_ARRAY_TYPES:
            if size is None:
                self.take(self.count(depth), target, depth, text=False)
            else:
                self.run.append(_Item(f"{size}s", target))
        elif base in UNPACK_CHARS and self.numpy:
            self.numpy_array(base, size, target, depth)
        elif base in UNPACK_CHARS:
            self.number_array(base, size, target, depth)
        else:
            self.each_element(base, size, target, depth)

    def number_array(self, base: str, size: int | None, target: str, depth: int) -> None:
        chars = UNPACK_CHARS[base]
        if size == 0:  # nothing on the wire (an `_Item` of count 0 would be one value)
            self.add(depth, f"{target} = {'[]' if base == 'bool' else '()'}")
            return
        if size is not None:
            self.run.append(_Item(f"{size}{chars}", target, size, as_list=base == "bool"))
            return
        count = self.count(depth)
        start = self.offset()
        values = f"_array_struct('{chars}', {count}).unpack_from(data, {start})"
        self.add(depth, f"{target} = {'list(' + values + ')' if base == 'bool' else values}")
        width = SIZES[chars]
        self.add(depth, f"p = {start} + {count}{'' if width == 1 else f' * {width}'}")
        self.dynamic, self.delta = True, 0

    def numpy_array(self, base: str, size: int | None, target: str, depth: int) -> None:
        count = self.count(depth) if size is None else str(size)
        self.flush(depth)
        self.uses_length = True
        start = self.offset()
        end = self.src.local("z")
        width = SIZES[UNPACK_CHARS[base]]
        self.add(depth, f"{end} = {start} + {count} * {width}")
        self.add(depth, f"if {end} > L: _short(L, {end})")
        dtype = NUMPY_DTYPES[base]
        self.add(depth, f"{target} = numpy.frombuffer(data, {dtype!r}, {count}, {start})")
        if size is None:
            self.add(depth, f"p = {end}")
            self.dynamic, self.delta = True, 0
        else:
            self.delta += size * width

    def each_element(self, base: str, size: int | None, target: str, depth: int) -> None:
        count = self.count(depth) if size is None else str(size)
        self.flush(depth)
        self.settle(depth)
        message = size is None and base != "string" and base not in TIME_CHARS
        if message and _carries_nothing(self.lookup(base), self.lookup):
            # Elements that take no bytes: no end of data stops a count of billions.
            self.add(depth, f"if {count} > {MAX_EMPTY_ELEMENTS}: _too_many({count})")
        items = self.src.local("l")
        self.add(depth, f"{target} = {items} = []")
        self.add(depth, f"for _ in range({count}):")
        inner = depth + 1
        reuse, self.reuse = self.reuse, False  # array elements are always new, as in genpy
        if base == "string":
            length = self.count(inner)
            self.take(length, f"{items}_v", inner, text=True)
            element = f"{items}_v"
        elif base in TIME_CHARS:
            element = self.new_time(base, f"{items}_v", inner)
        else:
            element = self.src.local("e")
            self.add(inner, f"{element} = _new({self.src.bind(self.class_of(base), 'C')})")
            self.message(self.lookup(base), element, inner)
        self.flush(inner)
        self.settle(inner)
        self.add(inner, f"{items}.append({element})")
        self.reuse = reuse


#: The most elements with no fields (``std_msgs/Empty[]``) a message may say it holds: each
#: costs an object and nothing on the wire, so four bytes could ask for billions.
MAX_EMPTY_ELEMENTS = 1 << 20


def _carries_nothing(spec: MsgSpec, lookup: Lookup) -> bool:
    """Whether messages of ``spec`` take no bytes on the wire."""
    for field in spec.fields:
        if field.array_len == 0:
            continue
        if field.is_array and field.array_len is None:
            return False
        if field.is_builtin or not _carries_nothing(lookup(field.base_type), lookup):
            return False
    return True
