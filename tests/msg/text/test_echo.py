"""The echo text, CSV form, field paths and YAML strings of rosx.msg, against ROS 1's output.

Golden texts pin the format; where Debian's ROS 1 is installed (``/usr/bin/python3`` with genpy
and rostopic), every known message type is also filled deterministically, sent through the
wire format to genpy, and printed by rostopic's own echo callback for comparison.
"""

from __future__ import annotations

import io
import json
import math
import random
import struct
import subprocess
from typing import Any

import pytest

from rosx.msg.codec.classes import get_message_class
from rosx.msg.codec.rostime import Duration, Time
from rosx.msg.spec import PRIMITIVE_TYPES
from rosx.msg.store import default_store
from rosx.msg.text.echo import (
    CLEAR_SCREEN,
    SEPARATOR,
    echo_record,
    format_message,
    format_value,
)
from rosx.msg.text.echocsv import csv_header, csv_row
from rosx.msg.text.fieldpath import FieldPathError, field_type, parse_field_path
from rosx.msg.text.yamlstr import quoted, string_list
from tests.support.ros1 import ROS1_PYTHON, ros1_python_imports


def ros1_available() -> bool:
    return ros1_python_imports("genpy", "genpy.dynamic", "rostopic", "yaml")


needs_ros1 = pytest.mark.skipif(not ros1_available(), reason="ROS 1 (genpy, rostopic) not found")


def msg(type_name: str, *args: Any, **kwds: Any) -> Any:
    return get_message_class(type_name)(*args, **kwds)


def wire(value: Any) -> Any:
    """``value`` as a subscriber receives it: serialised and read back."""
    buff = io.BytesIO()
    value.serialize(buff)
    return type(value)().deserialize(buff.getvalue())


# -- golden text -----------------------------------------------------------------------------


def test_twist_nests_with_a_trailing_space_after_the_key() -> None:
    twist = msg("geometry_msgs/Twist")
    twist.linear.x = 2.0
    twist.angular.z = -1.8
    assert format_message(twist) == (
        "linear: \n  x: 2.0\n  y: 0.0\n  z: 0.0\nangular: \n  x: 0.0\n  y: 0.0\n  z: -1.8"
    )
    assert str(twist) == format_message(twist)


def test_float32_values_show_their_float64_expansion() -> None:
    pose = msg("turtlesim/Pose")
    pose.deserialize(struct.pack("<5f", 5.544444561004639, 0.1, -1.5707963, 0.0, 1e-05))
    assert format_message(pose) == (
        "x: 5.544444561004639\n"
        "y: 0.10000000149011612\n"
        "theta: -1.570796251296997\n"
        "linear_velocity: 0.0\n"
        "angular_velocity: 9.999999747378752e-06"
    )


@pytest.mark.parametrize(
    ("value", "text"),
    [
        (1e-05, "1e-05"),
        (0.1, "0.1"),
        (-0.0, "-0.0"),
        (1e16, "1e+16"),
        (123456789.0, "123456789.0"),
        (math.inf, "inf"),
        (-math.inf, "-inf"),
        (math.nan, "nan"),
        (2, "2"),
    ],
)
def test_floats_print_as_python_does(value: float, text: str) -> None:
    assert format_message(msg("std_msgs/Float64", value)) == f"data: {text}"


def test_header_time_and_string_fields() -> None:
    header = msg("std_msgs/Header", seq=7, stamp=Time(1700000000, 5000), frame_id="map")
    assert format_message(header) == (
        'seq: 7\nstamp: \n  secs: 1700000000\n  nsecs:      5000\nframe_id: "map"'
    )
    empty = format_message(msg("std_msgs/Header"))
    assert empty == "seq: 0\nstamp: \n  secs: 0\n  nsecs:         0\nframe_id: ''"


def test_bool_and_duration() -> None:
    assert format_message(msg("std_msgs/Bool", True)) == "data: True"
    assert format_message(msg("std_msgs/Duration", Duration(-2, 5))) == (
        "data: \n  secs: -2\n  nsecs:         5"
    )


