"""`dot`: a `ViewGraph` as Graphviz DOT, in rqt_graph's shape.

As rqt_graph's ``dotcode.py`` writes it: ``rankdir=LR``; nodes are ellipses named ``n_/name``
(red when unreachable), topics boxes named ``t_/name``, grouped topics ``box3d``; node → node
edges carry their topic as label; namespaces become nested ``cluster_`` subgraphs.
"""

from __future__ import annotations

from rosx.graph.view import Kind, Vertex, ViewGraph

_SHAPES = {Kind.NODE: "ellipse", Kind.TOPIC: "box", Kind.GROUP: "box3d"}


def _quote(text: str) -> str:
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def _dot_name(vertex_id: str) -> str:
    kind, _, name = vertex_id.partition(":")
    return _quote(f"{kind}_{name}")


def _vertex_line(vertex: Vertex) -> str:
    attrs = [f"label={_quote(vertex.label)}", f"shape={_SHAPES[vertex.kind]}"]
    url = vertex.label if vertex.kind is Kind.NODE else f"topic:{vertex.label}"
    if vertex.unreachable:
        attrs.append("color=red")
        url += " (DEAD)"
    attrs.append(f"URL={_quote(url)}")
    return f"{_dot_name(vertex.id)} [{', '.join(attrs)}];"


def dot(graph: ViewGraph, *, grouped: bool = True) -> str:
    """The DOT text; ``grouped`` draws namespace clusters."""
    lines = ["digraph graphname {", "  graph [rankdir=LR, rank=same, ranksep=0.2];"]
    tree: dict[tuple[str, ...], list[Vertex]] = {}
    for vertex in graph.vertices:
        tree.setdefault(vertex.clusters if grouped else (), []).append(vertex)
    _cluster(lines, tree, (), 1)
    for edge in graph.edges:
        attrs = f" [label={_quote(edge.label)}]" if edge.label else ""
        lines.append(f"  {_dot_name(edge.source)} -> {_dot_name(edge.target)}{attrs};")
    lines.append("}")
    return "\n".join(lines) + "\n"


def _cluster(
    lines: list[str], tree: dict[tuple[str, ...], list[Vertex]], path: tuple[str, ...], depth: int
) -> None:
    indent = "  " * depth
    lines += [indent + _vertex_line(v) for v in tree.get(path, [])]
    children = sorted(
        {key[len(path)] for key in tree if len(key) > len(path) and key[: len(path)] == path}
    )
    for child in children:
        lines.append(f"{indent}subgraph {_quote('cluster_' + child)} {{")
        lines.append(f"{indent}  label={_quote(child)};")
        _cluster(lines, tree, (*path, child), depth + 1)
        lines.append(indent + "}")
