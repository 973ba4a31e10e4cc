"""Launch files under fuzz: the plan's entry point reads them or refuses them with `LaunchError`.

Documents are built of roslaunch's own tags and attributes, their values of substitutions
(``$(arg)``, ``$(find)``, ``$(env)``, ``$(optenv)``, ``$(anon)``, ``$(dirname)``, ``$(eval)`` of
small Python expressions, unbalanced and unknown ones) and of random text; files of random
bytes and valid files cut short are read too. `load_launch` (with roslaunch's printing of the
plan) gives a plan or a `LaunchError` whose text is one line; never another exception, never a
hang. The named bombs (``$(eval)`` of huge powers, repetitions, ranges and comprehensions, an
include of itself, XML entities that expand a billionfold) stay within `MEMORY_BOUND`.
"""

from __future__ import annotations

import tempfile
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given
from hypothesis import strategies as st

from rosx.launch import LaunchError, load_launch, summary_text
from rosx.packages.index import PackageIndex
from tests.support.fuzz import MEMORY_BOUND, fuzz_settings, no_hang, peak_allocation
from tests.support.launch_plan import PACKAGE_XML

pytestmark = pytest.mark.fuzz

_EXPRESSIONS = st.one_of(
    st.sampled_from(
        [
            "1 + 2",
            "arg('x') == 'a'",
            "'a' * 3",
            "2 ** 10",
            "9 ** 9 ** 9",
            "pow(10, 10 ** 9)",
            "'x' * 10 ** 9",
            "'x'.center(10 ** 9)",
            "factorial(10 ** 6)",
            "str(10 ** 5000)",
            "1 / 0",
            "undefined_name",
            "__import__('os')",
            "().__class__",
            "(",
            "",
        ]
    ),
    st.text(alphabet="0123456789+-*/%()<>=!&|^~ .'\"abcxz[]{}:,_", max_size=24),
)
_SUBSTITUTIONS = st.one_of(
    st.sampled_from(
        [
            "$(arg x)",
            "$(arg missing)",
            "$(find demo)",
            "$(find nowhere)",
            "$(env HOME)",
            "$(env NOT_SET)",
            "$(optenv NOT_SET default)",
            "$(anon n)",
            "$(dirname)",
            "$(unknown x)",
            "$(arg",
            "$(",
            "$()",
            "$(eval",
        ]
    ),
    _EXPRESSIONS.map(lambda e: f"$(eval {e})"),
)
_VALUES = st.lists(
    st.one_of(_SUBSTITUTIONS, st.text(alphabet="abc /._-$(){}:=01", max_size=8)), max_size=3
).map("".join)
_TAGS = st.sampled_from(
    [
        "arg",
        "param",
        "node",
        "group",
        "include",
        "rosparam",
        "remap",
        "env",
        "machine",
        "test",
        "launch",
        "unknown",
    ]
)
_ATTRIBUTES = st.sampled_from(
    [
        "name",
        "value",
        "default",
        "type",
        "pkg",
        "ns",
        "if",
        "unless",
        "file",
        "command",
        "textfile",
        "args",
        "output",
        "respawn",
        "required",
        "from",
        "to",
        "address",
        "param",
        "test-name",
        "clear_params",
        "pass_all_args",
        "subst_value",
        "doc",
        "launch-prefix",
    ]
)
_TYPES = st.sampled_from(["str", "int", "double", "bool", "yaml", "auto", "nonsense"])


@st.composite
def _element(draw: st.DrawFn, depth: int = 0) -> str:
    tag = draw(_TAGS)
    attributes = draw(st.dictionaries(_ATTRIBUTES, _VALUES, max_size=4))
    if tag in ("param", "arg") and draw(st.booleans()):
        attributes["type"] = draw(_TYPES)
    text = "".join(f' {name}="{_escape(value)}"' for name, value in attributes.items())
    children = []
    if depth < 2:
        children = draw(st.lists(_element(depth + 1), max_size=3))
    body = "".join(children)
    if tag == "rosparam" and draw(st.booleans()):
        body += _escape(draw(st.sampled_from(["a: 1", "[1, 2", "{x: $(arg x)}", "b: &a [*a]"])))
    return f"<{tag}{text}>{body}</{tag}>" if body else f"<{tag}{text}/>"


def _escape(value: str) -> str:
    return value.replace("&", "&amp;").replace("<", "&lt;").replace('"', "&quot;")


launch_files = st.builds(
    lambda args, elements: (
        '<launch><arg name="x" default="a"/>' + "".join(args) + "".join(elements) + "</launch>"
    ),
    st.lists(
        st.builds(
            lambda name, value: f'<arg name="{name}" default="{_escape(value)}"/>',
            st.sampled_from(["y", "z", "x"]),
            _VALUES,
        ),
        max_size=2,
    ),
    st.lists(_element(), max_size=5),
)


@pytest.fixture(scope="module")
def folder() -> Any:
    with tempfile.TemporaryDirectory() as name:
        root = Path(name)
        (root / "pkgs" / "demo").mkdir(parents=True)
        (root / "pkgs" / "demo" / "package.xml").write_text(PACKAGE_XML.format(name="demo"))
        yield root


def _refuse_commands(argv: list[str]) -> tuple[int, str]:
    return 1, ""  # <param command=…> runs nothing under fuzz


