"""The parameter tree: subtrees, types, deletion, names, searchParam's rules and the
paramUpdate notifications rosmaster computes. No sockets."""

from __future__ import annotations

import pytest

from rosx.master.actions import ParamUpdate
from rosx.master.params import ParamTree, namespace_key, param_updates


def test_set_get_types_are_kept() -> None:
    tree = ParamTree()
    values = {
        "/i": 7,
        "/f": 1.5,
        "/b": True,
        "/s": "text",
        "/bin": b"\x00\xff",
        "/l": [1, "two", [3.0]],
        "/d": {"x": {"y": 1}},
    }
    for key, value in values.items():
        tree.set(key, value)
    for key, value in values.items():
        assert tree.get(key) == value
        assert type(tree.get(key)) is type(value)


def test_dict_replaces_the_namespace() -> None:
    tree = ParamTree()
    tree.set("/ns/a", 1)
    tree.set("/ns/b", 2)
    tree.set("/ns", {"c": 3})
    assert tree.get("/ns") == {"c": 3}
    assert not tree.has("/ns/a")
    assert tree.get("/ns/c") == 3


def test_getting_a_namespace_returns_the_subtree() -> None:
    tree = ParamTree()
    tree.set("/a/b/c", 1)
    tree.set("/a/d", "x")
    assert tree.get("/a") == {"b": {"c": 1}, "d": "x"}
    assert tree.get("/") == {"a": {"b": {"c": 1}, "d": "x"}}
    assert tree.get("/a/b/") == {"c": 1}


def test_setting_below_a_value_turns_it_into_a_namespace() -> None:
    tree = ParamTree()
    tree.set("/a", 5)
    tree.set("/a/b", 6)
    assert tree.get("/a") == {"b": 6}


def test_missing_keys() -> None:
    tree = ParamTree()
    tree.set("/a", 5)
    for key in ("/b", "/a/b", "/x/y"):
        with pytest.raises(KeyError):
            tree.get(key)
        assert not tree.has(key)
    assert tree.has("/")


def test_root() -> None:
    tree = ParamTree()
    with pytest.raises(TypeError, match="cannot set root of parameter tree to non-dictionary"):
        tree.set("/", 1)
    tree.set("/", {"a": 1})
    assert tree.get("/a") == 1
    with pytest.raises(KeyError):
        tree.delete("/")


def test_delete() -> None:
    tree = ParamTree()
    tree.set("/a/b", 1)
    tree.set("/a/c", 2)
    tree.delete("/a/b")
    assert tree.get("/a") == {"c": 2}
    tree.delete("/a")
    assert not tree.has("/a")
    for key in ("/a", "/a/c", "/nope/x"):
        with pytest.raises(KeyError):
            tree.delete(key)
    tree.set("/v", 1)
    with pytest.raises(KeyError):
        tree.delete("/v/x")


def test_names_skip_namespaces() -> None:
    tree = ParamTree()
    tree.set("/a/b", 1)
    tree.set("/a/c/d", 2)
    tree.set("/e", {})
    tree.set("/f", 3)
    assert tree.names() == ["/a/b", "/a/c/d", "/f"]


@pytest.fixture
def searchable() -> ParamTree:
    tree = ParamTree()
    tree.set("/robot_description", "top")
    tree.set("/pr2/robot_description", {"base": 1})
    tree.set("/pr2/foo/private", 1)
    tree.set("/global_only", 2)
    return tree


@pytest.mark.parametrize(
    ("ns", "key", "found"),
    [
        ("/pr2/foo", "robot_description", "/pr2/robot_description"),
        ("/pr2/foo", "robot_description/arm", "/pr2/robot_description/arm"),
        ("/other/node", "robot_description", "/robot_description"),
        ("/", "robot_description", "/robot_description"),
        ("/pr2/foo", "private", "/pr2/foo/private"),  # the node's own namespace comes first
        ("/pr2", "foo/private", "/pr2/foo/private"),
        ("/a/b/c", "global_only", "/global_only"),
        ("/a", "missing", None),
        ("/a", "/global_only", "/global_only"),
        ("/a", "/missing", None),
    ],
)
def test_search(searchable: ParamTree, ns: str, key: str, found: str | None) -> None:
    assert searchable.search(ns, key) == found


def test_search_refusals(searchable: ParamTree) -> None:
    with pytest.raises(ValueError, match="invalid key"):
        searchable.search("/a", "~private")
    with pytest.raises(ValueError, match="invalid key"):
        searchable.search("/a", "")
    with pytest.raises(ValueError, match="namespace must be global"):
        searchable.search("relative", "x")


def test_namespace_key() -> None:
    assert namespace_key("/") == "/"
    assert namespace_key("/a//b/") == "/a/b/"
    assert namespace_key("/a") == "/a/"


SUBS = {
    "/a/": {("/n1", "http://n1:1/"): None},
    "/a/b/": {("/n2", "http://n2:1/"): None},
    "/z/": {("/n3", "http://n3:1/"): None},
}


def test_update_of_a_subscribed_key_and_below_it() -> None:
    assert param_updates(SUBS, "/a", 5) == [ParamUpdate("http://n1:1/", "/n1", "/a/", 5)]
    assert param_updates(SUBS, "/a/b/c", 5) == [
        ParamUpdate("http://n1:1/", "/n1", "/a/b/c/", 5),
        ParamUpdate("http://n2:1/", "/n2", "/a/b/c/", 5),
    ]
    assert param_updates(SUBS, "/q", 5) == []
    assert param_updates({}, "/a", 5) == []


def test_the_setter_does_not_hear_its_own_change() -> None:
    assert param_updates(SUBS, "/a", 5, ignore_caller="/n1") == []


def test_setting_a_namespace_reaches_keys_inside_it() -> None:
    updates = param_updates(SUBS, "/", {"a": {"b": 1, "c": 2}})
    assert updates == [
        ParamUpdate("http://n3:1/", "/n3", "/z/", {}),  # no longer in the tree
        ParamUpdate("http://n1:1/", "/n1", "/a/", {"b": 1, "c": 2}),
        ParamUpdate("http://n2:1/", "/n2", "/a/b/", 1),
    ]


def test_deleting_a_namespace_tells_subscribers_below_it() -> None:
    assert param_updates(SUBS, "/a", {}) == [
        ParamUpdate("http://n1:1/", "/n1", "/a/", {}),
        ParamUpdate("http://n2:1/", "/n2", "/a/b/", {}),
    ]
