"""YAML arguments of rostopic pub / rosservice call: loading, filling messages, error texts.

Where Debian's ROS 1 is installed, the same words are loaded with PyYAML and filled by
rostopic's and rosservice's own code in ``/usr/bin/python3``, and the results compared.
"""

from __future__ import annotations

import json
import random
import re
import subprocess
import sys
from typing import Any

import pytest

from rosx.msg.codec.classes import get_message_class
from rosx.msg.codec.message import MessageException
from rosx.msg.codec.rostime import Duration, Time
from rosx.msg.store import default_store
from rosx.msg.text.echo import format_message
from rosx.msg.text.yamlargs import (
    call_error_text,
    fill_message_args,
    load_args,
    printable_args,
    publish_error_text,
)
from rosx.msg.text.yamlload import YAMLLoadError, load, load_all, load_stream, split_stream
from tests.support.ros1 import ROS1_PYTHON, ros1_python_imports

NOW = Time(1700000000, 500)


def ros1_available() -> bool:
    return ros1_python_imports("genpy", "genpy.dynamic", "rostopic", "rosservice", "yaml")


needs_ros1 = pytest.mark.skipif(not ros1_available(), reason="ROS 1 (genpy, rostopic) not found")


def filled(type_name: str, *words: str) -> Any:
    value = get_message_class(type_name)()
    fill_message_args(value, load_args(words), clock=lambda: NOW)
    return value


# -- loading ---------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "value"),
    [
        ("yes", True),
        ("Off", False),
        ("y", "y"),
        ("1e5", "1e5"),
        ("1e-05", "1e-05"),
        ("1.0e+5", 100000.0),
        ("010", 8),
        ("0x1F", 31),
        ("1:30", 90),
        ("~", None),
        ("", None),
        ("{x:5}", {"x:5": None}),
        ("{linear:{x: 2.0}}", {"linear": {"x": 2.0}}),
        ("{a: 1, a: 2}", {"a": 2}),
        ("[1, 2.5, two]", [1, 2.5, "two"]),
    ],
)
def test_yaml_is_read_as_pyyaml_reads_it(text: str, value: object) -> None:
    assert load(text) == value


def test_yaml_errors_read_as_pyyaml_words_them() -> None:
    with pytest.raises(YAMLLoadError) as caught:
        load("[1, 2")
    assert str(caught.value) == (
        "while parsing a flow sequence\n"
        '  in "<unicode string>", line 1, column 1:\n'
        "    [1, 2\n"
        "    ^\n"
        "expected ',' or ']', but got '<stream end>'\n"
        '  in "<unicode string>", line 1, column 6:\n'
        "    [1, 2\n"
        "         ^"
    )
    with pytest.raises(YAMLLoadError, match=r"^expected '<document start>', but found ']'\n"):
        load("[1]]")


def test_streams_of_documents() -> None:
    assert load_all("a: 1\n---\nb: 2\n") == [{"a": 1}, {"b": 2}]
    lines = ["x: 1\n", "y: 2\n", "---\n", "\n", "---\n", "z: 3\n"]
    assert list(split_stream(lines)) == ["x: 1\ny: 2", ""]
    errors: list[YAMLLoadError] = []
    lines = ["[1\n", " ---\n", "data: 1\n", "---\n", "~\n", "---\n", "data: 2\n"]
    assert list(load_stream(lines, errors.append)) == [{"data": 1}]
    assert [str(e).splitlines()[0] for e in errors] == ["while parsing a flow sequence"]
    with pytest.raises(YAMLLoadError) as caught:
        load_all("a: 1\n]\n", filename="f.yaml")
    assert str(caught.value) == (
        'while parsing a block mapping\n  in "f.yaml", line 1, column 1\n'
        "expected <block end>, but found ']'\n  in \"f.yaml\", line 2, column 1"
    )


def test_empty_words_for_rosservice() -> None:
    assert load_args(["", "1"]) == [None, 1]
    assert load_args(["", "1"], empty_is_string=True) == ["", 1]


def test_ruamel_is_imported_only_when_loading() -> None:
    code = (
        "import sys, rosx.msg.text.yamlargs, rosx.msg.text.echo;"
        "assert not [m for m in sys.modules if m.startswith('ruamel')];"
        "rosx.msg.text.yamlargs.load_args(['1']);"
        "assert 'ruamel.yaml' in sys.modules"
    )
    subprocess.run([sys.executable, "-c", code], check=True, timeout=60)


