"""``rosbag info``'s text and the ``rosbag`` Python API, over bags written here."""

from __future__ import annotations

from pathlib import Path

import pytest

from rosx.bag import api
from rosx.bag.info import format_text, format_yaml, lookup_key, summarize
from rosx.bag.reader import BagReader
from rosx.msg.codec.classes import get_message_class
from rosx.msg.codec.rostime import Time
from tests.support.cli import rosx

String = get_message_class("std_msgs/String")
Int32 = get_message_class("std_msgs/Int32")


@pytest.fixture
def bag_path(tmp_path: Path) -> Path:
    path = tmp_path / "api.bag"
    with api.Bag(path, "w") as bag:
        for i in range(5):
            bag.write("chatter", String(data=f"foo {i}"), Time(100 + i))
            bag.write("numbers", Int32(data=i), Time(100 + i, 5))
    return path


def test_info_text_is_ros1s(bag_path: Path, utc: None) -> None:
    with BagReader(bag_path) as bag:
        text = format_text(summarize(bag, "api.bag"))
    assert text == (
        "path:        api.bag\n"
        "version:     2.0\n"
        "duration:    4.0s\n"
        "start:       Jan 01 1970 00:01:40.00 (100.00)\n"
        "end:         Jan 01 1970 00:01:44.00 (104.00)\n"
        f"size:        {bag_path.stat().st_size / 1024:.1f} KB\n"
        "messages:    10\n"
        "compression: none [1/1 chunks]\n"
        "types:       std_msgs/Int32  [da5909fbe378aeaf85e547e830cc1bb7]\n"
        "             std_msgs/String [992ce8a1687cec8c8bd883ec73ca41d1]\n"
        "topics:      chatter   5 msgs    : std_msgs/String\n"
        "             numbers   5 msgs    : std_msgs/Int32"
    )


def test_info_yaml_and_keys(bag_path: Path) -> None:
    with BagReader(bag_path) as bag:
        summary = summarize(bag, "api.bag", freq=True)
    yaml = format_yaml(summary)
    assert "indexed: True\ncompression: none\ntypes:\n    - type: std_msgs/Int32\n" in yaml
    assert "      frequency: 1.0000\n" in yaml
    assert lookup_key(summary, "topics[1].type") == "std_msgs/Int32"
    assert lookup_key(summary, "duration") == "4.0"  # %.6f, then read back as YAML
    assert lookup_key(summary, "nope") is None


def test_the_cli_reports_bad_files_in_one_line(tmp_path: Path) -> None:
    bad = tmp_path / "notbag.txt"
    bad.write_text("hello\n")
    result = rosx("rosbag", "info", str(bad))
    assert (result.status, result.err) == (
        1,
        f"ERROR reading {bad}: This does not appear to be a bag file\n",
    )
    missing = rosx("rosbag", "info", str(tmp_path / "missing.bag"))
    assert missing.status == 1
    assert "No such file or directory" in missing.err and "Traceback" not in missing.err


def test_read_messages_as_the_tutorials_do(bag_path: Path) -> None:
    with api.Bag(bag_path) as bag:
        got = [(topic, msg.data, t.to_nsec()) for topic, msg, t in bag.read_messages()]
        assert got[:2] == [("chatter", "foo 0", 100_000_000_000), ("numbers", 0, 100_000_000_005)]
        assert len(got) == 10
        assert [
            m.data for _, m, _ in bag.read_messages(topics=["numbers"], start_time=Time(102))
        ] == [2, 3, 4]
        assert bag.get_message_count() == 10
        assert bag.get_message_count("chatter") == 5
        assert (bag.get_start_time(), bag.get_end_time()) == (100.0, 104.000000005)
        info = bag.get_type_and_topic_info()
        assert info.msg_types == {
            "std_msgs/Int32": "da5909fbe378aeaf85e547e830cc1bb7",
            "std_msgs/String": "992ce8a1687cec8c8bd883ec73ca41d1",
        }
        assert info.topics["chatter"] == api.TopicTuple("std_msgs/String", 5, 1, 1.0)
        raw = next(bag.read_messages(raw=True))
        assert raw.message[0] == "std_msgs/String" and raw.message[2] == String._md5sum


def test_types_unknown_here_decode_from_the_recorded_definition(tmp_path: Path) -> None:
    from rosx.bag.writer import BagWriter

    definition = "int32 a\nmy_pkg/Inner inner\n" + "=" * 80 + "\nMSG: my_pkg/Inner\nstring s\n"
    path = tmp_path / "custom.bag"
    with BagWriter(path) as writer:
        conn = writer.add_connection(
            "/custom",
            {
                "type": "my_pkg/Outer",
                "md5sum": "*",
                "message_definition": definition,
                "topic": "/custom",
            },
        )
        writer.write(conn, 1, b"\x07\x00\x00\x00\x02\x00\x00\x00hi")
    with api.Bag(path) as bag:
        ((_, msg, _),) = list(bag.read_messages())
    assert (msg.a, msg.inner.s) == (7, "hi")


def test_bag_exceptions_have_ros1s_names(tmp_path: Path) -> None:
    bad = tmp_path / "x.bag"
    bad.write_bytes(b"")
    with pytest.raises(api.ROSBagException, match="empty file"):
        api.Bag(bad)
    assert issubclass(api.ROSBagUnindexedException, api.ROSBagException)
