"""rviz configs under fuzz: a ``.rviz`` file is read, or refused with one line.

Documents made of an rviz config's own keys (``Visualization Manager``, ``Displays`` with
``Class``, ``Name``, ``Enabled``, ``Topic``, ``Color``, groups of displays, ``Global Options``,
``Tools``, ``Views``), with values of every YAML kind, anchors and aliases, and random text, are
read as ``rosx rviz -d FILE`` reads them (`parse_config`, then every display's options and
colours): an `RvizConfig` or a `ConfigError` whose text is one line naming the file; never
another exception, never a hang.
"""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from rosx_commands.rviz.config import ConfigError, parse_color, parse_config
from tests.support.fuzz import MEMORY_BOUND, fuzz_settings, no_hang, peak_allocation

pytestmark = pytest.mark.fuzz

_SCALARS = st.one_of(
    st.sampled_from(
        [
            *["rviz/LaserScan", "rviz/Group", "rviz/TF", "rviz/Map", "rviz/TopDownOrtho", "true"],
            *[
                "false",
                "~",
                "1",
                "-1",
                "0",
                "1e999",
                "-.inf",
                ".nan",
                '"255; 0; 0"',
                "'1e999; 0; 0'",
            ],
            *[
                "'nan; 1; 2'",
                "'; ;'",
                "/scan",
                "map",
                "''",
                "[]",
                "{}",
                "*a",
                "&a x",
                "!!binary aGk=",
            ],
        ]
    ),
    st.text(alphabet="abcxyz019 .-_;:/", max_size=10),
)
_DISPLAY_KEYS = st.sampled_from(
    ["Class", "Name", "Enabled", "Value", "Topic", "Color", "Size (m)", "Alpha", "Displays"]
)


@st.composite
def _display(draw: st.DrawFn, indent: int, depth: int = 0) -> str:
    pad = " " * indent
    lines = [f"{pad}- Class: {draw(_SCALARS)}"]
    for key in draw(st.lists(_DISPLAY_KEYS, max_size=4)):
        if key == "Displays" and depth < 2:
            inner = draw(st.lists(_display(indent + 4, depth + 1), max_size=2))
            anchor = draw(st.sampled_from(["", "", " &g", " *g", " *d"]))
            lines.append(f"{pad}  Displays:{anchor}")
            if not anchor.startswith(" *"):
                lines += inner
        else:
            lines.append(f"{pad}  {key}: {draw(_SCALARS)}")
    return "\n".join(lines)


@st.composite
def configs(draw: st.DrawFn) -> str:
    lines = ["Visualization Manager:"]
    if draw(st.booleans()):
        lines.append(f"  Global Options:\n    Fixed Frame: {draw(_SCALARS)}")
        lines.append(f"    Background Color: {draw(_SCALARS)}")
    anchor = draw(st.sampled_from(["", " &d"]))
    lines.append(f"  Displays:{anchor}")
    lines += draw(st.lists(_display(4), max_size=3))
    if draw(st.booleans()):
        lines.append(f"  Tools:\n    - Class: {draw(_SCALARS)}\n      Topic: {draw(_SCALARS)}")
    if draw(st.booleans()):
        lines.append(f"  Views:\n    Current:\n      Class: {draw(_SCALARS)}")
        for key in draw(st.lists(st.sampled_from(["X", "Y", "Scale", "Angle", "Distance"]))):
            lines.append(f"      {key}: {draw(_SCALARS)}")
    return "\n".join(lines)


@fuzz_settings(150)
@given(text=st.one_of(configs(), st.text(max_size=80)))
def test_rviz_configs_are_read_or_refused_in_one_line(text: str) -> None:
    try:
        with no_hang():
            config = parse_config(text, "fuzz.rviz")
            for display in config.displays:
                parse_color(display.get("Color"), (0, 0, 0))
                display.get("Topic")
    except ConfigError as error:
        assert str(error).startswith("cannot load fuzz.rviz")
        assert "\n" not in str(error)


SELF_HOLDING = """\
Visualization Manager:
  Displays: &d
    - Class: rviz/Group
      Name: loop
      Displays: *d
"""


def test_a_group_that_holds_itself_holds_nothing() -> None:
    # ruamel's round-trip loader gives an alias inside its own anchor an empty list.
    with no_hang():
        assert parse_config(SELF_HOLDING, "loop.rviz").displays == []


def test_a_config_nested_too_deeply_is_refused() -> None:
    refused: list[ConfigError] = []

    def parse() -> None:
        try:
            with no_hang():
                parse_config("Visualization Manager: " + "[" * 5000, "deep.rviz")
        except ConfigError as error:
            refused.append(error)

    assert peak_allocation(parse) < MEMORY_BOUND
    assert [str(error) for error in refused] == [
        "cannot load deep.rviz (line 1): collections nested more than 200 deep"
    ]


@pytest.mark.parametrize("text", ["1e999; 0; 0", "-1e999; 2; 3", "nan; 1; 2"])
def test_colours_out_of_range_fall_back_to_the_default(text: str) -> None:
    assert parse_color(text, (1, 2, 3)) == (1, 2, 3)


@pytest.mark.parametrize("value", ["-_", "._"])
def test_scalars_ruamel_cannot_construct_are_refused(value: str) -> None:
    with pytest.raises(ConfigError, match=r"^cannot load x.rviz: invalid value \("):
        parse_config(f"Visualization Manager:\n  Tools:\n    - Class: {value}\n", "x.rviz")
