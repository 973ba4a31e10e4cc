"""The Master and Parameter API methods without sockets: rosmaster's argument checks, reply
codes and texts, name resolution against the caller, the notifications owed, the reply cache."""

from __future__ import annotations

from typing import Any

import pytest

from rosx.master.actions import Action, ParamUpdate, PublisherUpdate, ShutdownNode
from rosx.master.api import MasterApi
from rosx.master.validation import resolve_for_caller
from rosx.transport.server import EncodedResponse
from rosx.wire.xmlrpc import MethodResponse, decode_response

A = "http://a:1/"
B = "http://b:2/"


class Harness:
    def __init__(self) -> None:
        self.actions: list[Action] = []
        self.shutdowns: list[tuple[str, str]] = []
        self.api = MasterApi(
            "http://localhost:11311/",
            4242,
            notify=self.actions.extend,
            on_shutdown=lambda caller, msg: self.shutdowns.append((caller, msg)),
        )

    def __call__(self, method: str, *params: Any) -> Any:
        reply = self.api.call(method, *params)
        if isinstance(reply, EncodedResponse):
            decoded = decode_response(reply.body)
            assert isinstance(decoded, MethodResponse)
            assert decoded.value == reply.value
            return decoded.value
        return reply


@pytest.fixture
def m() -> Harness:
    return Harness()


@pytest.mark.parametrize(
    ("name", "caller", "resolved"),
    [
        ("x", "/a/node", "/a/x"),
        ("/x", "/a/node", "/x"),
        ("~x", "/a/node", "/a/node/x"),
        ("", "/a/node", "/a/"),
        ("x//y/", "/node", "/x/y"),
        ("x", "", "/x"),
        ("~x", "bare", "bare/x"),  # rosgraph does not make it global either
    ],
)
def test_resolution_against_the_caller(name: str, caller: str, resolved: str) -> None:
    assert resolve_for_caller(name, caller) == resolved


def test_call_shape_errors(m: Harness) -> None:
    assert m("getPid") == [-1, "missing required caller_id parameter", -1]
    assert m("getPid", "/a", "x") == [-1, "Error: bad call arity", -1]
    assert m("getPid", 3) == [-1, "caller_id must be a string", -1]
    assert m("getPid", "/a") == [1, "", 4242]
    assert m("getUri", "/a") == [1, "", "http://localhost:11311/"]
    assert m("getSystemState") == [-1, "missing required caller_id parameter", [[], [], []]]
    assert m("shutdown", "/a") == [-1, "Error: bad call arity", 0]  # msg is required


@pytest.mark.parametrize(
    ("params", "reply"),
    [
        (("/n", "", 1), [-1, "ERROR: parameter [key] must be specified and non-empty", 0]),
        (("/n", 5, 1), [-1, "ERROR: parameter [key] must be a string", 0]),
        (
            ("/n", "/", 1),
            [
                -1,
                "Error: invalid arguments: cannot set root of parameter tree to non-dictionary",
                0,
            ],
        ),
        (("/n", "k", None), [-1, "ERROR: parameter [value] must be specified", 0]),
        (("/n", "~p", {"x": 1}), [1, "parameter /n/p set", 0]),
    ],
)
def test_set_param_checks(m: Harness, params: tuple[Any, ...], reply: list[Any]) -> None:
    assert m("setParam", *params) == reply


def test_param_round_trip(m: Harness) -> None:
    assert m("setParam", "/a/n", "x", {"y": [1, 2]}) == [1, "parameter /a/x set", 0]
    assert m("getParam", "/a/n", "x/y") == [1, "Parameter [/a/x/y]", [1, 2]]
    assert m("getParam", "/a/n", "/") == [1, "Parameter [/]", {"a": {"x": {"y": [1, 2]}}}]
    assert m("getParam", "/a/n", "nope") == [-1, "Parameter [/a/nope] is not set", 0]
    assert m("hasParam", "/a/n", "x") == [1, "/a/x", True]
    assert m("hasParam", "/a/n", "nope") == [1, "/a/nope", False]
    assert m("getParamNames", "/") == [1, "Parameter names", ["/a/x/y"]]
    assert m("deleteParam", "/a/n", "x") == [1, "parameter /a/x deleted", 0]
    assert m("deleteParam", "/a/n", "x") == [-1, "parameter [/a/x] is not set", 0]
    assert m("deleteParam", "/a/n", "/") == [-1, "parameter [/] is not set", 0]


