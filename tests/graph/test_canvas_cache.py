"""The character canvas's junctions, and the layout and drawing caches."""

from __future__ import annotations

from rosx.graph import layout, text
from rosx.graph.builder import build
from rosx.graph.canvas import Canvas
from rosx.graph.options import GraphOptions, Mode
from rosx.graph.text import draw
from tests.support.graph_states import lab1


def test_lines_join_into_junctions_and_text_wins() -> None:
    canvas = Canvas(3, 2)
    canvas.hline(2, 0, 4)
    canvas.vline(2, 0, 4)
    canvas.hline(0, 2, 4)
    canvas.write(4, 4, "▶")
    assert canvas.lines() == ["  ┌──", "  │", "──┼──", "  │", "  │ ▶"]


def test_same_graph_draws_from_the_cache_as_a_copy() -> None:
    graph = build(lab1(), GraphOptions(mode=Mode.ALL))
    text._cache.clear()
    layout._cache.clear()
    first = draw(graph)
    again = draw(graph)
    assert again == first
    assert again is not first and again.lines is not first.lines
    assert len(layout._cache) == 1
