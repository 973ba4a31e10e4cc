"""The trail canvas: aliased square-capped strokes, in order, and the colour sensor's pixel."""

from __future__ import annotations

import numpy as np
import pytest

from rosx_turtle.engine import Canvas, Segments
from rosx_turtle.engine.raster import stroke_pixels


def strokes(
    *lines: tuple[float, float, float, float, int], rgb: tuple[int, int, int] = (255, 0, 0)
) -> Segments:
    array = np.array([line[:4] for line in lines], np.float64)
    return Segments(
        array[:, 0],
        array[:, 1],
        array[:, 2],
        array[:, 3],
        np.tile(np.array(rgb, np.uint8), (len(lines), 1)),
        np.array([line[4] for line in lines], np.int32),
    )


def brute_force(
    x0: float, y0: float, x1: float, y1: float, width: int, size: int
) -> set[tuple[int, int]]:
    """Every pixel centre tested against the rectangle, one by one (the rule, spelled out)."""
    length = np.hypot(x1 - x0, y1 - y0)
    ux, uy = ((x1 - x0) / length, (y1 - y0) / length) if length else (1.0, 0.0)
    half = width / 2
    found = set()
    for row in range(size):
        for column in range(size):
            along = (column - x0) * ux + (row - y0) * uy
            across = (row - y0) * ux - (column - x0) * uy
            if -half <= along < length + half and -half <= across < half:
                found.add((row, column))
    return found


def pixels(segments: Segments, size: int) -> set[tuple[int, int]]:
    flat, _ = stroke_pixels(segments, size)
    return {(int(f) // size, int(f) % size) for f in flat}


def test_a_horizontal_stroke_is_width_pixels_thick_with_square_caps() -> None:
    covered = pixels(strokes((10.0, 20.0, 15.0, 20.0, 3)), 64)
    assert covered == {(row, column) for row in (19, 20, 21) for column in range(9, 17)}


def test_a_one_pixel_stroke() -> None:
    covered = pixels(strokes((10.0, 20.0, 10.0, 25.0, 1)), 64)
    assert covered == {(row, 10) for row in range(20, 26)}


def test_a_zero_length_stroke_is_a_square() -> None:
    covered = pixels(strokes((10.0, 10.0, 10.0, 10.0, 3)), 64)
    assert covered == {(r, c) for r in (9, 10, 11) for c in (9, 10, 11)}


@pytest.mark.parametrize("seed", range(6))
def test_random_strokes_match_the_rule(seed: int) -> None:
    rng = np.random.default_rng(seed)
    size = 48
    for _ in range(12):
        x0, y0 = rng.uniform(-5, size + 5, 2)
        if rng.random() < 0.5:
            x1, y1 = x0 + rng.uniform(-3, 3), y0 + rng.uniform(-3, 3)
        else:
            x1, y1 = rng.uniform(-5, size + 5, 2)
        width = int(rng.choice([1, 2, 3, 4, 7, 20]))
        expected = brute_force(x0, y0, x1, y1, width, size)
        assert pixels(strokes((x0, y0, x1, y1, width)), size) == expected


def test_strokes_are_cut_and_grouped_but_keep_their_order() -> None:
    rng = np.random.default_rng(11)
    size = 64
    lines = []
    for k in range(40):
        x0, y0 = rng.uniform(0, size, 2)
        far = k % 3 == 0
        x1, y1 = (rng.uniform(0, size, 2)) if far else (x0 + rng.uniform(-2, 2), y0 + 1.0)
        lines.append((x0, y0, x1, y1, int(rng.choice([1, 3, 9]))))
    segments = strokes(*lines)
    flat, owner = stroke_pixels(segments, size)
    assert (np.diff(owner) >= 0).all()
    for k, line in enumerate(lines):
        assert {(int(f) // size, int(f) % size) for f in flat[owner == k]} == brute_force(
            *line, size
        )


def test_later_strokes_paint_over_earlier_ones() -> None:
    canvas = Canvas((0, 0, 0), size=32)
    red = strokes((0.0, 10.0, 31.0, 10.0, 3), rgb=(255, 0, 0))
    blue = strokes((10.0, 0.0, 10.0, 31.0, 3), rgb=(0, 0, 255))
    canvas.draw(red + blue)
    assert tuple(canvas.pixels[10, 10]) == (0, 0, 255)
    assert tuple(canvas.pixels[10, 20]) == (255, 0, 0)
    assert tuple(canvas.pixels[20, 20]) == (0, 0, 0)


def test_canvas_fill_version_and_snapshot() -> None:
    canvas = Canvas()
    assert canvas.pixels.shape == (500, 500, 3)
    assert tuple(canvas.pixels[0, 0]) == (69, 86, 255)
    version = canvas.version
    copy = canvas.snapshot()
    canvas.fill((1, 2, 3))
    assert canvas.version > version
    assert tuple(copy[0, 0]) == (69, 86, 255)
    assert copy.flags["C_CONTIGUOUS"]


def test_sample_rounds_like_qt_and_reads_black_off_the_canvas() -> None:
    canvas = Canvas((0, 0, 0), size=32)
    canvas.pixels[3, 2] = (9, 9, 9)
    # 2.5 px → 3 (half up), 2.49 px → 2; positions are metres (45 px each).
    colours = canvas.sample([2 / 45, 2.49 / 45, 40 / 45], [2.5 / 45, 3.6 / 45, 0.0])
    assert colours.tolist() == [[9, 9, 9], [0, 0, 0], [0, 0, 0]]
    assert canvas.sample([2.49 / 45], [3.0 / 45]).tolist() == [[9, 9, 9]]
