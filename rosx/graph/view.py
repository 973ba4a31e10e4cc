"""`ViewGraph`: the graph as drawn, with vertices (nodes, topics, topic groups) and edges.

Vertex ids keep nodes and topics apart when they share a name: ``n:/name`` for a node,
``t:/name`` for a topic or a topic group (rqt_graph's ``n_``/``t_`` prefixes in DOT).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from enum import Enum


class Kind(str, Enum):
    """What a vertex is: a node, a topic, or a group of topics drawn as one."""

    NODE = "node"  # an ellipse in rqt_graph
    TOPIC = "topic"  # a box
    GROUP = "group"  # a 3-D box: grouped action, image or tf topics


@dataclass(frozen=True)
class Vertex:
    """One vertex of the drawn graph: its id, label, kind and namespace clusters."""

    id: str
    label: str
    kind: Kind
    unreachable: bool = False
    #: Enclosing namespaces, outermost first (rqt_graph's namespace clusters).
    clusters: tuple[str, ...] = ()


@dataclass(frozen=True)
class Edge:
    """One edge of the drawn graph, between two vertex ids."""

    source: str
    target: str
    #: The topic, on node → node edges (Nodes only); empty otherwise.
    label: str = ""


@dataclass(frozen=True)
class ViewGraph:
    """The graph rqt_graph draws: vertices and edges after its modes and filters."""

    vertices: tuple[Vertex, ...] = ()
    edges: tuple[Edge, ...] = ()

    def vertex(self, vertex_id: str) -> Vertex | None:
        """The vertex with id ``vertex_id``, or None if the view does not hold it."""
        return next((v for v in self.vertices if v.id == vertex_id), None)


#: What a vanished vertex's label says in the drawing.
GONE = "(gone)"


def node_id(name: str) -> str:
    """The vertex id of node ``name``."""
    return "n:" + name


def topic_id(name: str) -> str:
    """The vertex id of topic ``name``."""
    return "t:" + name


@dataclass(frozen=True)
class Changes:
    """What appeared and what vanished between two views (vertex ids, and edges)."""

    appeared: frozenset[str] = frozenset()
    vanished: frozenset[str] = frozenset()
    appeared_edges: frozenset[Edge] = frozenset()
    vanished_edges: frozenset[Edge] = frozenset()

    def __bool__(self) -> bool:
        return bool(self.appeared or self.vanished or self.appeared_edges or self.vanished_edges)

    def summary(self) -> str:
        """``+ /a  - /b`` style, vertices sorted; empty when nothing changed."""
        parts = [f"+ {vertex_id[2:]}" for vertex_id in sorted(self.appeared)]
        parts += [f"- {vertex_id[2:]}" for vertex_id in sorted(self.vanished)]
        return "  ".join(parts)


def changes(before: ViewGraph | None, after: ViewGraph) -> Changes:
    """The difference from ``before`` to ``after`` (nothing when there was no before)."""
    if before is None:
        return Changes()
    old = {v.id for v in before.vertices}
    new = {v.id for v in after.vertices}
    return Changes(
        frozenset(new - old),
        frozenset(old - new),
        frozenset(set(after.edges) - set(before.edges)),
        frozenset(set(before.edges) - set(after.edges)),
    )


def vanished(before: ViewGraph, after: ViewGraph) -> ViewGraph:
    """What ``before`` holds and ``after`` does not: its vertices, and its edges."""
    ids = {v.id for v in after.vertices}
    edges = set(after.edges)
    return ViewGraph(
        tuple(v for v in before.vertices if v.id not in ids),
        tuple(e for e in before.edges if e not in edges),
    )


def with_ghosts(graph: ViewGraph, ghosts: ViewGraph) -> ViewGraph:
    """``graph`` with what vanished from it (``ghosts``) drawn in again, so a view can show it
    faded: the ghost vertices, labelled ``(gone)`` (a faded colour alone is easily missed), and
    the ghost edges whose ends are still drawn."""
    ids = {v.id for v in graph.vertices}
    gone = tuple(
        dataclasses.replace(v, label=f"{v.label} {GONE}")
        for v in ghosts.vertices
        if v.id not in ids
    )
    vertices = graph.vertices + gone
    present = {v.id for v in vertices}
    edges = set(graph.edges)
    extra = tuple(
        e for e in ghosts.edges if e not in edges and e.source in present and e.target in present
    )
    return ViewGraph(vertices, graph.edges + extra) if ghosts.vertices or extra else graph
