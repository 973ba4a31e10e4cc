"""`Record`: immutable values compared by fields (the wire layer's events, the message specs).

A subclass names its fields, in order, in ``__match_args__`` (so ``case Fault(code, message)``
works), reuses that tuple as ``__slots__``, declares their types, and has a typed ``__init__``
that passes them by name to ``Record.__init__``. This is what a frozen, slotted dataclass gives;
it is written out because command-line tools import these layers on start-up, where importing
`dataclasses` costs about 12 ms and creating each dataclass about 0.4 ms more.
"""

from __future__ import annotations

TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any


class Record:
    """Immutable value with equality, hashing and repr derived from ``__match_args__``."""

    __match_args__: tuple[str, ...] = ()
    __slots__ = ()

    def __init__(self, **fields: object) -> None:
        for name, value in fields.items():
            object.__setattr__(self, name, value)

    def __setattr__(self, name: str, value: Any) -> None:
        raise AttributeError(f"{type(self).__name__} is immutable; cannot set {name!r}")

    def __delattr__(self, name: str) -> None:
        raise AttributeError(f"{type(self).__name__} is immutable; cannot delete {name!r}")

    def _values(self) -> tuple[object, ...]:
        return tuple(getattr(self, name) for name in self.__match_args__)

    def __eq__(self, other: object) -> bool:
        if type(other) is not type(self):
            return NotImplemented
        assert isinstance(other, Record)
        return self._values() == other._values()

    def __hash__(self) -> int:
        return hash((type(self).__qualname__, self._values()))

    def __repr__(self) -> str:
        fields = ", ".join(f"{name}={getattr(self, name)!r}" for name in self.__match_args__)
        return f"{type(self).__name__}({fields})"
