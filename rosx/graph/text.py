"""`draw`: a `ViewGraph` as text, left to right, the way rqt_graph lays it out.

Nodes are round boxes (``╭─╮``; dashed when unreachable), topics square boxes (``┌─┐``),
grouped topics double boxes (``╔═╗``). Edges leave a box on its right, run down or up a track
of their own between two columns and enter the next box on its left with an arrowhead. In
*Nodes only*, an edge's topic is written on it, halfway between the two nodes.
"""

from __future__ import annotations

import threading
from collections import OrderedDict
from dataclasses import dataclass, field

from rosx.graph.canvas import Canvas
from rosx.graph.layout import Layering, Route, layered
from rosx.graph.view import Edge, Kind, Vertex, ViewGraph

#: Rows between two stacked boxes; columns a gutter has beside its tracks.
ROW_GAP = 1
GUTTER_MARGIN = 2

_BORDERS = {
    Kind.NODE: ("╭", "╮", "╰", "╯", "─", "│"),
    Kind.TOPIC: ("┌", "┐", "└", "┘", "─", "│"),
    Kind.GROUP: ("╔", "╗", "╚", "╝", "═", "║"),
}
_DEAD_BORDERS = ("╭", "╮", "╰", "╯", "┄", "┆")
_LABEL = "l:"
#: Drawings kept for graphs seen again (the live view mostly redraws the same graph).
CACHE_SIZE = 4
_cache: OrderedDict[ViewGraph, Drawing] = OrderedDict()
_cache_lock = threading.Lock()


@dataclass(frozen=True)
class Box:
    """Where a vertex is drawn: top-left corner and size, in characters."""

    x: int
    y: int
    width: int
    height: int


@dataclass
class Drawing:
    """The lines of a drawing and where each vertex landed."""

    lines: list[str] = field(default_factory=list)
    boxes: dict[str, Box] = field(default_factory=dict)

    def __str__(self) -> str:
        return "\n".join(self.lines)


def with_label_vertices(graph: ViewGraph) -> ViewGraph:
    """Labelled edges split in two around a label vertex, so the layout leaves room for it."""
    vertices = list(graph.vertices)
    edges: list[Edge] = []
    for edge in graph.edges:
        if not edge.label:
            edges.append(edge)
            continue
        label_id = f"{_LABEL}{edge.source}>{edge.target}>{edge.label}"
        vertices.append(Vertex(label_id, edge.label, Kind.TOPIC))
        edges += [Edge(edge.source, label_id), Edge(label_id, edge.target)]
    return ViewGraph(tuple(vertices), tuple(edges))


def draw(graph: ViewGraph) -> Drawing:
    """Draw ``graph``; an empty graph draws as no lines. A graph drawn lately is not drawn
    again: its drawing comes back (a copy, sharing the lines' strings)."""
    if not graph.vertices:
        return Drawing()
    with _cache_lock:
        drawing = _cache.get(graph)
        if drawing is not None:
            _cache.move_to_end(graph)
    if drawing is None:
        split = with_label_vertices(graph)
        drawing = render(split, layered(split))
        with _cache_lock:
            _cache[graph] = drawing
            while len(_cache) > CACHE_SIZE:
                _cache.popitem(last=False)
    return Drawing(list(drawing.lines), dict(drawing.boxes))


def _size(vertex: Vertex | None) -> tuple[int, int]:
    if vertex is None:
        return 1, 1
    if vertex.id.startswith(_LABEL):
        return len(vertex.label) + 2, 1
    return len(vertex.label) + 4, 3


