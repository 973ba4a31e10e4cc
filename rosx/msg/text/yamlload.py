"""YAML loading with the semantics of PyYAML's ``safe_load``, which ROS 1's tools use.

``rostopic pub``, ``rosservice call`` and ``rosparam`` read their arguments as YAML 1.1 the way
PyYAML does: ``yes``/``on`` are booleans but ``y`` is a string, a float needs a dot (``1e5`` and
``1e-05`` stay strings), ``010`` is octal, ``1:30`` is sexagesimal, a repeated key keeps the last
value. This module loads with ruamel.yaml's pure-Python safe loader, given PyYAML's implicit-type
rules and scanning of plain scalars, and words its errors as PyYAML's. ruamel.yaml is imported on
first use (10-20 ms).

``rostopic pub`` and ``rosservice call`` read standard input as documents each ended by a ``---``
line; `split_stream` and `load_stream` read such a stream (dropping an unterminated last
document, as rostopic does). ``-f FILE`` is an ordinary YAML stream: `load_all`.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable, Iterator
from functools import cache

TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

_BLANKS = "\0 \t\r\n\x85\u2028\u2029"


class YAMLLoadError(ValueError):
    """Text that is not valid YAML; ``str()`` is PyYAML's description with its marks."""


#: The deepest a document may nest collections. PyYAML's scanner and ruamel's take a time
#: that grows with the square of the depth (5 000 ``[`` take ruamel half a minute), and
#: PyYAML's composer fails with a RecursionError by 800; real documents nest a few levels.
MAX_DEPTH = 200
#: The most values a document may hold once its aliases are expanded. An alias shares its
#: anchor's value, so a few lines of nested aliases (``b: [*a, *a, …]``, ``c: [*b, *b, …]``)
#: make a value of billions, which every consumer (the master's XML-RPC, a message, a dump)
#: walks in full. PyYAML and rosparam set no bound.
MAX_EXPANDED = 1_000_000


#: PyYAML's implicit resolvers (YAML 1.1 as PyYAML reads it): tag, pattern, and the first
#: characters of the scalars each is tried on ("" for the empty scalar).
_RESOLVERS = (
    (
        "bool",
        r"^(?:yes|Yes|YES|no|No|NO|true|True|TRUE|false|False|FALSE|on|On|ON|off|Off|OFF)$",
        tuple("yYnNtTfFoO"),
    ),
    (
        "float",
        r"""^(?:[-+]?(?:[0-9][0-9_]*)\.[0-9_]*(?:[eE][-+][0-9]+)?
        |\.[0-9][0-9_]*(?:[eE][-+][0-9]+)?
        |[-+]?[0-9][0-9_]*(?::[0-5]?[0-9])+\.[0-9_]*
        |[-+]?\.(?:inf|Inf|INF)
        |\.(?:nan|NaN|NAN))$""",
        tuple("-+0123456789."),
    ),
    (
        "int",
        r"""^(?:[-+]?0b[0-1_]+
        |[-+]?0[0-7_]+
        |[-+]?(?:0|[1-9][0-9_]*)
        |[-+]?0x[0-9a-fA-F_]+
        |[-+]?[1-9][0-9_]*(?::[0-5]?[0-9])+)$""",
        tuple("-+0123456789"),
    ),
    ("merge", r"^(?:<<)$", ("<",)),
    ("null", r"^(?:~|null|Null|NULL|)$", ("~", "n", "N", "")),
    (
        "timestamp",
        r"""^(?:[0-9]{4}-[0-9]{2}-[0-9]{2}
        |[0-9]{4}-[0-9]{1,2}-[0-9]{1,2}
         (?:[Tt]|[ \t]+)[0-9]{1,2}:[0-9]{2}:[0-9]{2}(?:\.[0-9]*)?
         (?:[ \t]*(?:Z|[-+][0-9]{1,2}(?::[0-9]{2})?))?)$""",
        tuple("0123456789"),
    ),
    ("value", r"^(?:=)$", ("=",)),
    ("yaml", r"^(?:!|&|\*)$", ("!", "&", "*")),
)


