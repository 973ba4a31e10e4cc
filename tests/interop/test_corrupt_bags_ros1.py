"""Damaged bags through Debian's rosbag and through rosx: rosx never keeps fewer messages.

The same files (a bag cut at every record boundary, and with a byte damaged every few dozen
bytes) are read as they are and after a reindex (what ``rosbag reindex`` does) by ROS 1's
rosbag, in one process of its Python, and by rosx. ROS 1's reindex loses the chunks whose
index records were cut, fails outright on a cut index, and its reader lets KeyError and
UnicodeDecodeError out on damaged records; rosx's reindex makes every file a readable bag,
and keeps at least as many messages as ROS 1's on each.
"""

from __future__ import annotations

import json
import shutil
import subprocess
from pathlib import Path

import pytest

from rosx.bag.errors import BagError
from rosx.bag.reader import BagReader
from rosx.bag.reindex import reindex
from tests.support.bags import record_ends, sample_bag
from tests.support.ros1 import ROS1_PYTHON, needs_ros1, ros1_python_imports

pytestmark = [
    needs_ros1,
    pytest.mark.skipif(not ros1_python_imports("rosbag"), reason="ROS 1's rosbag is absent"),
]

#: Each file: messages read as it is, then after ROS 1's reindex ("-" when either fails).
ROS1_READER = """
import json, shutil, sys
import rosbag

def count(path):
    try:
        with rosbag.Bag(path) as bag:
            return sum(1 for _ in bag.read_messages())
    except Exception as error:
        return type(error).__name__

results = {}
for path in sys.argv[1:]:
    before = count(path)
    copy = path + ".ros1.bag"
    shutil.copyfile(path, copy)
    try:
        bag = rosbag.Bag(copy, "a", allow_unindexed=True)
        for _ in bag.reindex():
            pass
        bag.close()
        after = count(copy)
    except Exception as error:
        after = type(error).__name__
    results[path] = [before, after]
print(json.dumps(results))
"""


def _rosx(path: Path) -> tuple[int | str, int | str]:
    def count() -> int | str:
        try:
            with BagReader(path) as bag:
                return sum(1 for _ in bag.messages())
        except BagError as error:
            return type(error).__name__

    before = count()
    reindex(path)
    return before, count()


def test_rosx_keeps_at_least_what_ros1_keeps_of_every_damaged_bag(tmp_path: Path) -> None:
    whole = tmp_path / "whole.bag"
    sample_bag(whole)
    data = whole.read_bytes()
    files = []
    for end in record_ends(data)[:-1]:
        files.append(tmp_path / f"cut{end}.bag")
        files[-1].write_bytes(data[:end])
    for pos in range(13, len(data), 53):
        damaged = bytearray(data)
        damaged[pos] ^= 0xFF
        files.append(tmp_path / f"flip{pos}.bag")
        files[-1].write_bytes(bytes(damaged))
    done = subprocess.run(
        [ROS1_PYTHON, "-c", ROS1_READER, *map(str, files)],
        capture_output=True,
        text=True,
        timeout=300,
        check=True,
    )
    ros1 = json.loads(done.stdout)
    ros1_total = rosx_total = 0
    for path in files:
        copy = tmp_path / f"{path.stem}.rosx.bag"
        shutil.copyfile(path, copy)
        _, after = _rosx(copy)
        assert isinstance(after, int), f"{path.name}: rosx's reindex left {after}"
        ros1_after = ros1[str(path)][1]
        if isinstance(ros1_after, int):
            assert after >= ros1_after, f"{path.name}: rosx kept {after}, ROS 1 {ros1_after}"
            ros1_total += ros1_after
        rosx_total += after
    assert rosx_total > ros1_total
