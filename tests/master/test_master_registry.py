"""The master's registry as a data structure: registrations, notifications owed, replacement of
nodes, unregistration texts (rosmaster's), system state. No sockets."""

from __future__ import annotations

from rosx.master.actions import PublisherUpdate, ShutdownNode
from rosx.master.registry import REPLACED, Registry

A = "http://a:1/"
B = "http://b:2/"
C = "http://c:3/"


def test_publisher_then_subscriber() -> None:
    reg = Registry()
    out = reg.register_publisher("/chatter", "std_msgs/String", "/talker", A)
    assert out.status == "Registered [/talker] as publisher of [/chatter]"
    assert out.value == []
    assert out.actions == []
    out = reg.register_subscriber("/chatter", "std_msgs/String", "/listener", B)
    assert out.status == "Subscribed to [/chatter]"
    assert out.value == [A]
    assert out.actions == []
    assert reg.node_api("/talker") == A
    assert reg.node_api("/listener") == B


def test_new_publisher_notifies_every_subscriber_with_all_publishers() -> None:
    reg = Registry()
    reg.register_subscriber("/t", "std_msgs/String", "/s1", A)
    reg.register_subscriber("/t", "std_msgs/String", "/s2", B)
    out = reg.register_publisher("/t", "std_msgs/String", "/p1", C)
    assert out.value == [A, B]
    assert out.actions == [PublisherUpdate(A, "/t", [C]), PublisherUpdate(B, "/t", [C])]
    out = reg.register_publisher("/t", "std_msgs/String", "/p2", "http://d:4/")
    assert out.actions == [
        PublisherUpdate(A, "/t", [C, "http://d:4/"]),
        PublisherUpdate(B, "/t", [C, "http://d:4/"]),
    ]


def test_registering_twice_is_one_registration() -> None:
    reg = Registry()
    reg.register_publisher("/t", "std_msgs/String", "/p", A)
    reg.register_publisher("/t", "std_msgs/String", "/p", A)
    assert reg.publisher_apis("/t") == [A]
    assert reg.system_state() == [[["/t", ["/p"]]], [], []]


def test_unregister_publisher_texts_and_notification() -> None:
    reg = Registry()
    reg.register_subscriber("/t", "std_msgs/String", "/s", B)
    reg.register_publisher("/t", "std_msgs/String", "/p", A)
    reg.register_publisher("/u", "std_msgs/String", "/p", A)
    wrong_api = reg.unregister_publisher("/t", "/p", C)
    assert (wrong_api.status, wrong_api.value, wrong_api.actions) == (
        "[/p] is not a known provider of [/t]",
        0,
        [],
    )
    out = reg.unregister_publisher("/t", "/p", A)
    assert (out.status, out.value) == ("Unregistered [/p] as provider of [/t]", 1)
    assert out.actions == [PublisherUpdate(B, "/t", [])]
    unknown = reg.unregister_publisher("/t", "/nobody", A)
    assert (unknown.status, unknown.value) == ("[/nobody] is not a registered node", 0)


def test_node_is_forgotten_with_its_last_registration() -> None:
    reg = Registry()
    reg.register_publisher("/t", "std_msgs/String", "/p", A)
    reg.register_subscriber("/u", "std_msgs/String", "/p", A)
    reg.unregister_publisher("/t", "/p", A)
    assert reg.node_api("/p") == A
    reg.unregister_subscriber("/u", "/p", A)
    assert reg.node_api("/p") is None
    assert reg.system_state() == [[], [], []]


def test_failed_unregister_of_an_empty_node_forgets_it() -> None:
    # rosmaster checks for emptiness after every unregister, successful or not.
    reg = Registry()
    reg.register_param_subscriber("/k/", "/n", A)
    reg.unregister_param_subscriber("/k/", "/n", A)
    assert reg.node_api("/n") is None


def test_same_name_new_uri_replaces_the_node_and_shuts_the_old_one_down() -> None:
    reg = Registry()
    reg.register_publisher("/t", "std_msgs/String", "/n", A)
    reg.register_subscriber("/u", "std_msgs/String", "/n", A)
    reg.register_service("/srv", "rosrpc://a:9", "/n", A)
    reg.register_param_subscriber("/p/", "/n", A)
    out = reg.register_publisher("/v", "std_msgs/String", "/n", B)
    assert out.actions == [ShutdownNode(A, "/n", REPLACED)]
    shutdown = out.actions[0]
    assert isinstance(shutdown, ShutdownNode)
    assert shutdown.message == "[/n] Reason: new node registered with same name"
    assert reg.node_api("/n") == B
    assert reg.system_state() == [[["/v", ["/n"]]], [], []]
    assert reg.service_api("/srv") is None
    assert reg.param_subscribers == {}


