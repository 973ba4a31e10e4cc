"""Stage world files under fuzz: read, built, rasterised and stepped, or refused.

Worlds made of the world-file language's own pieces (properties with numbers, strings and
``[ ]`` lists, entities nested in ``( )``, ``define``, ``include``, comments) and of random
text, and a valid world cut short anywhere, go through what ``stageros WORLD`` does with a file:
`parse` (includes of another file and of itself), `build`, `load_world`'s grid and a step of the
simulation with every laser scanned. Each either works or raises `WorldFileError` whose text is
one line naming ``file:line``; never another exception, never a hang. Worlds whose grid or
lasers would take gigabytes are refused before they are allocated.
"""

from __future__ import annotations

import tempfile
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given
from hypothesis import strategies as st

from rosx_turtle.stage.engine.simulation import StageSim
from rosx_turtle.stage.world.load import load_world
from rosx_turtle.stage.world.worldfile import WorldFileError
from tests.support.fuzz import fuzz_settings, no_hang, peak_allocation
from tests.support.stage_worlds import ROOM, room

pytestmark = pytest.mark.fuzz

#: What a world file of a few hundred bytes may make the simulator allocate at most.
WORLD_MEMORY_BOUND = 256 << 20

_NUMBERS = st.one_of(
    st.sampled_from(["0", "1", "-1", "0.02", "1e9", "-1e9", "1e-9", "nan", "inf", "180", "0.5"]),
    st.floats(allow_nan=True, allow_infinity=True).map(repr),
    st.integers(-(10**12), 10**12).map(str),
)
_STRINGS = st.sampled_from(['"gps"', '"odom"', '"diff"', '"omni"', '"r0"', '""', '"x', '"map.pgm"'])
_VALUES = st.one_of(
    _NUMBERS,
    _STRINGS,
    st.lists(st.one_of(_NUMBERS, _STRINGS), max_size=5).map(lambda v: "[ " + " ".join(v) + " ]"),
    st.sampled_from(["[", "]", "[ 1 2", "word"]),
)
_PROPERTIES = st.sampled_from(
    [
        *["pose", "size", "name", "color", "drive", "localization", "range", "fov", "samples"],
        *["resolution", "interval_sim", "bitmap", "origin", "boundary", "laser_return"],
        *["ranger_return", "range_max", "range_min", "localization_origin", "update_interval"],
    ]
)
_KINDS = st.sampled_from(
    [
        *["model", "position", "ranger", "sensor", "laser", "window", "floorplan", "bot"],
        *["wall", "hokuyo", "unknown", "define"],
    ]
)


@st.composite
def _statement(draw: st.DrawFn, depth: int = 0) -> str:
    kind = draw(st.sampled_from(["property", "property", "entity", "define", "include", "junk"]))
    if kind == "property" or (kind == "entity" and depth >= 3):
        return f"{draw(_PROPERTIES)} {draw(_VALUES)}"
    if kind == "entity":
        body = " ".join(draw(st.lists(_statement(depth + 1), max_size=4)))
        return f"{draw(_KINDS)} ( {body} {draw(st.sampled_from([')', ')', '', '))']))}"
    if kind == "define":
        body = " ".join(draw(st.lists(_statement(depth + 1), max_size=3)))
        return f"define {draw(_KINDS)} {draw(_KINDS)} ( {body} )"
    if kind == "include":
        included = draw(st.sampled_from(['"other.inc"', '"main.world"', '"no.inc"', "x"]))
        return f"include {included}"
    return draw(st.text(alphabet='()[]"# \n.-01abc', max_size=12))


worlds = st.one_of(
    st.lists(_statement(), max_size=8).map("\n".join),
    st.lists(_statement(), max_size=4).map(lambda s: ROOM + "\n".join(s)),
    st.text(max_size=120),
)


@pytest.fixture(scope="module")
def folder() -> Any:
    with tempfile.TemporaryDirectory() as name:
        root = Path(name)
        (root / "other.inc").write_text('define bot position ( size [ 0.3 0.3 0.2 ] drive "diff" )')
        (root / "map.pgm").write_bytes(b"P5\n4 2\n255\n" + bytes([0, 255] * 4))
        yield root


def _run(folder: Path, text: str) -> None:
    path = folder / "main.world"
    path.write_text(text)
    try:
        with no_hang():
            world, grid = load_world(path)
            sim = StageSim(world, grid)
            for robot in range(len(world.robots)):
                sim.set_command(robot, 0.5, 0.0, 0.3)
            sim.step(scan_all=True)
    except WorldFileError as error:
        text = str(error)
        assert text
        assert "\n" not in text


@fuzz_settings(120)
@given(text=worlds)
def test_world_files_load_and_step_or_are_refused(folder: Path, text: str) -> None:
    _run(folder, text)


def test_a_world_cut_anywhere_is_refused_in_one_line(folder: Path) -> None:
    whole = room('pose [ 1 1 0 0 ] name "r0"', extra='model ( bitmap "map.pgm" size [ 2 1 1 ] )\n')
    for end in range(0, len(whole), 7):
        _run(folder, whole[:end])


BOMBS = {
    # Ten kilometres of wall at a micrometre: 10^19 cells.
    "grid cells": "resolution 0.000001\nmodel ( size [ 10000 10000 1 ] )\n",
    "grid far apart": "model ( pose [ -1e9 0 0 0 ] )\nmodel ( pose [ 1e9 0 0 0 ] )\n",
    "laser beams": "position ( ranger ( sensor ( range [ 0 8 ] fov 180 samples 1e9 ) ) )\n",
    "a step of three hundred years": "interval_sim 9223372036855.0\nposition ( )\n",
    "defines that double": "define d0 model ( )\n"
    + "".join(f"define d{i + 1} model ( d{i} ( ) d{i} ( ) )\n" for i in range(30))
    + "d30 ( )\n",
    "entities nested deep": "model ( " * 5000 + ") " * 5000,
    "defines in a chain": "".join(f"define d{i + 1} d{i} ( )\n" for i in range(3000))
    + "define d0 model ( )\nd3000 ( )\n",
}


@pytest.mark.parametrize("name", sorted(BOMBS))
def test_worlds_that_ask_for_gigabytes_are_refused(folder: Path, name: str) -> None:
    assert peak_allocation(lambda: _run(folder, BOMBS[name])) < WORLD_MEMORY_BOUND
    _run(folder, BOMBS[name])