@cache
def depth_limited(scanner: type) -> type:
    """A subclass of the ruamel.yaml scanner class ``scanner`` that refuses collections nested
    more than `MAX_DEPTH` deep (a `ScannerError`, before the square-of-the-depth time)."""
    from ruamel.yaml.scanner import ScannerError  # noqa: PLC0415 - ruamel loads lazily

    class DepthLimited(scanner):  # type: ignore[misc]
        def fetch_flow_collection_start(self, token_class: Any, to_push: str) -> None:
            self._check_depth()
            super().fetch_flow_collection_start(token_class, to_push)

        def add_indent(self, column: int) -> bool:
            self._check_depth()
            return bool(super().add_indent(column))

        def _check_depth(self) -> None:
            if self.flow_level + len(self.indents) >= MAX_DEPTH:
                raise ScannerError(
                    None,
                    None,
                    f"collections nested more than {MAX_DEPTH} deep",
                    self.reader.get_mark(),
                )

    return DepthLimited


@cache
def _loader_factory() -> Any:
    # ruamel.yaml takes 10-20 ms to import: only commands that read YAML pay for it.
    from ruamel.yaml import YAML  # noqa: PLC0415 - ruamel loads only on this path
    from ruamel.yaml.composer import Composer, ComposerError  # noqa: PLC0415 - ruamel loads only on this path
    from ruamel.yaml.constructor import SafeConstructor  # noqa: PLC0415 - ruamel loads only on this path
    from ruamel.yaml.events import AliasEvent  # noqa: PLC0415 - ruamel loads only on this path
    from ruamel.yaml.resolver import VersionedResolver  # noqa: PLC0415 - ruamel loads only on this path
    from ruamel.yaml.scanner import Scanner  # noqa: PLC0415 - ruamel loads only on this path
    from ruamel.yaml.tokens import ScalarToken  # noqa: PLC0415 - ruamel loads only on this path

    entries: dict[str | None, list[tuple[str, re.Pattern[str]]]] = {}
    for name, pattern, firsts in _RESOLVERS:
        compiled = re.compile(pattern, re.VERBOSE)
        for first in firsts:
            entries.setdefault(first, []).append((f"tag:yaml.org,2002:{name}", compiled))
    # Tuples: ruamel extends the list it gets with ``+=``, which must not change the table.
    table = {key: tuple(value) for key, value in entries.items()} | {None: ()}

    class PyYAMLResolver(VersionedResolver):
        """ruamel's resolver, reading YAML 1.1 with exactly PyYAML's implicit types."""

        @property
        def versioned_resolver(self) -> dict[str | None, tuple[tuple[str, re.Pattern[str]], ...]]:
            return table

    class PyYAMLConstructor(SafeConstructor):
        """PyYAML's values: a repeated key replaces the earlier value; unnamed time zones."""

        def check_mapping_key(self, *args: Any) -> bool:
            return True

        def construct_yaml_timestamp(self, node: Any, values: Any = None) -> Any:
            import datetime as dt  # noqa: PLC0415 - ruamel has imported it by now

            value = super().construct_yaml_timestamp(node, values)
            offset = value.utcoffset() if isinstance(value, dt.datetime) else None
            return value if offset is None else value.replace(tzinfo=dt.timezone(offset))

    PyYAMLConstructor.add_constructor(
        "tag:yaml.org,2002:timestamp", PyYAMLConstructor.construct_yaml_timestamp
    )

    class PyYAMLScanner(depth_limited(Scanner)):  # type: ignore[misc]
        """Plain scalars end where PyYAML ends them: in flow context, ``a:{`` is ``a`` + ``:``.
        Collections nest at most `MAX_DEPTH` deep."""

        def scan_plain(self) -> Any:
            reader = self.reader
            chunks: list[str] = []
            start_mark = end_mark = reader.get_mark()
            indent = self.indent + 1
            spaces: list[str] = []
            stops = _BLANKS + (",[]{}" if self.flow_level else "")
            while reader.peek() != "#":
                length = 0
                while True:
                    ch = reader.peek(length)
                    if (
                        ch in _BLANKS
                        or (ch == ":" and reader.peek(length + 1) in stops)
                        or (self.flow_level and ch in ",?[]{}")
                    ):
                        break
                    length += 1
                if length == 0:
                    break
                self.allow_simple_key = False
                chunks.extend(spaces)
                chunks.append(reader.prefix(length))
                reader.forward(length)
                end_mark = reader.get_mark()
                spaces = self.scan_plain_spaces(indent, start_mark)
                if (
                    not spaces
                    or reader.peek() == "#"
                    or (not self.flow_level and reader.column < indent)
                ):
                    break
            return ScalarToken("".join(chunks), True, start_mark, end_mark)

    class PyYAMLComposer(Composer):
        """A reused anchor is an error, not a warning; aliases may not make a value its own
        part, nor expand a document beyond `MAX_EXPANDED` values."""

        def compose_document(self) -> Any:
            node = super().compose_document()
            expanded: dict[int, int] = {}

            def size(item: Any, path: set[int]) -> int:
                known = expanded.get(id(item))
                if known is not None:
                    return known
                if id(item) in path:
                    raise ComposerError(
                        None, None, "found an alias inside its own anchor", item.start_mark
                    )
                total = 1
                if isinstance(item.value, list):
                    path.add(id(item))
                    for child in item.value:
                        for part in child if isinstance(child, tuple) else (child,):
                            total += size(part, path)
                    path.discard(id(item))
                if total > MAX_EXPANDED:
                    raise ComposerError(
                        None,
                        None,
                        f"aliases expand the document beyond {MAX_EXPANDED} values",
                        item.start_mark,
                    )
                expanded[id(item)] = total
                return total

            if node is not None:
                size(node, set())
            return node

        def compose_node(self, parent: Any, index: Any) -> Any:
            event = self.parser.peek_event()
            anchor = getattr(event, "anchor", None)
            if anchor in self.anchors and not isinstance(event, AliasEvent):
                raise ComposerError(
                    f"found duplicate anchor {anchor!r}; first occurrence",
                    self.anchors[anchor].start_mark,
                    "second occurrence",
                    event.start_mark,
                )
            return super().compose_node(parent, index)

    def make() -> Any:
        yaml = YAML(typ="safe", pure=True)
        yaml.version = (1, 1)
        yaml.Resolver = PyYAMLResolver
        yaml.Constructor = PyYAMLConstructor
        yaml.Scanner = PyYAMLScanner
        yaml.Composer = PyYAMLComposer
        return yaml

    return make


