"""roswtf's tf checks (tf's tfwtf plugin): its rules on what /tf carried, in its words."""

from __future__ import annotations

import threading
import time
from collections.abc import Callable
from typing import Any

from rosx.msg.codec.classes import get_message_class
from rosx.node import Node
from rosx_commands.roswtf.report import Findings
from rosx_commands.roswtf.tf_checks import check_tf, rules

TFMessage = get_message_class("tf2_msgs/TFMessage")
TransformStamped = get_message_class("geometry_msgs/TransformStamped")


def _message(*links: tuple[str, str], stamp: float = 100.0, w: float = 1.0) -> Any:
    transforms = []
    for parent, child in links:
        t = TransformStamped()
        t.header.frame_id = parent
        t.child_frame_id = child
        t.header.stamp.secs = int(stamp)
        t.transform.rotation.w = w
        transforms.append(t)
    return TFMessage(transforms)


def _findings(heard: list[tuple[Any, float, str]]) -> tuple[list[str], list[str]]:
    findings = Findings()
    findings.run(rules(heard))
    return findings.warnings, findings.errors


def test_a_quiet_tf_is_a_warning() -> None:
    assert _findings([]) == (["No tf messages"], [])


def test_tfs_rules_in_tfs_words() -> None:
    heard = [
        (_message(("world", "a"), ("a", "b")), 100.2, "/one"),
        (_message(("b", "a"), stamp=103.0, w=0.5), 100.5, "/two"),
    ]
    warnings, errors = _findings(heard)
    assert warnings == [
        "Received out-of-date/future transforms:\n"
        " * receiving transform from [/two] that differed from ROS time by 2.5s\n",
        "Received non-normalized rotation in transforms:\n"
        " * rotation from [b] to [a] is not unit length, 0.5\n",
    ]
    assert errors == [
        "TF re-parenting contention:\n * reparenting of [a] to [b] by [/two]\n",
        "TF cycle detection::\n"
        " * Frame a is in a loop. It's loop has elements:\na -> b\n"
        " * Frame b is in a loop. It's loop has elements:\nb -> a\n",
        "TF multiple authority contention:\n"
        " * node [/two] publishing transform [a] with parent [b] already published by node [/one]\n",
    ]


def test_the_checks_listen_to_tf_when_it_is_published(make_node: Callable[..., Node]) -> None:
    talker = make_node("talker")
    publisher = talker.advertise("/tf", TFMessage, queue_size=10)
    stop = threading.Event()

    def send() -> None:
        while not stop.wait(0.05):
            now = time.time()
            publisher.publish(_message(("world", "base"), stamp=now))

    sender = threading.Thread(target=send, daemon=True)
    sender.start()
    said: list[str] = []
    findings = Findings()
    try:
        check_tf(talker.master.uri, ["/rosout", "/tf"], findings, said.append)
    finally:
        stop.set()
        sender.join()
    assert said == ["running tf checks, this will take a second...", "... tf checks complete"]
    assert (findings.warnings, findings.errors) == ([], [])
    said.clear()
    check_tf(talker.master.uri, ["/rosout"], findings, said.append)
    assert said == []
