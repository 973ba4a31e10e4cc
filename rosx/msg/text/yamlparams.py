"""Parameter values as YAML, with the rules of ROS 1's ``rosparam``.

Reading (`load_value` for ``rosparam set``, `load_documents` for ``rosparam load``) is PyYAML's
``safe_load`` (see `rosx.msg.text.yamlload`) plus what rosparam registers with it:

* ``!degrees X`` and a plain ``deg(X)`` are ``float(X) * pi / 180``; an ``X`` that is not a
  number is refused with ``invalid degree value: …``;
* ``!radians EXPR`` and a plain ``rad(EXPR)`` are the value of an arithmetic expression in which
  ``pi`` stands for π (``2*pi``, ``pi/2``); anything else is refused with ``invalid radian
  expression: …`` (rosparam evaluates the text as Python; rosx accepts numbers, ``pi``,
  ``+ - * / // % **`` and parentheses only);
* ``!!binary`` gives bytes, sent to the master as XML-RPC base64.

Writing (`dump_value`) is ``yaml.dump`` (`rosx.msg.text.yamldump`), whose resolver rosparam also
taught ``deg(…)``/``rad(…)``: strings of that shape are quoted so that they read back as strings.

`check_value` refuses what the Parameter Server cannot hold: null, dates (a time stamp is sent as
XML-RPC's ``dateTime.iso8601``, as ROS 1 sends it), sets, integers outside 32 bits, dictionaries
with keys that are not strings.
"""

from __future__ import annotations

import datetime as dt
import math
import re
from functools import cache

from rosx.msg.text.yamldump import dump

# The PyYAML-compatible loader and PyYAML's wording of errors, extended below for rosparam.
from rosx.msg.text.yamlload import (
    _CONSTRUCTION_ERRORS,
    _TOO_DEEP,
    YAMLLoadError,
    _describe,
    _loader_factory,
    invalid_value,
)
from rosx.names.resolution import ns_join

TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

_DEGREES = re.compile(r"^deg\([^\)]*\)$")
_RADIANS = re.compile(r"^rad\([^\)]*\)$")
_INT32 = (-(2**31), 2**31 - 1)


class AngleError(ValueError):
    """A ``!degrees``/``!radians`` value that is not a number or an expression; rosparam's text."""


class ParamValueError(ValueError):
    """A value the Parameter Server cannot store."""


def load_value(text: str) -> Any:
    """One YAML document as ``rosparam set`` reads its value argument.

    Raises:
        YAMLLoadError: the text is not YAML (PyYAML's description).
        AngleError: a ``deg()``/``rad()`` value that cannot be computed.
    """
    from ruamel.yaml.error import YAMLError  # noqa: PLC0415 - ruamel loads lazily

    try:
        return _params_loader()().load(text)
    except YAMLError as error:
        raise YAMLLoadError(_describe(error, "<unicode string>")) from None
    except RecursionError:
        raise YAMLLoadError(_TOO_DEEP) from None
    except AngleError:
        raise
    except _CONSTRUCTION_ERRORS as error:
        raise YAMLLoadError(invalid_value(error)) from None


def load_documents(text: str) -> list[Any]:
    """Every document of a YAML stream, as ``rosparam load`` reads a file or stdin."""
    from ruamel.yaml.error import YAMLError  # noqa: PLC0415 - ruamel loads lazily

    try:
        return list(_params_loader()().load_all(text))
    except YAMLError as error:
        raise YAMLLoadError(_describe(error, "<unicode string>")) from None
    except RecursionError:
        raise YAMLLoadError(_TOO_DEEP) from None
    except AngleError:
        raise
    except _CONSTRUCTION_ERRORS as error:
        raise YAMLLoadError(invalid_value(error)) from None


def dump_value(value: object) -> str:
    """``value`` as rosparam's ``yaml.dump(value)`` writes it."""
    return dump(value, implicit=_angle_shaped)


