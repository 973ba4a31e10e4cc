"""The builder under rqt_graph's modes, filters and hide rules, on synthetic states."""

from __future__ import annotations

import pytest

from rosx.graph.builder import build
from rosx.graph.dot import dot
from rosx.graph.options import GraphOptions, Mode, NameFilter
from rosx.graph.state import BusLink, GraphState
from rosx.graph.text import draw
from rosx.graph.view import Edge, Kind, changes
from tests.support.graph_states import PUBS, SUBS, lab1

SHOW_ALL = GraphOptions(
    mode=Mode.ALL, hide_debug=False, hide_dead_sinks=False, hide_leaf_topics=False
)


def labels(options: GraphOptions, state: GraphState | None = None) -> set[str]:
    return {v.id for v in build(state or lab1(), options).vertices}


def test_defaults_are_rqt_graphs() -> None:
    options = GraphOptions()
    assert options.mode is Mode.NODES
    assert (options.namespace_filter, options.topic_filter, options.group_depth) == ("/", "/", 2)
    assert options.hide_debug and options.hide_dead_sinks and options.hide_leaf_topics
    assert options.hide_unreachable and options.hide_params and not options.hide_tf


def test_nodes_only_labels_the_edge_with_its_topic() -> None:
    graph = build(lab1())
    assert {v.id for v in graph.vertices} == {"n:/teleop_turtle", "n:/turtlesim"}
    assert graph.edges == (Edge("n:/teleop_turtle", "n:/turtlesim", "/turtle1/cmd_vel"),)


def test_active_mode_follows_bus_info() -> None:
    assert labels(GraphOptions(mode=Mode.ACTIVE)) == {
        "n:/teleop_turtle",
        "n:/turtlesim",
        "t:/turtle1/cmd_vel",
    }
    gone = labels(GraphOptions(mode=Mode.ACTIVE), lab1(teleop_connected=False))
    assert "t:/turtle1/cmd_vel" not in gone


def test_all_mode_shows_registrations_without_connections() -> None:
    state = lab1(teleop_connected=False)
    assert "t:/turtle1/cmd_vel" in labels(GraphOptions(mode=Mode.ALL), state)


def test_show_everything() -> None:
    found = labels(SHOW_ALL)
    assert {"n:/rosout", "t:/rosout", "t:/rosout_agg", "t:/turtle1/pose"} <= found


def test_dead_sinks_and_leaf_topics() -> None:
    dead_shown = GraphOptions(mode=Mode.ALL, hide_leaf_topics=False, hide_dead_sinks=False)
    assert "t:/turtle1/pose" in labels(dead_shown)
    assert "t:/turtle1/pose" not in labels(GraphOptions(mode=Mode.ALL, hide_leaf_topics=False))


@pytest.mark.parametrize(
    ("text", "accepted", "refused"),
    [
        ("/", ["/a", "/b/c"], []),
        ("/turtlesim", ["/turtlesim"], ["/turtlesim2", "/teleop_turtle"]),
        ("/turtle.*", ["/turtlesim", "/turtle1/pose"], ["/teleop_turtle"]),
        ("-/rosout.*", ["/turtlesim"], ["/rosout", "/rosout_agg"]),
        ("/t.*,-/turtlesim", ["/teleop_turtle"], ["/turtlesim", "/x"]),
    ],
)
def test_filters(text: str, accepted: list[str], refused: list[str]) -> None:
    name_filter = NameFilter.parse(text)
    assert all(name_filter.accepts(n) for n in accepted)
    assert not any(name_filter.accepts(n) for n in refused)


def test_a_bad_regex_is_refused() -> None:
    with pytest.raises(ValueError, match="bad filter"):
        NameFilter.parse("/a[")


def test_namespace_filter_removes_nodes_and_their_edges() -> None:
    graph = build(lab1(), GraphOptions(mode=Mode.ACTIVE, namespace_filter="-/teleop_turtle"))
    assert "n:/teleop_turtle" not in {v.id for v in graph.vertices}
    assert all("teleop" not in e.source for e in graph.edges)


def test_unreachable_nodes_hidden_or_marked() -> None:
    state = GraphState(PUBS, SUBS, bus_info={"/turtlesim": None, "/teleop_turtle": ()})
    assert "n:/turtlesim" not in labels(GraphOptions(), state)
    shown = build(state, GraphOptions(hide_unreachable=False, mode=Mode.ALL))
    vertex = shown.vertex("n:/turtlesim")
    assert vertex is not None and vertex.unreachable


