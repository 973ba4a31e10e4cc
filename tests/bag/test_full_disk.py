"""A full disk: writing stops with one clear error and leaves a bag of what was written.

The disk is a file object that takes at most ``room`` bytes (as a full file system does: a short
write, then ``ENOSPC``; cutting the file back frees its room again), injected as the writer's
opener. A real small file system (tmpfs, root only) checks the same through the CLI.
"""

from __future__ import annotations

import errno
import io
import os
import shutil
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any, BinaryIO

import pytest

from rosx.bag.reader import BagReader
from rosx.bag.recorder import Recorder, RecordOptions
from rosx.bag.writer import BagWriter
from rosx.msg.codec.classes import get_message_class
from rosx.node import Node
from tests.support.procs import free_port, stop, wait_for

String = get_message_class("std_msgs/String")
ROSBAG = [sys.executable, "-m", "rosx_commands", "rosbag"]


class SmallDisk(io.RawIOBase):
    """A file that may grow to ``room`` bytes; past that a write fails with ``ENOSPC``."""

    def __init__(self, path: str, mode: str, room: int) -> None:
        self.raw = Path(path).open(mode, buffering=0)  # noqa: SIM115 - closed by close()
        self.room = room

    def writable(self) -> bool:
        return True

    def write(self, data: Any) -> int:
        free = self.room - self.raw.tell()
        if free <= 0:
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
        return self.raw.write(memoryview(data)[:free])

    def seek(self, offset: int, whence: int = 0) -> int:
        return self.raw.seek(offset, whence)

    def tell(self) -> int:
        return self.raw.tell()

    def truncate(self, size: int | None = None) -> int:
        return self.raw.truncate(size)

    def close(self) -> None:
        self.raw.close()
        super().close()


def small_disk(room: int) -> Callable[[str, str], BinaryIO]:
    def opener(path: str, mode: str) -> BinaryIO:
        return SmallDisk(path, mode, room)  # type: ignore[return-value]

    return opener


def _serialized(text: str) -> bytes:
    buff = io.BytesIO()
    String(data=text).serialize(buff)
    return buff.getvalue()


def _header() -> dict[str, str]:
    return {
        "callerid": "/talker",
        "md5sum": String._md5sum,
        "message_definition": String._full_text,
        "topic": "/chatter",
        "type": String._type,
    }


def _texts(path: Path) -> list[str]:
    with BagReader(path) as bag:
        return [String().deserialize(d).data for _, _, d in bag.messages()]


def test_a_writer_that_runs_out_of_room_keeps_every_complete_chunk(tmp_path: Path) -> None:
    path = tmp_path / "full.bag"
    writer = BagWriter(path, chunk_threshold=1000, opener=small_disk(20_000))
    conn = writer.add_connection("/chatter", _header())
    written = 0
    with pytest.raises(OSError, match="No space left on device") as failure:
        for i in range(10_000):
            writer.write(conn, 10**9 + i, _serialized(f"message {i:05d} " + "x" * 40))
            written = i + 1
    assert failure.value.errno == errno.ENOSPC
    with pytest.raises(OSError, match="No space left on device"):
        writer.write(conn, 2 * 10**9, _serialized("after"))
    writer.close()
    kept = writer.message_count  # the index may have needed the room of the last chunks
    assert 0 < kept < written
    assert path.stat().st_size <= 20_000
    assert _texts(path) == [f"message {i:05d} " + "x" * 40 for i in range(kept)]
    from rosbags.rosbag1 import Reader

    with Reader(path) as other:
        assert other.message_count == kept


def test_a_full_disk_before_the_first_chunk_leaves_an_empty_bag_that_opens(
    tmp_path: Path,
) -> None:
    path = tmp_path / "tiny.bag"
    writer = BagWriter(path, chunk_threshold=100_000, opener=small_disk(5000))
    conn = writer.add_connection("/chatter", _header())
    for i in range(50):
        writer.write(conn, 10**9 + i, _serialized("x" * 200))
    with pytest.raises(OSError):
        writer.close()
    with BagReader(path) as bag:
        assert bag.message_count() == 0
        assert bag.connections == {}