@pytest.mark.parametrize(
    ("text", "shown"),
    [
        ("turtle2", '"turtle2"'),
        ("", "''"),
        ("a: b", '"a: b"'),
        ("yes", '"yes"'),
        ('say "hi"\\', r'"say \"hi\"\\"'),
        ("line1\nline2\ttab", r'"line1\nline2\ttab"'),
        ("héllo €😀", r'"h\xE9llo \u20AC\U0001F600"'),
        ("\x00\x07\x1b\x7f", r'"\0\a\e\x7F"'),
        (
            "word " * 20,
            '"word word word word word word word word word word word word word word word'
            ' word word\\\n  \\ word word word "',
        ),
        ("x" * 90, '"' + "x" * 90 + '"'),
    ],
)
def test_strings_are_double_quoted_yaml(text: str, shown: str) -> None:
    assert format_message(msg("std_msgs/String", text)) == f"data: {shown}"


def test_uint8_arrays_show_numbers_and_char_arrays_bytes() -> None:
    image = msg("sensor_msgs/Image", height=1, data=b"\x01\x02\xff")
    assert "\ndata: [1, 2, 255]" in format_message(image)
    assert format_message(msg("std_msgs/UInt8MultiArray", data=b"")).endswith("data: []")
    assert format_message(msg("std_msgs/UInt8MultiArray", data=[4, 5])).endswith("data: [4, 5]")
    sound = msg("turtlesim/Color", 1, 2, 3)
    assert format_message(sound) == "r: 1\ng: 2\nb: 3"


JOINT_STATE = "\n".join(
    [
        "header: ",
        "  seq: 3",
        "  stamp: ",
        "    secs: 10",
        "    nsecs:  20000000",
        "  frame_id: ''",
        "name: ",
        "  - shoulder",
        "  - 'yes'",
        "  - ''",
        '  - "tab\\there"',
        "position: [0.5, -1.25]",
        "velocity: []",
        "effort: [0.0]",
    ]
)


def test_string_arrays_are_yaml_block_lists() -> None:
    state = msg(
        "sensor_msgs/JointState",
        name=["shoulder", "yes", "", "tab\there"],
        position=[0.5, -1.25],
        effort=(0.0,),
    )
    state.header.seq = 3
    state.header.stamp = Time(10, 20000000)
    assert format_message(state) == JOINT_STATE
    assert format_message(wire(state)) == JOINT_STATE


DIAGNOSTICS = "\n".join(
    [
        "header: ",
        "  seq: 0",
        "  stamp: ",
        "    secs: 0",
        "    nsecs:         0",
        "  frame_id: ''",
        "status: ",
        "  - ",
        "    level: 1",
        '    name: "motor: left"',
        '    message: "hot"',
        "    hardware_id: ''",
        "    values: ",
        "      - ",
        '        key: "temp"',
        '        value: "71.5"',
        "      - ",
        '        key: "unit"',
        '        value: "C"',
        "  - ",
        "    level: 0",
        "    name: ''",
        "    message: ''",
        "    hardware_id: ''",
        "    values: []",
    ]
)


def test_arrays_of_messages_are_dash_items_with_nested_fields() -> None:
    key_value = get_message_class("diagnostic_msgs/KeyValue")
    status = msg(
        "diagnostic_msgs/DiagnosticStatus",
        level=1,
        name="motor: left",
        message="hot",
        values=[key_value("temp", "71.5"), key_value("unit", "C")],
    )
    array = msg(
        "diagnostic_msgs/DiagnosticArray",
        status=[status, msg("diagnostic_msgs/DiagnosticStatus")],
    )
    assert format_message(array) == DIAGNOSTICS


def test_nested_arrays_in_marker_array() -> None:
    point = get_message_class("geometry_msgs/Point")
    marker = msg("visualization_msgs/Marker", ns="a", points=[point(1.0, 2.0, 3.0)])
    text = format_message(msg("visualization_msgs/MarkerArray", markers=[marker]))
    assert text.startswith("markers: \n  - \n    header: \n      seq: 0\n")
    assert '\n    ns: "a"\n' in text
    assert "\n    points: \n      - \n        x: 1.0\n        y: 2.0\n        z: 3.0\n" in text
    assert "\n    colors: []\n" in text
    assert text.endswith("\n    mesh_use_embedded_materials: False")
    assert format_message(msg("visualization_msgs/MarkerArray")) == "markers: []"


