"""Parser, type store, md5 sums and full definitions."""

from __future__ import annotations

import os
import time
from pathlib import Path

import pytest

from rosx.msg.parser import InvalidMsgSpecError, parse_msg, parse_srv
from rosx.msg.spec import Field
from rosx.msg.store import TypeStore, UnknownTypeError

# md5 sums as ROS 1 (genmsg) computes them.
KNOWN_MD5 = {
    "geometry_msgs/Twist": "9f195f881246fdfa2798d1d3eebca84a",
    "std_msgs/Header": "2176decaecbce78abc3b96ef049fabed",
    "std_msgs/Empty": "d41d8cd98f00b204e9800998ecf8427e",
    "std_msgs/String": "992ce8a1687cec8c8bd883ec73ca41d1",
    "turtlesim/Pose": "863b248d5016ca62ea2e895ae5265cf9",
    "turtlesim/Color": "353891e354491c51aabe32df673fb446",
    "sensor_msgs/Image": "060021388200f6f0f447d0fcd9c64743",
    "rosgraph_msgs/Log": "acffd30cd6b6de30f120938c17c593fb",
    "sensor_msgs/NavSatStatus": "331cdbddfa4bc96ffc3b9ad98900a54c",
}
KNOWN_SRV_MD5 = {
    "turtlesim/Spawn": "0b2d2e872a8e2887d5ed626f2bf2c561",
    "std_srvs/Empty": "d41d8cd98f00b204e9800998ecf8427e",
    "std_srvs/Trigger": "937c9679a518e3a18d831e57125ea522",
    "roscpp/GetLoggers": "32e97e85527d4678a8f9279894bb64b0",
    "roscpp/SetLoggerLevel": "51da076440d78ca1684d36c868df61ea",
}


@pytest.fixture(scope="module")
def store() -> TypeStore:
    return TypeStore([])


@pytest.mark.parametrize(("name", "md5"), sorted(KNOWN_MD5.items()))
def test_message_md5(store: TypeStore, name: str, md5: str) -> None:
    assert store.md5(name) == md5


@pytest.mark.parametrize(("name", "md5"), sorted((k, v) for k, v in KNOWN_SRV_MD5.items() if v))
def test_service_md5(store: TypeStore, name: str, md5: str) -> None:
    assert store.srv_md5(name) == md5


def test_parse_fields_constants_and_comments() -> None:
    spec = parse_msg(
        "pkg/Thing",
        "# comment\nHeader header\nint8 A=-1 # trailing\nstring S= keep # this too \n"
        "float64[9] K\nOther[] others\nother_pkg/T[3] ts\nuint8[] data\ntime t\n",
    )
    assert [c.name for c in spec.constants] == ["A", "S"]
    assert spec.constants[0].value == -1
    assert spec.constants[1].value == "keep # this too"
    assert spec.fields == (
        Field("header", "std_msgs/Header"),
        Field("K", "float64", True, 9),
        Field("others", "pkg/Other", True, None),
        Field("ts", "other_pkg/T", True, 3),
        Field("data", "uint8", True, None),
        Field("t", "time"),
    )
    assert spec.has_header
    assert spec.fields[1].type == "float64[9]"


@pytest.mark.parametrize(
    ("text", "message", "line"),
    [
        ("int32 a\nint32\n", "Invalid declaration: int32", 2),
        ("int32 1a\n", "1a is not a legal message field name", 1),
        ("in-t32 a\n", "in-t32 is not a legal message field type", 1),
        ("\n\nuint8 X=256\n", "cannot coerce [256] to uint8 (out of bounds)", 3),
        ("time T=1\n", "time is not a legal constant type", 1),
        ("int32 a\nint32 a\n", "Duplicate field name [a] in [p/M]", None),
    ],
)
def test_parse_errors_name_the_line(text: str, message: str, line: int | None) -> None:
    with pytest.raises(InvalidMsgSpecError) as caught:
        parse_msg("p/M", text)
    assert (str(caught.value), caught.value.line) == (message, line)


def test_srv_splits_at_the_first_dashes_line() -> None:
    spec = parse_srv("p/S", "int32 a\n---\nint32 b\n")
    assert spec.request.full_name == "p/SRequest"
    assert [f.name for f in spec.response.fields] == ["b"]
    with pytest.raises(InvalidMsgSpecError) as caught:
        parse_srv("p/S", "int32 a\n---\nint32\n")
    assert caught.value.line == 3


