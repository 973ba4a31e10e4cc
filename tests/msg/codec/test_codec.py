"""Tests for the ROS 1 wire codec of generated classes (rosx.msg.codec.serializer/deserializer).

Golden bytes are written out by hand from the wire format (little-endian, no padding, uint32
counts). Every standard type round-trips from its defaults. The last section serialises the
same populated messages with genpy (Debian's /usr/bin/python3, in a subprocess) and compares
bytes and class attributes; it is skipped where genpy is absent.
"""

from __future__ import annotations

import io
import json
import logging
import random
import subprocess
from pathlib import Path
from typing import Any

import pytest

from rosx.msg.codec.classes import get_message_class
from rosx.msg.codec.message import DeserializationError, Message, SerializationError
from rosx.msg.codec.rostime import Duration, Time
from rosx.msg.codec.wiretypes import INTEGER_RANGES
from rosx.msg.store import TypeStore, default_store
from tests.support.msgpackages import EVERY_KIND, make_package

ROS1_PYTHON = Path("/usr/bin/python3")


def ser(msg: Message) -> bytes:
    buff = io.BytesIO()
    msg.serialize(buff)
    return buff.getvalue()


def cls(name: str, store: TypeStore | None = None) -> Any:
    return get_message_class(name, store)


@pytest.fixture
def store(tmp_path: Path) -> TypeStore:
    make_package(
        tmp_path,
        "x",
        {
            "All": EVERY_KIND,
            "Sub": "int32 a\ntime t\n",
            "Fixed": "float64[9] k\nuint8[3] rgb\nstring[2] names\n",
            "Times": "time t\nduration d\nstd_msgs/Header h\n",
            "Packed": "bool b\nchar c\nuint8[3] rgb\nfloat32[2] f\ntime t\nduration d\nSub sub\n",
        },
    )
    return TypeStore([tmp_path])


# -- golden bytes ---------------------------------------------------------------------------


def test_twist_bytes() -> None:
    twist = cls("geometry_msgs/Twist")()
    twist.linear.x, twist.linear.y, twist.linear.z = 1.0, 2.0, 3.0
    twist.angular.z = -0.5
    expected = bytes.fromhex(
        "000000000000f03f" "0000000000000040" "0000000000000840"
        "0000000000000000" "0000000000000000" "000000000000e0bf"
    )  # fmt: skip
    assert ser(twist) == expected
    assert cls("geometry_msgs/Twist")().deserialize(expected) == twist


def test_header_bytes() -> None:
    header = cls("std_msgs/Header")(seq=1, stamp=Time(2, 3), frame_id="map")
    expected = bytes.fromhex("01000000020000000300000003000000") + b"map"
    assert ser(header) == expected
    assert cls("std_msgs/Header")().deserialize(expected) == header


def test_utf8_string_bytes() -> None:
    text = cls("std_msgs/String")(data="é✓")
    expected = bytes.fromhex("05000000c3a9e29c93")
    assert ser(text) == expected
    assert cls("std_msgs/String")().deserialize(expected).data == "é✓"


def test_uint8_array_bytes_from_bytes_list_and_tuple() -> None:
    array = cls("std_msgs/UInt8MultiArray")
    expected = bytes.fromhex("000000000000000003000000010203")
    assert ser(array(data=b"\x01\x02\x03")) == expected
    assert ser(array(data=[1, 2, 3])) == expected
    assert ser(array(data=(1, 2, 3))) == expected
    assert ser(array(data=bytearray(b"\x01\x02\x03"))) == expected
    assert array().deserialize(expected).data == b"\x01\x02\x03"


def test_fixed_arrays_have_no_count(store: TypeStore) -> None:
    fixed = cls("x/Fixed", store)(k=[float(i) for i in range(9)], rgb=[1, 2, 255], names=["a", ""])
    expected = (
        b"".join(_f64(float(i)) for i in range(9))
        + bytes.fromhex("0102ff")
        + bytes.fromhex("01000000") + b"a"
        + bytes.fromhex("00000000")
    )  # fmt: skip
    assert ser(fixed) == expected
    back = cls("x/Fixed", store)().deserialize(expected)
    assert back.k == tuple(float(i) for i in range(9)) and back.rgb == b"\x01\x02\xff"
    assert back.names == ["a", ""]