def test_fixed_arrays_and_empty_messages() -> None:
    info = msg("sensor_msgs/CameraInfo")
    text = format_message(info)
    assert "\nK: [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]\n" in text
    assert "\nroi: \n  x_offset: 0\n" in text
    assert format_message(msg("std_msgs/Empty")) == ""
    assert echo_record(format_message(msg("std_msgs/Empty"))) == "\n---\n"


def test_noarr_and_nostr_replace_fields_but_not_inside_message_arrays() -> None:
    state = msg("sensor_msgs/JointState", name=["a", "b"], position=[1.0])
    state.header.frame_id = "base"
    assert format_message(state, noarr=True, nostr=True) == (
        "header: \n  seq: 0\n  stamp: \n    secs: 0\n    nsecs:         0\n"
        '  frame_id: "<string length: 4>"\n'
        'name: "<array type: string, length: 2>"\n'
        'position: "<array type: float64, length: 1>"\n'
        'velocity: "<array type: float64, length: 0>"\n'
        'effort: "<array type: float64, length: 0>"'
    )
    assert 'name: "<array type: string, length: 2>"' in format_message(state, nostr=True)
    assert "position: [1.0]" in format_message(state, nostr=True)
    info = msg("sensor_msgs/CameraInfo")
    # rostopic strips "[]" characters from the right only.
    assert 'K: "<array type: float64[9, length: 9>"' in format_message(info, noarr=True)
    key_value = get_message_class("diagnostic_msgs/KeyValue")
    status = msg("diagnostic_msgs/DiagnosticStatus", values=[key_value("k", "v")])
    array = msg("diagnostic_msgs/DiagnosticArray", status=[status])
    assert '        key: "k"' in format_message(array, nostr=True)


def test_fixed_numeric_width_and_time_offset() -> None:
    point = msg("geometry_msgs/Point", 1.23456, -2.0, 100000.5)
    assert format_message(point, fixed_numeric_width=4) == "x: 1.23\ny: -2.0\nz: 100000"
    header = msg("std_msgs/Header", seq=5, stamp=Time(100, 5))
    assert format_message(header, fixed_numeric_width=3) == (
        "seq:   5\nstamp: \n  secs: 100\n  nsecs:   5\nframe_id: ''"
    )
    joints = msg("sensor_msgs/JointState", position=[1.5, 2.25])
    assert "position: [1.50, 2.25]" in format_message(joints, fixed_numeric_width=4)
    offset = format_message(header, time_offset=Time(101, 0))
    assert "stamp: \n  secs: -1\n  nsecs:         5" in offset


def test_field_values() -> None:
    stamp = Time(3, 4)
    assert format_value(stamp, "time") == "\nsecs: 3\nnsecs:         4"
    assert format_value(2.5, "float64") == "2.5"
    assert format_value("x", "string", nostr=True) == '"<string length: 1>"'
    assert format_value(b"\x07\x08", "uint8[]") == "[7, 8]"
    assert format_value(b"\x07\x08", "uint8[]", noarr=True) == ('"<array type: uint8, length: 2>"')
    point = get_message_class("geometry_msgs/Point")
    assert format_value([point(), point(x=1.0)], "geometry_msgs/Point[]") == (
        "\n- \n  x: 0.0\n  y: 0.0\n  z: 0.0\n- \n  x: 1.0\n  y: 0.0\n  z: 0.0"
    )
    assert format_value(["a b", "c"], "string[]") == "\n- a b\n- c"


def test_echo_record() -> None:
    assert SEPARATOR == "---"
    assert echo_record("data: 1") == "data: 1\n---\n"
    assert echo_record("data: 1", clear=True) == CLEAR_SCREEN + "data: 1\n---\n"
    assert CLEAR_SCREEN == "\x1b[2J\x1b[;H"