def test_service_halves_are_messages(store: TypeStore) -> None:
    assert [f.name for f in store.msg("turtlesim/SpawnRequest").fields] == [
        "x",
        "y",
        "theta",
        "name",
    ]


def test_unknown_types(store: TypeStore) -> None:
    with pytest.raises(UnknownTypeError) as caught:
        store.msg("std_msgs/Nope")
    assert caught.value.package_known
    with pytest.raises(UnknownTypeError) as caught:
        store.msg("nopkg/Nope")
    assert not caught.value.package_known


def _package(root: Path, name: str, msgs: dict[str, str]) -> Path:
    directory = root / name
    (directory / "msg").mkdir(parents=True)
    (directory / "package.xml").write_text(
        f"<package format='2'>\n  <name>{name}</name>\n</package>\n"
    )
    for short, text in msgs.items():
        (directory / "msg" / f"{short}.msg").write_text(text)
    return directory


def test_user_packages_and_full_text(tmp_path: Path) -> None:
    _package(
        tmp_path / "src",
        "lab2",
        {"Goal": "# goal\nPoint p\ngeometry_msgs/Vector3 v\nPoint q\n", "Point": "float32 x\n"},
    )
    store = TypeStore([tmp_path / "src"])
    assert store.full_text("lab2/Goal") == (
        "# goal\nPoint p\ngeometry_msgs/Vector3 v\nPoint q\n\n"
        + "=" * 80
        + "\nMSG: lab2/Point\nfloat32 x\n\n"
        + "=" * 80
        + "\nMSG: geometry_msgs/Vector3\n"
        + store.msg("geometry_msgs/Vector3").text
    )
    assert "lab2/Goal" in store.types("msg")
    assert store.find("Goal", "msg") == ["lab2/Goal"]


def test_first_package_on_the_path_wins_for_the_types_it_has(tmp_path: Path) -> None:
    _package(tmp_path / "a", "std_msgs", {"String": "string data\nint8 extra\n"})
    _package(tmp_path / "b", "std_msgs", {"String": "int8 other\n"})
    store = TypeStore([tmp_path / "a", tmp_path / "b"])
    assert [f.name for f in store.msg("std_msgs/String").fields] == ["data", "extra"]
    assert [f.name for f in store.msg("std_msgs/Header").fields] == ["seq", "stamp", "frame_id"]
    assert {"std_msgs/String", "std_msgs/Header"} <= set(store.types("msg"))


def test_a_package_without_types_shadows_none_of_the_bundled_ones(tmp_path: Path) -> None:
    # Debian's libroscpp-dev leaves /usr/share/roscpp holding a manifest and no msg/srv files.
    (tmp_path / "roscpp").mkdir()
    (tmp_path / "roscpp" / "package.xml").write_text("<package><name>roscpp</name></package>\n")
    store = TypeStore([tmp_path])
    bundled = TypeStore([])
    assert store.md5("roscpp/Logger") == bundled.md5("roscpp/Logger")
    assert store.srv_md5("roscpp/GetLoggers") == bundled.srv_md5("roscpp/GetLoggers")
    assert store.types("srv") == bundled.types("srv")
    with pytest.raises(UnknownTypeError) as caught:
        store.msg("roscpp/Nope")
    assert caught.value.package_known


def test_crawl_skips_ignored_and_hidden_directories(tmp_path: Path) -> None:
    _package(tmp_path / "ws" / "ignored", "gone", {"A": "int8 a\n"})
    (tmp_path / "ws" / "ignored" / "CATKIN_IGNORE").touch()
    _package(tmp_path / "ws" / ".hidden", "hidden", {"A": "int8 a\n"})
    _package(tmp_path / "ws" / "deep" / "er", "found", {"A": "int8 a\n"})
    store = TypeStore([tmp_path / "ws"])
    assert set(store.path_packages) == {"found"}


def test_self_embedding_type_is_an_error_not_a_hang(tmp_path: Path) -> None:
    _package(tmp_path, "loop", {"A": "B b\n", "B": "A a\n"})
    with pytest.raises(InvalidMsgSpecError):
        TypeStore([tmp_path]).md5("loop/A")


