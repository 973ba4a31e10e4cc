"""Bags cut short at every record boundary, and with a byte damaged every few bytes.

Each opens as far as it is readable or is refused with `BagError`; ``rosbag reindex`` makes
every one of them a readable bag again, keeping every chunk whose record is whole (a damaged
chunk costs that chunk alone) and saying in one line what it kept and dropped; ``rosbag check``
of a damaged bag says so in one line. `tests/interop/test_corrupt_bags_ros1.py` puts the same
files through Debian's rosbag.
"""

from __future__ import annotations

import re
import shutil
from pathlib import Path

import pytest

from rosx.bag.errors import BagError
from rosx.bag.reader import BagReader
from rosx.bag.reindex import reindex
from tests.support.bags import MESSAGES, chunk_spans, record_ends, sample_bag
from tests.support.cli import rosx


@pytest.fixture(scope="module")
def whole(tmp_path_factory: pytest.TempPathFactory) -> Path:
    path = tmp_path_factory.mktemp("bags") / "whole.bag"
    sample_bag(path)
    return path


def _messages(path: Path) -> int | None:
    """How many messages the bag gives; None when it is refused (with BagError only)."""
    try:
        with BagReader(path) as bag:
            return sum(1 for _ in bag.messages())
    except BagError as error:
        assert str(error)
        return None


def test_a_bag_cut_at_any_record_boundary_keeps_every_whole_chunk(
    whole: Path, tmp_path: Path
) -> None:
    data = whole.read_bytes()
    spans = chunk_spans(whole)
    for end in record_ends(data):
        cut = tmp_path / f"cut{end}.bag"
        cut.write_bytes(data[:end])
        if end < len(data):
            assert _messages(cut) is None  # unindexed, as ROS 1 says
        report = reindex(cut)
        whole_chunks = [count for start, stop, count in spans if stop <= end]
        assert (report.chunks, report.messages) == (len(whole_chunks), sum(whole_chunks))
        assert _messages(cut) == sum(whole_chunks)


@pytest.mark.parametrize("compression", ["none", "bz2"])
def test_a_bag_damaged_anywhere_is_read_or_refused_and_reindexed(
    tmp_path: Path, compression: str
) -> None:
    original = tmp_path / "whole.bag"
    sample_bag(original, compression)
    data = original.read_bytes()
    most_in_a_chunk = max(count for _, _, count in chunk_spans(original))
    for pos in range(13, len(data), 31):
        damaged = bytearray(data)
        damaged[pos] ^= 0xFF
        path = tmp_path / f"flip{pos}.bag"
        path.write_bytes(bytes(damaged))
        _messages(path)
        reindex(path)
        kept = _messages(path)
        assert kept is not None, pos
        assert kept >= MESSAGES - most_in_a_chunk, pos


def test_rosbag_reindex_says_what_it_kept_and_dropped(whole: Path, tmp_path: Path) -> None:
    data = whole.read_bytes()
    first_chunk_end = chunk_spans(whole)[0][1]
    path = tmp_path / "cut.bag"
    path.write_bytes(data[: first_chunk_end + 30])
    result = rosx("rosbag", "reindex", "-q", str(path))
    assert result.status == 0
    assert (
        result.err
        == f"{path}: kept 2 messages in 1 chunk; dropped 30 bytes, damaged or cut short\n"
    )
    assert rosx("rosbag", "info", str(path)).status == 0


def test_rosbag_check_of_a_damaged_bag_says_so_in_one_line(whole: Path, tmp_path: Path) -> None:
    damaged = bytearray(whole.read_bytes())
    start = chunk_spans(whole)[1][0]
    damaged[start + 70] ^= 0xFF  # inside the second chunk's first record header
    path = tmp_path / "damaged.bag"
    path.write_bytes(bytes(damaged))
    result = rosx("rosbag", "check", str(path))
    assert result.status == 1
    assert result.err.startswith(f"ERROR reading {path}: ")
    assert result.err.endswith(".  Run rosbag reindex.\n")
    assert result.err.count("\n") == 1
    shutil.copyfile(path, tmp_path / "again.bag")
    assert rosx("rosbag", "reindex", "-q", str(tmp_path / "again.bag")).status == 0
    assert rosx("rosbag", "check", str(tmp_path / "again.bag")).out == (
        "Bag file does not need any migrations.\n"
    )


_LOG_TIME = r"\[\d+\.\d{9}\]"


@pytest.mark.parametrize(
    "content", [bytes(range(256)) * 40, b"a text file\n", b""], ids=["random", "text", "empty"]
)
def test_rosbag_play_of_a_file_that_is_no_bag_says_what_ros1s_says(
    tmp_path: Path, content: bytes
) -> None:
    path = tmp_path / "bad.bag"
    path.write_bytes(content)
    result = rosx("rosbag", "play", str(path))
    assert result.status == 1  # ROS 1's exits 0 (README.md)
    assert re.fullmatch(rf"\[ INFO\] {_LOG_TIME}: Opening {re.escape(str(path))}\n", result.out)
    assert re.fullmatch(rf"\[FATAL\] {_LOG_TIME}: Error reading version line\n", result.err)


@pytest.mark.parametrize("cut", ["unindexed", "cut short"])
def test_rosbag_play_of_an_unindexed_bag_says_to_reindex_it(
    whole: Path, tmp_path: Path, cut: str
) -> None:
    data = whole.read_bytes()
    path = tmp_path / "cut.bag"
    if cut == "unindexed":  # as a killed recorder leaves it: the header's index_pos is 0
        with BagReader(whole) as bag:
            index_pos = bag.index_pos
        field = b"index_pos=" + index_pos.to_bytes(8, "little")
        data = data.replace(field, b"index_pos=" + bytes(8), 1)[:index_pos]
    else:
        data = data[: chunk_spans(whole)[1][0] + 40]
    path.write_bytes(data)
    result = rosx("rosbag", "play", str(path))
    assert (result.status, result.err) == (
        1,
        f"Bag file {path} is unindexed.  Run rosbag reindex.\n",
    )