def test_array_of_nested_messages() -> None:
    polygon = cls("geometry_msgs/Polygon")()
    point = cls("geometry_msgs/Point32")
    polygon.points = [point(1.0, 2.0, 3.0), point(0.5, 0.0, -1.0)]
    expected = bytes.fromhex("020000000000803f00000040000040400000003f00000000000080bf")
    assert ser(polygon) == expected
    assert cls("geometry_msgs/Polygon")().deserialize(expected) == polygon


def test_turtle_pose_bytes() -> None:
    pose = cls("turtlesim/Pose")(5.5, 5.5, 0.0, 1.0, -1.0)
    expected = bytes.fromhex("0000b0400000b040000000000000803f000080bf")
    assert ser(pose) == expected
    assert cls("turtlesim/Pose")().deserialize(expected) == pose


def test_small_types_bytes() -> None:
    assert ser(cls("std_msgs/Empty")()) == b""
    assert cls("std_msgs/Empty")().deserialize(b"") == cls("std_msgs/Empty")()
    assert ser(cls("std_msgs/Bool")(True)) == b"\x01"
    assert ser(cls("std_msgs/Bool")(2)) == b"\x02"  # genpy packs the int as given
    assert cls("std_msgs/Bool")().deserialize(b"\x02").data is True
    assert ser(cls("std_msgs/Duration")(Duration(-1, 5))) == bytes.fromhex("ffffffff05000000")
    assert ser(cls("std_msgs/Time")(Time(1, 2))) == bytes.fromhex("0100000002000000")
    assert ser(cls("std_msgs/Char")(65)) == b"A"
    assert ser(cls("std_msgs/Int64")(-2)) == bytes.fromhex("feffffffffffffff")


def test_only_a_messages_own_times_are_canonicalised(store: TypeStore) -> None:
    # time (1, 10**9 + 1), duration (0, -1), then a Header whose stamp is (1, 10**9 + 1)
    overflow = bytes.fromhex("0100000001ca9a3b")
    data = overflow + bytes.fromhex("00000000ffffffff") + bytes.fromhex("07000000") + overflow
    times = cls("x/Times", store)().deserialize(data + bytes.fromhex("00000000"))
    assert (times.t.secs, times.t.nsecs) == (2, 1)
    assert (times.d.secs, times.d.nsecs) == (-1, 999_999_999)
    assert (times.h.stamp.secs, times.h.stamp.nsecs) == (1, 1_000_000_001)  # nested: as sent
    header = cls("std_msgs/Header")().deserialize(data[16:] + bytes.fromhex("00000000"))
    assert (header.stamp.secs, header.stamp.nsecs) == (2, 1)


def test_deserialize_fills_nested_values_in_place_as_genpy() -> None:
    from rosx.msg.codec.codegen import variant

    odometry = cls("nav_msgs/Odometry")
    sent = populate(odometry, random.Random(3))
    data = ser(sent)
    target = odometry()
    header, position = target.header, target.pose.pose.position
    assert target.deserialize(data) is target and target == sent
    assert target.header is header and target.pose.pose.position is position
    target.pose.pose = None  # a field that is not a message is replaced
    assert target.deserialize(data) == sent
    bare = object.__new__(odometry)  # never initialised: every value is new
    assert bare.deserialize(data) == sent
    fresh = odometry()
    kept = fresh.header
    assert variant(odometry, "deserialize_fresh")(fresh, data) == sent and fresh.header is not kept


def test_every_kind_round_trips(store: TypeStore) -> None:
    every = cls("x/All", store)
    msg = every()
    msg.b, msg.bs, msg.bf = True, [True, False], [False, True, True]
    msg.c, msg.cs, msg.cf = 7, b"xy", b"abcd"
    msg.u8, msg.u8f, msg.i8, msg.by = b"\x00\xff", bytes(range(5)), [-128, 127], -1
    msg.f, msg.f9 = 0.25, [float(i) / 4 for i in range(9)]
    msg.s, msg.ss, msg.sf = "ß", ["", "a"], ["b", "c"]
    msg.t, msg.ts, msg.d = Time(4, 5), [Time(1), Time(2)], Duration(-3, 7)
    msg.df = [Duration(1), Duration(-1)]
    sub = cls("x/Sub", store)
    msg.sub, msg.subs, msg.subf = sub(1, Time(2)), [sub(3, Time(4))], [sub(), sub(-1, Time(9))]
    msg.h.seq, msg.h.frame_id, msg.u64 = 9, "base", 2**64 - 1
    data = ser(msg)
    back = every().deserialize(data)
    assert back == msg and ser(back) == data
    # From any bytes-like buffer, without copying it first.
    assert every().deserialize(memoryview(data)) == msg
    assert every().deserialize(bytearray(data) + b"trailing") == msg


