"""A message's default instance as YAML, as ROS 1's ``rosmsg-proto`` writes it for tab completion.

rosmsg-proto fills a default instance (one default element in each variable-length array, unless
asked not to), then dumps it with PyYAML: block style, except that once a message with more than
four fields, or an array of more than four elements, has been met, PyYAML's mixed style takes over
for what follows (a collection of scalars only is written in flow style, ``{secs: 0, nsecs: 0}``,
``[0.0, 0.0]``). Flow collections fold past column 80, indented two spaces more than their key.
``flow=True`` writes everything in flow style, ``flow=False`` nothing. Fields keep their order.

`prototype` gives the text; the quotes around it and the ``--prefix`` are the caller's.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from collections.abc import Callable

    from rosx.msg.spec import MsgSpec

_WIDTH = 80
_MANY = 4  # rosmsg's MAX_DEFAULT_NON_FLOW_ITEMS
_INTEGERS = {
    "byte",
    "char",
    "int8",
    "uint8",
    "int16",
    "uint16",
    "int32",
    "uint32",
    "int64",
    "uint64",
}


class _Map(list[tuple[str, object]]):
    """An ordered mapping, with the flow style PyYAML decided for it."""

    flow: bool = False


class _Seq(list[object]):
    flow: bool = False


class _Binary(bytes):
    pass


class _Builder:
    """Builds the instance the way PyYAML's representer walks it, deciding styles as it does."""

    def __init__(self, spec_of: Callable[[str], MsgSpec], flow: bool | None, fill: bool) -> None:
        self.spec_of = spec_of
        self.requested = flow
        self.style: bool | None = bool(flow)  # PyYAML's default_flow_style while representing
        self.fill = fill
        self.excluded: set[str] = set()

    def scalar(self, base: str, *, in_array: bool = False) -> object:
        if base in _INTEGERS:
            return 0
        if base in ("float32", "float64"):
            return 0 if in_array else 0.0
        if base == "string":
            return ""
        if base == "bool":
            return False
        return self.message(
            {"time": "std_msgs/Time", "duration": "std_msgs/Duration"}.get(base, base)
        )

    def message(self, name: str) -> _Map:
        if name in ("std_msgs/Time", "std_msgs/Duration"):
            fields: list[tuple[str, object]] = [("secs", 0), ("nsecs", 0)]
            return self._mapping(fields)
        spec = self.spec_of(name)
        items: list[tuple[str, object]] = []
        for field in spec.fields:
            if field.name in self.excluded:
                continue
            if not field.is_array:
                items.append((field.name, field))
                continue
            if field.base_type in ("uint8", "char"):
                items.append((field.name, _Binary(bytes(field.array_len or 0))))
            elif field.array_len is not None:
                if field.array_len > _MANY:
                    self.style = self.requested
                items.append((field.name, ("fixed", field)))
            else:
                items.append((field.name, ("variable", field)))
        if len(items) > _MANY:
            self.style = self.requested
        return self._mapping(items)

    def _value(self, value: object) -> object:
        from rosx.msg.spec import Field  # noqa: PLC0415 - the message layer loads on first use

        if isinstance(value, Field):
            return self.scalar(value.base_type)
        if isinstance(value, tuple) and len(value) == 2 and isinstance(value[1], Field):
            kind, field = value
            if kind == "fixed":
                items = [self.scalar(field.base_type) for _ in range(field.array_len or 0)]
            elif self.fill:
                items = [self.scalar(field.base_type, in_array=True)]
            else:
                items = []
            return self._sequence(items)
        return value

    def _mapping(self, items: list[tuple[str, object]]) -> _Map:
        node = _Map()
        best = True
        for key, value in items:
            child = self._value(value)
            if isinstance(child, (_Map, _Seq, _Binary)):
                best = False
            node.append((key, child))
        node.flow = self.style if self.style is not None else best
        return node

    def _sequence(self, items: list[object]) -> _Seq:
        node = _Seq(items)
        best = not any(isinstance(i, (_Map, _Seq, _Binary)) for i in items)
        node.flow = self.style if self.style is not None else best
        return node


def _scalar(value: object) -> str:
    if isinstance(value, _Binary):
        import base64  # noqa: PLC0415 - base64 is not needed at start-up

        return f'!!binary "{base64.b64encode(value).decode()}"'
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return "''"
    return repr(value)


class _Writer:
    def __init__(self) -> None:
        self.text = ""

    @property
    def column(self) -> int:
        return len(self.text) - (self.text.rfind("\n") + 1)

    def flow(self, node: object, indent: int) -> None:
        if not isinstance(node, (_Map, _Seq)) or not node:
            self.text += (
                ("{}" if isinstance(node, _Map) else "[]")
                if isinstance(node, (_Map, _Seq))
                else _scalar(node)
            )
            return
        opening, closing = ("{", "}") if isinstance(node, _Map) else ("[", "]")
        self.text += opening
        for number, item in enumerate(node):
            if number:
                self.text += ","
                if self.column > _WIDTH:
                    self.text += "\n" + " " * indent
                else:
                    self.text += " "
            if isinstance(item, tuple) and isinstance(node, _Map):
                self.text += f"{item[0]}: "
                self.flow(item[1], indent + 2)
            else:
                self.flow(item, indent + 2)
        self.text += closing

    def block_value(self, value: object, indent: int) -> None:
        """What follows ``key:`` in a block mapping at ``indent``."""
        if isinstance(value, _Map) and value and not value.flow:
            self.text += "\n"
            self.block_map(value, indent + 2)
        elif isinstance(value, _Seq) and value and not value.flow:
            self.text += "\n"
            self.block_seq(value, indent)
        else:
            self.text += " "
            self.flow(value, indent + 2)

    def block_map(self, node: _Map, indent: int, *, first_inline: bool = False) -> None:
        for number, (key, value) in enumerate(node):
            if number or not first_inline:
                if self.text and not self.text.endswith("\n"):
                    self.text += "\n"
                self.text += " " * indent
            self.text += f"{key}:"
            self.block_value(value, indent)

    def block_seq(self, node: _Seq, indent: int) -> None:
        for item in node:
            if self.text and not self.text.endswith("\n"):
                self.text += "\n"
            self.text += " " * indent + "- "
            if isinstance(item, _Map) and item and not item.flow:
                self.block_map(item, indent + 2, first_inline=True)
            elif isinstance(item, _Seq) and item and not item.flow:
                self.block_seq(item, indent + 2)
            else:
                self.flow(item, indent + 2)


def prototype(
    name: str,
    spec_of: Callable[[str], MsgSpec],
    *,
    flow: bool | None = None,
    fill_arrays: bool = True,
    exclude: tuple[str, ...] = (),
) -> str:
    """The YAML of a default ``name`` message, as rosmsg-proto writes it (without quotes).

    Args:
        name: The message type (a service's ``pkg/SrvRequest`` half too).
        spec_of: The type store's ``msg``.
        flow: ``-f 1`` (True), ``-f 0`` (False) or the heuristic mix (None).
        fill_arrays: One default element in each variable-length array (not ``-e``).
        exclude: Field names left out at any depth (``-x``).

    Raises:
        UnknownTypeError: ``name`` or a type it uses is not known.
    """
    builder = _Builder(spec_of, flow, fill_arrays)
    builder.excluded = set(exclude)
    root = builder.message(name)
    writer = _Writer()
    if root.flow or not root:
        writer.flow(root, 2)
    else:
        writer.block_map(root, 0)
    return writer.text


__all__ = ["prototype"]