def load(text: str) -> Any:
    """One YAML document, as ``yaml.safe_load(text)``; `YAMLLoadError` if it is not YAML."""
    from ruamel.yaml.error import YAMLError  # noqa: PLC0415 - see _loader_factory

    try:
        return _loader_factory()().load(text)
    except YAMLError as error:
        raise YAMLLoadError(_describe(error, "<unicode string>")) from None
    except RecursionError:
        raise YAMLLoadError(_TOO_DEEP) from None
    except _CONSTRUCTION_ERRORS as error:
        raise YAMLLoadError(invalid_value(error)) from None


def load_all(text: str, *, filename: str | None = None) -> list[Any]:
    """Every document of a YAML stream, as ``list(yaml.safe_load_all(text))``.

    With ``filename`` errors read as PyYAML's for an open file: named after it, no snippets.
    """
    from ruamel.yaml.error import YAMLError  # noqa: PLC0415 - see _loader_factory

    try:
        return list(_loader_factory()().load_all(text))
    except RecursionError:
        raise YAMLLoadError(_TOO_DEEP) from None
    except _CONSTRUCTION_ERRORS as error:
        raise YAMLLoadError(invalid_value(error)) from None
    except YAMLError as error:
        if filename is None:
            raise YAMLLoadError(_describe(error, "<unicode string>")) from None
        raise YAMLLoadError(_describe(error, filename, snippets=False)) from None


