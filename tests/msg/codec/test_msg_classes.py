"""Tests for generated message and service classes (rosx.msg.codec.classes, rosx.msg.codec.message).

What a rospy script sees: class attributes as genpy sets them, constructors and their errors,
defaults, equality, copying and pickling, service classes, the per-store cache, and what loading
a class imports. Attribute values are compared with genpy's own classes in test_codec.py.
"""

from __future__ import annotations

import copy
import json
import pickle
import subprocess
import sys
import textwrap
from pathlib import Path
from typing import Any

import pytest

from rosx.msg.codec.classes import get_message_class, get_service_class
from rosx.msg.codec.message import Message, ServiceDefinition
from rosx.msg.codec.rostime import Duration, Time
from rosx.msg.store import TypeStore, UnknownTypeError
from tests.support.msgpackages import EVERY_KIND, make_package

ROOT = Path(__file__).resolve().parents[3]


@pytest.fixture
def store(tmp_path: Path) -> TypeStore:
    make_package(
        tmp_path,
        "x",
        {
            "All": EVERY_KIND,
            "Sub": "int32 a\ntime t\n",
            "Keywords": "int32 from\nstring self\nbool ok\nint32 class=1\n",
            "Nothing": "",
        },
        {"Ask": "string question\n---\nint64 answer\n"},
    )
    return TypeStore([tmp_path])


# -- class attributes -----------------------------------------------------------------------


def test_twist_class_attributes() -> None:
    twist = get_message_class("geometry_msgs/Twist")
    assert issubclass(twist, Message)
    assert twist.__name__ == "Twist"
    assert twist._type == "geometry_msgs/Twist"
    assert twist._md5sum == "9f195f881246fdfa2798d1d3eebca84a"
    assert twist._has_header is False
    assert twist.__slots__ == ["linear", "angular"]
    assert twist._slot_types == ["geometry_msgs/Vector3", "geometry_msgs/Vector3"]
    assert "MSG: geometry_msgs/Vector3" in twist._full_text
    assert twist._spec is not None and twist._spec.full_name == "geometry_msgs/Twist"


def test_image_class_attributes() -> None:
    image = get_message_class("sensor_msgs/Image")
    assert image._md5sum == "060021388200f6f0f447d0fcd9c64743"
    assert image._has_header is True
    assert image._slot_types == [
        "std_msgs/Header", "uint32", "uint32", "string", "uint8", "uint32", "uint8[]",
    ]  # fmt: skip
    assert image._full_text.startswith("std_msgs/Header header\n") is False
    assert "=" * 80 + "\nMSG: std_msgs/Header\n" in image._full_text


def test_header_and_turtle_pose() -> None:
    header = get_message_class("std_msgs/Header")
    assert header._md5sum == "2176decaecbce78abc3b96ef049fabed"
    assert header._slot_types == ["uint32", "time", "string"]
    # The original file, comments included, as genpy's classes carry it (ROS 1's sends it as the
    # connection header's message_definition).
    assert header._full_text.startswith("# Standard metadata for higher-level stamped data types.")
    assert header._full_text.endswith(
        "time stamp\n#Frame this data is associated with\nstring frame_id\n"
    )
    assert get_message_class("Header") is header
    pose = get_message_class("turtlesim/Pose")
    assert pose._md5sum == "863b248d5016ca62ea2e895ae5265cf9"
    assert pose.__slots__ == ["x", "y", "theta", "linear_velocity", "angular_velocity"]


def test_constants_are_class_attributes(store: TypeStore) -> None:
    log: Any = get_message_class("rosgraph_msgs/Log")
    assert (log.DEBUG, log.INFO, log.WARN, log.ERROR, log.FATAL) == (1, 2, 4, 8, 16)
    status: Any = get_message_class("sensor_msgs/NavSatStatus")
    assert status.STATUS_NO_FIX == -1
    every: Any = get_message_class("x/All", store)
    assert every.SMALL == -3
    assert every.GREETING == "hello # not a comment"


def test_python_keywords_get_an_underscore(store: TypeStore) -> None:
    keywords: Any = get_message_class("x/Keywords", store)
    assert keywords.__slots__ == ["from_", "self_", "ok"]
    assert keywords._slot_types == ["int32", "string", "bool"]
    assert keywords.class_ == 1
    msg = keywords(from_=3, self_="me")
    assert keywords().deserialize(_serialize(msg)) == msg


# -- construction ---------------------------------------------------------------------------


