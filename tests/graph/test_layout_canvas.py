"""The canvas the layout is drawn on keeps what it holds when it grows."""

from __future__ import annotations

from rosx.graph.canvas import Canvas


def test_growing_wider_and_taller_keeps_the_drawing() -> None:
    canvas = Canvas(2, 2)
    canvas.vline(1, 0, 2)
    canvas.write(0, 1, "a")
    canvas.hline(1, 1, 6)
    canvas.vline(6, 1, 4)
    canvas.write(7, 4, "◀")
    assert canvas.lines() == [" │", "a├────┐", " │    │", "      │", "      │◀"]
    assert (canvas.width, canvas.height) == (8, 5)


def test_empty_rows_and_columns_are_not_drawn() -> None:
    canvas = Canvas(40, 10)
    canvas.vline(3, 2, 2)  # a line of one row is nothing
    canvas.hline(1, 0, 1)
    assert canvas.lines() == ["", "──"]