def frame(msg: Message) -> bytes:
    """What a publisher sends: the serialized size (uint32), then the bytes."""
    data = ser(msg)
    return len(data).to_bytes(4, "little") + data


def test_a_fixed_size_type_makes_its_frame_in_one_pack(store: TypeStore) -> None:
    packed = cls("x/Packed", store)
    assert "_frame" in vars(packed)  # generated, not Message's
    msg = packed(b=True, c=7, rgb=b"\x01\x02\x03", f=[0.5, -2.0], t=Time(4, 5), d=Duration(-3, 7))
    msg.sub.a, msg.sub.t = -9, Time(1, 2)
    assert msg._frame() == frame(msg)
    assert packed()._frame() == frame(packed())
    assert "_frame" not in vars(cls("x/Fixed", store))  # strings: Message's
    # uint8[N] given as a list, or as bytes of another length, is packed as `serialize` packs it
    for rgb in ([1, 2, 3], b"\x01", b"\x01\x02\x03\x04"):
        msg.rgb = rgb
        assert msg._frame() == frame(msg)


def test_frame_errors_name_the_field_as_serialize_does(store: TypeStore) -> None:
    twist = cls("geometry_msgs/Twist")()
    twist.angular.z = "a"
    with pytest.raises(SerializationError, match=r"^field angular\.z must be float type$"):
        twist._frame()
    packed = cls("x/Packed", store)(f=[1.0])
    with pytest.raises(SerializationError, match=r"^field f must have 2 elements, not 1$"):
        packed._frame()


# -- every standard type --------------------------------------------------------------------


def _standard_types() -> list[str]:
    store = default_store()
    names = store.types("msg")
    for service in store.types("srv"):
        names += [service + "Request", service + "Response"]
    return names


@pytest.mark.parametrize("name", _standard_types())
def test_standard_type_round_trips_from_defaults(name: str) -> None:
    msg_class = cls(name)
    data = ser(msg_class())
    back = msg_class().deserialize(data)
    assert back == msg_class()
    assert ser(back) == data
    assert msg_class().deserialize(data + b"\0") == back
    assert msg_class()._frame() == frame(msg_class())


@pytest.mark.parametrize(
    "name", ["sensor_msgs/PointCloud2", "nav_msgs/Odometry", "std_msgs/Float32MultiArray"]
)
def test_populated_round_trip(name: str) -> None:
    msg = populate(cls(name), random.Random(name))
    data = ser(msg)
    assert ser(cls(name)().deserialize(data)) == data
    assert msg._frame() == frame(msg)


# -- errors ---------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("name", "fields", "text"),
    [
        ("std_msgs/Int8", {"data": 200}, "field data exceeds specified width [int8]"),
        ("std_msgs/UInt32", {"data": -1}, "field data must be unsigned integer type"),
        ("std_msgs/UInt16", {"data": 1 << 16}, "field data exceeds specified width [uint16]"),
        ("std_msgs/Int32", {"data": 1.0}, "field data must be an integer type"),
        ("std_msgs/Float64", {"data": "1"}, "field data must be float type"),
        ("std_msgs/Bool", {"data": 256}, "field data is not a bool"),
        ("std_msgs/String", {"data": 5}, "field data must be of type str"),
        ("std_msgs/String", {"data": b"abc"}, "field data must be a str, not bytes"),
        (
            "std_msgs/UInt8MultiArray",
            {"data": [1, 300]},
            "field data[1] exceeds specified width [uint8]",
        ),
        (
            "std_msgs/UInt8MultiArray",
            {"data": "ab"},
            "field data must be bytes or a list of ints, not str",
        ),
        ("std_msgs/UInt8MultiArray", {"data": memoryview(b"a")}, "field data must be bytes or a"),
        (
            "std_msgs/Float32MultiArray",
            {"data": "ab"},
            "field data must be a list or tuple type. Only",
        ),
        ("std_msgs/Header", {"stamp": Duration(-1)}, "field stamp must be of type Time"),
        ("std_msgs/Header", {"stamp": 5}, "field stamp must be of type Time"),
        ("std_msgs/Header", {"seq": -1}, "field seq must be unsigned integer type"),
    ],
)
def test_serialization_errors_name_the_field(name: str, fields: dict[str, Any], text: str) -> None:
    with pytest.raises(SerializationError, match="^" + _escape(text)):
        ser(cls(name)(**fields))


