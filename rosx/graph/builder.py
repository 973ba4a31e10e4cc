"""`build`: rqt_graph's view of a `GraphState` under `GraphOptions`.

The steps and their order are rqt_graph's (``dotcode.py`` ``generate_dotgraph``):

1. nodes pass the namespace filter, topics the topic filter;
2. node/topic edges come from the nodes' bus info (*active*) or the master (*all*, and *Nodes
   only*, whose topics are chosen on these edges);
3. dead sinks (a topic nobody receives from) and leaf topics (one edge) go, then tf and
   dynamic_reconfigure topics when hidden;
4. with topics drawn, action topics (all five of ``goal``, ``cancel``, ``status``, ``result``,
   ``feedback``), image_transport variants (three or more of a ``…/compressed`` family) and
   ``/tf`` + ``/tf_static`` collapse into one group box each;
5. edges to vanished vertices go, then topics left without edges;
6. *Nodes only* keeps node → node edges (from bus info) on the topics still standing;
7. "Hide: Debug" removes debug nodes and topics (and node → node edges on ``/rosout`` & co.);
8. unreachable nodes go when hidden.
"""

from __future__ import annotations

from collections import defaultdict

from rosx.graph.options import QUIET_EDGE_TOPICS, GraphOptions, Mode, NameFilter, is_quiet
from rosx.graph.state import GraphState
from rosx.graph.view import Edge, Kind, Vertex, ViewGraph, node_id, topic_id

ACTION_SUFFIXES = ("/goal", "/cancel", "/status", "/result", "/feedback")
IMAGE_SUFFIXES = ("/compressed", "/compressedDepth", "/theora", "")
TF_TOPICS = ("/tf", "/tf_static")
PARAM_SUFFIXES = ("/parameter_updates", "/parameter_descriptions")


def build(state: GraphState, options: GraphOptions | None = None) -> ViewGraph:
    """The graph rqt_graph would draw; raises `ValueError` for a bad filter."""
    options = options or GraphOptions()
    node_filter = NameFilter.parse(options.namespace_filter)
    topic_filter = NameFilter.parse(options.topic_filter)
    nodes = [n for n in state.nodes if node_filter.accepts(n)]
    topics = {t for t in state.topics if topic_filter.accepts(t)}

    edges = _active_edges(state) if options.mode is Mode.ACTIVE else _master_edges(state)
    topics, edges = _hide_leaves(topics, edges, options)
    topics, edges = _hide_topics(topics, edges, options)
    groups: dict[str, str] = {}  # topic → its group box's name
    if options.mode is not Mode.NODES:
        if options.group_actions:
            groups.update(_families(topics, "/feedback", ACTION_SUFFIXES, 5, "/action_topics"))
        if options.group_images:
            groups.update(_families(topics, "/compressed", IMAGE_SUFFIXES, 3, "/image_topics"))
        if options.group_tf and not options.hide_tf:
            groups.update({t: "/tf" for t in TF_TOPICS if t in topics})
    ids = {node_id(n) for n in nodes} | {topic_id(t) for t in topics}
    edges = {e for e in edges if e.source in ids and e.target in ids}
    edges = {Edge(_regroup(e.source, groups), _regroup(e.target, groups)) for e in edges}
    linked = {i for e in edges for i in (e.source, e.target)}
    group_names = {g for g in groups.values() if topic_id(g) in linked}
    topics = {t for t in topics - groups.keys() if topic_id(t) in linked}

    if options.mode is Mode.NODES:
        edges = {e for e in _node_edges(state) if e.label in topics}
        topics, group_names = set(), set()
    if options.hide_debug:
        nodes = [n for n in nodes if not is_quiet(n)]
        topics = {t for t in topics if not is_quiet(t)}
        if options.mode is Mode.NODES:
            edges = {e for e in edges if e.label not in QUIET_EDGE_TOPICS}
    if options.hide_unreachable:
        nodes = [n for n in nodes if not state.unreachable(n)]

    vertices = [
        Vertex(node_id(n), n, Kind.NODE, state.unreachable(n), _clusters(n, options.group_depth))
        for n in nodes
    ]
    vertices += [
        Vertex(topic_id(t), t, Kind.TOPIC, clusters=_clusters(t, options.group_depth))
        for t in sorted(topics)
    ]
    vertices += [
        Vertex(topic_id(g), g, Kind.GROUP, clusters=_clusters(g, options.group_depth))
        for g in sorted(group_names)
    ]
    present = {v.id for v in vertices}
    kept = sorted(
        (e for e in edges if e.source in present and e.target in present),
        key=lambda e: (e.source, e.target, e.label),
    )
    return ViewGraph(tuple(vertices), tuple(kept))


