"""The pond's drawing, without a terminal: fitting, shrinking, sprites, rows, scenes, feeds."""

from __future__ import annotations

import math

import numpy as np
import pytest

from rosx_turtle.engine.constants import CENTRE, DEFAULT_BACKGROUND
from rosx_turtle.view.adapt import SceneMaker, background_of
from rosx_turtle.view.fit import fit_square
from rosx_turtle.view.halfblock import UPPER_HALF, CellPainter
from rosx_turtle.view.raster import Shrinker
from rosx_turtle.view.renderer import PondRenderer
from rosx_turtle.view.scene import Scene, TurtlePose
from rosx_turtle.view.sprite import DIRECTIONS, direction_of, sprite_offsets
from rosx_turtle.view.status import arrow, pose_echo, status_text
from tests.support.tui import Pond

BLUE = DEFAULT_BACKGROUND


def canvas(fill: tuple[int, int, int] = BLUE) -> np.ndarray:
    pixels = np.empty((500, 500, 3), np.uint8)
    pixels[:] = fill
    return pixels


@pytest.mark.parametrize(
    ("width", "height", "side", "left", "top"),
    [
        (80, 24, 48, 16, 0),  # wide: limited by the rows, two pixels each
        (40, 40, 40, 0, 10),  # tall: limited by the columns
        (81, 50, 80, 0, 5),  # an odd width loses a column to keep two pixels a row
        (1, 1, 0, 0, 0),  # too small to draw
    ],
)
def test_fit_keeps_the_world_square_and_centred(
    width: int, height: int, side: int, left: int, top: int
) -> None:
    fit = fit_square(width, height)
    assert (fit.side, fit.left, fit.top, fit.rows) == (side, left, top, side // 2)


def test_shrinking_keeps_thin_trails_at_full_colour() -> None:
    pixels = canvas()
    pixels[243:246, :] = (255, 0, 0)  # a 3-pixel pen across the pond
    pixels[:, 100] = (0, 255, 0)  # a 1-pixel pen down it
    small = Shrinker(50, 500).shrink(pixels, BLUE)
    assert small.shape == (50, 50, 3)
    assert (small[24, 0] == (255, 0, 0)).all()  # 3 of 10 rows: shown fully
    r, g, b = small[0, 10].tolist()  # 1 of 10 columns: a clear tint, not lost
    assert g > 150 and b < 170 and r < BLUE[0]
    assert (small[5, 40] == BLUE).all()


def test_shrinking_again_only_the_band_that_changed() -> None:
    shrinker = Shrinker(100, 500)
    before, after = canvas(), canvas()
    after[300:303, 50:60] = (255, 255, 0)
    band = shrinker.changed_rows(before, after)
    assert band == slice(60, 61)
    assert shrinker.changed_rows(before, before.copy()) is None
    whole = shrinker.shrink(after, BLUE)
    assert (shrinker.shrink(after, BLUE, band) == whole[band]).all()


def test_a_pond_bigger_than_the_canvas_samples_it() -> None:
    pixels = canvas()
    pixels[0:250] = (0, 0, 0)
    big = Shrinker(600, 500).shrink(pixels, BLUE)
    assert big.shape == (600, 600, 3)
    assert (big[299] == 0).all() and (big[301] == BLUE).all()


def test_the_head_leads_in_every_direction() -> None:
    assert direction_of(0.0) == 0 and direction_of(math.pi / 2) == 4
    assert direction_of(-math.pi) == direction_of(math.pi) == 8
    for scale in (3.0, 7.0, 12.0, 40.0):
        for direction in range(DIRECTIONS):
            rows, cols, parts = sprite_offsets(scale, direction)
            head = parts == parts.max()
            angle = direction * 2 * math.pi / DIRECTIONS
            ahead = cols[head] * math.cos(angle) - rows[head] * math.sin(angle)
            assert ahead.mean() > 1.0  # the head is in front of the centre


def test_cells_are_half_blocks_in_runs() -> None:
    upper = np.array([[1, 2, 3], [1, 2, 3], [9, 9, 9]], np.uint8)
    lower = np.array([[4, 5, 6], [4, 5, 6], [4, 5, 6]], np.uint8)
    painter = CellPainter()
    segments = painter.row(upper, lower)
    assert [s.text for s in segments] == [UPPER_HALF * 2, UPPER_HALF]
    style = segments[0].style
    assert style is not None and style.color is not None and style.bgcolor is not None
    assert style.color.triplet == (1, 2, 3) and style.bgcolor.triplet == (4, 5, 6)
    assert painter.row(upper, lower)[0].style is style  # one style per colour pair


def scene(x: float, theta: float = 0.0, pixels: np.ndarray | None = None) -> Scene:
    turtle = TurtlePose("turtle1", x, CENTRE, theta)
    return Scene(canvas() if pixels is None else pixels, 1, BLUE, (turtle,))


def test_the_renderer_repaints_only_rows_that_changed() -> None:
    renderer = PondRenderer()
    assert renderer.resize(50, 30) == list(range(30))
    first = scene(3.0)
    assert renderer.update(first) == list(range(2, 27))  # 25 rows, centred: margins stay
    assert renderer.update(first) == []  # nothing changed
    assert renderer.update(scene(3.0)) == []  # an equal scene: the same picture
    moved = renderer.update(scene(6.0))
    assert moved and len(moved) <= 6  # the rows around the turtle
    assert renderer.update(scene(6.0, theta=math.pi)) == moved  # turned: the same rows
    assert all(sum(len(s.text) for s in renderer.line(y)) == 50 for y in range(30))


def test_status_and_echo_texts() -> None:
    turtle = TurtlePose("turtle1", 5.544444561004639, 5.544444561004639, 0.0)
    assert status_text([turtle]) == "turtle1 → x=5.54 y=5.54 θ=0.00"
    assert status_text([]) == "no turtles (call /spawn or /reset)"
    assert arrow(math.pi / 2) == "↑" and arrow(-3 * math.pi / 4) == "↙"
    assert pose_echo(turtle).splitlines() == [
        "x: 5.544444561004639",
        "y: 5.544444561004639",
        "theta: 0.0",
        "linear_velocity: 0.0",
        "angular_velocity: 0.0",
    ]


def test_scenes_from_the_engine() -> None:
    pond = Pond()
    maker = SceneMaker()
    first = maker.make(pond.sim)
    assert maker.make(pond.sim) is first  # nothing changed
    assert first.background == BLUE
    (turtle,) = first.turtles
    assert (turtle.name, turtle.x, turtle.y) == ("turtle1", CENTRE, CENTRE)
    pond.drive("turtle1", 2.0, 0.0, ticks=10)
    moved = maker.make(pond.sim)
    assert moved.canvas_version != first.canvas_version and moved.canvas is not first.canvas
    assert moved.turtles[0].x > CENTRE and moved.turtles[0].linear_velocity == 2.0
    pond.sim.clear((10, 20, 30))
    assert maker.make(pond.sim).background == (10, 20, 30)


def test_the_background_survives_trails() -> None:
    pixels = canvas()
    pixels[:, :200] = (255, 255, 255)  # trails over two fifths of the pond
    assert background_of(pixels, BLUE) == BLUE
    assert background_of(canvas((1, 2, 3)), BLUE) == (1, 2, 3)