def test_search_param(m: Harness) -> None:
    m("setParam", "/", "/a", 1)
    assert m("searchParam", "/a/b", "a") == [1, "Found [/a]", "/a"]
    assert m("searchParam", "/a/b", "q") == [
        -1,
        "Cannot find parameter [q] in an upwards search",
        "",
    ]
    assert m("searchParam", "/a", "~p") == [0, "Internal failure: invalid key", 0]
    assert m("searchParam", "", "p") == [0, "Internal failure: namespace must be global", 0]


def test_param_subscriptions(m: Harness) -> None:
    assert m("subscribeParam", "/n", A, "foo") == [1, "Subscribed to parameter [/foo]", {}]
    assert m("lookupNode", "/x", "/n") == [1, "node api", A]
    m("setParam", "/other", "foo", 3)
    assert m.actions == [ParamUpdate(A, "/n", "/foo/", 3)]
    m.actions.clear()
    m("setParam", "/n", "foo", 4)  # the subscriber's own change is not echoed back
    assert m.actions == []
    m("deleteParam", "/n", "foo")
    assert m.actions == [ParamUpdate(A, "/n", "/foo/", {})]
    assert m("subscribeParam", "/n", A, "/") == [1, "Subscribed to parameter [/]", {}]
    assert m("unsubscribeParam", "/n", A, "foo") == [1, "Unsubscribe to parameter [/foo]", 1]
    assert m("unsubscribeParam", "/n", A, "/") == [1, "Unsubscribe to parameter [/]", 1]
    assert m("lookupNode", "/x", "/n") == [-1, "unknown node [/n]", ""]
    assert m("unsubscribeParam", "/n", A, "foo") == [1, "Unsubscribe to parameter [/foo]", 1]
    assert m("subscribeParam", "/n", "ftp://x", "foo")[:2] == [
        -1,
        "ERROR: parameter [caller_api] is not an RPC URI",
    ]


@pytest.mark.parametrize(
    ("params", "status"),
    [
        (("t:x", "std_msgs/String", A), "ERROR: parameter [topic] contains illegal chars"),
        (("a b", "std_msgs/String", A), "ERROR: parameter [topic] contains illegal chars"),
        (("/", "std_msgs/String", A), "ERROR: parameter [topic] cannot be the global namespace"),
        (("", "std_msgs/String", A), "ERROR: parameter [topic] must be a non-empty string"),
        ((3, "std_msgs/String", A), "ERROR: parameter [topic] must be a non-empty string"),
        (("t", "String", A), "ERROR: parameter [topic_type] is not a valid package resource name"),
        (("t", "", A), "ERROR: parameter [topic_type] must be a non-empty string"),
        (("t", "a/b", "ftp://h:1/"), "ERROR: parameter [caller_api] is not an RPC URI"),
        (("t", "a/b", ""), "ERROR: parameter [caller_api] is not an XMLRPC URI"),
    ],
)
def test_register_publisher_checks(m: Harness, params: tuple[Any, ...], status: str) -> None:
    assert m("registerPublisher", "/n", *params) == [-1, status, []]
    assert m("registerSubscriber", "/n", *params) == [-1, status, []]


