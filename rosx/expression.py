"""Python expressions evaluated without Python's ``eval``: a small interpreter over the AST.

Two users: roslaunch's ``$(eval EXPR)`` (`rosx.launch.substitution`, with the names roslaunch
offers) and rosparam's ``rad(EXPR)`` (`rosx.msg.text.yamlparams`, numbers and ``pi`` only).

`evaluate` takes literals, names (from the caller's ``lookup``), arithmetic, comparisons,
``and``/``or``/``not``, conditional expressions, subscripts and slices, list/tuple/dict/set
displays and comprehensions, f-strings, calls of what ``lookup`` gives, and calls of public
methods of strings, numbers and containers except ``format`` and ``format_map``, which could
reach into objects. Nothing else: no attribute of other objects, no ``lambda``, no assignment.
Huge values (repeated strings, powers, ranges, comprehensions) are refused. `arithmetic` takes
numbers, names, ``+ - * / // % **`` and parentheses only, in floats.

Pure: the standard library's ``ast``, ``builtins``, ``math`` and ``operator``, nothing of rosx.
"""

from __future__ import annotations

import ast
import builtins
import math
import operator
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from collections.abc import Callable, Mapping

_BINARY: dict[type[ast.operator], Callable[[Any, Any], Any]] = {
    ast.Add: operator.add,
    ast.Sub: operator.sub,
    ast.Mult: operator.mul,
    ast.Div: operator.truediv,
    ast.FloorDiv: operator.floordiv,
    ast.Mod: operator.mod,
    ast.Pow: operator.pow,
    ast.LShift: operator.lshift,
    ast.RShift: operator.rshift,
    ast.BitOr: operator.or_,
    ast.BitXor: operator.xor,
    ast.BitAnd: operator.and_,
}
_UNARY: dict[type[ast.unaryop], Callable[[Any], Any]] = {
    ast.UAdd: operator.pos,
    ast.USub: operator.neg,
    ast.Not: operator.not_,
    ast.Invert: operator.invert,
}
_COMPARE: dict[type[ast.cmpop], Callable[[Any, Any], Any]] = {
    ast.Eq: operator.eq,
    ast.NotEq: operator.ne,
    ast.Lt: operator.lt,
    ast.LtE: operator.le,
    ast.Gt: operator.gt,
    ast.GtE: operator.ge,
    ast.Is: operator.is_,
    ast.IsNot: operator.is_not,
    ast.In: lambda a, b: a in b,
    ast.NotIn: lambda a, b: a not in b,
}
#: Python's harmless built-in functions, by name (``range`` bounded by `_MAX_SIZE`).
SAFE_BUILTINS: dict[str, Any] = {
    name: getattr(builtins, name)
    for name in [
        "abs",
        "all",
        "any",
        "bin",
        "bool",
        "chr",
        "dict",
        "divmod",
        "enumerate",
        "filter",
        "float",
        "frozenset",
        "hex",
        "int",
        "len",
        "list",
        "map",
        "max",
        "min",
        "oct",
        "ord",
        "pow",
        "range",
        "repr",
        "reversed",
        "round",
        "set",
        "sorted",
        "str",
        "sum",
        "tuple",
        "zip",
    ]
}
_MAX_SIZE = 10_000_000


def _range(*args: int) -> range:
    """``range``, refused beyond `_MAX_SIZE` items (a runaway loop would hang the launch)."""
    span = range(*args)
    if len(span) > _MAX_SIZE:
        raise ValueError("range too large")
    return span


SAFE_BUILTINS["range"] = _range
#: Everything public in `math`, by name.
MATH = {name: value for name, value in vars(math).items() if not name.startswith("_")}
_SAFE_TYPES = (str, int, float, bool, list, tuple, dict, set, frozenset, range, bytes)
_UNSAFE_METHODS = frozenset({"format", "format_map"})