# -- CSV -------------------------------------------------------------------------------------


def test_csv_header_and_rows() -> None:
    twist = msg("geometry_msgs/Twist")
    twist.linear.x = 0.5
    assert csv_header(twist) == (
        "%time,field.linear.x,field.linear.y,field.linear.z,"
        "field.angular.x,field.angular.y,field.angular.z"
    )
    assert csv_row(twist, Time(5, 6)) == "5000000006,0.5,0.0,0.0,0.0,0.0,0.0"
    assert csv_row(twist, Time(5, 6), time_offset=Time(5, 0)) == "6,0.5,0.0,0.0,0.0,0.0,0.0"


def test_csv_uses_header_stamps_expands_arrays_and_skips_bytes() -> None:
    state = msg("sensor_msgs/JointState", name=["a", "b,c"], position=[1.0, 2.0], effort=[True])
    state.header.stamp = Time(7, 8)
    state.header.frame_id = "f"
    assert csv_header(state) == (
        "%time,field.header.seq,field.header.stamp,field.header.frame_id,"
        "field.name0,field.name1,field.position0,field.position1,field.effort0"
    )
    assert csv_row(state, Time(1, 0)) == "7000000008,0,7000000008,f,a,b,c,1.0,2.0,1"
    assert csv_row(state, Time(1, 0), bag_time=Time(2, 0)).startswith("2000000000,")
    assert csv_header(state, noarr=True, nostr=True) == (
        "%time,field.header.seq,field.header.stamp"
    )
    image = msg("sensor_msgs/Image", data=b"\x01")
    assert "field.data" not in csv_header(image)
    assert csv_header(msg("std_msgs/Empty")) == "%time,"
    assert csv_row(msg("std_msgs/Empty"), Time(1, 0)) == "1000000000,"
    assert csv_header(msg("std_msgs/Bool", True)) == "%time,field.data"
    assert csv_row(msg("std_msgs/Bool", True), Time(1, 0)) == "1000000000,1"


def test_csv_nested_message_arrays() -> None:
    point = get_message_class("geometry_msgs/Point")
    polygon = msg("geometry_msgs/Polygon", points=[point(1.0, 2.0, 3.0), point()])
    header = "%time," + ",".join(f"field.points{i}.{a}" for i in range(2) for a in "xyz")
    assert csv_header(polygon) == header
    assert csv_row(polygon, Time(0, 1)) == "1,1.0,2.0,3.0,0.0,0.0,0.0"
    assert csv_header(2.5) == "%time,field"


# -- field paths ----------------------------------------------------------------------------


def test_field_paths_select_and_slice() -> None:
    point = get_message_class("geometry_msgs/Point32")
    polygon = msg("geometry_msgs/Polygon", points=[point(x=1.0), point(x=2.0), point(x=3.0)])
    assert parse_field_path("/points[1]/x").evaluate(polygon) == 2.0
    assert parse_field_path("/points[0:2]/x").evaluate(polygon) == [1.0, 2.0]
    assert parse_field_path("/points[::-1]/x").evaluate(polygon) == [3.0, 2.0, 1.0]
    assert parse_field_path("").evaluate(polygon) is polygon
    store = default_store()
    path = parse_field_path("/points[1]/x")
    assert field_type(store.msg, "geometry_msgs/Polygon", path) == "float32"
    assert field_type(store.msg, "geometry_msgs/Polygon", parse_field_path("/points[0]")) == (
        "geometry_msgs/Point32[]"
    )
    stamp = parse_field_path("/header/stamp/nsecs")
    assert field_type(store.msg, "geometry_msgs/PolygonStamped", stamp) == "int32"