#: Nesting deeper than Python's stack (PyYAML's own recursion fails there too).
_TOO_DEEP = "the document is nested too deeply"
#: What a value's constructor raises for a scalar its tag does not fit (``!!int x``, a
#: timestamp of month 13, ``!!bool 2``): PyYAML lets these escape.
_CONSTRUCTION_ERRORS = (ValueError, TypeError, OverflowError, LookupError)


def invalid_value(error: Exception) -> str:
    """The text of `YAMLLoadError` for a scalar its tag cannot make a value of."""
    return f"invalid value: {error}"


def split_stream(lines: Iterable[str]) -> Iterator[str]:
    """The documents of a ``---``-separated line stream, as ``rostopic pub`` reads stdin.

    A document ends at a line that is ``---`` once stripped; its text is yielded without
    trailing whitespace. Text after the last ``---`` is dropped: rostopic publishes only
    complete documents.
    """
    buffer: list[str] = []
    for line in lines:
        if line.strip() == "---":
            yield "".join(buffer).rstrip()
            buffer = []
        else:
            buffer.append(line)


def load_stream(
    lines: Iterable[str], on_error: Callable[[YAMLLoadError], object] | None = None
) -> Iterator[Any]:
    """The values in a ``---``-separated stream (stdin of ``rostopic pub``, ``rosservice call``).

    Empty documents are skipped; an invalid one is passed to ``on_error`` (rostopic prints
    ``Invalid YAML: …`` and reads on) and skipped.
    """
    for text in split_stream(lines):
        try:
            value = load(text)
        except YAMLLoadError as error:
            if on_error is not None:
                on_error(error)
            continue
        if value is not None:
            yield value


def _describe(error: Exception, name: str, *, snippets: bool = True) -> str:
    """The error as PyYAML words it (ruamel adds line numbers to the caret, and notes)."""
    context = getattr(error, "context", None)
    context_mark = getattr(error, "context_mark", None)
    problem = getattr(error, "problem", None)
    problem_mark = getattr(error, "problem_mark", None)
    if problem is None and context is None:
        return str(error)
    lines: list[str] = []
    if context is not None:
        lines.append(str(context))
    if context_mark is not None and (
        problem is None
        or problem_mark is None
        or (context_mark.line, context_mark.column) != (problem_mark.line, problem_mark.column)
    ):
        lines.append(_mark(context_mark, name, snippets))
    if problem is not None:
        # ruamel shows some tokens as one-element tuples: "found (']',)".
        lines.append(re.sub(r"\(('[^']*'),\)", r"\1", str(problem)))
    if problem_mark is not None:
        lines.append(_mark(problem_mark, name, snippets))
    return "\n".join(lines)


_LINE_ENDS = "\0\r\n\x85\u2028\u2029"


def _mark(mark: Any, name: str, snippets: bool) -> str:
    where = f'  in "{name}", line {mark.line + 1}, column {mark.column + 1}'
    buffer = getattr(mark, "buffer", None)
    if buffer is None or not snippets:
        return where
    pointer: int = mark.pointer
    # The snippet shows at most ~75 characters around the pointer, cut with " ... ".
    half = 75 / 2 - 1
    head = tail = ""
    start = pointer
    while start > 0 and buffer[start - 1] not in _LINE_ENDS:
        start -= 1
        if pointer - start > half:
            head, start = " ... ", start + 5
            break
    end = pointer
    while end < len(buffer) and buffer[end] not in _LINE_ENDS:
        end += 1
        if end - pointer > half:
            tail, end = " ... ", end - 5
            break
    caret = " " * (4 + pointer - start + len(head)) + "^"
    return f"{where}:\n    {head}{buffer[start:end]}{tail}\n{caret}"


__all__ = ["YAMLLoadError", "load", "load_all", "load_stream", "split_stream"]