def test_actions_tf_and_params_grouping() -> None:
    pubs = {f"/move{s}": ("/server",) for s in ("/status", "/result", "/feedback")}
    pubs |= {"/tf": ("/server",), "/tf_static": ("/server",)}
    pubs |= {"/s/parameter_updates": ("/server",), "/s/parameter_descriptions": ("/server",)}
    subs = {f"/move{s}": ("/client",) for s in ("/status", "/result", "/feedback")}
    subs |= {"/move/goal": ("/server",), "/move/cancel": ("/server",)}
    pubs |= {"/move/goal": ("/client",), "/move/cancel": ("/client",)}
    subs |= dict.fromkeys(("/tf", "/tf_static", "/s/parameter_updates"), ("/client",))
    subs |= {"/s/parameter_descriptions": ("/client",)}
    graph = build(GraphState(pubs, subs), GraphOptions(mode=Mode.ALL))
    kinds = {v.label: v.kind for v in graph.vertices}
    assert kinds["/move/action_topics"] is Kind.GROUP
    assert kinds["/tf"] is Kind.GROUP
    assert "/move/goal" not in kinds and "/s/parameter_updates" not in kinds
    hidden = build(GraphState(pubs, subs), GraphOptions(mode=Mode.ALL, hide_tf=True))
    assert "/tf" not in {v.label for v in hidden.vertices}


def test_namespace_clusters() -> None:
    graph = build(lab1(), GraphOptions(mode=Mode.ACTIVE))
    vertex = graph.vertex("t:/turtle1/cmd_vel")
    assert vertex is not None and vertex.clusters == ("/turtle1",)
    flat = build(lab1(), GraphOptions(mode=Mode.ACTIVE, group_depth=0))
    assert all(not v.clusters for v in flat.vertices)


def test_changes_between_refreshes() -> None:
    before = build(lab1(), GraphOptions(mode=Mode.ACTIVE))
    after = build(lab1(teleop_connected=False), GraphOptions(mode=Mode.ACTIVE))
    diff = changes(before, after)
    assert diff.vanished == {"t:/turtle1/cmd_vel"}
    assert diff.summary() == "- /turtle1/cmd_vel"
    assert not changes(after, after)


def test_dot_has_rqt_graphs_shapes() -> None:
    text = dot(build(lab1()))
    assert "rankdir=LR" in text
    assert '"n_/teleop_turtle" [label="/teleop_turtle", shape=ellipse' in text
    assert '"n_/teleop_turtle" -> "n_/turtlesim" [label="/turtle1/cmd_vel"];' in text
    topics = dot(build(lab1(), GraphOptions(mode=Mode.ACTIVE)))
    assert 'subgraph "cluster_/turtle1"' in topics
    assert '"t_/turtle1/cmd_vel" [label="/turtle1/cmd_vel", shape=box' in topics


def test_text_drawing_of_lab1() -> None:
    assert str(draw(build(lab1(), GraphOptions(mode=Mode.ACTIVE, group_depth=0)))) == (
        "╭────────────────╮      ┌──────────────────┐      ╭────────────╮\n"
        "│ /teleop_turtle │─────▶│ /turtle1/cmd_vel │─────▶│ /turtlesim │\n"
        "╰────────────────╯      └──────────────────┘      ╰────────────╯"
    )


def test_text_drawing_frames_namespaces_as_rqt_graph_groups_them() -> None:
    assert str(draw(build(lab1(), GraphOptions(mode=Mode.ACTIVE)))) == (
        "                        ┌╌ /turtle1 ╌╌╌╌╌╌╌╌╌╌╌┐\n"
        "╭────────────────╮      ╎ ┌──────────────────┐ ╎      ╭────────────╮\n"
        "│ /teleop_turtle │──────╎▶│ /turtle1/cmd_vel │─╎─────▶│ /turtlesim │\n"
        "╰────────────────╯      ╎ └──────────────────┘ ╎      ╰────────────╯\n"
        "                        └╌╌╌╌╌╌╌╌╌╌╌╌╌╌╌╌╌╌╌╌╌╌┘"
    )


def test_text_drawing_of_a_cycle_and_a_wide_graph() -> None:
    pubs = {"/a": ("/x",), "/b": ("/y",)}
    subs = {"/a": ("/y",), "/b": ("/x",)}
    text = str(draw(build(GraphState(pubs, subs), GraphOptions(mode=Mode.ALL))))
    assert "◀" in text and "▶" in text
    for name in ("/x", "/y", "/a", "/b"):
        assert f" {name} " in text


def test_node_edges_from_bus_info_resolve_uris() -> None:
    state = GraphState(
        {"/t": ("/p",)},
        {"/t": ("/s",)},
        node_uris={"/p": "http://h:9/", "/s": "http://h:8/"},
        bus_info={"/s": (BusLink("/t", "http://h:9", "i"),), "/p": ()},
    )
    assert build(state).edges == (Edge("n:/p", "n:/s", "/t"),)