# -- filling ---------------------------------------------------------------------------------


def test_dict_and_positional_forms() -> None:
    twist = filled("geometry_msgs/Twist", "{linear: {x: 2.0}, angular: {z: 1}}")
    assert format_message(twist) == (
        "linear: \n  x: 2.0\n  y: 0.0\n  z: 0.0\nangular: \n  x: 0.0\n  y: 0.0\n  z: 1"
    )
    twist = filled("geometry_msgs/Twist", "[2.0, 0, 0]", "{z: -1.5}")
    assert (twist.linear.x, twist.linear.y, twist.angular.z) == (2.0, 0, -1.5)
    spawn = filled("turtlesim/SpawnRequest", "2", "3.5", "0.2", "turtle2")
    assert format_message(spawn) == 'x: 2\ny: 3.5\ntheta: 0.2\nname: "turtle2"'
    assert filled("std_msgs/String", "{data: }").data == ""


def test_now_auto_and_integer_times() -> None:
    header = filled("std_msgs/Header", "{seq: 4, stamp: now, frame_id: map}")
    assert (header.seq, header.stamp, header.frame_id) == (4, NOW, "map")
    pose = filled("geometry_msgs/PoseStamped", "{header: auto, pose: {orientation: {w: 1}}}")
    assert (pose.header.seq, pose.header.stamp, pose.header.frame_id) == (0, NOW, "")
    assert filled("std_msgs/Time", "now").data == NOW
    stamp = filled("std_msgs/Time", "1700000000123456789").data
    assert (stamp.secs, stamp.nsecs) == (1700000000, 123456716)  # via float seconds, as genpy
    assert filled("std_msgs/Duration", "{data: {secs: -1}}").data == Duration(-1, 0)


def test_arrays() -> None:
    state = filled("sensor_msgs/JointState", "{name: [a, b], position: [1, 2.5]}")
    assert (state.name, state.position) == (["a", "b"], [1, 2.5])
    markers = filled("visualization_msgs/MarkerArray", "{markers: [{ns: a}, {id: 3}]}")
    assert [(m.ns, m.id) for m in markers.markers] == [("a", 0), ("", 3)]
    assert filled("std_msgs/UInt8MultiArray", "{data: [1, 2]}").data == [1, 2]
    info = filled("sensor_msgs/CameraInfo", "{K: [1, 0, 0, 0, 1, 0, 0, 0, 1]}")
    assert info.K == [1, 0, 0, 0, 1, 0, 0, 0, 1]


@pytest.mark.parametrize(
    ("type_name", "words", "kind", "text"),
    [
        ("geometry_msgs/Twist", ["[1, 2, 3]"], MessageException,
         "Not enough arguments:\n * Given: [[1, 2, 3]]\n * Expected: ['linear', 'angular']"),
        ("geometry_msgs/Vector3", ["1", "2", "3", "4"], MessageException,
         "Too many arguments:\n * Given: [1, 2, 3, 4]\n * Expected: ['x', 'y', 'z']"),
        ("geometry_msgs/Twist", ["{linear: {w: 1}}"], MessageException,
         "No field name [linear.w]"),
        ("geometry_msgs/Twist", ["{linear: 5}"], ValueError, "invalid msg_args type: 5"),
        ("std_msgs/Header", ["{stamp: later}"], MessageException, "No key named [later]"),
        ("sensor_msgs/JointState", ["{name: a}"], MessageException,
         "Field [name] must be a list or tuple instead of: str"),
        ("sensor_msgs/CameraInfo", ["{K: [1, 2]}"], MessageException,
         "Field [K] has incorrect number of elements: 2 != 9"),
        ("visualization_msgs/MarkerArray", ["{markers: [{nope: 1}]}"], MessageException,
         "No field name [nope]"),
        ("geometry_msgs/Twist", ["{x:5}"], MessageException,
         "No field name [x:5]: YAML needs a space after the colon, write {x: 5}"),
        ("geometry_msgs/Twist", ["{linear: {x:2.0}}"], MessageException,
         "No field name [linear.x:2.0]: YAML needs a space after the colon, write {x: 2.0}"),
    ],
)  # fmt: skip
def test_errors(type_name: str, words: list[str], kind: type[Exception], text: str) -> None:
    with pytest.raises(kind) as caught:
        filled(type_name, *words)
    assert str(caught.value) == text