def render(graph: ViewGraph, layering: Layering) -> Drawing:
    """Turn a layering into characters."""
    vertices = {v.id: v for v in graph.vertices}
    columns = layering.columns
    sizes = [[_size(vertices.get(s) if s else None) for s in slots] for slots in columns]
    widths = [max(w for w, _ in column) for column in sizes]
    heights = [sum(h for _, h in column) + ROW_GAP * (len(column) - 1) for column in sizes]
    tallest = max(heights)
    tops: list[list[int]] = []
    for column, height in zip(sizes, heights, strict=True):
        y = (tallest - height) // 2
        tops.append([])
        for _, h in column:
            tops[-1].append(y)
            y += h + ROW_GAP

    def mid(slot: tuple[int, int]) -> int:
        c, r = slot
        return tops[c][r] + sizes[c][r][1] // 2

    segments: dict[int, list[tuple[tuple[int, int], tuple[int, int]]]] = {}
    for route in layering.routes:
        for a, b in zip(route.slots, route.slots[1:], strict=False):
            segments.setdefault(a[0], []).append((a, b))
    tracks = [_tracks(segments.get(gutter, []), mid) for gutter in range(len(columns) - 1)]
    lefts = [0]
    for c in range(len(columns) - 1):
        lefts.append(lefts[c] + widths[c] + 2 * len(set(tracks[c].values())) + GUTTER_MARGIN * 2)

    def span(slot: tuple[int, int]) -> tuple[int, int]:
        c, r = slot
        x = lefts[c] + (widths[c] - sizes[c][r][0]) // 2
        return x, x + sizes[c][r][0] - 1

    canvas = Canvas(lefts[-1] + widths[-1], tallest)
    drawing = Drawing()
    for route in layering.routes:
        _route(canvas, route, tracks, lefts, widths, span, mid)
    for c, slots in enumerate(columns):
        for r, slot_id in enumerate(slots):
            x0, x1 = span((c, r))
            if slot_id is None:
                canvas.hline(mid((c, r)), lefts[c], lefts[c] + widths[c] - 1)
                continue
            vertex = vertices[slot_id]
            _box(canvas, vertex, x0, tops[c][r])
            if not slot_id.startswith(_LABEL):
                drawing.boxes[slot_id] = Box(x0, tops[c][r], x1 - x0 + 1, sizes[c][r][1])
    drawing.lines = canvas.lines()
    return drawing


def _tracks(
    segments: list[tuple[tuple[int, int], tuple[int, int]]], mid: object
) -> dict[tuple[int, int], int]:
    """A track per tail slot in a gutter; tails whose rows overlap get different ones."""
    spans: dict[tuple[int, int], list[int]] = {}
    for a, b in segments:
        rows = spans.setdefault(a, [])
        rows += [mid(a), mid(b)]  # type: ignore[operator]
    ends: list[int] = []
    assigned: dict[tuple[int, int], int] = {}
    for tail, rows in sorted(spans.items(), key=lambda item: min(item[1])):
        low, high = min(rows), max(rows)
        track = next((i for i, end in enumerate(ends) if end < low), len(ends))
        if track == len(ends):
            ends.append(high)
        ends[track] = high
        assigned[tail] = track
    return assigned


def _route(
    canvas: Canvas,
    route: Route,
    tracks: list[dict[tuple[int, int], int]],
    lefts: list[int],
    widths: list[int],
    span: object,
    mid: object,
) -> None:
    for a, b in zip(route.slots, route.slots[1:], strict=False):
        gutter = a[0]
        ya, yb = mid(a), mid(b)  # type: ignore[operator]
        start = span(a)[1] + 1  # type: ignore[operator]
        end = span(b)[0] - 1  # type: ignore[operator]
        x = lefts[gutter] + widths[gutter] + GUTTER_MARGIN + 2 * tracks[gutter][a]
        canvas.hline(ya, start, x)
        canvas.vline(x, ya, yb)
        canvas.hline(yb, x, end)
    head_slot = route.slots[0] if route.reversed else route.slots[-1]
    target = route.edge.target
    if target.startswith(_LABEL):
        return
    if route.reversed:
        canvas.write(span(head_slot)[1] + 1, mid(head_slot), "◀")  # type: ignore[operator]
    else:
        canvas.write(span(head_slot)[0] - 1, mid(head_slot), "▶")  # type: ignore[operator]


def _box(canvas: Canvas, vertex: Vertex, x: int, y: int) -> None:
    if vertex.id.startswith(_LABEL):
        canvas.write(x, y, f" {vertex.label} ")
        return
    borders = _DEAD_BORDERS if vertex.unreachable else _BORDERS[vertex.kind]
    tl, tr, bl, br, horizontal, vertical = borders
    inner = len(vertex.label) + 2
    canvas.write(x, y, tl + horizontal * inner + tr)
    canvas.write(x, y + 1, f"{vertical} {vertex.label} {vertical}")
    canvas.write(x, y + 2, bl + horizontal * inner + br)