def test_topic_types() -> None:
    reg = Registry()
    reg.register_subscriber("/a", "*", "/s", A)
    assert reg.topic_type_list() == []
    reg.register_subscriber("/a", "std_msgs/Int32", "/s", A)
    reg.register_subscriber("/a", "std_msgs/String", "/s2", B)
    assert reg.topic_type_list() == [["/a", "std_msgs/Int32"]]
    reg.register_publisher("/a", "std_msgs/String", "/p", C)
    assert reg.topic_type_list() == [["/a", "std_msgs/String"]]
    reg.register_publisher("/a", "*", "/p2", C)
    assert reg.topic_type_list() == [["/a", "std_msgs/String"]]
    reg.register_publisher("/b", "*", "/p", C)
    assert reg.topic_type_list() == [["/a", "std_msgs/String"], ["/b", "*"]]
    reg.unregister_publisher("/b", "/p", C)
    assert ["/b", "*"] in reg.topic_type_list()  # types are never forgotten


def test_published_topics_by_subgraph() -> None:
    reg = Registry()
    reg.register_publisher("/a/x", "std_msgs/String", "/p", A)
    reg.register_publisher("/ab", "std_msgs/Int8", "/p", A)
    reg.register_subscriber("/a/y", "std_msgs/String", "/s", B)
    assert reg.published_topics("") == [["/a/x", "std_msgs/String"], ["/ab", "std_msgs/Int8"]]
    assert reg.published_topics("/a") == [["/a/x", "std_msgs/String"]]
    assert reg.published_topics("/a/") == [["/a/x", "std_msgs/String"]]


def test_services_have_one_provider_the_last() -> None:
    reg = Registry()
    first = reg.unregister_service("/srv", "/n", "rosrpc://a:9")
    assert first.status == "[/n] is not a registered node"
    out = reg.register_service("/srv", "rosrpc://a:9", "/n", A)
    assert (out.status, out.value) == ("Registered [/n] as provider of [/srv]", 1)
    reg.register_service("/srv", "rosrpc://b:9", "/m", B)
    assert reg.service_api("/srv") == "rosrpc://b:9"
    assert reg.system_state()[2] == [["/srv", ["/m"]]]
    stale = reg.unregister_service("/srv", "/n", "rosrpc://a:9")
    assert (stale.status, stale.value) == (
        "[rosrpc://a:9] is no longer the current service api handle for [/srv]",
        0,
    )
    assert reg.node_api("/n") == A  # it still lists the service it lost, as in rosmaster
    done = reg.unregister_service("/srv", "/m", "rosrpc://b:9")
    assert (done.status, done.value) == ("Unregistered [/m] as provider of [/srv]", 1)
    assert reg.service_api("/srv") is None
    assert reg.node_api("/m") is None


def test_unregister_service_before_any_service_existed() -> None:
    reg = Registry()
    reg.register_publisher("/t", "std_msgs/String", "/n", A)
    out = reg.unregister_service("/s", "/n", "rosrpc://a:9")
    assert (out.status, out.value) == ("[/n] is not a provider of [/s]", 0)
    reg.register_service("/other", "rosrpc://a:9", "/n", A)
    out = reg.unregister_service("/s", "/n", "rosrpc://a:9")
    assert out.status == "[rosrpc://a:9] is no longer the current service api handle for [/s]"


def test_system_state_order_and_version() -> None:
    reg = Registry()
    v0 = reg.version
    reg.register_publisher("/b", "std_msgs/String", "/n1", A)
    reg.register_publisher("/a", "std_msgs/String", "/n2", B)
    reg.register_publisher("/b", "std_msgs/String", "/n2", B)
    reg.register_subscriber("/a", "std_msgs/String", "/n1", A)
    assert reg.version > v0
    assert reg.system_state() == [
        [["/b", ["/n1", "/n2"]], ["/a", ["/n2"]]],
        [["/a", ["/n1"]]],
        [],
    ]
    v1 = reg.version
    reg.unregister_subscriber("/a", "/n1", C)  # nothing removed
    assert reg.system_state()[1] == [["/a", ["/n1"]]]
    reg.unregister_subscriber("/a", "/n1", A)
    assert reg.version > v1