def check_value(value: object, name: str = "") -> None:
    """Raise `ParamValueError` unless XML-RPC (and so the Parameter Server) can carry ``value``.

    ``name`` is the parameter being set; errors name it, or the key below it that is wrong.
    """
    if isinstance(value, bool | float | str | bytes):
        return
    if isinstance(value, int):
        if not _INT32[0] <= value <= _INT32[1]:
            raise ParamValueError(
                f"cannot set parameter [{name}]: {value} is beyond the Parameter Server's 32-bit "
                f"integers ({_INT32[0]} to {_INT32[1]})"
            )
        return
    if isinstance(value, list | tuple):
        for item in value:
            check_value(item, name)
        return
    if isinstance(value, dict):
        for key, item in value.items():
            if not isinstance(key, str):
                raise ParamValueError(
                    f"YAML dictionaries must have string keys. Invalid dictionary is:\n{value}"
                )
            path = ns_join(name, key) if name else key
            if item is None and ":" in key:
                # The hint for ``{x:5}`` (the message-arguments module's, loaded only here).
                from rosx.msg.text.yamlargs import _colon_hint  # noqa: PLC0415 - the text forms load on first use

                raise ParamValueError(f"cannot set parameter [{path}]{_colon_hint(key, item)}")
            check_value(item, path)
        return

    if isinstance(value, dt.datetime):
        return  # sent as XML-RPC's dateTime.iso8601, as ROS 1's rosparam sends it
    raise ParamValueError(
        f"cannot set parameter [{name}]: the Parameter Server cannot store {_describe_value(value)}"
    )


def _describe_value(value: object) -> str:
    if value is None:
        return "null (an empty value)"

    if isinstance(value, dt.date):
        return f"a date ({value}); quote it for a string"
    return f"a {type(value).__name__} ({value!r})"


def _angle_shaped(text: str) -> bool:
    return _DEGREES.match(text) is not None or _RADIANS.match(text) is not None


def degrees(text: str) -> float:
    """The radians of ``!degrees text`` / ``deg(text)``."""
    expression = text.strip()[4:-1] if text.startswith("deg(") else text
    try:
        return float(expression) * math.pi / 180.0
    except ValueError:
        raise AngleError(f"invalid degree value: {text}") from None


def radians(text: str) -> float:
    """The value of ``!radians text`` / ``rad(text)``."""
    value = text.strip()
    expression = value[4:-1] if value.startswith("rad(") else value
    try:
        return float(_arithmetic(expression))
    except (ValueError, ArithmeticError, SyntaxError, RecursionError):
        raise AngleError(f"invalid radian expression: {value}") from None


def _arithmetic(expression: str) -> float:
    from rosx.expression import arithmetic  # noqa: PLC0415 - only angle expressions need it

    return arithmetic(expression, {"pi": math.pi})


@cache
def _params_loader() -> Any:
    make = _loader_factory()
    base = make()
    resolver_class = base.Resolver
    constructor_class = base.Constructor

    class ParamsResolver(resolver_class):  # type: ignore[misc, valid-type]
        """PyYAML's implicit types and rosparam's ``deg(…)`` and ``rad(…)``."""

        @property
        def versioned_resolver(self) -> dict[str | None, tuple[tuple[str, re.Pattern[str]], ...]]:
            table = dict(super().versioned_resolver)
            table["d"] = (*table.get("d", ()), ("!degrees", _DEGREES))
            table["r"] = (*table.get("r", ()), ("!radians", _RADIANS))
            return table

    class ParamsConstructor(constructor_class):  # type: ignore[misc, valid-type]
        """Angles as floats."""

    def construct_degrees(constructor: Any, node: Any) -> float:
        return degrees(str(constructor.construct_scalar(node)))

    def construct_radians(constructor: Any, node: Any) -> float:
        return radians(str(constructor.construct_scalar(node)))

    ParamsConstructor.add_constructor("!degrees", construct_degrees)
    ParamsConstructor.add_constructor("!radians", construct_radians)

    def make_params_loader() -> Any:
        yaml = make()
        yaml.Resolver = ParamsResolver
        yaml.Constructor = ParamsConstructor
        return yaml

    return make_params_loader


__all__ = [
    "AngleError",
    "ParamValueError",
    "YAMLLoadError",
    "check_value",
    "degrees",
    "dump_value",
    "load_documents",
    "load_value",
    "radians",
]
