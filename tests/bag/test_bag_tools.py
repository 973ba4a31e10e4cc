"""The ROS tools that read bags (``rostopic echo/list -b``, ``rosmsg show -b``) and
``rosx rosbag``'s file commands, on bags written here; golden text as ROS 1 prints it."""

from __future__ import annotations

from pathlib import Path

import pytest

from rosx.bag import api
from rosx.bag.reader import BagReader
from rosx.msg.codec.classes import get_message_class
from rosx.msg.codec.rostime import Time
from tests.support.cli import rosx

String = get_message_class("std_msgs/String")
Twist = get_message_class("geometry_msgs/Twist")


@pytest.fixture
def bag(tmp_path: Path) -> str:
    path = tmp_path / "t.bag"
    with api.Bag(path, "w") as out:
        for i in range(3):
            twist = Twist()
            twist.linear.x = float(i)
            out.write("/cmd", twist, Time(10 + i))
            out.write("/chatter", String(data=f"hello {i}"), Time(10 + i, 1))
    return str(path)


def test_echo_from_a_bag(bag: str) -> None:
    result = rosx("rostopic", "echo", "-b", bag, "/chatter", "-n", "2")
    assert (result.status, result.out) == (0, 'data: "hello 0"\n---\ndata: "hello 1"\n---\n')
    every = rosx("rostopic", "echo", "-b", bag, "-a", "-n", "2")
    assert every.out.startswith("linear: \n  x: 0.0\n")
    assert every.out.endswith('---\ndata: "hello 0"\n---\n')
    plot = rosx("rostopic", "echo", "-p", "-b", bag, "/chatter")
    assert plot.out.splitlines()[:2] == ["%time,field.data", "10000000001,hello 0"]


@pytest.fixture
def scan_bag(tmp_path: Path) -> str:
    """One laser scan (header stamped 5 s, recorded at 20.000000007 s) and one tf message."""
    path = tmp_path / "scan.bag"
    scan = get_message_class("sensor_msgs/LaserScan")(ranges=[1.0, 2.0, 3.0])
    scan.header.seq, scan.header.stamp, scan.header.frame_id = 3, Time(5), "base_scan"
    transform = get_message_class("geometry_msgs/TransformStamped")(child_frame_id="b")
    with api.Bag(path, "w") as out:
        out.write("/scan", scan, Time(20, 7))
        out.write("/tf", get_message_class("tf2_msgs/TFMessage")([transform]), Time(21))
    return str(path)


@pytest.mark.parametrize(
    ("argv", "out", "err"),
    [
        (["/scan/header/frame_id"], '"base_scan"\n---\n', ""),
        (["/scan/ranges[0]"], "1.0\n---\n", ""),
        (["/scan/ranges[1:]"], "[2.0, 3.0]\n---\n", ""),
        (["/tf/transforms[0]/child_frame_id"], '"b"\n---\n', ""),
        (
            ["-p", "/scan/header"],
            "%time,field.seq,field.stamp,field.frame_id\n20000000007,3,5000000000,base_scan\n",
            "",
        ),
        (["/scan/nope"], "", "no field named nope in /nope\n"),
    ],
)
def test_echo_a_field_from_a_bag(scan_bag: str, argv: list[str], out: str, err: str) -> None:
    result = rosx("rostopic", "echo", "-b", scan_bag, *argv)
    assert (result.status, result.out, result.err) == (0, out, err)


def test_echo_plot_from_a_bag_times_rows_by_the_record(scan_bag: str) -> None:
    result = rosx("rostopic", "echo", "-b", scan_bag, "-p", "/scan")
    assert result.status == 0
    assert result.out.splitlines()[1].startswith("20000000007,3,5000000000,base_scan,")


def test_list_and_show_from_a_bag(bag: str) -> None:
    assert rosx("rostopic", "list", "-b", bag).out == "/cmd\n/chatter\n"
    shown = rosx("rosmsg", "show", "-b", bag, "geometry_msgs/Twist")
    assert shown.out.startswith("geometry_msgs/Vector3 linear\n  float64 x\n")