def test_error_texts_of_the_tools() -> None:
    twist = get_message_class("geometry_msgs/Twist")()
    assert printable_args(twist) == "linear.x linear.y linear.z angular.x angular.y angular.z"
    error = MessageException("No field name [w]")
    assert publish_error_text(error, twist) == (
        "No field name [w]\n\nArgs are: [linear.x linear.y linear.z angular.x angular.y angular.z]"
    )
    request = get_message_class("turtlesim/SpawnRequest")()
    assert call_error_text(error, [1, "a", {"x": 1}], request) == (
        "Incompatible arguments to call service:\nNo field name [w]\n"
        "Provided arguments are:\n * 1 (type int)\n * a (type str)\n * {'x': 1} (type dict)"
        "\n\nService arguments are: [x y theta name]"
    )
    header = get_message_class("std_msgs/Header")()
    assert printable_args(header) == "seq stamp frame_id"


# -- ROS 1 cross-checks ----------------------------------------------------------------------

_ORACLE = r"""
import io, json, sys
import yaml
import genpy, genpy.dynamic, genpy.message, rospy, rostopic, rosservice

registry = {}
original = genpy.message.get_message_class
def get_message_class(name, reload_on_error=False):
    return registry.get(name) or original(name, reload_on_error)
genpy.message.get_message_class = get_message_class
rospy.get_rostime = lambda: genpy.Time(1700000000, 500)
rospy.init_node = lambda *args, **kwds: None
rosservice.rospy.ServiceProxy = lambda name, cls: (lambda request: None)

def run(job):
    words = job["words"]
    if job["service"]:
        words = ["''" if w == "" else w for w in words]  # as rosservice call does
    try:
        args = [yaml.safe_load(w) for w in words]
    except Exception as e:
        return ["yaml", str(e)]
    cls = registry[job["type"]]
    try:
        if job["service"]:
            service = type("S", (), {"_request_class": cls, "_type": job["type"]})
            request, _ = rosservice.call_service("/s", args, service_class=service)
            return ["ok", genpy.message.strify_message(request)]
        value = cls()
        rostopic._fillMessageArgs(value, args)
        return ["ok", genpy.message.strify_message(value)]
    except (rostopic.ROSTopicException, rosservice.ROSServiceException) as e:
        return ["error", str(e)]
    except ValueError as e:
        return ["value", str(e)]

results = []
for job in json.load(sys.stdin):
    if job["type"] not in registry:
        registry.update(genpy.dynamic.generate_dynamic(job["type"], job["full_text"]))
    results.append(run(job))
json.dump(results, sys.stdout)
"""

