"""`layered` on graphs with no source vertex and on components large enough to break their
cycles by Eades, Lin and Smyth's order (`LARGE_COMPONENT`)."""

from __future__ import annotations

import random

from rosx.graph import layout
from rosx.graph.builder import build
from rosx.graph.layout import LARGE_COMPONENT, Layering
from rosx.graph.options import GraphOptions, Mode
from rosx.graph.state import GraphState
from rosx.graph.text import draw, with_label_vertices
from rosx.graph.view import Edge, Kind, Vertex, ViewGraph


def graph(edges: list[tuple[str, str]]) -> ViewGraph:
    names = sorted({name for edge in edges for name in edge})
    return ViewGraph(
        tuple(Vertex(n, n, Kind.NODE) for n in names), tuple(Edge(a, b) for a, b in edges)
    )


def random_state(nodes: int, topics: int, seed: int) -> GraphState:
    """Each topic has one publisher and two subscribers, picked at random."""
    rng = random.Random(seed)
    pubs, subs = {}, {}
    for t in range(topics):
        pub, *sub = rng.sample(range(nodes), 3)
        pubs[f"/t{t}"] = (f"/n{pub}",)
        subs[f"/t{t}"] = tuple(f"/n{s}" for s in sub)
    return GraphState(pubs, subs)


def check(view: ViewGraph, layering: Layering) -> None:
    """Every vertex has one slot; every edge runs column by column from its tail's slot to its
    head's (backwards when reversed)."""
    where = {}
    for c, column in enumerate(layering.columns):
        for r, slot in enumerate(column):
            if slot is not None:
                assert slot not in where
                where[slot] = (c, r)
    assert set(where) == {v.id for v in view.vertices}
    assert sorted(map(repr, (r.edge for r in layering.routes))) == sorted(
        repr(e) for e in view.edges if e.source != e.target
    )
    for route in layering.routes:
        tail, head = route.slots[0], route.slots[-1]
        if route.reversed:
            tail, head = head, tail
        assert (tail, head) == (where[route.edge.source], where[route.edge.target])
        columns = [c for c, _ in route.slots]
        assert columns == list(range(columns[0], columns[0] + len(columns)))


def test_a_cycle_without_sources_lays_out() -> None:
    # /a and /c talk to each other; /d, which only /c reaches, is met first: the search from
    # /d does not break the cycle through it, so /d is no source for grandalf to rank from
    view = graph([("/a", "/b"), ("/a", "/c"), ("/c", "/a"), ("/d", "/b"), ("/c", "/d")])
    check(view, layout._layered(view))


def test_large_components_lay_out_in_few_columns() -> None:
    view = with_label_vertices(build(random_state(60, 150, 1), GraphOptions(mode=Mode.NODES)))
    assert len(view.vertices) >= LARGE_COMPONENT
    layering = layout._layered(view)
    check(view, layering)
    # a depth-first search's feedback left 84 columns
    assert len(layering.columns) < 60
    assert layout._layered(view) == layering


def test_large_graph_draws_every_box() -> None:
    state = random_state(40, 100, 2)
    for mode in (Mode.NODES, Mode.ALL):
        view = build(state, GraphOptions(mode=mode))
        drawing = draw(view)
        assert set(drawing.boxes) == {v.id for v in view.vertices}