def _fresh_standard_texts() -> dict[str, str]:
    from rosx.msg import standard

    standard._texts.cache_clear()
    try:
        return dict(standard.standard_types())
    finally:
        standard._texts.cache_clear()


def _cache_file() -> Path:
    """The cache file of this process's rosbags and Python."""
    from rosx.msg import standard

    tag = standard._store_tag()
    assert tag is not None
    path = standard._cache_path(tag)
    assert path is not None
    return path


def test_standard_texts_come_back_from_the_cache_unchanged(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    built = _fresh_standard_texts()
    cache = _cache_file()
    assert cache.parent == tmp_path / "rosx"
    assert cache.is_file()
    assert _fresh_standard_texts() == built
    assert (
        built["geometry_msgs/Twist"]
        == "geometry_msgs/Vector3 linear\ngeometry_msgs/Vector3 angular\n"
    )


@pytest.mark.parametrize("content", [b"", b"\x00garbage", b"\xe9\x02\x00\x00\x00"])
def test_a_damaged_cache_is_built_again(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, content: bytes
) -> None:
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    expected = _fresh_standard_texts()
    cache = _cache_file()
    cache.write_bytes(content)
    assert _fresh_standard_texts() == expected
    assert cache.read_bytes() != content


def test_virtual_environments_sharing_the_cache_folder_keep_their_own_files(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Two rosbags installs (two venvs) each build their texts once, then both read them."""
    from rosx.msg import standard

    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    tag = standard._store_tag()
    assert tag is not None
    other = ("/elsewhere/rosbags/typesys/stores/ros1_noetic.py", *tag[1:])
    builds: list[int] = []
    build = standard._texts_from_rosbags

    def counted() -> dict[str, str]:
        builds.append(1)
        return build()

    monkeypatch.setattr(standard, "_texts_from_rosbags", counted)
    for each in (tag, other, tag, other):
        monkeypatch.setattr(standard, "_store_tag", lambda each=each: each)
        assert "geometry_msgs/Twist" in _fresh_standard_texts()
    assert len(builds) == 2
    assert len(list((tmp_path / "rosx").iterdir())) == 2


def test_writing_a_cache_file_removes_those_long_unwritten(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    from rosx.msg import standard

    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    folder = tmp_path / "rosx"
    folder.mkdir()
    stale, recent, unrelated = (
        folder / "ros1_noetic_types.marshal",  # the name of an older rosx's single file
        folder / "ros1_noetic_types-py3.9-0badcafe.marshal",
        folder / "notes.txt",
    )
    long_ago = time.time() - (standard.STALE_DAYS + 1) * 86400
    for path in (stale, recent, unrelated):
        path.write_bytes(b"x")
    for path in (stale, unrelated):
        os.utime(path, (long_ago, long_ago))
    _fresh_standard_texts()
    assert sorted(folder.iterdir()) == sorted([_cache_file(), recent, unrelated])


def test_an_unwritable_cache_folder_costs_only_time(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    (tmp_path / "rosx").write_text("a file where the folder would be")
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    assert "geometry_msgs/Twist" in _fresh_standard_texts()
    assert list(tmp_path.iterdir()) == [tmp_path / "rosx"]


def test_the_shipped_definition_files_hash_as_rosbags_field_lists() -> None:
    """The standard packages' original files (comments included) give the md5 sums the types
    had from rosbags' field lists alone: shipping the files changed no sum."""
    from rosx.msg.md5 import message_md5
    from rosx.msg.parser import parse_msg
    from rosx.msg.spec import MsgSpec
    from rosx.msg.standard import standard_text
    from rosx.packages.crawl import bundled_packages

    store = TypeStore([])
    sums: dict[str, str] = {}

    def rebuilt(name: str) -> MsgSpec:
        text = standard_text(name)
        return parse_msg(name, text) if text is not None else store.msg(name)

    def rebuilt_md5(name: str) -> str:
        if name not in sums:
            sums[name] = message_md5(rebuilt(name), rebuilt, rebuilt_md5)
        return sums[name]

    compared = 0
    for package, directory in bundled_packages().items():
        for path in sorted(directory.glob("msg/*.msg")):
            name = f"{package}/{path.stem}"
            if standard_text(name) is not None:
                assert store.md5(name) == rebuilt_md5(name), name
                assert store.msg(name).text == path.read_text(encoding="utf-8")
                compared += 1
    assert compared > 130
