"""Tests for rosx.names: validation texts, resolution tables, remapping arguments, anonymous names.

The last section compares against ROS 1's own rosgraph/rospy, run with Debian's /usr/bin/python3
in a subprocess; it is skipped where that interpreter cannot import rosgraph.
"""

from __future__ import annotations

import json
import random
import subprocess
import sys
from typing import Any

import pytest

from rosx.names import (
    InvalidNameError,
    RemapArgs,
    anonymous_name,
    anonymous_node_name,
    basename,
    canonicalize,
    check_name,
    is_global,
    is_legal_base_name,
    is_legal_name,
    is_legal_remap,
    is_private,
    make_global_ns,
    namespace_of,
    ns_join,
    parse_remap_args,
    resolve,
    resolve_remappings,
    ros_namespace,
    script_resolve_name,
    strip_remap_args,
    validate,
)
from tests.support.ros1 import ros1_python_imports

# ---------------------------------------------------------------------------------------------
# Validation


def test_validate_space_gives_roscpp_text() -> None:
    assert validate("my turtle") == (
        "Character [ ] at element [2] is not valid in Graph Resource Name [my turtle].  "
        "Valid characters are a-z, A-Z, 0-9, / and _."
    )


def test_validate_digit_first_gives_roscpp_text() -> None:
    assert validate("1abc") == (
        "Character [1] is not valid as the first character in Graph Resource Name [1abc].  "
        "Valid characters are a-z, A-Z, / and in some cases ~."
    )


@pytest.mark.parametrize(
    ("name", "char", "index"),
    [
        ("a~b", "~", 1),
        ("/foo/~bar", "~", 5),
        ("~~x", "~", 1),
        ("/turtle1/cmd-vel", "-", 12),
        ("a.b", ".", 1),
        ("/a:b", ":", 2),
        ("abcé", "é", 3),
    ],
)
def test_validate_later_character(name: str, char: str, index: int) -> None:
    assert validate(name) == (
        f"Character [{char}] at element [{index}] is not valid in Graph Resource Name [{name}].  "
        "Valid characters are a-z, A-Z, 0-9, / and _."
    )


@pytest.mark.parametrize(("name", "char"), [("_x", "_"), (" a", " "), ("-", "-"), ("éa", "é")])
def test_validate_first_character(name: str, char: str) -> None:
    assert validate(name) == (
        f"Character [{char}] is not valid as the first character in Graph Resource Name "
        f"[{name}].  Valid characters are a-z, A-Z, / and in some cases ~."
    )


@pytest.mark.parametrize(
    "name",
    ["", "/", "~", "a", "/a/b", "~private", "~a/b_2", "a//b", "/a/", "//", "Z9_"],
)
def test_validate_accepts(name: str) -> None:
    assert validate(name) is None


def test_check_name_raises_with_text() -> None:
    with pytest.raises(InvalidNameError) as caught:
        check_name("my turtle")
    assert str(caught.value) == validate("my turtle")
    assert caught.value.message == validate("my turtle")
    assert isinstance(caught.value, ValueError)
    assert check_name("/ok") == "/ok"


@pytest.mark.parametrize(
    ("name", "legal"),
    [
        ("", True),
        ("/", True),
        ("~", True),
        ("a", True),
        ("/a/b_c/d1", True),
        ("~a/b", True),
        ("a/", True),
        ("a//b", False),
        ("//", False),
        ("a~b", False),
        ("1a", False),
        ("_a", False),
        ("a b", False),
        ("a-b", False),
        ("a\n", False),
        ("aé", False),
    ],
)
def test_is_legal_name(name: str, legal: bool) -> None:
    assert is_legal_name(name) is legal


@pytest.mark.parametrize(
    ("name", "legal"),
    [
        ("talker", True),
        ("Talker_2", True),
        ("", False),
        ("/talker", False),
        ("~talker", False),
        ("a/b", False),
        ("2talker", False),
        ("_talker", False),
    ],
)
def test_is_legal_base_name(name: str, legal: bool) -> None:
    assert is_legal_base_name(name) is legal