def test_nested_and_array_errors() -> None:
    twist = cls("geometry_msgs/Twist")()
    twist.linear.x = "a"
    with pytest.raises(SerializationError, match=r"^field linear\.x must be float type$"):
        ser(twist)
    twist = cls("geometry_msgs/Twist")(linear=5)
    with pytest.raises(
        SerializationError, match=r"field linear must be of type \[geometry_msgs/Vector3\]"
    ):
        ser(twist)
    polygon = cls("geometry_msgs/Polygon")(points=[cls("geometry_msgs/Point32")(), 5])
    with pytest.raises(
        SerializationError, match=r"^field points\[1\] must be of type \[geometry_msgs/Point32\]$"
    ):
        ser(polygon)
    # Elements are duck-typed, as by genpy: a Vector3 has what a Point32 needs.
    duck = cls("geometry_msgs/Polygon")(points=[cls("geometry_msgs/Vector3")(1.0, 2.0, 3.0)])
    assert ser(duck) == ser(
        cls("geometry_msgs/Polygon")(points=[cls("geometry_msgs/Point32")(1.0, 2.0, 3.0)])
    )
    header = cls("std_msgs/Header")(frame_id=None)
    header.frame_id = None
    with pytest.raises(SerializationError, match=r"^field frame_id must be of type str$"):
        ser(header)


def test_wrong_fixed_length_raises(store: TypeStore) -> None:
    camera = cls("sensor_msgs/CameraInfo")()
    camera.K = [0.0] * 8
    with pytest.raises(SerializationError, match=r"^field K must have 9 elements, not 8$"):
        ser(camera)
    fixed = cls("x/Fixed", store)()
    fixed.names = ["a"]
    with pytest.raises(SerializationError, match="field names must have 2 elements, not 1"):
        ser(fixed)
    fixed = cls("x/Fixed", store)(rgb=[1, 2])
    with pytest.raises(SerializationError, match="field rgb must have 3 elements, not 2"):
        ser(fixed)


def test_fixed_uint8_bytes_are_padded_or_cut_as_genpy(store: TypeStore) -> None:
    short = cls("x/Fixed", store)(rgb=b"\x01")
    assert ser(short)[72:75] == b"\x01\0\0"
    long = cls("x/Fixed", store)(rgb=b"\x01\x02\x03\x04")
    assert ser(long)[72:75] == b"\x01\x02\x03"


def test_short_data_raises_deserialization_error() -> None:
    with pytest.raises(DeserializationError, match="geometry_msgs/Twist"):
        cls("geometry_msgs/Twist")().deserialize(b"\0" * 47)
    with pytest.raises(DeserializationError):
        cls("std_msgs/String")().deserialize(b"\x05\0\0\0ab")  # genpy would return "ab"
    with pytest.raises(DeserializationError):
        cls("std_msgs/UInt8MultiArray")().deserialize(b"\0" * 8 + b"\x09\0\0\0" + b"\1")
    with pytest.raises(DeserializationError):
        cls("std_msgs/Float64MultiArray")().deserialize(b"\0" * 8 + b"\x02\0\0\0" + b"\0" * 15)


def test_invalid_utf8_is_replaced_and_logged_once(caplog: pytest.LogCaptureFixture) -> None:
    string = cls("diagnostic_msgs/KeyValue")
    data = b"\x02\0\0\0\xffA" + b"\x01\0\0\0\xfe"
    with caplog.at_level(logging.ERROR, logger="rosout"):
        first = string().deserialize(data)
        second = string().deserialize(data)
    assert (first.key, first.value) == ("\ufffdA", "\ufffd")
    assert second == first
    messages = [
        r.getMessage() for r in caplog.records if "diagnostic_msgs/KeyValue" in r.getMessage()
    ]
    assert len(messages) == 1 and messages[0].startswith(
        "Characters replaced when decoding message"
    )


