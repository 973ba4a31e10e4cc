"""Substitution args: ``$(find)``, ``$(arg)``, ``$(env)``, ``$(optenv)``, ``$(anon)``,
``$(dirname)`` and ``$(eval)``, as roslaunch's ``substitution_args`` resolves them.

The rules (wiki roslaunch/XML, "substitution args"):

* ``$(…)`` is found by a small scanner: no escapes, a ``$`` or ``(`` inside a substitution is an
  error, an unclosed one is left as text;
* every command is checked first (``Unknown substitution command [x]. Valid commands are …``);
  ``env``, ``optenv``, ``dirname``, ``anon`` and ``arg`` are replaced in a first pass, then
  ``find`` in a second pass over the result (so a path after ``$(find pkg)`` may itself come
  from an arg); each replacement replaces every identical ``$(…)`` of the text;
* ``$(eval EXPR)`` must span the whole attribute; EXPR is a Python expression over the args
  (bare names), ``arg()``, ``env()``, ``optenv()``, ``find()``, ``anon()``, ``dirname()``,
  ``true``/``false``, everything public in `math` and Python's harmless built-in functions
  (`evaluate`, with `rosx.expression`'s interpreter instead of Python's ``eval``); its value is
  ``str()``-ed;
* ``$(anon id)`` gives the same name for the same id within one scope.

Missing args raise `MissingArgError` (roslaunch's ``ArgException``), everything else
`SubstitutionError`; callers add the file, line and tag.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

from rosx.expression import MATH, SAFE_BUILTINS
from rosx.expression import evaluate as evaluate_expression
from rosx.launch.values import convert_value

if TYPE_CHECKING:
    from collections.abc import Callable, Mapping

    from rosx.packages.index import PackageIndex

_VALID = ["find", "env", "optenv", "dirname", "anon", "arg"]
_FIRST_PASS = frozenset({"env", "optenv", "dirname", "anon", "arg"})


class SubstitutionError(ValueError):
    """A substitution arg cannot be resolved; ``str()`` is roslaunch's text where it has one."""


class MissingArgError(SubstitutionError):
    """``$(arg name)`` of an arg that has no value."""

    def __init__(self, name: str) -> None:
        super().__init__(name)
        self.name = name


class MissingPackageError(SubstitutionError):
    """``$(find pkg)`` of a package that is not on the package path."""

    def __init__(self, name: str) -> None:
        super().__init__(name)
        self.name = name


@dataclass
class World:
    """What substitutions read outside the launch files: environment, packages, anon ids.

    Attributes:
        environ: For ``$(env)`` and ``$(optenv)``.
        package_index: For ``$(find)``.
        anonymous: Makes a fresh anonymous name from an id (rosgraph's ``anonymous_name``).
    """

    environ: Mapping[str, str]
    package_index: PackageIndex
    anonymous: Callable[[str], str]

    def env(self, name: str) -> str:
        """``$(env name)``: the variable's value; a `SubstitutionError` if it is unset."""
        try:
            return self.environ[name]
        except KeyError:
            raise SubstitutionError(f"environment variable '{name}' is not set") from None

    def optenv(self, name: str, default: str = "") -> str:
        """``$(optenv name default)``: the variable's value, or ``default`` if it is unset."""
        return self.environ.get(name, default)

    def find(self, package: str, path: str = "") -> str:
        """``$(find package)``, or the directory to read ``path`` from when one follows it:
        the first package on the package path, as ROS 1, unless only rosx's own package of
        that name has ``path`` (see `PackageIndex.directories`)."""
        from rosx.packages.index import PackageNotFoundError  # noqa: PLC0415 - the package index loads only when used

        try:
            first = self.package_index.find(package)
        except PackageNotFoundError:
            raise MissingPackageError(package) from None
        if path and not Path(first, path).exists():
            for directory in self.package_index.directories(package):
                if Path(directory, path).exists():
                    return str(directory)
        return str(first)