def test_defaults_of_every_kind(store: TypeStore) -> None:
    msg: Any = get_message_class("x/All", store)()
    assert msg.b is False and msg.bs == [] and msg.bf == [False, False, False]
    assert msg.c == 0 and msg.cs == b"" and msg.cf == b"\0" * 4
    assert msg.u8 == b"" and msg.u8f == b"\0" * 5 and msg.i8 == [] and msg.by == 0
    assert msg.f == 0.0 and isinstance(msg.f, float)
    assert msg.f9 == [0.0] * 9
    assert msg.s == "" and msg.ss == [] and msg.sf == ["", ""]
    assert msg.t == Time() and type(msg.t) is Time and msg.ts == []
    assert msg.d == Duration() and type(msg.d) is Duration
    assert msg.df == [Duration(), Duration()] and msg.df[0] is not msg.df[1]
    assert msg.sub._type == "x/Sub" and msg.sub.a == 0 and msg.sub.t == Time()
    assert msg.subs == [] and len(msg.subf) == 2 and msg.subf[0] is not msg.subf[1]
    assert msg.h.seq == 0 and msg.h.stamp == Time() and msg.h.frame_id == ""
    assert msg.u64 == 0


def test_defaults_are_fresh_per_instance() -> None:
    twist = get_message_class("geometry_msgs/Twist")
    first, second = twist(), twist()
    assert first.linear is not second.linear
    header = get_message_class("std_msgs/Header")
    assert header().stamp is not header().stamp


def test_positional_and_keyword_construction() -> None:
    vector = get_message_class("geometry_msgs/Vector3")
    twist = get_message_class("geometry_msgs/Twist")
    by_position = twist(vector(1.0, 2.0, 3.0), vector(z=0.5))
    assert (by_position.linear.x, by_position.linear.y, by_position.linear.z) == (1.0, 2.0, 3.0)
    assert (by_position.angular.x, by_position.angular.z) == (0.0, 0.5)
    by_keyword = twist(angular=vector(z=0.5))
    assert by_keyword.linear == vector() and by_keyword.angular.z == 0.5
    with_none = twist(None, None)
    assert with_none.linear == vector() and with_none == twist()


def test_construction_errors_have_genpy_texts() -> None:
    twist = get_message_class("geometry_msgs/Twist")
    with pytest.raises(TypeError) as wrong_count:
        twist(1)
    assert str(wrong_count.value) == (
        "Invalid number of arguments, args should be ['linear', 'angular'] args are(1,)"
    )
    with pytest.raises(
        TypeError, match="Message constructor may only use args OR keywords, not both"
    ):
        twist(1, angular=2)
    with pytest.raises(AttributeError, match=r"^foo is not an attribute of Twist$"):
        twist(foo=2)
    with pytest.raises(AttributeError):
        twist().foo = 1


def test_empty_message(store: TypeStore) -> None:
    nothing = get_message_class("x/Nothing", store)
    assert nothing.__slots__ == [] and nothing._slot_types == []
    assert nothing() == nothing()
    assert _serialize(nothing()) == b""
    with pytest.raises(TypeError):
        nothing(1)


# -- value behaviour ------------------------------------------------------------------------


def test_equality() -> None:
    vector = get_message_class("geometry_msgs/Vector3")
    point = get_message_class("geometry_msgs/Point")
    assert vector(1.0, 2.0, 3.0) == vector(1.0, 2.0, 3.0)
    assert vector(1.0, 2.0, 3.0) != vector(1.0, 2.0, 4.0)
    assert vector() != point()  # same fields, other type
    assert vector() != 0
    floats = get_message_class("std_msgs/Float64MultiArray")
    assert floats(data=[1.0, 2.0]) == floats(data=(1.0, 2.0))  # lists and tuples alike
    assert floats(data=[1.0]) != floats(data=[1.0, 2.0])
    with pytest.raises(TypeError):
        hash(vector())


def test_getstate_copy_and_pickle() -> None:
    pose_stamped = get_message_class("geometry_msgs/PoseStamped")
    msg = pose_stamped()
    msg.header.frame_id = "map"
    msg.header.stamp = Time(5, 6)
    msg.pose.position.x = 1.5
    assert msg.__getstate__()[0] is msg.header
    shallow = copy.copy(msg)
    assert shallow == msg and shallow.header is msg.header
    deep = copy.deepcopy(msg)
    assert (
        deep == msg
        and deep.header is not msg.header
        and deep.pose.position is not msg.pose.position
    )
    deep.pose.position.x = 2.0
    assert msg.pose.position.x == 1.5
    again = pickle.loads(pickle.dumps(msg))
    assert type(again) is pose_stamped and again == msg
    fresh = pose_stamped()
    fresh.__setstate__(msg.__getstate__())
    assert fresh == msg


def test_str_shows_fields() -> None:
    vector = get_message_class("geometry_msgs/Vector3")
    text = str(vector(1.5, 0.0, -2.0))
    assert "x: 1.5" in text and "z: -2.0" in text
    assert repr(vector(1.5, 0.0, -2.0)) == text