def test_global_and_private_predicates() -> None:
    assert is_global("/a") and not is_global("a") and not is_global("~a") and not is_global("")
    assert is_private("~a") and not is_private("/a") and not is_private("a") and not is_private("")


# ---------------------------------------------------------------------------------------------
# Name helpers


@pytest.mark.parametrize(
    ("name", "canonical"),
    [
        ("", ""),
        ("/", "/"),
        ("//", "/"),
        ("/a//b/", "/a/b"),
        ("a/b/", "a/b"),
        ("a///b", "a/b"),
        ("~x/", "~x"),
        ("~/x", "~/x"),
    ],
)
def test_canonicalize(name: str, canonical: str) -> None:
    assert canonicalize(name) == canonical


@pytest.mark.parametrize(
    ("ns", "name", "joined"),
    [
        ("/a", "b", "/a/b"),
        ("/a/", "b", "/a/b"),
        ("/", "b", "/b"),
        ("", "b", "b"),
        ("~", "b", "~b"),
        ("/a", "/b", "/b"),
        ("/a", "~b", "~b"),
        ("a", "b", "a/b"),
    ],
)
def test_ns_join(ns: str, name: str, joined: str) -> None:
    assert ns_join(ns, name) == joined


@pytest.mark.parametrize(
    ("name", "ns"),
    [
        ("", "/"),
        ("/", "/"),
        ("/wg/node1", "/wg/"),
        ("/wg/node1/", "/wg/"),
        ("/wg/", "/"),
        ("/node", "/"),
        ("node", "/"),
        ("a/b", "a/"),
    ],
)
def test_namespace_of(name: str, ns: str) -> None:
    assert namespace_of(name) == ns


@pytest.mark.parametrize(
    ("name", "base"),
    [("/a/b", "b"), ("/a/b/", "b"), ("b", "b"), ("~x", "x"), ("/", ""), ("", ""), ("a/~x", "x")],
)
def test_basename(name: str, base: str) -> None:
    assert basename(name) == base


def test_make_global_ns() -> None:
    assert make_global_ns("a") == "/a/"
    assert make_global_ns("/a/b") == "/a/b/"
    assert make_global_ns("/a/") == "/a/"
    assert make_global_ns("") == "/"
    with pytest.raises(ValueError, match=r"cannot turn \[~a\] into a global name"):
        make_global_ns("~a")


# ---------------------------------------------------------------------------------------------
# Resolution

RESOLUTION_TABLE = [
    # (name, namespace, node_name, resolved)
    ("chatter", "/", "talker", "/chatter"),
    ("chatter", "/a/b", "talker", "/a/b/chatter"),
    ("chatter", "/a/b/", "talker", "/a/b/chatter"),
    ("chatter", "a/b", "talker", "/a/b/chatter"),
    ("chatter", "", "talker", "/chatter"),
    ("x/y", "/a/b", "talker", "/a/b/x/y"),
    ("x//y/", "/a/b", "talker", "/a/b/x/y"),
    ("/chatter", "/a/b", "talker", "/chatter"),
    ("//chatter//", "/a/b", "talker", "/chatter"),
    ("/", "/a/b", "talker", "/"),
    ("~param", "/", "talker", "/talker/param"),
    ("~param", "/a/b", "talker", "/a/b/talker/param"),
    ("~param", "/a/b", "/a/b/talker", "/a/b/talker/param"),
    ("~param", "/", "/elsewhere/talker", "/elsewhere/talker/param"),
    ("~p/q", "/a/b", "talker", "/a/b/talker/p/q"),
    ("~/p", "/a/b", "talker", "/a/b/talker/p"),
    ("~", "/a/b", "talker", "/a/b/talker"),
    ("", "/", "talker", "/"),
    ("", "/a/b", "talker", "/a/b/"),
]