@dataclass
class Scope:
    """The substitution state of one launch scope (copied into child scopes).

    Attributes:
        args: Arg name -> value, of the args that have one.
        anon: Anon id -> name, of the ids resolved so far.
        arg_doc: Arg name -> (doc, default) of declared args without a ``value``.
        filename: The launch file, for ``$(dirname)``.
    """

    args: dict[str, str] = field(default_factory=dict)
    anon: dict[str, str] = field(default_factory=dict)
    arg_doc: dict[str, tuple[str | None, str | None]] = field(default_factory=dict)
    filename: str = ""

    def copy(self) -> Scope:
        """A copy whose dictionaries can change without touching this scope (for an include or
        group)."""
        return Scope(dict(self.args), dict(self.anon), dict(self.arg_doc), self.filename)


def collect(text: str) -> list[str]:
    """The contents of every complete ``$(…)`` of ``text``, in order (roslaunch's scanner)."""
    found: list[str] = []
    buffer: list[str] = []
    state = "out"  # out, dollar, open, inside
    for char in text:
        if char == "$":
            if state in ("open", "inside"):
                raise SubstitutionError(
                    f"Dollar signs '$' cannot be inside of substitution args [{text}]"
                )
            state = "dollar"
        elif char == "(":
            if state == "dollar":
                state = "open"
            elif state != "out":
                raise SubstitutionError(
                    f"Invalid left parenthesis '(' in substitution args [{text}]"
                )
        elif char == ")":
            if state == "inside":
                found.append("".join(buffer))
                buffer.clear()
            state = "out"
        elif state == "dollar":
            state = "out"
        elif state == "open":
            state = "inside"
        if state == "inside":
            buffer.append(char)
    return found


def resolve(text: str, scope: Scope, world: World) -> str:
    """``text`` with its substitution args resolved in ``scope``.

    Raises:
        MissingArgError: An ``$(arg)`` without a value.
        MissingPackageError: A ``$(find)`` of an unknown package.
        SubstitutionError: Anything else (unknown command, wrong number of words…).
    """
    if "$" not in text:
        return text
    if text.startswith("$(eval ") and text.endswith(")"):
        return evaluate(text[7:-1], scope, world)
    resolved = _pass(text, scope, world, first=True)
    return _pass(resolved, scope, world, first=False)


def _pass(text: str, scope: Scope, world: World, *, first: bool) -> str:
    resolved = text
    for inner in collect(text):
        words = inner.split()
        if not words or words[0] not in _VALID:
            raise SubstitutionError(
                f"Unknown substitution command [{inner}]. Valid commands are {_VALID}"
            )
        command, args = words[0], words[1:]
        if (command in _FIRST_PASS) != first:
            continue
        whole = f"$({inner})"
        if command == "find":
            resolved = _find(resolved, whole, args, world)
        else:
            resolved = resolved.replace(whole, _value(command, inner, args, scope, world))
    return resolved


def _value(command: str, inner: str, args: list[str], scope: Scope, world: World) -> str:
    if command == "env":
        if len(args) != 1:
            raise SubstitutionError(f"$(env var) command only accepts one argument [{inner}]")
        return world.env(args[0])
    if command == "optenv":
        if not args:
            raise SubstitutionError(f"$(optenv var) must specify an environment variable [{inner}]")
        return world.optenv(args[0], " ".join(args[1:]))
    if command == "dirname":
        return dirname(scope)
    if command == "anon":
        if len(args) != 1:
            problem = "must specify a name" if not args else "may only specify one name"
            raise SubstitutionError(f"$(anon var) {problem} [{inner}]")
        return anon(args[0], scope, world)
    if len(args) != 1:
        problem = "must specify a variable name" if not args else "may only specify one arg"
        raise SubstitutionError(f"$(arg var) {problem} [{inner}]")
    return arg(args[0], scope)


def arg(name: str, scope: Scope) -> str:
    """The value of arg ``name``; `MissingArgError` if it has none."""
    try:
        return scope.args[name]
    except KeyError:
        raise MissingArgError(name) from None


