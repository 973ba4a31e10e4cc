"""Python expressions evaluated without Python's ``eval``: a small interpreter over the AST.

Two users: roslaunch's ``$(eval EXPR)`` (`rosx.launch.substitution`, with the names roslaunch
offers) and rosparam's ``rad(EXPR)`` (`rosx.msg.text.yamlparams`, numbers and ``pi`` only).

`evaluate` takes literals, names (from the caller's ``lookup``), arithmetic, comparisons,
``and``/``or``/``not``, conditional expressions, subscripts and slices, list/tuple/dict/set
displays and comprehensions, f-strings, calls of what ``lookup`` gives, and calls of public
methods of strings, numbers and containers except ``format`` and ``format_map``, which could
reach into objects, and methods that change their object (``append``, ``update``…). Nothing
else: no attribute of other objects, no ``lambda``, no assignment. `arithmetic` takes numbers,
names, ``+ - * / // % **`` and parentheses only, in floats.

An expression of a few bytes may not take minutes or gigabytes: before anything that could
grow a value far beyond its operands (powers, products and shifts of integers, repeated
sequences, padding and replacing methods, ``%`` and format widths, ``factorial``, ``comb``,
``perm``, ``prod``, ``lcm``, ``sum`` of sequences) the size of the result is checked; no
value may hold more than `MAX_SIZE` items or characters, no integer more than `MAX_BITS` bits,
and an evaluation may take at most `BUDGET` steps and items made, all with `ValueError`.

Pure: the standard library's ``ast``, ``builtins``, ``math`` and ``operator``, nothing of rosx.
"""

from __future__ import annotations

import ast
import builtins
import math
import operator
import re
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
#: Python's harmless built-in functions, by name (``range`` bounded by `MAX_SIZE`).
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
#: The most items (characters, elements, comprehension rounds) one value may hold: far more
#: than a launch file computes, few enough to stay within megabytes.
MAX_SIZE = 100_000
#: The most bits an integer may have (Python prints at most 4 300 digits, about 14 300 bits).
MAX_BITS = 1 << 17
#: The most work one evaluation may do: values computed plus items of the values made.
BUDGET = 100_000


def _range(*args: int) -> range:
    """``range``, refused beyond `MAX_SIZE` items (a runaway loop would hang the launch)."""
    span = range(*args)
    if len(span) > MAX_SIZE:
        raise ValueError("range too large")
    return span


SAFE_BUILTINS["range"] = _range
#: Everything public in `math`, by name.
MATH = {name: value for name, value in vars(math).items() if not name.startswith("_")}
_SAFE_TYPES = (str, int, float, bool, list, tuple, dict, set, frozenset, range, bytes)
_UNSAFE_METHODS = frozenset(
    {"format", "format_map"}  # they reach into objects' attributes
    # They change their object: with a comprehension's variable, ``x.extend(x)`` doubles it
    # each round.
    | {"append", "extend", "insert", "pop", "remove", "reverse", "sort", "clear", "update"}
    | {"setdefault", "popitem", "add", "discard", "difference_update"}
    | {"intersection_update", "symmetric_difference_update"}
)
_SIZED = (str, bytes, list, tuple, dict, set, frozenset)
#: What creates a new value, whose size is charged to the budget.
_MAKERS = (
    ast.BinOp,
    ast.Call,
    ast.ListComp,
    ast.SetComp,
    ast.GeneratorExp,
    ast.DictComp,
    ast.List,
    ast.Tuple,
    ast.Set,
    ast.Dict,
    ast.JoinedStr,
    ast.FormattedValue,
    ast.Subscript,
)
#: Widths and precisions in ``%`` formats and format specifications.
_WIDTHS = re.compile(r"\*|\d+")


