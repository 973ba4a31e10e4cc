"""Stage's world-file syntax, sans-I/O: text in, a tree of entities out.

A world file is a list of statements (Stage's ``worldfile.cc`` grammar):

- ``name value`` or ``name [ value value ... ]``: a property of the enclosing entity;
- ``type ( statements )``: an entity (a model, ``window``, ``sensor``...), nested freely;
- ``define NAME PARENT ( statements )``: a new entity type, ``NAME``, that is ``PARENT`` with
  these properties and children as defaults;
- ``include "file"``: the statements of another file, in place.

Values are numbers or ``"strings"``; ``#`` starts a comment. `parse` reads one file and asks an
injected ``load`` function for each include, so this module touches no file system; it gives
`Entity` trees whose defined types are already expanded (each entity knows its base type and
carries its definitions' properties under its own). A syntax error is one `WorldFileError`
naming ``file:line``.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from collections.abc import Callable, Iterator

#: Nested includes deeper than this are taken for an include loop.
MAX_INCLUDE_DEPTH = 16
#: The deepest entities may nest (Stage's examples nest three or four deep).
MAX_NESTING = 64
#: The most entities a world may make, definitions expanded: a define holding two instances
#: of the previous one doubles with every line, a billion models in thirty.
MAX_ENTITIES = 20_000

_TOKEN = re.compile(
    r"""(?P<space>[ \t\r]+)|(?P<newline>\n)|(?P<comment>\#[^\n]*)
    |(?P<string>"[^"\n]*")|(?P<punct>[()\[\]])|(?P<word>[^\s()\[\]"\#]+)""",
    re.VERBOSE,
)


class WorldFileError(ValueError):
    """A world file that cannot be read; the message starts with ``file:line:``."""


@dataclass(frozen=True)
class Where:
    """A place in a world file."""

    file: str
    line: int

    def __str__(self) -> str:
        return f"{self.file}:{self.line}"


@dataclass(frozen=True)
class Value:
    """A property's value: numbers as floats, strings unquoted; always a tuple."""

    items: tuple[float | str, ...]
    where: Where


@dataclass
class Entity:
    """One entity: ``kind`` is its base type (after expanding ``define``), ``declared`` the
    type its statement named; ``props`` hold the definitions' values overridden by its own."""

    kind: str
    declared: str
    where: Where
    props: dict[str, Value] = field(default_factory=dict)
    children: list[Entity] = field(default_factory=list)


@dataclass(frozen=True)
class _Token:
    kind: str  # "string", "punct" or "word"
    text: str
    where: Where


@dataclass
class _Define:
    parent: str
    props: dict[str, Value]
    children: list[Entity]


def _tokens(text: str, file: str) -> Iterator[_Token]:
    line = 1
    for match in _TOKEN.finditer(text):
        kind = match.lastgroup or ""
        if kind == "newline":
            line += 1
        elif kind in ("string", "punct", "word"):
            yield _Token(kind, match.group(), Where(file, line))
    # finditer skips nothing: every character matches one of the groups


def _number_or_word(token: _Token) -> float | str:
    if token.kind == "string":
        return token.text[1:-1]
    try:
        return float(token.text)
    except ValueError:
        return token.text


