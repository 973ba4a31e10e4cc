"""``rosx rosbag play``'s options as a user sees them: what a subscriber receives, and when.

Each test runs the command as a process on the test's master and listens with a rosx
subscriber in this process. The keys (space, ``s``) are typed into a pseudo-terminal that is
the player's stdin.
"""

from __future__ import annotations

import os
import re
import select
import signal
import subprocess
import sys
import termios
import threading
import time
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest

from rosx.bag import api
from rosx.msg.codec.classes import get_message_class, get_service_class
from rosx.msg.codec.rostime import Time
from rosx.node import Node
from tests.support.cli import clean_environ, rosx
from tests.support.procs import stop, wait_for

String = get_message_class("std_msgs/String")
Clock = get_message_class("rosgraph_msgs/Clock")


def write_bag(path: Path, stamps: list[float], topics: tuple[str, ...] = ("/chatter",)) -> str:
    """A bag with one ``String`` per topic at each stamp (seconds); data ``TOPIC:INDEX``."""
    with api.Bag(path, "w") as bag:
        for i, stamp in enumerate(stamps):
            for topic in topics:
                bag.write(topic, String(data=f"{topic}:{i}"), Time.from_sec(100 + stamp))
    return str(path)


class Listener:
    """The data of every message received on ``topic``, in order."""

    def __init__(self, node: Node, topic: str, cls: Any = String) -> None:
        self.got: list[Any] = []
        self.at: list[float] = []
        self._lock = threading.Lock()
        self.sub = node.subscribe(topic, cls, self._heard)

    def _heard(self, msg: Any) -> None:
        with self._lock:
            self.got.append(getattr(msg, "data", msg))
            self.at.append(time.monotonic())

    def wait(self, count: int, timeout: float = 15.0) -> list[Any]:
        wait_for(lambda: len(self.got) >= count, timeout=timeout, what=f"{count} messages")
        with self._lock:
            return list(self.got)


class Play:
    """``rosx rosbag play ARGS…`` running; its output once it ends."""

    def __init__(
        self, master: str, args: list[str], stdin: Any = subprocess.DEVNULL, stdout: Any = None
    ) -> None:
        self.process = subprocess.Popen(
            [sys.executable, "-m", "rosx_commands", "rosbag", "play", *args],
            env=clean_environ(ROS_MASTER_URI=master),
            stdin=stdin,
            stdout=subprocess.PIPE if stdout is None else stdout,
            stderr=subprocess.PIPE,
            text=True,
            start_new_session=True,
        )
        self.out = ""
        self.err = ""

    def finish(self, timeout: float = 30) -> int:
        self.out, self.err = self.process.communicate(timeout=timeout)
        return self.process.returncode

    def interrupt(self) -> int:
        os.killpg(self.process.pid, signal.SIGINT)
        return self.finish()


@pytest.fixture
def play(master: str) -> Iterator[Callable[..., Play]]:
    started: list[Play] = []

    def start(*args: str, stdin: Any = subprocess.DEVNULL, stdout: Any = None) -> Play:
        started.append(Play(master, list(args), stdin, stdout))
        return started[-1]

    yield start
    for player in started:
        stop(player.process)


class Terminal:
    """A pseudo-terminal for the player's stdin and stdout: keys typed, screen text read (by a
    thread, so a player writing status lines never waits for the test)."""

    def __init__(self) -> None:
        self.keys, self.tty = os.openpty()
        self.text = ""
        self._done = threading.Event()
        self._reader = threading.Thread(target=self._read, daemon=True)
        self._reader.start()

    def _read(self) -> None:
        while not self._done.is_set():
            if select.select([self.keys], [], [], 0.05)[0]:
                try:
                    self.text += os.read(self.keys, 65536).decode(errors="replace")
                except OSError:  # every end of the terminal closed
                    return

    def type(self, keys: bytes) -> None:
        os.write(self.keys, keys)

    def wait_for_text(self, text: str) -> None:
        wait_for(lambda: text in self.text, what=f"{text!r} on the player's terminal")

    def close(self) -> None:
        self._done.set()
        self._reader.join()
        os.close(self.keys)
        os.close(self.tty)