class Interpreter:
    """The value of a parsed expression; names not bound by a comprehension come from
    ``lookup``, which raises `NameError` for a name it does not know."""

    def __init__(self, lookup: Callable[[str], Any]) -> None:
        self.lookup = lookup
        self.spent = 0

    def name(self, name: str, local: dict[str, Any]) -> Any:
        """The value of ``name``: a comprehension's variable, else the caller's."""
        if name in local:
            return local[name]
        return self.lookup(name)

    def value(self, node: ast.AST, local: dict[str, Any]) -> Any:
        """The value of ``node`` with the comprehension variables ``local``.

        Raises:
            ValueError: ``node`` is outside the language, too large a value, or the
                evaluation has spent its `BUDGET`.
        """
        self.charge(1)
        result = self.evaluate(node, local)
        if isinstance(node, _MAKERS):
            self.charge(_size(result))
        return result

    def charge(self, cost: int) -> None:
        """Count ``cost`` against the evaluation's `BUDGET`."""
        self.spent += cost
        if self.spent > BUDGET:
            raise ValueError("expression too costly")

    def evaluate(self, node: ast.AST, local: dict[str, Any]) -> Any:
        """`value`'s work, uncounted."""
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
                return self.formatted(inner, conversion, spec, local)
            case ast.Call(func=func, args=args, keywords=keywords):
                function = self.callable(func, local)
                positional = [self.metered(self.value(a, local)) for a in args]
                named = {k.arg: self.metered(self.value(k.value, local)) for k in keywords if k.arg}
                if len(named) != len(keywords) or any(isinstance(a, ast.Starred) for a in args):
                    raise ValueError("* and ** in calls are not supported")
                _check_call(function, positional, named)
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

    def formatted(
        self, inner: ast.expr, conversion: int, spec: ast.expr | None, local: dict[str, Any]
    ) -> str:
        """An f-string's ``{inner!conversion:spec}``."""
        shown = self.value(inner, local)
        _text_size(shown)
        if conversion == ord("r"):
            shown = repr(shown)
        elif conversion in (ord("s"), ord("a")):
            shown = str(shown) if conversion == ord("s") else ascii(shown)
        specification = "" if spec is None else str(self.value(spec, local))
        _check_widths(specification)
        return format(shown, specification)

    def metered(self, value: Any) -> Any:
        """``value``, or if it is a function, one whose calls are checked and counted as the
        interpreter's own (``map``, ``filter``, ``sorted`` call it from C, out of sight)."""
        if not callable(value):
            return value

        def call(*args: Any, **named: Any) -> Any:
            self.charge(1)
            _check_call(value, list(args), named)
            result = value(*args, **named)
            self.charge(_size(result))
            return result

        return call

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
                    self.charge(1)
                    inner = dict(scope)
                    _bind(generator.target, item, inner)
                    if all(self.value(test, inner) for test in generator.ifs):
                        following.append(inner)
                        if len(following) > MAX_SIZE:
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


def _size(value: Any) -> int:
    """What a value costs: its items, or an integer's 64-bit words; refused when too large."""
    if isinstance(value, _SIZED):
        if len(value) > MAX_SIZE:
            raise ValueError("result too large")
        return len(value)
    if isinstance(value, int):
        if value.bit_length() > MAX_BITS:
            raise ValueError("integer too large")
        return value.bit_length() >> 6
    return 0


def _text_size(value: Any) -> int:
    """About how many characters ``str(value)`` has; refused beyond `MAX_SIZE` (a list of
    one long string repeated prints it every time)."""
    total, pending = 0, [value]
    while pending:
        item = pending.pop()
        if isinstance(item, str | bytes):
            total += len(item) + 3
        elif isinstance(item, int):
            total += item.bit_length() // 3 + 1
        elif isinstance(item, dict):
            total += 2 * len(item) + 2
            pending += item.keys()
            pending += item.values()
        elif isinstance(item, list | tuple | set | frozenset):
            total += 2 * len(item) + 2
            pending += item
        else:
            total += 24
        if total > MAX_SIZE:
            raise ValueError("result too large")
    return total


def _bits(value: Any) -> int:
    return value.bit_length() if isinstance(value, int) else 0


def _check_size(op: ast.operator, a: Any, b: Any) -> None:
    """Refuse ``a op b`` before computing it when the result would be too large."""
    if isinstance(op, ast.Pow):
        _check_pow(a, b)
    elif isinstance(op, ast.LShift) and isinstance(b, int) and _bits(a) + b > MAX_BITS:
        raise ValueError("shift too large")
    elif isinstance(op, ast.Mult):
        if isinstance(a, int) and isinstance(b, int) and _bits(a) + _bits(b) > MAX_BITS:
            raise ValueError("integer too large")
        for seq, count in ((a, b), (b, a)):
            sized = isinstance(seq, str | list | tuple | bytes) and isinstance(count, int)
            if sized and len(seq) * count > MAX_SIZE:
                raise ValueError("result too large")
    elif isinstance(op, ast.Mod) and isinstance(a, str | bytes):
        _check_widths(a if isinstance(a, str) else a.decode("latin-1"))
        _text_size(b)