_CASES: list[tuple[str, list[str]]] = [
    ("geometry_msgs/Twist", ["{linear: {x: 2.0, y: 0.0, z: 0.0}, angular: {z: 1.8}}"]),
    ("geometry_msgs/Twist", ["[2.0, 0.0, 0.0]", "[0.0, 0.0, 1.8]"]),
    ("geometry_msgs/Twist", ["[2, 0, 0]", "{z: 1}"]),
    ("geometry_msgs/Twist", ["{linear: {x: 2}}"]),
    ("geometry_msgs/Twist", ["[1, 2]", "[3, 4, 5]"]),
    ("geometry_msgs/Twist", ["[1, 2, 3]"]),
    ("geometry_msgs/Twist", ["1", "2"]),
    ("geometry_msgs/Twist", ["1", "2", "3"]),
    ("geometry_msgs/Twist", ["{linear: 5}"]),
    ("geometry_msgs/Twist", ["{linear: [1, 2, 3, 4]}"]),
    ("geometry_msgs/Twist", ["{linear: {w: 1}}"]),
    ("geometry_msgs/Twist", ["{linear: {x: }}"]),
    ("geometry_msgs/Twist", ["{linear: now}"]),
    ("geometry_msgs/Twist", []),
    ("geometry_msgs/Twist", ["[1, 2"]),
    ("geometry_msgs/Twist", ["{linear:{x: 2.0}}"]),
    ("geometry_msgs/Twist", ["{}"]),
    ("geometry_msgs/Twist", ["~"]),
    ("geometry_msgs/Vector3", ["1e-05", "1.0e-05", ".5"]),
    ("geometry_msgs/Vector3", ["y", "yes", "0x10"]),
    ("std_msgs/String", ["hello"]),
    ("std_msgs/String", ["{data: hello}"]),
    ("std_msgs/String", ["{data: }"]),
    ("std_msgs/String", ["yes"]),
    ("std_msgs/String", ["data: 'it''s'"]),
    ("std_msgs/String", ["'multi\n\nline'"]),
    ("std_msgs/String", ["a", "b"]),
    ("std_msgs/Empty", []),
    ("std_msgs/Empty", [""]),
    ("std_msgs/Empty", ["{}"]),
    ("std_msgs/Header", ["{seq: 1, stamp: now, frame_id: map}"]),
    ("std_msgs/Header", ["auto"]),
    ("std_msgs/Header", ["{stamp: {secs: 1, nsecs: 2}}"]),
    ("std_msgs/Header", ["{stamp: [3, 4]}"]),
    ("std_msgs/Header", ["{stamp: [3]}"]),
    ("std_msgs/Header", ["{stamp: 1500000000123456789}"]),
    ("std_msgs/Header", ["{stamp: 1.5}"]),
    ("std_msgs/Header", ["{stamp: later}"]),
    ("std_msgs/Header", ["{stamp: {secs: 1, nope: 2}}"]),
    ("std_msgs/Header", ["[1, now, x]"]),
    ("std_msgs/Header", ["1", "now", "x"]),
    ("std_msgs/Time", ["now"]),
    ("std_msgs/Time", ["{data: now}"]),
    ("std_msgs/Time", ["1700000000000000001"]),
    ("std_msgs/Duration", ["now"]),
    ("std_msgs/Duration", ["{data: {secs: -1, nsecs: 5}}"]),
    ("std_msgs/Duration", ["-5"]),
    ("geometry_msgs/PoseStamped", ["{header: auto}"]),
    ("geometry_msgs/PoseStamped", ["{header: {frame_id: map}, pose: {orientation: {w: 1}}}"]),
    ("geometry_msgs/PoseStamped", ["{pose: {position: {q: 1}}}"]),
    ("geometry_msgs/PoseStamped", ["{pose: auto}"]),
    ("geometry_msgs/PoseStamped", ["auto", "[[1, 2, 3], [0, 0, 0, 1]]"]),
    ("sensor_msgs/JointState", ["{header: auto, name: [a, b], position: [1, 2.5]}"]),
    ("sensor_msgs/JointState", ["{name: a}"]),
    ("sensor_msgs/JointState", ["{position: [1, x]}"]),
    ("sensor_msgs/CameraInfo", ["{K: [1, 2, 3]}"]),
    ("sensor_msgs/CameraInfo", ["{K: [1, 0, 0, 0, 1, 0, 0, 0, 1], D: []}"]),
    ("sensor_msgs/CameraInfo", ["{roi: {do_rectify: true}}"]),
    ("visualization_msgs/MarkerArray", ["{markers: [{ns: a, id: 1}, {pose: {position: {x: 1}}}]}"]),
    ("visualization_msgs/MarkerArray", ["{markers: [{nope: 1}]}"]),
    ("visualization_msgs/MarkerArray", ["{markers: [5]}"]),
    ("visualization_msgs/MarkerArray", ["{markers: [[]]}"]),
    ("visualization_msgs/MarkerArray", ["{markers: {ns: a}}"]),
    ("visualization_msgs/MarkerArray", ["[[{header: auto, points: [[1, 2, 3]]}]]"]),
    ("visualization_msgs/Marker", ["{lifetime: 5, header: {stamp: 7}}"]),
    ("std_msgs/UInt8MultiArray", ["{data: [1, 2, 300]}"]),
    ("std_msgs/UInt8MultiArray", ["{data: abc}"]),
    ("std_msgs/UInt8MultiArray", ["{layout: {dim: [{label: x, size: 2, stride: 2}]}}"]),
    ("diagnostic_msgs/DiagnosticArray", ["{status: [{level: 2, values: [{key: k, value: v}]}]}"]),
    ("diagnostic_msgs/DiagnosticArray", ["{status: [{values: {key: k}}]}"]),
    ("turtlesim/Pose", ["1", "2", "3", "4", "5"]),
    ("turtlesim/Color", ["{r: 255, g: -1}"]),
]

_SERVICE_CASES: list[tuple[str, list[str]]] = [
    ("turtlesim/SpawnRequest", ["2.0", "2.0", "0.2", ""]),
    ("turtlesim/SpawnRequest", ["2", "2", "0", "turtle2"]),
    ("turtlesim/SpawnRequest", ["{x: 1, name: t}"]),
    ("turtlesim/SpawnRequest", ["1", "2"]),
    ("turtlesim/SpawnRequest", ["{x: 1, nope: 2}"]),
    ("turtlesim/SpawnRequest", ["{x:1}"]),
    ("turtlesim/TeleportAbsoluteRequest", ["1", "1", "0"]),
    ("turtlesim/SetPenRequest", ["{r: 255, width: 3, 'off': 1}"]),
    ("std_srvs/SetBoolRequest", ["true"]),
    ("std_srvs/EmptyRequest", [""]),
    ("std_srvs/EmptyRequest", []),
]