def _master_edges(state: GraphState) -> set[Edge]:
    edges = {Edge(node_id(n), topic_id(t)) for t, ns in state.publishers.items() for n in ns}
    edges |= {Edge(topic_id(t), node_id(n)) for t, ns in state.subscribers.items() for n in ns}
    return edges


def _active_edges(state: GraphState) -> set[Edge]:
    if state.bus_info is None:
        return _master_edges(state)
    edges: set[Edge] = set()
    for node, links in state.bus_info.items():
        for link in links or ():
            if link.direction == "o":
                edges.add(Edge(node_id(node), topic_id(link.topic)))
            elif link.direction == "i":
                edges.add(Edge(topic_id(link.topic), node_id(node)))
    return edges


def _node_edges(state: GraphState) -> set[Edge]:
    """Node → node edges labelled by topic: live connections, or registrations unasked."""
    if state.bus_info is None:
        return {
            Edge(node_id(p), node_id(s), topic)
            for topic, pubs in state.publishers.items()
            for p in pubs
            for s in state.subscribers.get(topic, ())
        }
    by_uri = {uri.rstrip("/"): name for name, uri in state.node_uris.items()}
    edges: set[Edge] = set()
    for node, links in state.bus_info.items():
        for link in links or ():
            peer = link.peer if link.peer.startswith("/") else by_uri.get(link.peer.rstrip("/"))
            if peer is None:
                continue
            if link.direction == "o":
                edges.add(Edge(node_id(node), node_id(peer), link.topic))
            elif link.direction == "i":
                edges.add(Edge(node_id(peer), node_id(node), link.topic))
    return edges


def _hide_leaves(
    topics: set[str], edges: set[Edge], options: GraphOptions
) -> tuple[set[str], set[Edge]]:
    if not (options.hide_dead_sinks or options.hide_leaf_topics):
        return topics, edges
    outgoing: dict[str, int] = defaultdict(int)
    incoming: dict[str, int] = defaultdict(int)
    for edge in edges:
        outgoing[edge.source] += 1
        incoming[edge.target] += 1
    removed = {
        t
        for t in topics
        if (tid := topic_id(t)) in outgoing or tid in incoming
        if (options.hide_leaf_topics and outgoing[tid] + incoming[tid] < 2)
        or (options.hide_dead_sinks and not outgoing[tid])
    }
    return topics - removed, _without(edges, removed)


def _hide_topics(
    topics: set[str], edges: set[Edge], options: GraphOptions
) -> tuple[set[str], set[Edge]]:
    removed: set[str] = set()
    if options.hide_params:
        for topic in topics:
            if topic.endswith(PARAM_SUFFIXES[0]):
                prefix = topic[: -len(PARAM_SUFFIXES[0])]
                family = {prefix + s for s in PARAM_SUFFIXES}
                if family <= topics:
                    removed |= family
    if options.hide_tf:
        removed |= {t for t in TF_TOPICS if t in topics}
    return topics - removed, _without(edges, removed)


def _without(edges: set[Edge], topics: set[str]) -> set[Edge]:
    ids = {topic_id(t) for t in topics}
    return {e for e in edges if e.source not in ids and e.target not in ids}


def _families(
    topics: set[str], trigger: str, suffixes: tuple[str, ...], needed: int, name: str
) -> dict[str, str]:
    grouped: dict[str, str] = {}
    for topic in sorted(topics):
        if topic.endswith(trigger):
            prefix = topic[: -len(trigger)]
            members = [prefix + s for s in suffixes if prefix + s in topics]
            if len(members) >= needed:
                grouped.update(dict.fromkeys(members, prefix + name))
    return grouped


def _regroup(vertex_id: str, groups: dict[str, str]) -> str:
    if vertex_id.startswith("t:") and vertex_id[2:] in groups:
        return topic_id(groups[vertex_id[2:]])
    return vertex_id


def _clusters(name: str, depth: int) -> tuple[str, ...]:
    """rqt_graph's nested namespace boxes around ``name``, ``depth`` levels at most."""
    parts = name.split("/")
    if depth <= 0 or len(parts) < 3:
        return ()
    return tuple("/".join(parts[:i]) for i in range(2, min(2 + depth, len(parts))))