@pytest.mark.parametrize(("name", "namespace", "node", "resolved"), RESOLUTION_TABLE)
def test_resolve_table(name: str, namespace: str, node: str, resolved: str) -> None:
    assert resolve(name, namespace, node) == resolved


REMAPS = {
    "chatter": "talk",
    "/abs": "rel/target",
    "~priv": "/global_target",
    "other": "~mine",
    "__name": "renamed",
    "_rate": "10",
}

REMAP_TABLE = [
    # (name, namespace, resolved) with node "talker" and REMAPS
    ("chatter", "/", "/talk"),
    ("chatter", "/a/b", "/a/b/talk"),
    ("/chatter", "/a/b", "/chatter"),
    ("/a/b/chatter", "/a/b", "/a/b/talk"),
    ("chatter/", "/a/b", "/a/b/talk"),
    ("/abs", "/a/b", "/a/b/rel/target"),
    ("abs", "/", "/rel/target"),
    ("abs", "/a/b", "/a/b/abs"),
    ("~priv", "/a/b", "/global_target"),
    ("/a/b/talker/priv", "/a/b", "/global_target"),
    ("priv", "/a/b", "/a/b/priv"),
    ("other", "/a", "/a/talker/mine"),
    ("renamed", "/", "/renamed"),
    ("__name", "/", "/__name"),
    ("rate", "/", "/rate"),
    ("", "/a", "/a/"),
]


@pytest.mark.parametrize(("name", "namespace", "resolved"), REMAP_TABLE)
def test_resolve_with_remappings(name: str, namespace: str, resolved: str) -> None:
    assert resolve(name, namespace, "talker", REMAPS, strict=False) == resolved


def test_resolve_remappings_table() -> None:
    assert resolve_remappings(REMAPS, "/a/b", "talker") == {
        "/a/b/chatter": "/a/b/talk",
        "/abs": "/a/b/rel/target",
        "/a/b/talker/priv": "/global_target",
        "/a/b/other": "/a/b/talker/mine",
    }


def test_resolved_remappings_can_be_passed_again() -> None:
    table = resolve_remappings(REMAPS, "/a/b", "talker")
    assert resolve_remappings(table, "/a/b", "talker") == table
    assert resolve("chatter", "/a/b", "talker", table) == "/a/b/talk"


def test_remapping_is_not_chained() -> None:
    remaps = {"a": "b", "b": "c"}
    assert resolve("a", "/", "n", remaps) == "/b"


def test_resolve_strict_refuses_invalid_name() -> None:
    with pytest.raises(InvalidNameError, match=r"element \[2\]"):
        resolve("my turtle", "/", "n")
    assert resolve("my turtle", "/", "n", strict=False) == "/my turtle"


def test_resolve_strict_refuses_invalid_remapping() -> None:
    with pytest.raises(InvalidNameError, match=r"Graph Resource Name \[bad target\]"):
        resolve("chatter", "/", "n", {"chatter": "bad target"})


def test_private_name_needs_node_name() -> None:
    with pytest.raises(ValueError, match=r"private name \[~x\]"):
        resolve("~x", "/a")
    assert resolve("x", "/a") == "/a/x"


# ---------------------------------------------------------------------------------------------
# Command-line tools


@pytest.mark.parametrize(
    ("name", "namespace", "resolved"),
    [
        ("chatter", "/", "/chatter"),
        ("chatter", "/a/b/", "/a/b/chatter"),
        ("chatter", "/a/b", "/a/b/chatter"),
        ("chatter", "a", "/a/chatter"),
        ("/turtle1/pose/", "/a", "/turtle1/pose/"),
        ("a//b", "/", "/a//b"),
        ("~p", "/", "/rostopic/p"),
        ("~p", "/a/b", "/a/b/rostopic/p"),
        ("", "/", "/"),
        ("", "/a", "/a/"),
    ],
)
def test_script_resolve_name(name: str, namespace: str, resolved: str) -> None:
    assert script_resolve_name("rostopic", name, namespace) == resolved


