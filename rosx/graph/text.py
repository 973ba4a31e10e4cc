"""`draw`: a `ViewGraph` as text, left to right, the way rqt_graph lays it out.

Nodes are round boxes (``╭─╮``; dashed when unreachable), topics square boxes (``┌─┐``),
grouped topics double boxes (``╔═╗``). Edges leave a box on its right, run down or up a track
of their own between two columns and enter the next box on its left with an arrowhead. In
*Nodes only*, an edge's topic is written on it, halfway between the two nodes.

Namespaces (rqt_graph's "Group: Namespaces") are dotted frames titled with the namespace.
rqt_graph's one box per namespace cannot stay a rectangle in a layered drawing, so each column
gathers a namespace's members one under the other inside a frame of its own: a namespace
spread over three columns is three frames bearing its name.
"""

from __future__ import annotations

import threading
from collections import OrderedDict
from collections.abc import Callable
from dataclasses import dataclass, field

from rosx.graph.canvas import Canvas
from rosx.graph.layout import Layering, Route, layered
from rosx.graph.view import Edge, Kind, Vertex, ViewGraph

#: Rows between two stacked boxes; columns a gutter has beside its tracks.
ROW_GAP = 1
GUTTER_MARGIN = 2
#: Columns between a namespace frame and what it holds.
FRAME_PAD = 2

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


#: A stretch of an edge: rows ``y0``..``y1`` and columns ``x0``..``x1``, ends included (one of
#: the two ranges is a single row or column).
Stretch = tuple[int, int, int, int]
#: A slot of a layering: ``(column, row)``.
Slot = tuple[int, int]


@dataclass(frozen=True)
class Frame:
    """A namespace's frame in one column; ``box`` is its outline."""

    namespace: str
    box: Box


@dataclass
class Drawing:
    """The lines of a drawing, where each vertex landed, the stretches each edge runs along
    (its arrowhead and, in *Nodes only*, its topic label included) and the namespace frames."""

    lines: list[str] = field(default_factory=list)
    boxes: dict[str, Box] = field(default_factory=dict)
    paths: dict[Edge, tuple[Stretch, ...]] = field(default_factory=dict)
    frames: tuple[Frame, ...] = ()

    def __str__(self) -> str:
        return "\n".join(self.lines)

    def copy(self) -> Drawing:
        """A copy whose containers can change without touching this one."""
        return Drawing(list(self.lines), dict(self.boxes), dict(self.paths), self.frames)


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
    return drawing.copy()


def _original(edge: Edge) -> Edge:
    """The graph's edge a drawn edge belongs to: a labelled edge was drawn as two halves
    around its label vertex (`with_label_vertices`)."""
    for end in (edge.source, edge.target):
        if end.startswith(_LABEL):
            source, target, label = end[len(_LABEL) :].split(">", 2)
            return Edge(source, target, label)
    return edge


def _size(vertex: Vertex | None) -> tuple[int, int]:
    if vertex is None:
        return 1, 1
    if vertex.id.startswith(_LABEL):
        return len(vertex.label) + 2, 1
    return len(vertex.label) + 4, 3


def _clusters(vertex: Vertex | None) -> tuple[str, ...]:
    return () if vertex is None else vertex.clusters


def _grouped(layering: Layering, vertices: dict[str, Vertex]) -> Layering:
    """``layering`` with each column's namespace members one under the other.

    A namespace moves up to where its first member was; everything else keeps its order.
    """
    moves: list[dict[int, int]] = []
    columns = []
    for slots in layering.columns:
        first: dict[tuple[str, ...], int] = {}
        keys = []
        for row, slot in enumerate(slots):
            path = _clusters(vertices.get(slot) if slot else None)
            key = []
            for depth in range(1, len(path) + 1):
                key.append(first.setdefault(path[:depth], row))
            keys.append((*key, row))
        order = sorted(range(len(slots)), key=keys.__getitem__)
        moves.append({old: new for new, old in enumerate(order)})
        columns.append(tuple(slots[old] for old in order))
    routes = tuple(
        Route(route.edge, tuple((c, moves[c][r]) for c, r in route.slots), route.reversed)
        for route in layering.routes
    )
    return Layering(tuple(columns), routes)


def _stack(
    column: list[tuple[str, ...]], heights: list[int]
) -> tuple[list[int], list[tuple[str, int, int, int]], int]:
    """Rows for one column's slots (given each one's namespaces and height), and its frames
    as ``(namespace, depth, top row, bottom row)``; returns also the column's height."""
    tops: list[int] = []
    frames: list[tuple[str, int, int, int]] = []
    open_: list[tuple[str, int]] = []  # (namespace, top row), outermost first
    y = 0

    def close(keep: int) -> None:
        nonlocal y
        while len(open_) > keep:
            namespace, top = open_.pop()
            frames.append((namespace, len(open_), top, y))
            y += 1

    for row, (path, height) in enumerate(zip(column, heights, strict=True)):
        keep = 0
        while keep < min(len(open_), len(path)) and open_[keep][0] == path[keep]:
            keep += 1
        close(keep)
        if row:
            y += ROW_GAP
        for namespace in path[keep:]:
            open_.append((namespace, y))
            y += 1
        tops.append(y)
        y += height
    close(0)
    return tops, frames, y