def test_topics_flow(m: Harness) -> None:
    assert m("registerSubscriber", "/ns/listener", "chatter", "std_msgs/String", B) == [
        1,
        "Subscribed to [/ns/chatter]",
        [],
    ]
    assert m("registerPublisher", "/ns/talker", "chatter", "std_msgs/String", A) == [
        1,
        "Registered [/ns/talker] as publisher of [/ns/chatter]",
        [B],
    ]
    assert m.actions == [PublisherUpdate(B, "/ns/chatter", [A])]
    state = [[["/ns/chatter", ["/ns/talker"]]], [["/ns/chatter", ["/ns/listener"]]], []]
    assert m("getSystemState", "/") == [1, "current system state", state]
    assert m("getTopicTypes", "/") == [
        1,
        "current system state",
        [["/ns/chatter", "std_msgs/String"]],
    ]
    assert m("getPublishedTopics", "/", "") == [
        1,
        "current topics",
        [["/ns/chatter", "std_msgs/String"]],
    ]
    assert m("getPublishedTopics", "/other/x", "ns") == [1, "current topics", []]
    assert m("getPublishedTopics", "/ns/x", "") == m("getPublishedTopics", "/", "/ns")
    assert m("getPublishedTopics", "/", 5) == [
        -1,
        "ERROR: parameter [subgraph] must be a string",
        0,
    ]
    m.actions.clear()
    assert m("unregisterPublisher", "/ns/talker", "chatter", A) == [
        1,
        "Unregistered [/ns/talker] as provider of [/ns/chatter]",
        1,
    ]
    assert m.actions == [PublisherUpdate(B, "/ns/chatter", [])]
    assert m("unregisterSubscriber", "/ns/listener", "/ns/chatter", A) == [
        1,
        "[/ns/listener] is not a known provider of [/ns/chatter]",
        0,
    ]
    assert m("getSystemState", "/") == [1, "current system state", [[], state[1], []]]


def test_system_state_is_encoded_once_per_change(m: Harness) -> None:
    m("registerPublisher", "/p", "/t", "std_msgs/String", A)
    first = m.api.call("getSystemState", "/a")
    assert m.api.call("getSystemState", "/b") is first
    m("registerPublisher", "/p", "/u", "std_msgs/String", A)
    assert m.api.call("getSystemState", "/a") is not first


def test_services(m: Harness) -> None:
    assert m("lookupService", "/c", "add") == [-1, "no provider", ""]
    assert m("registerService", "/ns/srv", "add", "rosrpc://h:5", A) == [
        1,
        "Registered [/ns/srv] as provider of [/ns/add]",
        1,
    ]
    assert m("lookupService", "/ns/c", "add") == [1, "rosrpc URI: [rosrpc://h:5]", "rosrpc://h:5"]
    assert m("getSystemState", "/")[2][2] == [["/ns/add", ["/ns/srv"]]]
    assert m("registerService", "/n", "s", "nope", A)[:2] == [
        -1,
        "ERROR: parameter [service_api] is not an RPC URI",
    ]
    assert m("unregisterService", "/ns/srv", "/ns/add", "rosrpc://h:5") == [
        1,
        "Unregistered [/ns/srv] as provider of [/ns/add]",
        1,
    ]


def test_lookup_node(m: Harness) -> None:
    m("registerPublisher", "/a/talker", "t", "std_msgs/String", A)
    assert m("lookupNode", "/a/x", "talker") == [1, "node api", A]
    assert m("lookupNode", "/x", "talker") == [-1, "unknown node [/talker]", ""]
    assert m("lookupNode", "/x", "a:b") == [
        -1,
        "ERROR: parameter [node] contains illegal chars",
        "",
    ]


def test_duplicate_name_shuts_the_old_node_down(m: Harness) -> None:
    m("registerPublisher", "/talker", "t", "std_msgs/String", A)
    m("registerPublisher", "/talker", "t", "std_msgs/String", B)
    assert m.actions == [ShutdownNode(A, "/talker", "new node registered with same name")]
    assert m("lookupNode", "/x", "/talker") == [1, "node api", B]


def test_shutdown(m: Harness) -> None:
    assert m("shutdown", "/x", "bye") == [1, "shutdown", 0]
    assert m.shutdowns == [("/x", "bye")]