class Interpreter:
    """The value of a parsed expression; names not bound by a comprehension come from
    ``lookup``, which raises `NameError` for a name it does not know."""

    def __init__(self, lookup: Callable[[str], Any]) -> None:
        self.lookup = lookup

    def name(self, name: str, local: dict[str, Any]) -> Any:
        """The value of ``name``: a comprehension's variable, else the caller's."""
        if name in local:
            return local[name]
        return self.lookup(name)

    def value(self, node: ast.AST, local: dict[str, Any]) -> Any:
        """The value of ``node`` with the comprehension variables ``local``.

        Raises:
            ValueError: ``node`` is outside the language, or too large a value.
        """
        match node:
            case ast.Constant(value=value):
                return value
            case ast.Name(id=name):
                return self.name(name, local)
            case ast.BinOp(left=left, op=op, right=right) if type(op) in _BINARY:
                a, b = self.value(left, local), self.value(right, local)
                _check_size(op, a, b)
                return _BINARY[type(op)](a, b)
            case ast.UnaryOp(op=op, operand=operand) if type(op) in _UNARY:
                return _UNARY[type(op)](self.value(operand, local))
            case ast.BoolOp(op=ast.And(), values=values):
                result: Any = True
                for item in values:
                    result = self.value(item, local)
                    if not result:
                        return result
                return result
            case ast.BoolOp(op=ast.Or(), values=values):
                result = False
                for item in values:
                    result = self.value(item, local)
                    if result:
                        return result
                return result
            case ast.Compare(left=left, ops=ops, comparators=comparators):
                current = self.value(left, local)
                for comparison, right in zip(ops, comparators, strict=True):
                    other = self.value(right, local)
                    if not _COMPARE[type(comparison)](current, other):
                        return False
                    current = other
                return True
            case ast.IfExp(test=test, body=body, orelse=orelse):
                return self.value(body if self.value(test, local) else orelse, local)
            case ast.Subscript(value=container, slice=index):
                return self.value(container, local)[self.value(index, local)]
            case ast.Slice(lower=lower, upper=upper, step=step):
                parts = [None if p is None else self.value(p, local) for p in (lower, upper, step)]
                return slice(*parts)
            case ast.List(elts=items):
                return [self.value(item, local) for item in items]
            case ast.Tuple(elts=items):
                return tuple(self.value(item, local) for item in items)
            case ast.Set(elts=items):
                return {self.value(item, local) for item in items}
            case ast.Dict(keys=keys, values=values):
                if any(key is None for key in keys):
                    raise ValueError("** in a dictionary display is not supported")
                return {
                    self.value(k, local): self.value(v, local)
                    for k, v in zip(keys, values, strict=True)
                    if k is not None
                }
            case ast.JoinedStr(values=parts):
                return "".join(str(self.value(part, local)) for part in parts)
            case ast.FormattedValue(value=inner, conversion=conversion, format_spec=spec):
                shown = self.value(inner, local)
                if conversion == ord("r"):
                    shown = repr(shown)
                elif conversion in (ord("s"), ord("a")):
                    shown = str(shown) if conversion == ord("s") else ascii(shown)
                return format(shown, "" if spec is None else self.value(spec, local))
            case ast.Call(func=func, args=args, keywords=keywords):
                function = self.callable(func, local)
                positional = [self.value(a, local) for a in args]
                named = {k.arg: self.value(k.value, local) for k in keywords if k.arg}
                if len(named) != len(keywords) or any(isinstance(a, ast.Starred) for a in args):
                    raise ValueError("* and ** in calls are not supported")
                return function(*positional, **named)
            case ast.ListComp(elt=elt, generators=generators):
                return [self.value(elt, scope) for scope in self.loops(generators, local)]
            case ast.SetComp(elt=elt, generators=generators):
                return {self.value(elt, scope) for scope in self.loops(generators, local)}
            case ast.GeneratorExp(elt=elt, generators=generators):
                return [self.value(elt, scope) for scope in self.loops(generators, local)]
            case ast.DictComp(key=key, value=item, generators=generators):
                return {
                    self.value(key, scope): self.value(item, scope)
                    for scope in self.loops(generators, local)
                }
        raise ValueError(f"{type(node).__name__} expressions are not supported")

    def callable(self, func: ast.expr, local: dict[str, Any]) -> Any:
        """What a call calls: a name's value, or a public method of a plain value."""
        if isinstance(func, ast.Attribute):
            owner = self.value(func.value, local)
            if (
                func.attr.startswith("_")
                or func.attr in _UNSAFE_METHODS
                or not isinstance(owner, _SAFE_TYPES)
            ):
                raise AttributeError(f"the method '{func.attr}' is not available")
            return getattr(owner, func.attr)
        function = self.value(func, local)
        if not callable(function):
            raise TypeError(f"'{type(function).__name__}' object is not callable")
        return function

    def loops(
        self, generators: list[ast.comprehension], local: dict[str, Any]
    ) -> list[dict[str, Any]]:
        """The variables of each round of a comprehension's loops, filters applied."""
        scopes = [dict(local)]
        for generator in generators:
            if generator.is_async:
                raise ValueError("async comprehensions are not supported")
            following: list[dict[str, Any]] = []
            for scope in scopes:
                for item in self.value(generator.iter, scope):
                    inner = dict(scope)
                    _bind(generator.target, item, inner)
                    if all(self.value(test, inner) for test in generator.ifs):
                        following.append(inner)
                        if len(following) > _MAX_SIZE:
                            raise ValueError("comprehension too large")
            scopes = following
        return scopes