def render(graph: ViewGraph, layering: Layering) -> Drawing:
    """Turn a layering into characters."""
    vertices = {v.id: v for v in graph.vertices}
    layering = _grouped(layering, vertices)
    columns = layering.columns
    paths = [[_clusters(vertices.get(s) if s else None) for s in slots] for slots in columns]
    sizes = [[_size(vertices.get(s) if s else None) for s in slots] for slots in columns]
    widths = [
        max(w + 2 * FRAME_PAD * len(path) for (w, _), path in zip(sizes[c], paths[c], strict=True))
        for c in range(len(columns))
    ]
    stacks = [_stack(paths[c], [h for _, h in sizes[c]]) for c in range(len(columns))]
    tallest = max(height for _, _, height in stacks)
    tops: list[list[int]] = []
    column_frames: list[list[tuple[str, int, int, int]]] = []
    for column_tops, stacked, height in stacks:
        shift = (tallest - height) // 2
        tops.append([y + shift for y in column_tops])
        column_frames.append([(ns, depth, y0 + shift, y1 + shift) for ns, depth, y0, y1 in stacked])

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
    paths_of: dict[Edge, list[Stretch]] = {}
    for route in layering.routes:
        stretches = paths_of.setdefault(_original(route.edge), [])
        stretches += _route(canvas, route, tracks, lefts, widths, span, mid)
    for c, slots in enumerate(columns):
        for r, slot_id in enumerate(slots):
            x0, x1 = span((c, r))
            if slot_id is None:
                y = mid((c, r))
                canvas.hline(y, lefts[c], lefts[c] + widths[c] - 1)
                continue
            vertex = vertices[slot_id]
            _box(canvas, vertex, x0, tops[c][r])
            box = Box(x0, tops[c][r], x1 - x0 + 1, sizes[c][r][1])
            if slot_id.startswith(_LABEL):
                edge = _original(Edge(slot_id, slot_id))
                paths_of.setdefault(edge, []).append((box.y, box.y, x0, x1))
            else:
                drawing.boxes[slot_id] = box
    frames: list[Frame] = []
    for c, column in enumerate(column_frames):
        for namespace, depth, y0, y1 in column:
            x0 = lefts[c] + FRAME_PAD * depth
            box = Box(x0, y0, widths[c] - 2 * FRAME_PAD * depth, y1 - y0 + 1)
            _frame(canvas, namespace, box)
            frames.append(Frame(namespace, box))
    drawing.lines = canvas.lines()
    drawing.paths = {edge: tuple(stretches) for edge, stretches in paths_of.items()}
    drawing.frames = tuple(frames)
    return drawing


def _tracks(segments: list[tuple[Slot, Slot]], mid: Callable[[Slot], int]) -> dict[Slot, int]:
    """A track per tail slot in a gutter; tails whose rows overlap get different ones."""
    spans: dict[tuple[int, int], list[int]] = {}
    for a, b in segments:
        rows = spans.setdefault(a, [])
        rows += [mid(a), mid(b)]
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
    span: Callable[[Slot], tuple[int, int]],
    mid: Callable[[Slot], int],
) -> list[Stretch]:
    """Draw one edge; returns the stretches it runs along."""
    stretches: list[Stretch] = []
    for a, b in zip(route.slots, route.slots[1:], strict=False):
        gutter = a[0]
        ya, yb = mid(a), mid(b)
        start = span(a)[1] + 1
        end = span(b)[0] - 1
        x = lefts[gutter] + widths[gutter] + GUTTER_MARGIN + 2 * tracks[gutter][a]
        canvas.hline(ya, start, x)
        canvas.vline(x, ya, yb)
        canvas.hline(yb, x, end)
        stretches += [(ya, ya, start, x), (yb, yb, x, end)]
        if ya != yb:
            stretches.append((min(ya, yb), max(ya, yb), x, x))
    for slot in route.slots[1:-1]:  # dummies: the edge crosses their column
        c = slot[0]
        y = mid(slot)
        stretches.append((y, y, lefts[c], lefts[c] + widths[c] - 1))
    head_slot = route.slots[0] if route.reversed else route.slots[-1]
    target = route.edge.target
    if target.startswith(_LABEL):
        return stretches
    y = mid(head_slot)
    if route.reversed:
        x = span(head_slot)[1] + 1
        canvas.write(x, y, "◀")
    else:
        x = span(head_slot)[0] - 1
        canvas.write(x, y, "▶")
    stretches.append((y, y, x, x))
    return stretches


def _frame(canvas: Canvas, namespace: str, box: Box) -> None:
    """A namespace's dotted frame, its name on the top border."""
    inner = box.width - 2
    title = f"╌ {namespace} "
    canvas.write(box.x, box.y, "┌" + title + "╌" * (inner - len(title)) + "┐")
    for y in range(box.y + 1, box.y + box.height - 1):
        canvas.write(box.x, y, "╎")
        canvas.write(box.x + box.width - 1, y, "╎")
    canvas.write(box.x, box.y + box.height - 1, "└" + "╌" * inner + "┘")


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