def anon(name: str, scope: Scope, world: World) -> str:
    """The anonymous name of id ``name`` in ``scope`` (made on first use)."""
    if name not in scope.anon:
        scope.anon[name] = world.anonymous(name)
    return scope.anon[name]


def dirname(scope: Scope) -> str:
    """The absolute directory of the launch file being read."""
    if not scope.filename:
        raise SubstitutionError(
            "Cannot substitute $(dirname), no file/directory information available."
        )
    return os.path.normpath(Path(scope.filename).absolute().parent)


class EvalError(SubstitutionError):
    """The expression of an ``$(eval)`` cannot be evaluated; ``str()`` says why."""


def evaluate(expression: str, scope: Scope, world: World) -> str:
    """``str()`` of the value of ``expression`` (the text inside ``$(eval …)``).

    The names are roslaunch's: the args by their bare names and ``arg(name)`` (typed as
    ``<param>``'s "auto" type does it: ``1`` is an int, ``true`` a bool), ``env``, ``optenv``,
    ``find``, ``anon``, ``dirname``, ``true``/``false``/``True``/``False``, `math`'s, and the
    harmless built-in functions; any text holding ``__`` is refused, as roslaunch refuses it.

    Raises:
        MissingArgError: ``arg(name)`` of an arg without value.
        EvalError: Anything else wrong with the expression.
    """
    if "__" in expression:
        raise EvalError("$(eval ...) may not contain double underscore expressions")
    functions: dict[str, Any] = {
        "anon": lambda name: anon(name, scope, world),
        "arg": lambda name: convert_value(arg(name, scope), "auto"),
        "dirname": lambda: dirname(scope),
        "true": True,
        "false": False,
        "True": True,
        "False": False,
        "env": world.env,
        "optenv": world.optenv,
        "find": world.find,
        **MATH,
    }

    def lookup(name: str) -> Any:
        if name in functions:
            return functions[name]
        if name in scope.args:
            return convert_value(scope.args[name], "auto")
        if name in SAFE_BUILTINS:
            return SAFE_BUILTINS[name]
        raise NameError(f"name '{name}' is not defined")

    try:
        return str(evaluate_expression(expression, lookup))
    except SyntaxError as error:
        raise EvalError(f"invalid syntax in $(eval {expression}): {error.msg}") from None
    except SubstitutionError:
        raise
    except (
        ArithmeticError,
        ValueError,
        TypeError,
        LookupError,
        AttributeError,
        NameError,
    ) as error:
        raise EvalError(f"$(eval {expression}): {error}") from None
    except MemoryError:
        raise EvalError(f"$(eval {expression}): out of memory") from None
    except RecursionError:
        raise EvalError(f"$(eval {expression}): expression too deep") from None


def _find(text: str, whole: str, args: list[str], world: World) -> str:
    # Only the first occurrence is replaced. The word that follows it (up to a space) is a path
    # inside the package, joined to the package's directory after one leading separator is
    # dropped: roslaunch looks for it in devel/install spaces first, and a source-space package
    # has it under its own directory, which is what rosx's index holds. Looking for the path
    # is ROS 1's too; here it lets rosx's own package serve the files a same-named package on
    # the path lacks.
    if len(args) != 1:
        raise SubstitutionError(f"$(find pkg) command only accepts one argument [{whole[2:-1]}]")
    index = text.find(whole)
    before, after = text[:index], text[index + len(whole) :]
    space = after.find(" ")
    path, rest = (after, "") if space < 0 else (after[:space], after[space:])
    path = path.replace("\\", "/")
    if path.startswith("/"):
        path = path[1:]
    package_dir = world.find(args[0], path)
    if path:
        package_dir = path if path.startswith("/") else f"{package_dir}/{path}"
    return before + package_dir + rest


__all__ = [
    "EvalError",
    "MissingArgError",
    "MissingPackageError",
    "Scope",
    "SubstitutionError",
    "World",
    "anon",
    "arg",
    "collect",
    "dirname",
    "evaluate",
    "resolve",
]