def _bind(target: ast.expr, item: Any, scope: dict[str, Any]) -> None:
    if isinstance(target, ast.Name):
        scope[target.id] = item
    elif isinstance(target, ast.Tuple | ast.List):
        items = list(item)
        if len(items) != len(target.elts):
            raise ValueError("wrong number of values to unpack")
        for sub, value in zip(target.elts, items, strict=True):
            _bind(sub, value, scope)
    else:
        raise ValueError("only names and tuples can be loop targets")


def _check_size(op: ast.operator, a: Any, b: Any) -> None:
    if isinstance(op, ast.Pow) and isinstance(b, int) and abs(b) > 10_000 and a not in (0, 1, -1):
        raise ValueError("exponent too large")
    if isinstance(op, ast.LShift) and isinstance(b, int) and b > 100_000:
        raise ValueError("shift too large")
    if isinstance(op, ast.Mult):
        for seq, count in ((a, b), (b, a)):
            sized = isinstance(seq, str | list | tuple | bytes) and isinstance(count, int)
            if sized and len(seq) * count > _MAX_SIZE:
                raise ValueError("result too large")


def evaluate(expression: str, lookup: Callable[[str], Any]) -> Any:
    """The value of the Python expression ``expression``, names given by ``lookup``.

    Raises:
        SyntaxError: ``expression`` is not a Python expression.
        ValueError: it uses what this language leaves out, or makes too large a value.
        ArithmeticError, TypeError, LookupError, AttributeError, NameError, RecursionError:
            as evaluating it in Python would (an unknown name, a method not offered…).
    """
    tree = ast.parse(expression.strip(), mode="eval")
    return Interpreter(lookup).value(tree.body, {})


_ARITHMETIC = (ast.Add, ast.Sub, ast.Mult, ast.Div, ast.FloorDiv, ast.Mod, ast.Pow)
_SIGNS = (ast.UAdd, ast.USub)


def arithmetic(expression: str, names: Mapping[str, float]) -> float:
    """The value of an arithmetic expression over numbers and ``names``, computed in floats.

    Raises:
        SyntaxError: ``expression`` is not a Python expression.
        ValueError: anything but numbers, ``names``, ``+ - * / // % **``, signs and
            parentheses, or an exponent above 1024.
        ArithmeticError, RecursionError: as Python would.
    """

    def value_of(node: ast.AST) -> float:
        if isinstance(node, ast.Constant) and isinstance(node.value, int | float):
            return float(node.value)
        if isinstance(node, ast.Name) and node.id in names:
            return names[node.id]
        if isinstance(node, ast.BinOp) and isinstance(node.op, _ARITHMETIC):
            if isinstance(node.op, ast.Pow) and abs(value_of(node.right)) > 1024:
                raise ValueError("exponent too large")
            return float(_BINARY[type(node.op)](value_of(node.left), value_of(node.right)))
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, _SIGNS):
            return float(_UNARY[type(node.op)](value_of(node.operand)))
        raise ValueError(f"not an arithmetic expression: {expression}")

    return value_of(ast.parse(expression.strip(), mode="eval").body)


__all__ = ["MATH", "SAFE_BUILTINS", "Interpreter", "arithmetic", "evaluate"]
