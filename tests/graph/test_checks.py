"""roswtf's graph analysis on synthetic states: expected and actual connections, isolated and
silent nodes."""

from __future__ import annotations

from rosx.graph.checks import actual_edges, expected_edges, isolated_nodes, silent_nodes
from rosx.graph.state import BusLink, GraphState
from tests.support.graph_states import PUBS, SUBS, URIS, lab1


def test_a_live_teleop_makes_the_edge_the_registrations_call_for() -> None:
    expected, unconnected = expected_edges(lab1())
    assert ("/turtle1/cmd_vel", "/teleop_turtle", "/turtlesim") in expected
    assert unconnected == {}
    actual = actual_edges(lab1())
    assert ("/turtle1/cmd_vel", "/teleop_turtle", "/turtlesim") in actual
    # /rosout reports its publisher by URI: h:1 is the teleop.
    assert ("/rosout", "/teleop_turtle", "/rosout") in actual


def test_a_missing_connection_is_expected_but_not_actual() -> None:
    state = lab1(teleop_connected=False)
    expected, _ = expected_edges(state)
    missing = expected - actual_edges(state)
    assert ("/turtle1/cmd_vel", "/teleop_turtle", "/turtlesim") in missing


def test_subscriptions_nobody_publishes_are_listed_per_subscriber() -> None:
    state = GraphState({}, {"/a": ("/n",), "/b": ("/n", "/m")})
    _, unconnected = expected_edges(state)
    assert unconnected == {"/n": ["/a", "/b"], "/m": ["/b"]}


def test_a_peer_uri_of_no_known_node_is_named_as_unknown() -> None:
    state = GraphState(
        {"/t": ("/p",)},
        {},
        {},
        {},
        {"/p": "http://p:1/"},
        {"/p": (BusLink("/t", "http://x:9/", "o"),)},
    )
    assert actual_edges(state) == {("/t", "/p", "unknown (http://x:9/)")}


def test_isolated_and_silent_nodes() -> None:
    bus = {"/quiet": (), "/server": (), "/gone": None}
    state = GraphState(
        PUBS, SUBS, {"/srv": ("/server",)}, {}, {**URIS, "/quiet": "http://q:1/"}, bus
    )
    state = GraphState(
        {**state.publishers, "/x": ("/quiet", "/server", "/gone", "/nowhere")},
        state.subscribers,
        state.services,
        state.topic_types,
        {**state.node_uris, "/server": "http://s:1/", "/gone": "http://g:1/"},
        {**bus, "/turtlesim": (), "/teleop_turtle": (), "/rosout": ()},
    )
    assert isolated_nodes(state) == ["/quiet", "/rosout", "/teleop_turtle", "/turtlesim"]
    assert silent_nodes(state) == ["/gone", "/nowhere"]