def test_deserialized_value_types(store: TypeStore) -> None:
    every = get_message_class("x/All", store)
    msg: Any = every()
    msg.bs, msg.i8, msg.u8, msg.ss = [True, False], [1, -2], [1, 2], ["a"]
    msg.subs = [get_message_class("x/Sub", store)(a=7)]
    msg.ts = [Time(1, 2)]
    back: Any = every().deserialize(_serialize(msg))
    assert back.b is False and back.bs == [True, False] and type(back.bs) is list
    assert type(back.bf) is list and all(type(v) is bool for v in back.bf)
    assert back.i8 == (1, -2) and type(back.i8) is tuple
    assert back.f9 == (0.0,) * 9 and type(back.f9) is tuple
    assert back.u8 == b"\x01\x02" and back.cs == b"" and back.cf == b"\0" * 4
    assert back.u8f == b"\0" * 5
    assert type(back.ss) is list and back.ss == ["a"] and type(back.sf) is list
    assert type(back.t) is Time and type(back.d) is Duration and back.ts == [Time(1, 2)]
    assert type(back.subs) is list and back.subs[0].a == 7


# -- services -------------------------------------------------------------------------------


def test_service_class() -> None:
    spawn = get_service_class("turtlesim/Spawn")
    assert issubclass(spawn, ServiceDefinition)
    assert spawn._type == "turtlesim/Spawn"
    assert spawn._md5sum == "0b2d2e872a8e2887d5ed626f2bf2c561"
    request, response = spawn._request_class, spawn._response_class
    assert request._type == "turtlesim/SpawnRequest"
    assert request._md5sum == "57f001c49ab7b11d699f8606c1f4f7ff"
    assert request.__slots__ == ["x", "y", "theta", "name"]
    assert response._type == "turtlesim/SpawnResponse"
    assert response._md5sum == "c1f3d28f1b044c871e6eff2e9fc3c667"
    assert get_message_class("turtlesim/SpawnRequest") is request
    assert request(1.0, 2.0, 0.0, "t2").name == "t2"


def test_service_of_a_user_package(store: TypeStore) -> None:
    ask = get_service_class("x/Ask", store)
    assert ask._request_class.__slots__ == ["question"]
    assert ask._response_class._slot_types == ["int64"]
    assert get_message_class("x/AskResponse", store) is ask._response_class


# -- lookup and cache -----------------------------------------------------------------------


def test_classes_are_cached_per_store(store: TypeStore, tmp_path: Path) -> None:
    assert get_message_class("x/Sub", store) is get_message_class("x/Sub", store)
    assert get_message_class("std_msgs/Header") is get_message_class("std_msgs/Header")
    other = TypeStore([tmp_path])
    assert get_message_class("x/Sub", other) is not get_message_class("x/Sub", store)
    assert get_message_class("x/All", store)().sub.__class__ is get_message_class("x/Sub", store)


def test_unknown_types_raise_the_stores_error(store: TypeStore) -> None:
    with pytest.raises(UnknownTypeError):
        get_message_class("x/Missing", store)
    with pytest.raises(UnknownTypeError):
        get_message_class("nopkg/Twist")
    with pytest.raises(UnknownTypeError):
        get_service_class("turtlesim/Nope")
    with pytest.raises(UnknownTypeError):
        get_message_class("not a type")


def test_types_embedding_each_other_are_refused(tmp_path: Path) -> None:
    make_package(tmp_path, "loop", {"A": "B b\n", "B": "A[] a\n"})
    with pytest.raises(ValueError, match="embed each other"):
        get_message_class("loop/A", TypeStore([tmp_path]))


_IMPORTS = """
import json, sys
from rosx.msg.codec.classes import get_message_class
from rosx.msg.store import TypeStore
from pathlib import Path
names = sys.argv[1:]
store = TypeStore([Path(sys.argv[1])])
for name in names[1:]:
    cls = get_message_class(name, store)
    cls().deserialize(b"\\0" * 4096)
print(json.dumps(sorted(m for m in ("numpy", "textual", "rosbags") if m in sys.modules)))
"""


@pytest.mark.parametrize(
    ("names", "allowed"),
    [
        (["x/Sub", "x/Keywords", "x/Nothing"], []),
        (["geometry_msgs/Twist", "sensor_msgs/Image"], ["rosbags"]),
    ],
)
def test_loading_classes_imports_little(
    store: TypeStore, tmp_path: Path, names: list[str], allowed: list[str]
) -> None:
    result = subprocess.run(
        [sys.executable, "-c", textwrap.dedent(_IMPORTS), str(tmp_path), *names],
        capture_output=True,
        text=True,
        check=True,
        cwd=ROOT,
    )
    assert set(json.loads(result.stdout)) <= set(allowed)


def _serialize(msg: Message) -> bytes:
    import io

    buff = io.BytesIO()
    msg.serialize(buff)
    return buff.getvalue()