def test_filter_compress_decompress(bag: str, tmp_path: Path) -> None:
    out = str(tmp_path / "even.bag")
    result = rosx("rosbag", "filter", bag, out, "topic == '/cmd' and m.linear.x != 1")
    assert result.status == 0, result.err
    with api.Bag(out) as filtered:
        assert [m.linear.x for _, m, _ in filtered.read_messages()] == [0.0, 2.0]
    assert rosx("rosbag", "compress", "--lz4", "-q", bag).status == 0
    with BagReader(bag) as compressed:
        assert compressed.chunk_header(0).compression == "lz4"
        assert compressed.message_count() == 6
    assert Path(bag.replace(".bag", ".orig.bag")).exists()
    again = rosx("rosbag", "compress", bag)
    assert (
        again.err
        == f"Skipping {bag}. Backup path {bag.replace('.bag', '.orig.bag')} already exists.\n"
    )
    assert rosx("rosbag", "decompress", "-f", "-q", bag).status == 0
    with BagReader(bag) as plain:
        assert plain.chunk_header(0).compression == "none"


@pytest.mark.parametrize("command", ["compress", "decompress", "reindex"])
def test_a_file_that_is_no_bag_is_one_error_line_and_exit_1(
    bag: str, tmp_path: Path, command: str
) -> None:
    junk = tmp_path / "junk.bag"
    junk.write_bytes(bytes(range(256)) * 40)
    result = rosx("rosbag", command, str(junk), bag)
    assert result.status == 1
    said = result.err.splitlines()[0]  # reindex then says what it kept of the other
    assert said == f"ERROR reading {junk}: This does not appear to be a bag file"
    assert Path(bag.replace(".bag", ".orig.bag")).exists()  # the other file is done


def test_reindex_of_a_bag_cut_short(bag: str, tmp_path: Path) -> None:
    cut = tmp_path / "cut.bag.active"
    cut.write_bytes(Path(bag).read_bytes()[:4200])
    info = rosx("rosbag", "info", str(cut))
    assert (info.status, info.err) == (1, f"ERROR bag unindexed: {cut}.  Run rosbag reindex.\n")
    result = rosx("rosbag", "reindex", "-q", str(cut))
    assert result.status == 0
    assert "dropped" in result.err
    assert rosx("rosbag", "info", str(cut)).status == 0


def test_fix_and_encrypt_say_they_are_not_supported(bag: str, tmp_path: Path) -> None:
    fixed = rosx("rosbag", "fix", bag, str(tmp_path / "out.bag"))
    assert fixed.status == 1 and fixed.err.startswith("rosx does not support rosbag fix")
    assert rosx("rosbag", "encrypt", bag).status == 1


def test_progress_lines_are_ros1s(bag: str, tmp_path: Path) -> None:
    with BagReader(bag) as source:
        total = sum(source.chunk_header(i).size for i in range(len(source.chunks)))
    size = f"{total / 1024:.1f} KB"
    out = "o.bag"
    result = rosx("rosbag", "decompress", "--output-dir", str(tmp_path), bag)
    path = _shown(str(tmp_path / Path(bag).name))
    assert result.status == 0, result.err
    assert result.out == (
        f"\r {path:<43}   0%   0.0 KB / {size:>8} --:-- ETA"
        f"\r {path:<43} 100% {size:>19} 00:00    \n"
    )
    filtered = rosx("rosbag", "filter", bag, str(tmp_path / out), "True")
    shown = _shown(str(tmp_path / out))
    assert filtered.out.endswith(f"\r {shown:<43} 100% {size:>19} 00:00    \n")


def _shown(path: str) -> str:
    """A path as ROS 1's progress line shows it, 80 columns wide: its last 40 characters."""
    return path if len(path) <= 43 else "..." + path[-40:]