# -- numpy variants -------------------------------------------------------------------------


def test_numpy_variants() -> None:
    numpy = pytest.importorskip("numpy")
    scan = cls("sensor_msgs/LaserScan")()
    scan.ranges = numpy.array([1.0, 2.5], dtype=numpy.float32)
    scan.intensities = [0.5]
    buff = io.BytesIO()
    scan.serialize_numpy(buff, numpy)
    plain = cls("sensor_msgs/LaserScan")(ranges=[1.0, 2.5], intensities=[0.5])
    assert buff.getvalue() == ser(plain)
    back = cls("sensor_msgs/LaserScan")().deserialize_numpy(buff.getvalue(), numpy)
    assert isinstance(back.ranges, numpy.ndarray) and back.ranges.dtype == numpy.float32
    assert back.ranges.tolist() == [1.0, 2.5]
    odometry = cls("nav_msgs/Odometry")()
    odometry.pose.covariance = numpy.arange(36, dtype=numpy.float64)
    buff = io.BytesIO()
    odometry.serialize_numpy(buff, numpy)
    back = cls("nav_msgs/Odometry")().deserialize_numpy(buff.getvalue(), numpy)
    assert back.pose.covariance.tolist() == list(range(36))
    assert ser(back) == buff.getvalue()


# -- against genpy --------------------------------------------------------------------------


def populate(msg_class: Any, rng: random.Random, store: TypeStore | None = None) -> Any:
    """A message of ``msg_class`` with every field set to a deterministic non-default value."""
    msg = msg_class()
    spec = msg_class._spec
    for field, attr in zip(spec.fields, msg_class.__slots__, strict=True):
        if field.is_array:
            count = field.array_len if field.array_len is not None else rng.randint(0, 3)
            if field.base_type in ("uint8", "char"):
                raw = bytes(rng.randrange(256) for _ in range(count))
                value: Any = raw if rng.random() < 0.7 else list(raw)
            else:
                value = [_scalar(field.base_type, rng, store) for _ in range(count)]
        else:
            value = _scalar(field.base_type, rng, store)
        setattr(msg, attr, value)
    return msg


def _scalar(base: str, rng: random.Random, store: TypeStore | None) -> Any:
    if base == "bool":
        return rng.random() < 0.5
    if base in INTEGER_RANGES:
        low, high = INTEGER_RANGES[base]
        return rng.choice([low, high, 0, rng.randint(low, high)])
    if base == "float32":
        return rng.randint(-4000, 4000) / 8
    if base == "float64":
        return rng.choice([rng.uniform(-1e9, 1e9), -0.0, 1e-300])
    if base == "string":
        return rng.choice(["", "map", "héllo wörld ✓", "x" * rng.randint(0, 40)])
    if base == "time":
        return Time(rng.randint(0, 2**32 - 1), rng.randint(0, 999_999_999))
    if base == "duration":
        return Duration(rng.randint(-(2**31), 2**31 - 1), rng.randint(0, 999_999_999))
    return populate(cls(base, store), rng, store)


def to_tree(value: Any) -> Any:
    if isinstance(value, Message):
        return {attr: to_tree(getattr(value, attr)) for attr in value.__slots__}
    if isinstance(value, Time):
        return {"__time__": [value.secs, value.nsecs]}
    if isinstance(value, Duration):
        return {"__duration__": [value.secs, value.nsecs]}
    if isinstance(value, bytes):
        return {"__bytes__": value.hex()}
    if isinstance(value, list | tuple):
        return [to_tree(item) for item in value]
    return value