@pytest.fixture
def terminal() -> Iterator[Terminal]:
    screen = Terminal()
    yield screen
    screen.close()


def write_messages(path: Path, messages: list[tuple[str, float, Any]]) -> str:
    """A bag of (topic, stamp in seconds after 100, message)."""
    with api.Bag(path, "w") as bag:
        for topic, stamp, msg in messages:
            bag.write(topic, msg, Time.from_sec(100 + stamp))
    return str(path)


def wait_for_publisher(listener: Listener) -> None:
    wait_for(
        lambda: listener.sub.get_num_connections() > 0,
        what="the player's publisher",
    )


def wait_for_keys(terminal: int) -> None:
    """Until the player reads keys one by one (its terminal out of line mode)."""
    wait_for(lambda: not termios.tcgetattr(terminal)[3] & termios.ICANON, what="the player's keys")


def test_pause_then_step_with_s_and_resume_with_space(
    make_node: Callable[..., Node], play: Callable[..., Play], tmp_path: Path
) -> None:
    bag = write_bag(tmp_path / "p.bag", [0.0, 0.01, 0.02, 0.03, 0.04])
    listener = Listener(make_node("listener"), "/chatter")
    keys, terminal = os.openpty()
    try:
        player = play("--pause", "-d", "0", bag, stdin=terminal)
        wait_for_publisher(listener)
        wait_for_keys(terminal)
        os.write(keys, b"s")
        assert listener.wait(1) == ["/chatter:0"]
        os.write(keys, b"s")
        assert listener.wait(2) == ["/chatter:0", "/chatter:1"]
        os.write(keys, b" ")
        assert listener.wait(5) == [f"/chatter:{i}" for i in range(5)]
        assert player.finish() == 0
    finally:
        os.close(keys)
        os.close(terminal)
    assert " [PAUSED ]  Bag Time:    100.000000   Duration: 0.000000 / 0.040000" in player.out
    assert " [RUNNING]  Bag Time:    100.0" in player.out
    assert player.out.endswith("\nDone.\n")


def test_space_pauses_a_running_playback(
    make_node: Callable[..., Node], play: Callable[..., Play], tmp_path: Path
) -> None:
    bag = write_bag(tmp_path / "slow.bag", [0.0, 0.1, 3600.0])
    listener = Listener(make_node("listener"), "/chatter")
    keys, terminal = os.openpty()
    try:
        player = play("-d", "0", "--wait-for-subscribers", bag, stdin=terminal)
        assert listener.wait(2) == ["/chatter:0", "/chatter:1"]
        wait_for_keys(terminal)
        os.write(keys, b" ")  # paused: the hour-long gap waits for the step
        os.write(keys, b"s")
        assert listener.wait(3) == ["/chatter:0", "/chatter:1", "/chatter:2"]
        assert player.finish() == 0
    finally:
        os.close(keys)
        os.close(terminal)