class _Parser:
    def __init__(self, load: Callable[[str, str], tuple[str, str]]) -> None:
        self.load = load
        self.defines: dict[str, _Define] = {}
        self.depth = 0
        self.nesting = 0
        self.entities = 0

    def parse_file(self, text: str, file: str, into: Entity) -> None:
        tokens = list(_tokens(text, file))
        end = self._statements(tokens, 0, into, top=True)
        if end != len(tokens):
            raise WorldFileError(f"{tokens[end].where}: unexpected '{tokens[end].text}'")

    def _statements(self, tokens: list[_Token], i: int, into: Entity, *, top: bool) -> int:
        while i < len(tokens):
            token = tokens[i]
            if token.text == ")" and token.kind == "punct":
                if top:
                    raise WorldFileError(f"{token.where}: ')' without a matching '('")
                return i
            if token.kind != "word":
                raise WorldFileError(f"{token.where}: expected a name, found '{token.text}'")
            name = token.text
            following = tokens[i + 1] if i + 1 < len(tokens) else None
            if name == "include":
                i = self._include(tokens, i, into)
            elif name == "define":
                i = self._define(tokens, i)
            elif following is not None and following.text == "(" and following.kind == "punct":
                child = self._entity(name, token.where)
                i = self._body(tokens, i + 2, child)
                into.children.append(child)
            else:
                i = self._property(tokens, i, into)
        if not top:
            raise WorldFileError(f"{tokens[-1].where}: missing ')' at the end of the file")
        return i

    def _body(self, tokens: list[_Token], i: int, entity: Entity) -> int:
        if self.nesting >= MAX_NESTING:
            raise WorldFileError(
                f"{tokens[i - 1].where}: entities nested more than {MAX_NESTING} deep"
            )
        self.nesting += 1
        try:
            i = self._statements(tokens, i, entity, top=False)
        finally:
            self.nesting -= 1
        return i + 1  # the ")"

    def _include(self, tokens: list[_Token], i: int, into: Entity) -> int:
        where = tokens[i].where
        if i + 1 >= len(tokens) or tokens[i + 1].kind != "string":
            raise WorldFileError(f'{where}: include needs a "file name"')
        if self.depth >= MAX_INCLUDE_DEPTH:
            raise WorldFileError(f"{where}: includes nested too deep (an include loop?)")
        name = tokens[i + 1].text[1:-1]
        try:
            text, file = self.load(name, where.file)
        except OSError as exc:
            reason = exc.strerror or str(exc)
            raise WorldFileError(f"{where}: cannot include '{name}': {reason}") from None
        self.depth += 1
        try:
            self.parse_file(text, file, into)
        finally:
            self.depth -= 1
        return i + 2

    def _define(self, tokens: list[_Token], i: int) -> int:
        where = tokens[i].where
        parts = tokens[i + 1 : i + 4]
        if (
            len(parts) < 3
            or parts[0].kind != "word"
            or parts[1].kind != "word"
            or parts[2].text != "("
        ):
            raise WorldFileError(f"{where}: expected 'define NAME PARENT ( ... )'")
        holder = Entity("", "", where)
        end = self._body(tokens, i + 4, holder)
        self.defines[parts[0].text] = _Define(parts[1].text, holder.props, holder.children)
        return end

    def _property(self, tokens: list[_Token], i: int, into: Entity) -> int:
        token = tokens[i]
        if i + 1 >= len(tokens):
            raise WorldFileError(f"{token.where}: '{token.text}' has no value")
        value = tokens[i + 1]
        if value.text == "[" and value.kind == "punct":
            items: list[float | str] = []
            j = i + 2
            while j < len(tokens) and not (tokens[j].kind == "punct" and tokens[j].text == "]"):
                if tokens[j].kind == "punct":
                    raise WorldFileError(f"{tokens[j].where}: unexpected '{tokens[j].text}'")
                items.append(_number_or_word(tokens[j]))
                j += 1
            if j >= len(tokens):
                raise WorldFileError(f"{value.where}: '[' without a matching ']'")
            into.props[token.text] = Value(tuple(items), token.where)
            return j + 1
        if value.kind == "punct":
            raise WorldFileError(f"{value.where}: unexpected '{value.text}' after '{token.text}'")
        into.props[token.text] = Value((_number_or_word(value),), token.where)
        return i + 2

    def _entity(self, declared: str, where: Where) -> Entity:
        """A new entity of type ``declared``, its definitions' defaults filled in."""
        chain: list[_Define] = []
        kind = declared
        seen: set[str] = set()
        while kind in self.defines:
            if kind in seen:
                raise WorldFileError(f"{where}: '{declared}' is defined in terms of itself")
            seen.add(kind)
            chain.append(self.defines[kind])
            kind = self.defines[kind].parent
        entity = Entity(kind, declared, where)
        for define in reversed(chain):  # the base type's defaults first
            entity.props.update(define.props)
            entity.children.extend(self._copy(child, where) for child in define.children)
        self._count(where)
        return entity

    def _copy(self, entity: Entity, where: Where) -> Entity:
        """A deep copy of a definition's child, counted as the entities it makes."""
        self._count(where)
        return Entity(
            entity.kind,
            entity.declared,
            entity.where,
            dict(entity.props),
            [self._copy(child, where) for child in entity.children],
        )

    def _count(self, where: Where) -> None:
        self.entities += 1
        if self.entities > MAX_ENTITIES:
            raise WorldFileError(f"{where}: the world makes more than {MAX_ENTITIES} models")


def parse(
    text: str, file: str, load: Callable[[str, str], tuple[str, str]] | None = None
) -> Entity:
    """The world in ``text`` (named ``file`` in messages) as an entity of kind ``world``.

    ``load(name, including_file)`` returns the text and the display name of an included file
    (raising `OSError` when it cannot); without it an include is an error.

    Raises:
        WorldFileError: the text is not a world file (the message names ``file:line``).
    """

    def refuse(name: str, including: str) -> tuple[str, str]:
        raise OSError(f"includes are not available here ({name})")

    world = Entity("world", "world", Where(file, 1))
    _Parser(load or refuse).parse_file(text, file, world)
    return world


__all__ = ["MAX_INCLUDE_DEPTH", "Entity", "Value", "Where", "WorldFileError", "parse"]