def test_ros_namespace() -> None:
    assert ros_namespace({}) == "/"
    assert ros_namespace({"ROS_NAMESPACE": "robot"}) == "/robot/"
    assert ros_namespace({"ROS_NAMESPACE": "/a/b"}) == "/a/b/"
    assert ros_namespace({"ROS_NAMESPACE": "/a"}, ["x", "__ns:=other"]) == "/other/"
    assert ros_namespace({}, ["__ns:=/x/"]) == "/x/"


# ---------------------------------------------------------------------------------------------
# Remapping arguments


def test_parse_remap_args_sorts_every_kind() -> None:
    argv = [
        "talker.py",
        "chatter:=talk",
        "~priv:=/g",
        "/abs:=rel",
        "__name:=bob",
        "__ns:=/robot",
        "__master:=http://host:11311",
        "__ip:=10.0.0.2",
        "__hostname:=box",
        "__log:=/tmp/x.log",
        "_rate:=10",
        "_gains:={p: 1, i: [2, 3]}",
        "--verbose",
        "positional",
    ]
    parsed = parse_remap_args(argv)
    assert dict(parsed.remappings) == {"chatter": "talk", "~priv": "/g", "/abs": "rel"}
    assert dict(parsed.special) == {
        "__name": "bob",
        "__ns": "/robot",
        "__master": "http://host:11311",
        "__ip": "10.0.0.2",
        "__hostname": "box",
        "__log": "/tmp/x.log",
    }
    assert dict(parsed.params) == {"rate": "10", "gains": "{p: 1, i: [2, 3]}"}
    assert list(parsed.argv) == ["talker.py", "--verbose", "positional"]
    assert list(parsed.ignored) == []
    assert (parsed.name, parsed.ns, parsed.master) == ("bob", "/robot", "http://host:11311")
    assert (parsed.ip, parsed.hostname, parsed.log) == ("10.0.0.2", "box", "/tmp/x.log")


def test_parse_remap_args_defaults() -> None:
    parsed = parse_remap_args(["a", "b"])
    assert parsed == RemapArgs(argv=("a", "b"))
    assert parsed.name is None and parsed.ns is None and parsed.log is None


def test_parse_remap_args_malformed() -> None:
    argv = [":=x", "1a:=b", "a b:=c", "foo:=", "a:=b:=c", "-x:=y", "x:=y\nz", " a := b "]
    parsed = parse_remap_args(argv)
    assert dict(parsed.remappings) == {}
    assert list(parsed.argv) == [":=x", "1a:=b", "a b:=c", "-x:=y", "x:=y\nz", " a := b "]
    assert list(parsed.ignored) == ["foo:=", "a:=b:=c"]


def test_parse_remap_args_strips_and_last_wins() -> None:
    parsed = parse_remap_args(["a:= b ", "a:=c", "_p:= 1 ", "_:=x", "__:=y"])
    assert dict(parsed.remappings) == {"a": "c", "_": "x"}
    assert dict(parsed.params) == {"p": "1"}
    assert dict(parsed.special) == {"__": "y"}


def test_strip_remap_args() -> None:
    argv = ["prog", "a:=b", "_p:=1", "__name:=n", "x", ":=y", "foo:="]
    assert strip_remap_args(argv) == ["prog", "x", ":=y"]


@pytest.mark.parametrize(
    ("arg", "legal"),
    [
        ("a:=b", True),
        ("~a:=b", True),
        ("/a/b:=c", True),
        ("_a:=1", True),
        ("__name:=x", True),
        ("a:=", True),
        ("a:=b:=c", True),
        (":=b", False),
        ("1:=b", False),
        ("a", False),
        ("a=b", False),
        ("a-b:=c", False),
        ("a:=b\nc", False),
    ],
)
def test_is_legal_remap(arg: str, legal: bool) -> None:
    assert is_legal_remap(arg) is legal