def _ours(type_name: str, words: list[str], service: bool) -> list[str]:
    try:
        args = load_args(words, empty_is_string=service)
    except YAMLLoadError as error:
        return ["yaml", str(error)]
    value = get_message_class(type_name)()
    try:
        fill_message_args(value, args, clock=lambda: NOW)
    except MessageException as error:
        if service:
            return ["error", call_error_text(error, args, value)]
        return ["error", publish_error_text(error, value)]
    except ValueError as error:
        return ["value", str(error)]
    return ["ok", format_message(value)]


def _without_hint(text: str) -> str:
    """Our text for ``{x:5}`` is ROS 1's plus a hint on the same line."""
    return re.sub(r": YAML needs a space after the colon, write \{[^\n]*\}", "", text)


@needs_ros1
def test_arguments_fill_messages_as_rostopic_and_rosservice_do() -> None:
    store = default_store()
    cases = [(t, w, False) for t, w in _CASES] + [(t, w, True) for t, w in _SERVICE_CASES]
    jobs = [
        {"type": t, "full_text": store.full_text(t), "words": w, "service": s} for t, w, s in cases
    ]
    done = subprocess.run(
        [ROS1_PYTHON, "-c", _ORACLE],
        input=json.dumps(jobs),
        capture_output=True,
        text=True,
        timeout=300,
        check=True,
    )
    theirs = json.loads(done.stdout)
    mismatches = []
    for (type_name, words, service), reference in zip(cases, theirs, strict=True):
        mine = _ours(type_name, words, service)
        mine[1] = _without_hint(mine[1])
        if mine != reference:
            mismatches.append(f"{type_name} {words}:\n{mine!r}\n!=\n{reference!r}")
    assert not mismatches, f"{len(mismatches)} differ:\n" + "\n\n".join(mismatches)


_PYYAML = r"""
import json, sys, yaml
out = []
for text in json.load(sys.stdin):
    try:
        out.append(["ok", repr(yaml.safe_load(text))])
    except Exception as e:
        out.append(["error", str(e)])
json.dump(out, sys.stdout)
"""


def _random_yaml(pick: random.Random, depth: int = 0) -> str:
    scalars = ["1", "-2", "0.5", "1e5", "1.0e+5", ".inf", "yes", "y", "No", "~", "null", "010"]
    scalars += ["0x1F", "1:30", "'q'", '"d\\n"', "a b", "x:5", "a: b", "2001-12-14", "", "now"]
    scalars += ["auto", "{", "]", "-", "#c", "'", "&a", "*a", "!!str 1", "<<", "=", "0b11"]
    roll = pick.random()
    if depth > 2 or roll < 0.5:
        return pick.choice(scalars)
    items = [_random_yaml(pick, depth + 1) for _ in range(pick.randint(0, 3))]
    if roll < 0.75:
        return "[" + ", ".join(items) + "]"
    keys = pick.sample(["x", "y", "data", "linear", "a:b", "stamp", "x"], len(items))
    return "{" + ", ".join(f"{k}: {v}" for k, v in zip(keys, items, strict=True)) + "}"


@needs_ros1
def test_yaml_loading_matches_pyyaml_safe_load() -> None:
    pick = random.Random(11)
    texts = [_random_yaml(pick) for _ in range(3000)]
    texts += ["a:\n  - 1\n  - {b: [2, 3]}\n", "- a\n- b: c\n", "? x\n: y", "a: |\n  t\n"]
    done = subprocess.run(
        [ROS1_PYTHON, "-c", _PYYAML],
        input=json.dumps(texts),
        capture_output=True,
        text=True,
        timeout=120,
        check=True,
    )
    theirs = json.loads(done.stdout)
    mismatches = []
    for text, reference in zip(texts, theirs, strict=True):
        try:
            mine = ["ok", repr(load(text))]
        except YAMLLoadError as error:
            mine = ["error", str(error)]
        if mine != reference:
            mismatches.append(f"{text!r}: {mine} != {reference}")
    assert not mismatches, f"{len(mismatches)} differ:\n" + "\n".join(mismatches[:10])
