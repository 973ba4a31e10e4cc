"""`layered`: a left-to-right Sugiyama layering of a `ViewGraph`, by grandalf.

grandalf ranks the vertices (cycles broken by reversing feedback edges), inserts a dummy
vertex wherever an edge spans several ranks and orders each rank to reduce crossings. What
comes out is columns of slots, each a vertex or a dummy, and for every edge the slots it runs
through; `text` turns that into characters. grandalf is imported on first use only.

The live view refreshes every second or so and mostly finds the same graph: `layered` keeps
the last few layerings, keyed by the graph's vertex ids and edges (all the layering depends
on), and hands them back without asking grandalf again.
"""

from __future__ import annotations

import threading
from collections import OrderedDict
from dataclasses import dataclass
from typing import Any

from rosx.graph.view import Edge, ViewGraph

#: Rounds of grandalf's crossing reduction (each sweeps down and up once).
ORDERING_ROUNDS = 2
#: Layerings kept for graphs seen again.
CACHE_SIZE = 4

_Key = tuple[tuple[str, ...], tuple[Edge, ...]]
_cache: OrderedDict[_Key, Layering] = OrderedDict()
_cache_lock = threading.Lock()


@dataclass(frozen=True)
class Route:
    """An edge's path: the slots it runs through, from its tail to its head, as
    ``(column, row)``; ``reversed`` when grandalf drew it backwards to break a cycle."""

    edge: Edge
    slots: tuple[tuple[int, int], ...]
    reversed: bool


@dataclass(frozen=True)
class Layering:
    """Columns of slots: a vertex id, or ``None`` for a dummy an edge passes through."""

    columns: tuple[tuple[str | None, ...], ...]
    routes: tuple[Route, ...]


def layered(graph: ViewGraph) -> Layering:
    """Lay out ``graph``: connected components one below the other, sharing columns."""
    key = (tuple(v.id for v in graph.vertices), graph.edges)
    with _cache_lock:
        if key in _cache:
            _cache.move_to_end(key)
            return _cache[key]
    layering = _layered(graph)
    with _cache_lock:
        _cache[key] = layering
        while len(_cache) > CACHE_SIZE:
            _cache.popitem(last=False)
    return layering


def _layered(graph: ViewGraph) -> Layering:
    from grandalf.graphs import Edge as GEdge
    from grandalf.graphs import Vertex as GVertex
    from grandalf.layouts import SugiyamaLayout, VertexViewer

    gvertices = {v.id: GVertex(v.id) for v in graph.vertices}
    for gvertex in gvertices.values():
        gvertex.view = VertexViewer(w=len(gvertex.data) + 4, h=3)
    gedges = []
    for edge in graph.edges:
        if edge.source != edge.target:
            gedge = GEdge(gvertices[edge.source], gvertices[edge.target], data=edge)
            gedges.append(gedge)
    columns: list[list[str | None]] = []
    routes: list[Route] = []
    for component in _components(list(gvertices.values()), gedges):
        layout = SugiyamaLayout(component)
        layout.init_all(roots=_roots(component), inverted_edges=_feedback(component))
        for _ in range(ORDERING_ROUNDS):
            for _ in layout.ordering_step():
                pass
        _place(layout, component, columns, routes)
    return Layering(tuple(tuple(c) for c in columns), tuple(routes))


def _components(vertices: list[Any], edges: list[Any]) -> list[Any]:
    """grandalf's ``Graph(vertices, edges).C``, in the same order, without its checks that
    scan the vertex and component lists once per edge (quadratic on large graphs)."""
    from grandalf.graphs import graph_core
    from grandalf.utils import Poset

    for vertex in vertices:
        vertex.c = Poset([vertex])
    sets = {id(v.c): v.c for v in vertices}  # in vertex order, as grandalf's list
    for edge in edges:
        x, y = edge.v
        edge.attach()
        if x.c is not y.c:
            merged = y.c
            x.c.update(merged)
            del sets[id(merged)]
            for z in merged:
                z.c = x.c
    components = []
    for vertex_set in sets.values():
        edge_set: set[Any] = set()
        for vertex in vertex_set:
            edge_set.update(vertex.e)
        components.append(graph_core(vertex_set, edge_set, True))
    return components


def _roots(component: Any) -> list[Any]:
    roots = [v for v in component.sV if not v.e_in()]
    return roots or [component.sV[0]]


def _feedback(component: Any) -> list[Any]:
    """Edges closing a cycle, found by an iterative depth-first search (grandalf's own is
    recursive and overflows Python's stack on large graphs)."""
    state: dict[Any, int] = {}  # 1 on the stack, 2 done
    feedback = []
    for root in [*_roots(component), *component.sV]:
        if root in state:
            continue
        state[root] = 1
        stack = [(root, iter(root.e_out()))]
        while stack:
            vertex, edges = stack[-1]
            edge = next(edges, None)
            if edge is None:
                state[vertex] = 2
                stack.pop()
                continue
            head = edge.v[1]
            if state.get(head) == 1:
                feedback.append(edge)
            elif head not in state:
                state[head] = 1
                stack.append((head, iter(head.e_out())))
    return feedback


def _place(
    layout: Any, component: Any, columns: list[list[str | None]], routes: list[Route]
) -> None:
    while len(columns) < len(layout.layers):
        columns.append([])
    position: dict[Any, tuple[int, int]] = {}
    for rank, layer in enumerate(layout.layers):
        column = columns[rank]
        for vertex in layer:
            position[vertex] = (rank, len(column))
            column.append(vertex.data if hasattr(vertex, "data") else None)
    for gedge in component.sE:
        tail, head = gedge.v
        reverse = layout.grx[tail].rank > layout.grx[head].rank
        ctrl = {0: head, 1: tail} if reverse else {0: tail, 1: head}
        if gedge in layout.ctrls:
            ctrl = layout.ctrls[gedge]
        slots = tuple(position[ctrl[r]] for r in sorted(ctrl))
        routes.append(Route(gedge.data, slots, reverse))