_GENPY_SIDE = r"""
import importlib, io, json, sys
import genpy, genpy.dynamic

request = json.load(sys.stdin)
dynamic = {}
for name, text in request["dynamic"].items():
    dynamic.update(genpy.dynamic.generate_dynamic(name, text))

def class_of(name):
    if name in dynamic:
        return dynamic[name]
    package, _, short = name.partition("/")
    for kind in ("msg", "srv"):
        try:
            module = importlib.import_module(package + "." + kind)
        except ImportError:
            continue
        if hasattr(module, short):
            return getattr(module, short)
    raise LookupError(name)

def value(type_, tree):
    base = type_.split("[")[0]
    if isinstance(tree, dict) and "__bytes__" in tree:
        return bytes.fromhex(tree["__bytes__"])
    if "[" in type_:
        return [value(base, item) for item in tree]
    if isinstance(tree, dict) and "__time__" in tree:
        return genpy.Time(*tree["__time__"])
    if isinstance(tree, dict) and "__duration__" in tree:
        return genpy.Duration(*tree["__duration__"])
    if isinstance(tree, dict):
        return build(base, tree)
    return tree

def build(name, tree):
    msg_class = class_of(name)
    msg = msg_class()
    for slot, type_ in zip(msg_class.__slots__, msg_class._slot_types):
        setattr(msg, slot, value(type_, tree[slot]))
    return msg

out = {"classes": {}, "bytes": []}
for name in request["classes"]:
    try:
        c = class_of(name)
    except LookupError:
        continue
    info = {"md5": c._md5sum, "type": c._type}
    if hasattr(c, "__slots__"):
        info.update(has_header=c._has_header, slots=list(c.__slots__),
                    slot_types=list(c._slot_types), full_text=c._full_text,
                    constants={k: getattr(c, k) for k in request["constants"].get(name, [])})
    out["classes"][name] = info
for name, tree in request["messages"]:
    try:
        buff = io.BytesIO()
        build(name, tree).serialize(buff)
        out["bytes"].append(buff.getvalue().hex())
    except Exception as exc:
        out["bytes"].append("error %s: %s" % (type(exc).__name__, exc))
def shape(value):
    if hasattr(value, "_slot_types"):
        if not hasattr(value, "_type"):
            return type(value).__name__
        return {slot: shape(getattr(value, slot)) for slot in value.__slots__}
    if isinstance(value, (list, tuple)):
        return [type(value).__name__] + [shape(item) for item in value]
    return type(value).__name__

out["shapes"] = []
for name, data in request.get("decode", []):
    out["shapes"].append(shape(class_of(name)().deserialize(bytes.fromhex(data))))
print(json.dumps(out))
"""

_GENPY_PACKAGES = (
    "std_msgs", "geometry_msgs", "sensor_msgs", "nav_msgs", "actionlib_msgs", "rosgraph_msgs",
    "turtlesim", "std_srvs",
)  # fmt: skip


def _genpy_available() -> bool:
    if not ROS1_PYTHON.exists():
        return False
    probe = [str(ROS1_PYTHON), "-c", "import genpy, geometry_msgs.msg"]
    return subprocess.run(probe, capture_output=True, check=False).returncode == 0


def _run_genpy(request: dict[str, Any]) -> dict[str, Any]:
    result = subprocess.run(
        [str(ROS1_PYTHON), "-c", _GENPY_SIDE],
        input=json.dumps(request),
        capture_output=True,
        text=True,
        check=True,
    )
    reply: dict[str, Any] = json.loads(result.stdout)
    return reply


def _shared_types() -> list[str]:
    return [n for n in _standard_types() if n.partition("/")[0] in _GENPY_PACKAGES]


needs_genpy = pytest.mark.skipif(
    not _genpy_available(), reason="genpy (Debian's /usr/bin/python3) not found"
)


@pytest.fixture(scope="module")
def genpy_classes() -> dict[str, Any]:
    names = _shared_types()
    constants = {n: [c.name for c in cls(n)._spec.constants] for n in names}
    request = {"dynamic": {}, "classes": names, "constants": constants, "messages": []}
    classes: dict[str, Any] = _run_genpy(request)["classes"]
    return classes


@needs_genpy
def test_genpy_knows_the_shared_types(genpy_classes: dict[str, Any]) -> None:
    assert len(genpy_classes) > 120  # the packages are there: the comparisons below are real
    assert "turtlesim/SpawnRequest" in genpy_classes and "sensor_msgs/Image" in genpy_classes


@needs_genpy
@pytest.mark.parametrize("name", _shared_types())
def test_class_attributes_match_genpy(name: str, genpy_classes: dict[str, Any]) -> None:
    if name not in genpy_classes:
        pytest.skip(f"{name} is not installed for genpy")
    theirs = genpy_classes[name]
    ours = cls(name)
    assert (ours._type, ours._md5sum, ours._has_header) == (
        theirs["type"],
        theirs["md5"],
        theirs["has_header"],
    )
    assert (ours.__slots__, ours._slot_types) == (theirs["slots"], theirs["slot_types"])
    assert {c.name: getattr(ours, c.name) for c in ours._spec.constants} == theirs["constants"]
    assert _definition(ours._full_text, name) == _definition(theirs["full_text"], name)


