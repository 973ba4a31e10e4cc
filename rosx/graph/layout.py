"""`layered`: a left-to-right Sugiyama layering of a `ViewGraph`, by grandalf.

grandalf ranks the vertices (cycles broken by reversing the feedback edges we pick, see
`LARGE_COMPONENT`), inserts a dummy vertex wherever an edge spans several ranks and orders
each rank to reduce crossings. What comes out is columns of slots, each a vertex or a dummy,
and for every edge the slots it runs through; `text` turns that into characters. grandalf is
imported on first use only.

The live view refreshes every second or so and mostly finds the same graph: `layered` keeps
the last few layerings, keyed by the graph's vertex ids and edges (all the layering depends
on), and hands them back without asking grandalf again.
"""

from __future__ import annotations

import heapq
import threading
from collections import OrderedDict, deque
from dataclasses import dataclass
from typing import Any

from rosx.graph.view import Edge, ViewGraph

#: Rounds of grandalf's crossing reduction (each sweeps down and up once).
ORDERING_ROUNDS = 2
#: Components with at least this many vertices break their cycles by Eades, Lin and Smyth's
#: vertex order and let grandalf's rank optimisation shorten edges (`_large_feedback`). A
#: depth-first search's feedback edges leave a path through nearly every vertex of a large,
#: dense graph: as many columns, and a dummy for each one an edge crosses (a 200-node ROS graph
#: got 260 columns and 75,000 dummies, most of the time grandalf and the drawing took). Smaller
#: components keep the depth-first layout they always had.
LARGE_COMPONENT = 100
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
    from grandalf.graphs import Edge as GEdge  # grandalf only to lay out a graph
    from grandalf.graphs import Vertex as GVertex  # grandalf only to lay out a graph
    from grandalf.layouts import SugiyamaLayout, VertexViewer  # grandalf only to lay out a graph

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
        large = len(component.sV) >= LARGE_COMPONENT
        feedback = _large_feedback(component) if large else _feedback(component)
        # grandalf ranks from these and from every vertex the feedback leaves without in-edges
        layout.init_all(roots=_sources(component), inverted_edges=feedback, optimize=large)
        for _ in range(ORDERING_ROUNDS):
            for _ in layout.ordering_step():
                pass
        _place(layout, component, columns, routes)
    return Layering(tuple(tuple(c) for c in columns), tuple(routes))


def _components(vertices: list[Any], edges: list[Any]) -> list[Any]:
    """grandalf's ``Graph(vertices, edges).C``, vertices in the same order, built directly.

    grandalf's `graph_core` checks that a component is connected at a cost quadratic in its
    vertices, and its `Graph` scans the vertex and component lists once per edge and gathers a
    component's edges in a set, whose order (hence where grandalf puts dummies) changed from
    run to run. Here a component's edges keep the order of ``edges``."""
    from grandalf.graphs import graph_core  # grandalf only to lay out a graph
    from grandalf.utils import Poset  # grandalf only to lay out a graph

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
    edge_lists: dict[int, list[Any]] = {key: [] for key in sets}
    for edge in edges:
        edge_lists[id(edge.v[0].c)].append(edge)
    components = []
    for key, vertex_set in sets.items():
        component = graph_core(directed=True)
        component.sV = vertex_set
        component.sE = Poset(edge_lists[key])
        for vertex in vertex_set:
            vertex.c = component
        components.append(component)
    return components


def _sources(component: Any) -> list[Any]:
    """Vertices without in-edges (none when every vertex is on a cycle)."""
    return [v for v in component.sV if not v.e_in()]


def _feedback(component: Any) -> list[Any]:
    """Edges closing a cycle, found by an iterative depth-first search (grandalf's own is
    recursive and overflows Python's stack on large graphs)."""
    state: dict[Any, int] = {}  # 1 on the stack, 2 done
    feedback = []
    for root in [*_sources(component), *component.sV]:
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


def _large_feedback(component: Any) -> list[Any]:
    """Edges running backwards in Eades, Lin and Smyth's order of the vertices: sinks are
    peeled off to the back, sources to the front, and when neither is left the vertex with
    most out- over in-edges goes to the front. It reverses fewer edges than a depth-first
    search and leaves short paths, so few ranks (see `LARGE_COMPONENT`)."""
    vertices = list(component.sV)
    ins = {v: len(v.e_in()) for v in vertices}
    outs = {v: len(v.e_out()) for v in vertices}
    sinks = deque(v for v in vertices if not outs[v])
    sources = deque(v for v in vertices if outs[v] and not ins[v])
    # (in - out, index, vertex): the top has most out- over in-edges; entries go stale
    # when a vertex's degrees change, and a new one is pushed
    heap = [(ins[v] - outs[v], i, v) for i, v in enumerate(vertices)]
    heapq.heapify(heap)
    index = {v: i for i, v in enumerate(vertices)}
    left = set(vertices)
    front: list[Any] = []
    back: list[Any] = []
    while left:
        if sinks:
            vertex, side = sinks.popleft(), back
        elif sources:
            vertex, side = sources.popleft(), front
        else:
            key, _, vertex = heapq.heappop(heap)
            if vertex in left and key != ins[vertex] - outs[vertex]:
                continue  # stale: the vertex has a newer entry
            side = front
        if vertex not in left:
            continue  # placed already
        left.discard(vertex)
        side.append(vertex)
        for edge in vertex.e_out():
            head = edge.v[1]
            if head in left:
                ins[head] -= 1
                if not ins[head] and outs[head]:
                    sources.append(head)
                heapq.heappush(heap, (ins[head] - outs[head], index[head], head))
        for edge in vertex.e_in():
            tail = edge.v[0]
            if tail in left:
                outs[tail] -= 1
                if not outs[tail]:
                    sinks.append(tail)
                heapq.heappush(heap, (ins[tail] - outs[tail], index[tail], tail))
    position = {v: i for i, v in enumerate([*front, *reversed(back)])}
    return [e for e in component.sE if position[e.v[0]] > position[e.v[1]]]


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