@pytest.mark.parametrize(
    ("path", "error"),
    [
        ("/points[1", "missing closing ']' in slice spec 'points[1'"),
        ("/points[]", "'': empty array index"),
        ("/points[a]", "'a': non-integer array index step 'a'"),
        ("/points[1:b]", "'1:b': non-integer slice stop 'b'"),
        ("/points[c:]", "'c:': non-integer slice start 'c'"),
        ("/points[::d]", "'::d': non-integer slice step 'd'"),
        ("/points[1:2:3:4]", "'1:2:3:4': too many slice arguments"),
    ],
)
def test_field_path_syntax_errors(path: str, error: str) -> None:
    with pytest.raises(FieldPathError) as caught:
        parse_field_path(path)
    if not error.startswith("missing"):
        error = "field 'points' has invalid slice argument " + error
    assert str(caught.value) == error


def test_field_path_evaluation_errors() -> None:
    polygon = msg("geometry_msgs/Polygon", points=[])
    with pytest.raises(FieldPathError, match=r"^no field named nope in /nope$"):
        parse_field_path("/nope").evaluate(polygon)
    with pytest.raises(FieldPathError, match=r"^list index out of range: /points\[3\]$"):
        parse_field_path("/points[3]").evaluate(polygon)
    with pytest.raises(FieldPathError, match="no field named w"):
        field_type(default_store().msg, "geometry_msgs/Polygon", parse_field_path("/points/x/w"))


# -- YAML strings ----------------------------------------------------------------------------


def test_yaml_strings() -> None:
    assert quoted("a") == '"a"'
    assert string_list(["a", "1.5", "~", "- x", "a #b", "it's", "x\ny"]) == (
        "- a\n- '1.5'\n- '~'\n- '- x'\n- 'a #b'\n- it's\n- 'x\n\n  y'"
    )
    long_words = ("word " * 20).strip()
    assert string_list([long_words]) == (
        "- word word word word word word word word word word word word word word word word\n"
        "  word word word word"
    )


# -- ROS 1 cross-checks ----------------------------------------------------------------------

_ORACLE = r"""
import io, json, sys
import genpy, genpy.dynamic, genpy.message, rospy, rostopic

registry = {}
original = genpy.message.get_message_class
def get_message_class(name, reload_on_error=False):
    return registry.get(name) or original(name, reload_on_error)
genpy.message.get_message_class = get_message_class
NOW = genpy.Time(1700000000, 500)
rospy.get_rostime = lambda: NOW

def echo(data, topic, field_type=None, **options):
    options.setdefault("offset_time", False)
    plot = options.pop("plot", False)
    nostr = options.pop("nostr", False)
    noarr = options.pop("noarr", False)
    if plot:
        options["field_filter_fn"] = rostopic.create_field_filter(nostr, noarr)
    else:
        options["value_transform_fn"] = rostopic.create_value_transform(nostr, noarr)
    bag_time = options.pop("bag_time", None)
    callback = rostopic.CallbackEcho(topic, None, plot=plot, **options)
    out, sys.stdout = sys.stdout, io.StringIO()
    try:
        current = genpy.Time(*bag_time) if bag_time else None
        callback.callback(data, {"topic": "/t", "type_information": field_type}, current)
        return sys.stdout.getvalue()
    finally:
        sys.stdout = out

results = []
for job in json.load(sys.stdin):
    if job["type"] not in registry:
        registry.update(genpy.dynamic.generate_dynamic(job["type"], job["full_text"]))
    data = registry[job["type"]]().deserialize(bytes.fromhex(job["data"]))
    outputs = []
    for path, ftype, options in job["echoes"]:
        outputs.append(echo(data, "/t" + path, ftype, **options))
    results.append(outputs)
json.dump(results, sys.stdout)
"""

_STRINGS = [
    "",
    "turtle1",
    "a:b",
    "key: value",
    "yes",
    "123",
    "~",
    "héllo wörld",
    "line1\nline2",
    "tab\there",
    "quote\"and'apos",
    "back\\slash",
    " leading",
    "trailing ",
    "- dash",
    "#hash",
    "It is a long sentence with many words that will need folding past eighty columns.",
    "x" * 100,
    "a" * 70 + " " + "b" * 30,
]
_FLOATS = [0.1, 1e-05, -0.0, 1e100, 123456789.125, -2.5, math.inf, -math.inf, math.nan, 3.0]