def _load(root: Path, data: bytes) -> None:
    path = root / "main.launch"
    path.write_bytes(data)
    try:
        with no_hang():
            plan = load_launch(
                [str(path)],
                {},
                {"HOME": "/home/u"},
                PackageIndex([root / "pkgs"]),
                with_core=False,
                anonymous=lambda name: f"{name}_anon",
                run=_refuse_commands,
            )
            summary_text(plan)
    except LaunchError as error:
        text = str(error)
        assert text
        assert "\n" not in text, text


@fuzz_settings(80)
@given(text=launch_files)
def test_launch_files_load_or_are_refused(folder: Path, text: str) -> None:
    _load(folder, text.encode())


@fuzz_settings(50)
@given(data=st.binary(max_size=300))
def test_random_bytes_are_refused(folder: Path, data: bytes) -> None:
    _load(folder, data)


_VALID = (
    '<launch>\n  <arg name="rate" default="10"/>\n  <param name="r" value="$(arg rate)"/>\n'
    '  <group ns="g">\n    <node pkg="demo" type="run" name="n" args="$(eval 2 * 3)">\n'
    '      <remap from="a" to="b"/>\n      <param name="p" type="int" value="3"/>\n'
    "    </node>\n  </group>\n  <rosparam>a: 1\nb: [1, 2]</rosparam>\n</launch>\n"
)


def test_a_launch_file_cut_anywhere_is_refused_in_one_line(folder: Path) -> None:
    for end in range(len(_VALID)):
        _load(folder, _VALID[:end].encode())


# -- bombs ----------------------------------------------------------------------------------

_BILLION_LAUGHS = (
    '<?xml version="1.0"?><!DOCTYPE launch [<!ENTITY a "aaaaaaaaaa">'
    + "".join(f'<!ENTITY {chr(98 + i)} "{("&" + chr(97 + i) + ";") * 10}">' for i in range(9))
    + ']><launch><param name="p" value="&j;"/></launch>'
)
EVAL_BOMBS = [
    "9 ** 9 ** 9",
    "(9 ** 9999) ** 9999",
    "pow(10, 10 ** 9)",
    "pow(9 ** 9999, 9999)",
    "'x' * 10 ** 9",
    "'x' * 10 ** 6 * 10 ** 6",
    "list(range(10 ** 7))",
    "[x for x in range(10 ** 7)]",
    "[[0] * 10 ** 6 for x in range(10 ** 6)]",
    "'x'.center(10 ** 9)",
    "'ab'.zfill(10 ** 9)",
    "'x'.ljust(10 ** 9)",
    "('x' * 10 ** 6).replace('x', 'x' * 10 ** 6)",
    "factorial(10 ** 7)",
    "comb(10 ** 7, 5 * 10 ** 6)",
    "prod(range(1, 10 ** 5))",
    "1 << 10 ** 8",
    "(1 << 10 ** 5) ** 10 ** 4",
    "sum([[x] for x in range(10 ** 5)], [])",
    "sorted(range(10 ** 7))",
    "str(9 ** 9999) * 10 ** 5",
    "'%s' * 10 ** 6 % tuple(range(10 ** 6))",
    "'%0999999999d' % 1",
    "f'{1:>999999999}'",
    "str(['x' * 10 ** 5] * 10 ** 5)",
    "[l.extend(l) for l in [[1]] for i in range(64)]",
    "list(map(list, [range(10 ** 5)] * 10 ** 5))",
    "list(map(pow, [9] * 1000, [99999] * 1000))",
    "[list(range(10 ** 5)) for i in range(10 ** 4)]",
    "[[y for y in range(10 ** 5)] for x in range(10 ** 5)]",
    "(1).to_bytes(10 ** 9, 'big')",
    "('x' * 10 ** 5).expandtabs(10 ** 5)",
    "('\\t' * 10 ** 5).expandtabs(10 ** 4)",
    "('x' * 10 ** 5).join(['a'] * 10 ** 5)",
    "('x' * 10 ** 5).translate({120: 'y' * 10 ** 5})",
    "(10 ** 4000) * (10 ** 4000) * (10 ** 4000) * (10 ** 4000) * (10 ** 4000) * (10 ** 4000)",
]


@pytest.mark.parametrize("expression", EVAL_BOMBS)
def test_eval_bombs_are_refused_without_hanging_or_allocating(
    folder: Path, expression: str
) -> None:
    path = folder / "main.launch"
    path.write_text(f'<launch><param name="p" value="$(eval {expression})"/></launch>')
    refused: list[LaunchError] = []

    def load() -> None:
        try:
            with no_hang():
                load_launch([str(path)], {}, {}, PackageIndex([]), with_core=False)
        except LaunchError as error:
            refused.append(error)

    assert peak_allocation(load) < MEMORY_BOUND
    assert len(refused) == 1
    assert "\n" not in str(refused[0])


def test_an_include_of_itself_is_refused(folder: Path) -> None:
    _load(folder, b'<launch><include file="$(dirname)/main.launch"/></launch>')


def test_entities_that_expand_a_billionfold_are_refused(folder: Path) -> None:
    assert peak_allocation(lambda: _load(folder, _BILLION_LAUGHS.encode())) < MEMORY_BOUND
