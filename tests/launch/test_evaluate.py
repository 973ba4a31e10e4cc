"""``$(eval)``: Python expressions over the args, without Python's eval."""

from __future__ import annotations

import math

import pytest

from rosx.launch.substitution import EvalError, MissingArgError, Scope, World, evaluate, resolve
from rosx.packages.index import PackageIndex


@pytest.fixture
def world(index: PackageIndex) -> World:
    return World({"VAR": "from env"}, index, lambda name: f"{name}_anon")


def scope() -> Scope:
    args = {"n": "4", "f": "2.5", "yes": "true", "no": "False", "word": "robot", "u": "1_0"}
    return Scope(args=args, filename="/d/main.launch")


@pytest.mark.parametrize(
    ("expression", "value"),
    [
        ("1 + 2 * 3", "7"),
        ("2 ** 10", "1024"),
        ("7 // 2, 7 % 2", "(3, 1)"),
        ("1 / 3", str(1 / 3)),
        ("n * 2", "8"),
        ("f + 1", "3.5"),
        ("u", "1_0"),
        ("yes and not no", "True"),
        ("no or 'fallback'", "fallback"),
        ("1 < n <= 4", "True"),
        ("n == 4 != 5", "True"),
        ("'big' if n > 2 else 'small'", "big"),
        ("word.upper() + '!'", "ROBOT!"),
        ("word[1:3]", "ob"),
        ("', '.join([word, str(n)])", "robot, 4"),
        ("[i * i for i in range(n) if i % 2]", "[1, 9]"),
        ("{k: v for k, v in [('a', 1)]}", "{'a': 1}"),
        ("sum(x for x in [1, 2, 3])", "6"),
        ("f'{word}-{n:03d}'", "robot-004"),
        ("len(word)", "5"),
        ("min(3, n, 9), max([1, 2])", "(3, 2)"),
        ("int('7') + float('0.5')", "7.5"),
        ("round(pi, 3)", "3.142"),
        ("sqrt(16)", "4.0"),
        ("degrees(pi)", "180.0"),
        ("true, false, True, None", "(True, False, True, None)"),
        ("arg('n') + 1", "5"),
        ("arg('word')", "robot"),
        ("env('VAR')", "from env"),
        ("optenv('NOPE', 'dflt'), optenv('NOPE')", "('dflt', '')"),
        ("anon('x')", "x_anon"),
        ("dirname()", "/d"),
        ("{'k': n}['k']", "4"),
        ("-n, +n, ~n", "(-4, 4, -5)"),
        ("'a' in word, 'o' in word", "(False, True)"),
        ("sorted({3, 1, 2})", "[1, 2, 3]"),
    ],
)
def test_values(expression: str, value: str) -> None:
    world_ = World({"VAR": "from env"}, PackageIndex([]), lambda name: f"{name}_anon")
    assert evaluate(expression, scope(), world_) == value


def test_find(world: World, index: PackageIndex) -> None:
    assert evaluate("find('demo') + '/x'", scope(), world) == f"{index.find('demo')}/x"


def test_only_a_whole_attribute_is_evaluated(world: World) -> None:
    assert resolve("$(eval n + 1)", scope(), world) == "5"


@pytest.mark.parametrize(
    ("expression", "message"),
    [
        ("__import__('os')", "$(eval ...) may not contain double underscore expressions"),
        ("nope + 1", "$(eval nope + 1): name 'nope' is not defined"),
        ("1 / 0", "$(eval 1 / 0): division by zero"),
        ("1 +", "invalid syntax in $(eval 1 +): invalid syntax"),
        ("word.format(1)", "$(eval word.format(1)): the method 'format' is not available"),
        ("open('/etc/passwd')", "$(eval open('/etc/passwd')): name 'open' is not defined"),
        ("(lambda: 1)()", "$(eval (lambda: 1)()): Lambda expressions are not supported"),
        ("math.pi", "$(eval math.pi): Attribute expressions are not supported"),
        ("2 ** 100000", "$(eval 2 ** 100000): exponent too large"),
        ("sum(range(10 ** 12))", "$(eval sum(range(10 ** 12))): range too large"),
        ("'x' * 10 ** 9", "$(eval 'x' * 10 ** 9): result too large"),
        ("n.bit_length", "$(eval n.bit_length): Attribute expressions are not supported"),
        ("[x := 1]", "$(eval [x := 1]): NamedExpr expressions are not supported"),
    ],
)
def test_refusals(world: World, expression: str, message: str) -> None:
    with pytest.raises(EvalError) as error:
        evaluate(expression, scope(), world)
    assert str(error.value) == message


def test_missing_arg_is_a_missing_arg(world: World) -> None:
    with pytest.raises(MissingArgError):
        evaluate("arg('nope')", scope(), world)


def test_env_of_an_unset_variable(world: World) -> None:
    with pytest.raises(Exception, match="environment variable 'NOPE' is not set"):
        evaluate("env('NOPE')", scope(), world)


def test_math_is_there() -> None:
    world_ = World({}, PackageIndex([]), str)
    assert evaluate("e", Scope(), world_) == str(math.e)