def test_no_room_for_the_bag_header_is_an_error_and_leaves_no_file(tmp_path: Path) -> None:
    path = tmp_path / "none.bag"
    with pytest.raises(OSError, match="No space left on device"):
        BagWriter(path, opener=small_disk(100))
    assert not path.exists()


def test_recording_onto_a_full_disk_stops_with_one_error_and_a_bag_that_opens(
    make_node: Callable[..., Node], tmp_path: Path
) -> None:
    logged: list[tuple[str, str]] = []
    talker = make_node("talker")
    pub = talker.advertise("/chatter", String, queue_size=None)
    recorder = Recorder(
        make_node("record"),
        RecordOptions(
            topics=["/chatter"], prefix=str(tmp_path / "rec"), append_date=False, chunk_size=2048
        ),
        lambda level, text: logged.append((level, text)),
        opener=small_disk(50_000),
    )
    recorder.start()
    wait_for(lambda: pub.get_num_connections() == 1, what="the recorder")
    sent = 0
    while not recorder.stopping and sent < 100_000:
        pub.publish(String(data=f"message {sent:06d} " + "x" * 100))
        sent += 1
    wait_for(lambda: recorder.stopping, what="the recorder to stop by itself")
    recorder.stop()
    errors = [text for level, text in logged if level == "ERROR"]
    assert len(errors) == 1
    kept = _texts(tmp_path / "rec.bag")
    assert errors[0] == (
        f"Error writing to '{tmp_path}/rec.bag': No space left on device.  Recording stopped; "
        f"the bag keeps the {len(kept)} messages written before."
    )
    assert recorder.error == errors[0]
    assert not (tmp_path / "rec.bag.active").exists()
    assert 0 < len(kept) < sent
    assert kept == [f"message {i:06d} " + "x" * 100 for i in range(len(kept))]


@pytest.mark.skipif(
    sys.platform != "linux" or os.geteuid() != 0 or shutil.which("mount") is None,
    reason="mounting a small tmpfs needs Linux and root",
)
def test_rosbag_record_on_a_full_file_system(tmp_path: Path) -> None:
    disk = tmp_path / "disk"
    disk.mkdir()
    mounted = subprocess.run(
        ["mount", "-t", "tmpfs", "-o", "size=256k", "tmpfs", str(disk)],
        capture_output=True,
        check=False,
    )
    if mounted.returncode != 0:
        pytest.skip(f"cannot mount a tmpfs here: {mounted.stderr.decode().strip()}")
    try:
        _record_until_full(disk)
    finally:
        subprocess.run(["umount", str(disk)], check=False)


def _record_until_full(disk: Path) -> None:
    from rosx.master.server import MasterThread

    with MasterThread(port=free_port(), host="127.0.0.1", advertised_host="127.0.0.1") as core:
        environ = {**os.environ, "ROS_MASTER_URI": core.uri, "ROS_HOME": str(disk.parent)}
        record = subprocess.Popen(
            [*ROSBAG, "record", "--chunksize", "16", "-O", "full", "/chatter"],
            cwd=disk,
            env=environ,
            stdin=subprocess.DEVNULL,
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
            start_new_session=True,
        )
        node = Node("talker", master_uri=core.uri, environ={}).start()
        try:
            pub = node.advertise("/chatter", String, queue_size=None)
            wait_for(lambda: pub.get_num_connections() == 1, what="the recorder")
            sent = 0
            while record.poll() is None and sent < 200_000:
                pub.publish(String(data=f"message {sent:06d} " + "x" * 100))
                sent += 1
            _, err = record.communicate(timeout=30)
        finally:
            node.shutdown("test over")
            stop(record)
    assert record.returncode == 1
    lines = [line for line in err.splitlines() if line]
    assert len(lines) == 1
    assert lines[0].startswith("[ERROR] [")
    assert lines[0].endswith(
        "]: Error writing to 'full.bag': No space left on device.  Recording stopped; "
        f"the bag keeps the {len(_texts(disk / 'full.bag'))} messages written before."
    )
    assert not (disk / "full.bag.active").exists()
    kept = _texts(disk / "full.bag")
    assert kept == [f"message {i:06d} " + "x" * 100 for i in range(len(kept))]
    assert kept