class Filler:
    """Deterministic, non-default values for every field of a message type."""

    def __init__(self, seed: str) -> None:
        self.random = random.Random(seed)
        self.count = 0

    def message(self, type_name: str) -> Any:
        value = get_message_class(type_name)()
        for field in default_store().msg(type_name).fields:
            name = value.__slots__[default_store().msg(type_name).fields.index(field)]
            if field.is_array:
                size = field.array_len
                size = self.random.randint(0, 3) if size is None else size
                if field.base_type in ("uint8", "char"):
                    setattr(value, name, bytes(self.random.randrange(256) for _ in range(size)))
                else:
                    setattr(value, name, [self.scalar(field.base_type) for _ in range(size)])
            else:
                setattr(value, name, self.scalar(field.base_type))
        return value

    def scalar(self, base: str) -> Any:
        self.count += 1
        pick = self.random
        if base not in PRIMITIVE_TYPES:
            return self.message(base)
        if base == "bool":
            return self.count % 2 == 0
        if base == "string":
            return pick.choice(_STRINGS)
        if base.startswith("float"):
            value = pick.choice(_FLOATS)
            return 1e30 if base == "float32" and value == 1e100 else value
        if base == "time":
            return Time(pick.randrange(2**31), pick.choice([0, 1, 999999999, 123456]))
        if base == "duration":
            return Duration(pick.randrange(-(2**31), 2**31), pick.choice([0, 5, 999999999]))
        bits = {"int8": 8, "byte": 8, "uint8": 8, "char": 8, "int16": 16, "uint16": 16}
        width = bits.get(base, 32 if base.endswith("32") else 64)
        if base.startswith("uint") or base == "char":
            return pick.randrange(2**width)
        return pick.randrange(-(2 ** (width - 1)), 2 ** (width - 1))


def _paths(type_name: str, value: Any) -> list[tuple[str, str | None]]:
    """Field paths worth echoing: every field, first elements, slices, one nested level."""
    spec = default_store().msg(type_name)
    paths: list[tuple[str, str | None]] = []
    for field, name in zip(spec.fields, value.__slots__, strict=True):
        if field.is_array and field.base_type in ("uint8", "char"):
            continue  # rostopic itself fails on these (ord() of an int)
        paths.append((f"/{name}", field.type))
        if field.is_array:
            paths.append((f"/{name}[0]", field.type))
            paths.append((f"/{name}[0:2]", field.type))
        if not field.is_builtin and not field.is_array:
            inner = default_store().msg(field.base_type)
            for sub in inner.fields:
                if not (sub.is_array and sub.base_type in ("uint8", "char")):
                    paths.append((f"/{name}/{sub.name}", sub.type))
    return paths


def _our_echo(
    value: Any, type_name: str, path: str, ftype: str | None, options: dict[str, Any]
) -> str:
    plot = options.get("plot", False)
    noarr, nostr = options.get("noarr", False), options.get("nostr", False)
    parsed = parse_field_path(path)
    try:
        data = parsed.evaluate(value)
    except FieldPathError:
        return ""
    if data is None:
        return ""
    if plot:
        bag = options.get("bag_time")
        row = csv_row(
            data,
            Time(1700000000, 500),
            bag_time=Time(*bag) if bag else None,
            time_offset=Time(1700000000, 500) if options.get("offset_time") else None,
            noarr=noarr,
            nostr=nostr,
        )
        return csv_header(data, noarr=noarr, nostr=nostr) + "\n" + row + "\n"
    declared = field_type(default_store().msg, type_name, parsed) if path else None
    offset = Time(1700000000, 500) if options.get("offset_time") else None
    kwargs: dict[str, Any] = {
        "noarr": noarr,
        "nostr": nostr,
        "fixed_numeric_width": options.get("fixed_numeric_width"),
        "time_offset": offset,
    }
    text = format_value(data, declared, **kwargs) if path else format_message(data, **kwargs)
    return echo_record(text)