def test_parsed_remappings_feed_resolution() -> None:
    parsed = parse_remap_args(["node", "chatter:=talk", "_rate:=5"])
    assert resolve("chatter", "/ns", "node", parsed.remappings) == "/ns/talk"
    assert resolve("rate", "/ns", "node", parsed.remappings) == "/ns/rate"


# ---------------------------------------------------------------------------------------------
# Anonymous names


def test_anonymous_name_form() -> None:
    rng = random.Random(7)
    expected_suffix = random.Random(7).randint(0, sys.maxsize)
    name = anonymous_name("rostopic", hostname="my-host.local", pid=4242, rng=rng)
    assert name == f"rostopic_my_host_local_4242_{expected_suffix}"
    assert is_legal_base_name(name)


def test_anonymous_name_replaces_in_base_and_ipv6_hosts() -> None:
    rng = random.Random(1)
    name = anonymous_name("a-b.c", hostname="fe80::1", pid=1, rng=rng)
    assert name.startswith("a_b_c_fe80__1_1_")
    assert validate(name) is None


def test_anonymous_name_defaults_vary() -> None:
    first, second = anonymous_name("x"), anonymous_name("x")
    assert first.startswith("x_") and first != second


def test_anonymous_node_name() -> None:
    assert anonymous_node_name("rostopic", pid=99, now=1700000000.1239) == (
        "rostopic_99_1700000000123"
    )


# ---------------------------------------------------------------------------------------------
# Against ROS 1 itself

ROS_PYTHON = "/usr/bin/python3"


ros1 = pytest.mark.skipif(
    not ros1_python_imports("rosgraph.names", "rospy.names"),
    reason="ROS 1's rospy/rosgraph not importable",
)

_ROS1_DRIVER = r"""
import json, os, random, socket, sys
cases = json.load(sys.stdin)
sys.argv = ["driver"]
import rosgraph.names as g
import rospy.names as rn
import rospy.client as rc
out = []
for op, args in cases:
    if op == "resolve_name":
        out.append(g.resolve_name(*args))
    elif op == "legal":
        out.append([bool(g.is_legal_name(args)), bool(g.is_legal_base_name(args)),
                    bool(g.is_legal_remap(args))])
    elif op == "helpers":
        name, ns = args
        out.append([g.canonicalize_name(name), g.namespace(name), g.ns_join(ns, name)])
    elif op == "script":
        ros_ns, script, name = args
        os.environ["ROS_NAMESPACE"] = ros_ns
        out.append(g.script_resolve_name(script, name))
    elif op == "argv":
        out.append([g.load_mappings(args), rc.myargv(args)])
    elif op == "rospy_remap":
        argv, node, names = args
        rn.reload_mappings(argv)
        rn.initialize_mappings(node)
        table = {k: v for k, v in rn.get_resolved_mappings().items() if not k.startswith("__")}
        out.append([table, [rn.resolve_name(n, node) for n in names]])
    elif op == "anonymous":
        base, host, pid, rand = args
        socket.gethostname = lambda: host
        os.getpid = lambda: pid
        random.randint = lambda a, b: rand
        out.append(g.anonymous_name(base))
json.dump(out, sys.stdout)
"""


def _ros1(cases: list[tuple[str, Any]]) -> list[Any]:
    done = subprocess.run(
        [ROS_PYTHON, "-c", _ROS1_DRIVER],
        input=json.dumps(cases),
        capture_output=True,
        text=True,
        check=True,
        timeout=60,
    )
    result: list[Any] = json.loads(done.stdout)
    return result


NAMES = [
    "",
    "/",
    "~",
    "a",
    "/a",
    "a/b",
    "/a/b/",
    "a//b",
    "//a",
    "~a",
    "~a/b/",
    "~/a",
    "1a",
    "_a",
    "a b",
    "a~b",
    "a-b",
    "A9_z",
]