def _check_widths(text: str) -> None:
    """Refuse ``%`` formats and format specifications that pad to huge widths."""
    for width in _WIDTHS.findall(text):
        if width == "*" or int(width) > MAX_SIZE:
            raise ValueError("format width too large")


def _check_call(function: Any, positional: list[Any], named: dict[str, Any]) -> None:
    """Refuse a call whose result would be too large, before making it."""
    owner = getattr(function, "__self__", None)
    if isinstance(owner, _SAFE_TYPES):
        if any(isinstance(a, int) and abs(a) > MAX_SIZE for a in [*positional, *named.values()]):
            raise ValueError("argument too large")
        if isinstance(owner, str | bytes):
            _check_text_method(owner, function.__name__, positional)
        return
    check = _FUNCTION_CHECKS.get(id(function))
    if check is not None:
        check(*positional, **named)


def _check_text_method(owner: str | bytes, name: str, args: list[Any]) -> None:
    # The methods of str and bytes whose result can be much longer than their operands.
    grows = 0
    if name == "join" and args and isinstance(args[0], _SIZED):
        grows = len(owner) * len(args[0]) + _text_size(args[0])
    elif name == "replace" and len(args) >= 2 and all(isinstance(a, str | bytes) for a in args[:2]):
        times = owner.count(args[0]) if args[0] else len(owner) + 1
        if len(args) > 2 and isinstance(args[2], int) and args[2] >= 0:
            times = min(times, args[2])
        grows = times * len(args[1])
    elif name == "expandtabs":
        size = args[0] if args and isinstance(args[0], int) else 8
        grows = (owner.count("\t") if isinstance(owner, str) else owner.count(b"\t")) * size
    elif name == "translate" and args and isinstance(args[0], dict | list | tuple):
        table = args[0].values() if isinstance(args[0], dict) else args[0]
        longest = max((len(v) for v in table if isinstance(v, str | bytes)), default=1)
        grows = len(owner) * longest
    if len(owner) + grows > MAX_SIZE:
        raise ValueError("result too large")


def _check_pow(base: Any = None, exponent: Any = None, mod: Any = None) -> None:
    whole = isinstance(base, int) and isinstance(exponent, int) and exponent > 0
    if mod is None and whole and base not in (0, 1, -1) and _bits(base) * exponent > MAX_BITS:
        raise ValueError("exponent too large")


def _check_factorial(n: Any = 0, k: Any = None) -> None:
    # n! has about n·log2(n) bits: 8 192! has 94 000.
    if isinstance(n, int) and n > MAX_BITS // 16:
        raise ValueError("argument too large")


def _check_product(*args: Any, **named: Any) -> None:
    # prod(iterable) and lcm(*integers): at most the sum of the factors' bits.
    values = args[0] if len(args) == 1 and not isinstance(args[0], int) else args
    if isinstance(values, range):
        bits = len(values) * max(_bits(abs(values.start)), _bits(abs(values.stop)))
    elif isinstance(values, list | tuple | set | frozenset):
        bits = sum(_bits(abs(v)) for v in values if isinstance(v, int))
    else:
        raise ValueError("a product of an iterator is not supported")
    if bits > MAX_BITS:
        raise ValueError("result too large")


def _check_sum(iterable: Any = (), start: Any = 0) -> None:
    # sum(lists, []) copies the growing total at every step.
    if not isinstance(start, int | float | complex):
        raise ValueError("sum of sequences is not supported")


def _check_text(value: Any = "", *more: Any, **named: Any) -> None:
    _text_size(value)


_FUNCTION_CHECKS: dict[int, Callable[..., None]] = {
    id(builtins.pow): _check_pow,
    id(builtins.sum): _check_sum,
    id(builtins.str): _check_text,
    id(builtins.repr): _check_text,
    id(math.factorial): _check_factorial,
    id(math.comb): _check_factorial,
    id(math.perm): _check_factorial,
    id(math.prod): _check_product,
    id(math.lcm): _check_product,
}


def evaluate(expression: str, lookup: Callable[[str], Any]) -> Any:
    """The value of the Python expression ``expression``, names given by ``lookup``.

    Raises:
        SyntaxError: ``expression`` is not a Python expression.
        ValueError: it uses what this language leaves out, or makes too large a value.
        ArithmeticError, TypeError, LookupError, AttributeError, NameError, RecursionError:
            as evaluating it in Python would (an unknown name, a method not offered…).
    """
    tree = ast.parse(expression.strip(), mode="eval")
    result = Interpreter(lookup).value(tree.body, {})
    _text_size(result)  # what the caller prints
    return result


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