@needs_genpy
def test_service_md5_sums_match_genpy() -> None:
    from rosx.msg.codec.classes import get_service_class

    names = [n for n in default_store().types("srv") if n.partition("/")[0] in _GENPY_PACKAGES]
    theirs = _run_genpy({"dynamic": {}, "classes": names, "constants": {}, "messages": []})[
        "classes"
    ]
    assert theirs, "no service of these packages is installed for genpy"
    for name, info in theirs.items():
        assert get_service_class(name)._md5sum == info["md5"], name


@needs_genpy
def test_populated_messages_serialize_as_genpy_does() -> None:
    messages = []
    for name in _shared_types():
        for seed in range(3):
            messages.append((name, populate(cls(name), random.Random(f"{name}{seed}"))))
    request = {
        "dynamic": {},
        "classes": [],
        "constants": {},
        "messages": [(n, to_tree(m)) for n, m in messages],
    }
    theirs = _run_genpy(request)["bytes"]
    compared = 0
    for (name, msg), expected in zip(messages, theirs, strict=True):
        if expected.startswith("error LookupError"):
            continue
        assert ser(msg).hex() == expected, name
        back = cls(name)().deserialize(bytes.fromhex(expected))
        assert ser(back).hex() == expected, name
        compared += 1
    assert compared > 350


@needs_genpy
def test_every_field_kind_serializes_as_genpy_does(store: TypeStore) -> None:
    every = cls("x/All", store)
    messages = [populate(every, random.Random(seed), store) for seed in range(20)]
    request = {
        "dynamic": {"x/All": every._full_text},
        "classes": [],
        "constants": {},
        "messages": [("x/All", to_tree(m)) for m in messages],
    }
    reply = _run_genpy({**request, "decode": [("x/All", ser(m).hex()) for m in messages]})
    for msg, expected, shape in zip(messages, reply["bytes"], reply["shapes"], strict=True):
        assert ser(msg).hex() == expected
        assert _shape(every().deserialize(bytes.fromhex(expected))) == shape


def _shape(value: Any) -> Any:
    """Python types of a deserialised value, as the genpy side reports them."""
    if isinstance(value, Message):
        return {attr: _shape(getattr(value, attr)) for attr in value.__slots__}
    if isinstance(value, list | tuple):
        return [type(value).__name__] + [_shape(item) for item in value]
    return type(value).__name__


_BUILTIN = frozenset(
    [
        "bool",
        "int8",
        "uint8",
        "int16",
        "uint16",
        "int32",
        "uint32",
        "int64",
        "uint64",
        "float32",
        "float64",
        "string",
        "char",
        "byte",
        "time",
        "duration",
    ]
)


def _definition(text: str, type_name: str) -> list[tuple[str, list[str], list[str]]]:
    """A full definition as (type, sorted constants, fields) per section, comments and spacing
    dropped and field types fully qualified: rosx's standard texts are rebuilt from field lists,
    so they qualify every name, carry no comments and list constants first."""
    sections: list[tuple[str, list[str], list[str]]] = [(type_name, [], [])]
    for line in text.split("\n"):
        if line.startswith("=" * 80):
            continue
        if line.startswith("MSG: "):
            sections.append((line[5:].strip(), [], []))
            continue
        name, constants, fields = sections[-1]
        is_string_constant = line.split()[:1] == ["string"] and "=" in line
        code = line if is_string_constant else line.split("#", 1)[0]
        if "=" in code:
            left, _, right = code.partition("=")
            constants.append(" ".join(left.split()) + "=" + right.strip())
            continue
        words = code.split()
        if not words:
            continue
        field_type, field_name = words
        base = field_type.split("[")[0]
        if base == "Header":
            field_type = "std_msgs/" + field_type
        elif base not in _BUILTIN and "/" not in base:
            field_type = name.partition("/")[0] + "/" + field_type
        fields.append(f"{field_type} {field_name}")
    return [(name, sorted(constants), fields) for name, constants, fields in sections]


def _f64(value: float) -> bytes:
    import struct

    return struct.pack("<d", value)


def _escape(text: str) -> str:
    import re

    return re.escape(text)