@ros1
def test_predicates_match_rosgraph() -> None:
    theirs = _ros1([("legal", name) for name in NAMES])
    ours = [[is_legal_name(n), is_legal_base_name(n), is_legal_remap(n)] for n in NAMES]
    assert ours == theirs


@ros1
def test_remap_predicate_matches_rosgraph() -> None:
    args = ["a:=b", ":=b", "_p:=1", "__x:=", "a:=b:=c", "1:=2", "~a/b:=c", "a b:=c", "x:=y\nz"]
    theirs = [row[2] for row in _ros1([("legal", arg) for arg in args])]
    assert [is_legal_remap(arg) for arg in args] == theirs


@ros1
def test_helpers_match_rosgraph() -> None:
    pairs = [(name, ns) for name in NAMES for ns in ["", "/", "/x", "/x/", "~", "y"]]
    theirs = _ros1([("helpers", [name, ns]) for name, ns in pairs])
    ours = [[canonicalize(name), namespace_of(name), ns_join(ns, name)] for name, ns in pairs]
    assert ours == theirs


@ros1
def test_resolution_matches_rosgraph() -> None:
    nodes = ["/talker", "/a/b/talker"]
    names = [n for n in NAMES if n not in {"1a", "_a", "a b", "a~b", "a-b"}]
    cases = [(name, node) for node in nodes for name in names]
    theirs = _ros1([("resolve_name", [name, node]) for name, node in cases])
    ours = [resolve(name, namespace_of(node), node) for name, node in cases]
    assert ours == theirs


@ros1
def test_remapped_resolution_matches_rospy() -> None:
    argv = ["prog", "chatter:=talk", "/abs:=rel/t", "~priv:=/g", "other:=~mine", "_p:=1", "x:="]
    names = ["chatter", "/a/b/chatter", "/abs", "abs", "~priv", "priv", "other", "x", "/chatter"]
    parsed = parse_remap_args(argv)
    for node in ["/talker", "/a/b/talker"]:
        [[their_table, theirs]] = _ros1([("rospy_remap", [argv, node, names])])
        ns = namespace_of(node)
        assert resolve_remappings(parsed.remappings, ns, node) == their_table
        assert [resolve(n, ns, node, parsed.remappings) for n in names] == theirs


@ros1
def test_argv_parsing_matches_rosgraph() -> None:
    argv = [
        "prog",
        "a:=b",
        " x",
        ":=y",
        "_p:=1",
        "__name:=n",
        "foo:=",
        "c:= d ",
        "_:=u",
        "--flag",
        "a:=b:=c",
    ]
    [[mappings, rest]] = _ros1([("argv", argv)])
    parsed = parse_remap_args(argv)
    assert {**parsed.remappings, **parsed.special} == mappings
    assert list(parsed.argv) == rest == strip_remap_args(argv)


@ros1
@pytest.mark.parametrize("ros_ns", ["/", "", "robot", "/a/b", "/a/b/"])
def test_script_resolution_matches_rosgraph(ros_ns: str) -> None:
    names = ["", "chatter", "/chatter", "~p", "a/b/", "/x//y"]
    theirs = _ros1([("script", [ros_ns, "rostopic", name]) for name in names])
    namespace = ros_namespace({"ROS_NAMESPACE": ros_ns})
    assert [script_resolve_name("rostopic", n, namespace) for n in names] == theirs


@ros1
def test_anonymous_name_matches_rosgraph() -> None:
    cases = [("rostopic", "my-host.local", 4242, 987654321), ("a-b", "fe80::1", 7, 0)]
    theirs = _ros1([("anonymous", list(case)) for case in cases])

    class Fixed(random.Random):
        def __init__(self, value: int) -> None:
            super().__init__()
            self.value = value

        def randint(self, a: int, b: int) -> int:
            return self.value

    ours = [anonymous_name(b, hostname=h, pid=p, rng=Fixed(r)) for b, h, p, r in cases]
    assert ours == theirs