def test_clock_is_published_at_hz(
    make_node: Callable[..., Node], play: Callable[..., Play], tmp_path: Path
) -> None:
    bag = write_bag(tmp_path / "c.bag", [i * 0.1 for i in range(16)])
    node = make_node("listener")
    clock = Listener(node, "/clock", Clock)
    chatter = Listener(node, "/chatter")
    player = play("--clock", "--hz", "20", "-d", "0", "-q", "--wait-for-subscribers", bag)
    chatter.wait(16)
    assert player.finish() == 0
    times = [msg.clock.to_sec() for msg in clock.got]
    assert times == sorted(times)
    assert all(100.0 <= t <= 101.5 for t in times)
    gaps = sorted(b - a for a, b in zip(clock.at, clock.at[1:], strict=False))
    assert 0.025 < gaps[len(gaps) // 2] < 0.1  # about 1 / 20 Hz apart
    assert Clock._type == clock.sub.type


def test_loop_plays_again_until_interrupted(
    make_node: Callable[..., Node], play: Callable[..., Play], tmp_path: Path
) -> None:
    bag = write_bag(tmp_path / "l.bag", [0.0, 0.01, 0.02])
    listener = Listener(make_node("listener"), "/chatter")
    player = play("-l", "-q", "-d", "0", "--wait-for-subscribers", bag)
    assert listener.wait(7)[:7] == [f"/chatter:{i % 3}" for i in range(7)]
    assert player.process.poll() is None
    assert player.interrupt() == 0


def test_keep_alive_serves_latched_topics_after_the_end(
    make_node: Callable[..., Node], play: Callable[..., Play], tmp_path: Path
) -> None:
    path = tmp_path / "k.bag"
    header = {
        "callerid": "/talker",
        "latching": "1",
        "md5sum": String._md5sum,
        "message_definition": String._full_text,
        "type": String._type,
    }
    with api.Bag(path, "w") as bag:
        for i in range(3):
            bag.write("/latched", String(data=str(i)), Time(100 + i), connection_header=header)
    first = Listener(make_node("early"), "/latched")
    player = play("-k", "-q", "-d", "0", "--wait-for-subscribers", str(path))
    assert first.wait(3) == ["0", "1", "2"]
    late = Listener(make_node("late"), "/latched")
    assert late.wait(1) == ["2"]
    assert player.process.poll() is None
    assert player.interrupt() == 0
    assert player.out.endswith("\nDone.\n")


def test_start_and_duration_select_a_window_as_ros1(
    make_node: Callable[..., Node], play: Callable[..., Play], tmp_path: Path
) -> None:
    bag = write_bag(tmp_path / "w.bag", [i * 0.5 for i in range(7)])
    listener = Listener(make_node("listener"), "/chatter")
    player = play("-s", "1", "-u", "1", "-i", "--wait-for-subscribers", bag)
    assert player.finish() == 0
    assert listener.wait(3) == ["/chatter:2", "/chatter:3", "/chatter:4"]
    assert " [RUNNING]  Bag Time:    101.000000   Duration: 0.000000 / 1.000000" in player.out


@pytest.mark.parametrize(
    ("window", "status"),
    [
        (["-s", "-5"], "Bag Time:    100.000000   Duration: 0.000000 / 1.900000"),
        (["-u", "1.5"], "Bag Time:    100.000000   Duration: 0.000000 / 1.450000"),
        (["-s", "0.5", "-u", "1"], "Bag Time:    100.700000   Duration: 0.000000 / 0.750000"),
    ],
    ids=["before-the-start", "duration", "both"],
)
def test_the_status_line_counts_from_the_first_to_the_last_message_played_as_ros1s(
    play: Callable[..., Play], tmp_path: Path, window: list[str], status: str
) -> None:
    bag = write_bag(tmp_path / "s.bag", [0.0, 0.3, 0.7, 1.2, 1.45, 1.9])
    player = play("-i", "-d", "0", *window, bag)
    assert player.finish() == 0
    assert f"\n [RUNNING]  {status}               \n" in player.out  # a text pipe reads \r as \n


@pytest.mark.parametrize("rate", ["0", "-1"])
def test_a_rate_not_above_zero_is_one_error_line_and_plays_nothing(
    tmp_path: Path, rate: str
) -> None:
    bag = write_bag(tmp_path / "r.bag", [0.0, 0.5])
    result = rosx("rosbag", "play", "-r", rate, bag)
    assert result.status == 1
    assert result.out == ""
    said = (
        f"The rate (-r {rate}) must be greater than 0 "
        "(-i publishes without waiting, --pause starts paused)"
    )
    assert re.fullmatch(rf"\[FATAL\] \[\d+\.\d{{9}}\]: {re.escape(said)}\n", result.err)


def test_topics_and_remaps_choose_and_rename_what_is_played(
    make_node: Callable[..., Node], play: Callable[..., Play], tmp_path: Path
) -> None:
    bag = write_bag(tmp_path / "t.bag", [0.0, 0.01], topics=("/a", "/b", "/c"))
    node = make_node("listener")
    renamed = Listener(node, "/renamed")
    others = {topic: Listener(node, topic) for topic in ("/a", "/b", "/c")}
    player = play("-q", "--wait-for-subscribers", bag, "--topics", "/a", "/b", "/a:=/renamed")
    assert renamed.wait(2) == ["/a:0", "/a:1"]
    assert others["/b"].wait(2) == ["/b:0", "/b:1"]
    assert player.finish() == 0
    assert others["/a"].got == []
    assert others["/c"].got == []


def test_delay_waits_after_advertising(
    make_node: Callable[..., Node], play: Callable[..., Play], tmp_path: Path
) -> None:
    bag = write_bag(tmp_path / "d.bag", [0.0])
    listener = Listener(make_node("listener"), "/chatter")
    player = play("-d", "1.5", "-q", bag)
    wait_for_publisher(listener)
    advertised = time.monotonic()
    listener.wait(1)
    assert listener.at[0] - advertised >= 1.0
    assert player.finish() == 0
    assert "\nWaiting 1.5 seconds after advertising topics... done.\n" in player.out


def test_wait_for_subscribers_holds_playback_until_each_topic_has_one(
    make_node: Callable[..., Node], play: Callable[..., Play], tmp_path: Path
) -> None:
    bag = write_bag(tmp_path / "ws.bag", [0.0, 0.01], topics=("/a", "/b"))
    node = make_node("listener")
    first = Listener(node, "/a")
    player = play("-d", "0", "--wait-for-subscribers", bag)
    wait_for_publisher(first)
    second = Listener(node, "/b")
    assert first.wait(2) == ["/a:0", "/a:1"]
    assert second.wait(2) == ["/b:0", "/b:1"]
    assert player.finish() == 0
    assert "Waiting for subscribers.\nFinished waiting for subscribers.\n" in player.out


def test_skip_empty_jumps_over_long_gaps(
    make_node: Callable[..., Node], play: Callable[..., Play], tmp_path: Path
) -> None:
    bag = write_bag(tmp_path / "gap.bag", [0.0, 0.01, 3600.0, 3600.01])
    listener = Listener(make_node("listener"), "/chatter")
    player = play("--skip-empty", "1", "-q", "-d", "0", "--wait-for-subscribers", bag)
    assert listener.wait(4) == [f"/chatter:{i}" for i in range(4)]
    assert player.finish() == 0


def test_pause_topics_pause_before_each_of_their_messages_and_t_turns_it_off(
    make_node: Callable[..., Node], play: Callable[..., Play], tmp_path: Path, terminal: Terminal
) -> None:
    bag = write_messages(
        tmp_path / "pt.bag",
        [
            ("/chatter", 0.0, String(data="c0")),
            ("/marker", 0.01, String(data="m0")),
            ("/marker", 0.02, String(data="m1")),
            ("/chatter", 0.03, String(data="c1")),
        ],
    )
    node = make_node("listener")
    chatter, marker = Listener(node, "/chatter"), Listener(node, "/marker")
    player = play(
        "-d", "0", "--pause-topics", "/marker", "--wait-for-subscribers", bag,
        stdin=terminal.tty, stdout=terminal.tty,
    )  # fmt: skip
    assert chatter.wait(1) == ["c0"]
    # Paused before /marker's first message, at the bag time of the one before it.
    terminal.wait_for_text(" [PAUSED ]  Bag Time:    100.000000   Duration: 0.000000 / 0.030000")
    assert marker.got == []
    wait_for_keys(terminal.tty)
    terminal.type(b"t")  # no more pausing on /marker
    terminal.type(b" ")
    assert marker.wait(2) == ["m0", "m1"]
    assert chatter.wait(2) == ["c0", "c1"]
    terminal.wait_for_text("Done.")
    assert player.process.wait(30) == 0


def test_pause_topics_pause_again_on_the_next_message(
    make_node: Callable[..., Node], play: Callable[..., Play], tmp_path: Path, terminal: Terminal
) -> None:
    bag = write_messages(
        tmp_path / "again.bag",
        [("/marker", 0.0, String(data="m0")), ("/marker", 0.01, String(data="m1"))],
    )
    marker = Listener(make_node("listener"), "/marker")
    player = play(
        "-d", "0", "--pause-topics", "/marker", "--wait-for-subscribers", bag,
        stdin=terminal.tty, stdout=terminal.tty,
    )  # fmt: skip
    terminal.wait_for_text("[PAUSED ]")
    wait_for_keys(terminal.tty)
    terminal.type(b" ")
    assert marker.wait(1) == ["m0"]
    terminal.wait_for_text(" [PAUSED ]  Bag Time:    100.000000   Duration: 0.000000 / 0.010000")
    assert marker.got == ["m0"]
    terminal.type(b"s")
    assert marker.wait(2) == ["m0", "m1"]
    assert player.process.wait(30) == 0


PointStamped = get_message_class("geometry_msgs/PointStamped")


def test_rate_control_topic_holds_playback_until_its_stamps_catch_up(
    make_node: Callable[..., Node], play: Callable[..., Play], tmp_path: Path, terminal: Terminal
) -> None:
    bag = write_bag(tmp_path / "rc.bag", [0.0, 0.1, 0.2, 0.3, 0.4])
    node = make_node("listener")
    chatter = Listener(node, "/chatter")
    control = node.advertise("/rc", PointStamped, queue_size=10)
    player = play(
        "-d", "0", "--rate-control-topic", "/rc", "--rate-control-max-delay", "0.15",
        "--wait-for-subscribers", bag, stdin=terminal.tty, stdout=terminal.tty,
    )  # fmt: skip
    wait_for(lambda: control.get_num_connections() == 1, what="the player on /rc")
    # Three messages go (the bag time is then 0.2 s past the start), the fourth waits.
    assert chatter.wait(3) == ["/chatter:0", "/chatter:1", "/chatter:2"]
    terminal.wait_for_text(
        " [DELAYED]  Bag Time:    100.200000   Duration: 0.200000 / 0.400000   Delay: "
    )
    assert len(chatter.got) == 3
    stamp = PointStamped()
    stamp.header.stamp = Time(100, 250_000_000)
    control.publish(stamp)
    assert chatter.wait(5) == [f"/chatter:{i}" for i in range(5)]
    terminal.wait_for_text("Done.")
    assert player.process.wait(30) == 0
    screen = terminal.text
    assert "rc.bag\r\n\r\nCreating rate control topic subscriber... done.\r\nWaiting 0" in screen


def test_rate_control_topic_without_a_header_first_is_reported(
    make_node: Callable[..., Node], play: Callable[..., Play], tmp_path: Path, terminal: Terminal
) -> None:
    bag = write_bag(tmp_path / "bad.bag", [0.0, 3600.0])
    node = make_node("listener")
    chatter = Listener(node, "/chatter")
    control = node.advertise("/rc", String, queue_size=10)
    player = play(
        "-d", "0", "--rate-control-topic", "/rc", "--wait-for-subscribers", bag,
        stdin=terminal.tty, stdout=terminal.tty,
    )  # fmt: skip
    wait_for(lambda: control.get_num_connections() == 1, what="the player on /rc")
    assert chatter.wait(1) == ["/chatter:0"]
    control.publish(String(data="no header"))
    terminal.wait_for_text(
        "WARNING: Rate control topic is bad, header is not first. MSG may be malformed."
    )
    os.killpg(player.process.pid, signal.SIGINT)
    assert player.process.wait(30) == 0


def test_pause_playback_service_pauses_and_resumes_as_ros1s(
    make_node: Callable[..., Node], play: Callable[..., Play], tmp_path: Path
) -> None:
    bag = write_bag(tmp_path / "svc.bag", [0.0, 0.01, 0.02, 3600.0])
    node = make_node("listener")
    listener = Listener(node, "/chatter")
    player = play("--pause", "-q", "-d", "0", bag)
    wait_for_publisher(listener)

    def service() -> str | None:
        services = node.master.call("getSystemState")[2]
        return next((name for name, _ in services if name.endswith("/pause_playback")), None)

    wait_for(lambda: service() is not None, what="the player's pause_playback service")
    name = service()
    assert name is not None and name.startswith("/play_")
    client = node.service_client(name, get_service_class("std_srvs/SetBool"))

    def call(data: bool) -> tuple[bool, str]:
        answer = client.call(client.request_class(data=data))
        return answer.success, answer.message

    assert call(True) == (False, "Bag is already paused.")
    assert listener.got == []
    assert call(False) == (True, "Playback is now resumed")
    assert listener.wait(3) == [f"/chatter:{i}" for i in range(3)]
    assert call(True) == (True, "Playback is now paused")  # in the hour before the last one
    assert call(True) == (False, "Bag is already paused.")
    assert player.interrupt() == 0
    assert listener.got == [f"/chatter:{i}" for i in range(3)]