_WHOLE_MESSAGE_OPTIONS: list[dict[str, Any]] = [
    {},
    {"noarr": True},
    {"nostr": True},
    {"noarr": True, "nostr": True},
    {"fixed_numeric_width": 4},
    {"offset_time": True},
    {"plot": True},
    {"plot": True, "bag_time": [12, 34]},
    {"plot": True, "noarr": True, "nostr": True},
    {"plot": True, "offset_time": True},
]
_FIELD_OPTIONS: list[dict[str, Any]] = [
    {},
    {"nostr": True},
    {"fixed_numeric_width": 3},
    {"plot": True, "bag_time": [1, 2]},
]


def _all_types() -> list[str]:
    store = default_store()
    names = store.types("msg")
    for service in store.types("srv"):
        names += [f"{service}Request", f"{service}Response"]
    return names


@needs_ros1
def test_every_message_type_echoes_as_rostopic_does() -> None:
    store = default_store()
    jobs, ours = [], []
    for type_name in _all_types():
        for round_ in range(2):
            value = wire(Filler(f"{type_name}/{round_}").message(type_name))
            buff = io.BytesIO()
            value.serialize(buff)
            echoes: list[tuple[str, str | None, dict[str, Any]]] = [
                ("", None, options) for options in _WHOLE_MESSAGE_OPTIONS
            ]
            for path, ftype in _paths(type_name, value) if round_ == 0 else []:
                echoes += [(path, ftype, options) for options in _FIELD_OPTIONS]
                # rostopic fails (len() of a number or message) on --noarr of one element.
                if "[0]" not in path or ftype == "string[]":
                    echoes.append((path, ftype, {"noarr": True}))
            jobs.append(
                {
                    "type": type_name,
                    "full_text": store.full_text(type_name),
                    "data": buff.getvalue().hex(),
                    "echoes": echoes,
                }
            )
            ours.append([_our_echo(value, type_name, p, t, o) for p, t, o in echoes])
    done = subprocess.run(
        [ROS1_PYTHON, "-c", _ORACLE],
        input=json.dumps(jobs),
        capture_output=True,
        text=True,
        timeout=600,
        check=True,
    )
    theirs = json.loads(done.stdout)
    mismatches = []
    for job, mine, reference in zip(jobs, ours, theirs, strict=True):
        for echo, a, b in zip(job["echoes"], mine, reference, strict=True):
            if a != b:
                mismatches.append(f"{job['type']} {echo}:\n{a!r}\n!=\n{b!r}")
    assert not mismatches, f"{len(mismatches)} differ; first:\n" + "\n\n".join(mismatches[:5])
    assert len(jobs) > 300


_PYYAML = r"""
import json, sys, yaml
cases = json.load(sys.stdin)
quoted = [yaml.dump(c, default_style='"').rstrip('\n') for c in cases]
lists = [yaml.dump(cases[i:i + 3]).rstrip('\n') for i in range(0, len(cases), 3)]
json.dump([quoted, lists], sys.stdout)
"""


@needs_ros1
def test_yaml_strings_match_pyyaml() -> None:
    pick = random.Random(7)
    pieces = [*"ab xyz:-#'\"\\,[]{}&*!|>%@`?~=<.0123456789eE+_\n\t\r", "é", "\x85", "\u2028"]
    pieces += ["\x00", "\x7f", "\U0001f600", "yes", "null", "1.5", "0x1F", "   ", "---", "..."]
    pieces += ["word ", "longword" * 3, "\ufeff", "\xa0"]
    cases = [
        "".join(pick.choice(pieces) for _ in range(pick.choice([0, 1, 2, 3, 8, 30, 70, 150])))
        for _ in range(3000)
    ]
    done = subprocess.run(
        [ROS1_PYTHON, "-c", _PYYAML],
        input=json.dumps(cases),
        capture_output=True,
        text=True,
        timeout=120,
        check=True,
    )
    want_quoted, want_lists = json.loads(done.stdout)
    assert [quoted(c) for c in cases] == want_quoted
    chunks = [cases[i : i + 3] for i in range(0, len(cases), 3)]
    assert [string_list(c) for c in chunks] == want_lists
