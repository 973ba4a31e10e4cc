"""Substitution args as roslaunch resolves them."""

from __future__ import annotations

import pytest

from rosx.launch.substitution import (
    MissingArgError,
    MissingPackageError,
    Scope,
    SubstitutionError,
    World,
    collect,
    resolve,
)
from rosx.packages.index import PackageIndex


@pytest.fixture
def world(index: PackageIndex) -> World:
    counter = iter(range(100))
    return World({"HOME_X": "/home/x", "EMPTY": ""}, index, lambda n: f"{n}_{next(counter)}")


def scope(**args: str) -> Scope:
    return Scope(args=dict(args), filename="/launch/dir/main.launch")


@pytest.mark.parametrize(
    ("text", "found"),
    [
        ("$(arg a)", ["arg a"]),
        ("x $(arg a) $(env B) y", ["arg a", "env B"]),
        ("$(arg a", []),
        ("$ (arg a)", []),
        ("$$(arg a)", ["arg a"]),
        ("$x(arg a)", []),
        ("$()", []),
        ("a)b$(c)", ["c"]),
    ],
)
def test_collect_finds_complete_substitutions(text: str, found: list[str]) -> None:
    assert collect(text) == found


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("$(arg $(x))", "Dollar signs '$' cannot be inside of substitution args [$(arg $(x))]"),
        ("$(arg (x)", "Invalid left parenthesis '(' in substitution args [$(arg (x)]"),
    ],
)
def test_collect_refuses_nesting(text: str, message: str) -> None:
    with pytest.raises(SubstitutionError, match=None) as error:
        collect(text)
    assert str(error.value) == message


def test_env_optenv_arg_dirname(world: World) -> None:
    s = scope(a="1")
    assert resolve("$(env HOME_X)/y", s, world) == "/home/x/y"
    assert resolve("$(optenv NOPE default with  spaces)", s, world) == "default with spaces"
    assert resolve("[$(optenv NOPE)]", s, world) == "[]"
    assert resolve("$(optenv EMPTY x)", s, world) == ""
    assert resolve("$(arg a)$(arg a)", s, world) == "11"
    assert resolve("$(dirname)/x", s, world) == "/launch/dir/x"


def test_anon_is_one_name_per_id_and_scope(world: World) -> None:
    s = scope()
    assert resolve("$(anon a) $(anon a) $(anon b)", s, world) == "a_0 a_0 b_1"
    assert resolve("$(anon a)", s.copy(), world) == "a_0"


def test_find_joins_the_following_word(world: World, index: PackageIndex) -> None:
    demo = str(index.find("demo"))
    s = scope()
    assert resolve("$(find demo)", s, world) == demo
    assert resolve("$(find demo)/launch/x.launch", s, world) == f"{demo}/launch/x.launch"
    assert resolve("$(find demo)suffix", s, world) == f"{demo}/suffix"
    assert resolve("$(find demo)/a b/c", s, world) == f"{demo}/a b/c"
    assert resolve("$(find demo)\\win", s, world) == f"{demo}/win"


def test_find_runs_after_the_args_it_may_come_from(world: World, index: PackageIndex) -> None:
    s = scope(where="$(find demo)", other="$(arg where)")
    assert resolve("$(arg where)/x", s, world) == f"{index.find('demo')}/x"
    # An arg's value is not resolved again for args: roslaunch's second pass only finds.
    assert resolve("$(arg other)", s, world) == "$(arg where)"


@pytest.mark.parametrize(
    ("text", "message"),
    [
        (
            "$(foo)",
            "Unknown substitution command [foo]. Valid commands are "
            "['find', 'env', 'optenv', 'dirname', 'anon', 'arg']",
        ),
        ("$(env A B)", "$(env var) command only accepts one argument [env A B]"),
        ("$(env NOPE)", "environment variable 'NOPE' is not set"),
        ("$(optenv)", "$(optenv var) must specify an environment variable [optenv]"),
        ("$(anon)", "$(anon var) must specify a name [anon]"),
        ("$(anon a b)", "$(anon var) may only specify one name [anon a b]"),
        ("$(arg)", "$(arg var) must specify a variable name [arg]"),
        ("$(arg a b)", "$(arg var) may only specify one arg [arg a b]"),
        ("$(find a b)", "$(find pkg) command only accepts one argument [find a b]"),
    ],
)
def test_errors_are_roslaunchs(world: World, text: str, message: str) -> None:
    with pytest.raises(SubstitutionError) as error:
        resolve(text, scope(), world)
    assert str(error.value) == message


def test_missing_arg_and_package(world: World) -> None:
    with pytest.raises(MissingArgError) as arg:
        resolve("$(arg nope)", scope(), world)
    assert arg.value.name == "nope"
    with pytest.raises(MissingPackageError) as package:
        resolve("$(find nope)", scope(), world)
    assert package.value.name == "nope"


def test_dirname_needs_a_file(world: World) -> None:
    with pytest.raises(SubstitutionError, match="no file/directory information"):
        resolve("$(dirname)", Scope(), world)


def test_unknown_command_refused_even_after_a_valid_one(world: World) -> None:
    with pytest.raises(SubstitutionError, match="Unknown substitution command"):
        resolve("$(arg a) $(eval 1)", scope(a="1"), world)
