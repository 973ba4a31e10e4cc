"""roswtf's tf checks (tf's ``tfwtf`` plugin): a second of ``/tf``, then its rules.

Warnings: no tf messages, transforms stamped more than a second away from the clock, rotations
that are not unit quaternions. Errors: a frame given two parents (re-parenting), a loop of
frames, a frame sent by two nodes (multiple authority); in tf's words. tf's plugin means to run
only when ``/tf`` is published, but its test (a ``filter`` object, always true on Python 3)
runs it, and says "No tf messages", on every graph; rosx's runs when ``/tf`` is published.
"""

from __future__ import annotations

import math
import threading
import time
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from collections.abc import Callable

    from rosx_commands.roswtf.report import Findings

#: How long tf's plugin listens (seconds).
LISTEN = 1.0
#: How deep tf's loop search goes.
_MAX_DEPTH = 100

Heard = list[tuple[Any, float, str]]


def rostime_delta(heard: Heard) -> list[str]:
    deltas: dict[str, float] = {}
    for message, received, callerid in heard:
        for t in message.transforms:
            delta = t.header.stamp.to_sec() - received
            if abs(delta) > 1.0 and abs(delta) > abs(deltas.get(callerid, 0.0)):
                deltas[callerid] = delta
    return [
        f"receiving transform from [{who}] that differed from ROS time by {delta}s"
        for who, delta in deltas.items()
    ]


def reparenting(heard: Heard) -> list[str]:
    errors: list[str] = []
    parents: dict[str, str] = {}
    for message, _, callerid in heard:
        for t in message.transforms:
            child, parent = t.child_frame_id, t.header.frame_id
            if child in parents and parents[child] != parent:
                text = f"reparenting of [{child}] to [{parent}] by [{callerid}]"
                if text not in errors:
                    errors.append(text)
            parents[child] = parent
    return errors


def cycle_detection(heard: Heard) -> list[str]:
    parents = {t.child_frame_id: t.header.frame_id for m, _, _ in heard for t in m.transforms}
    errors = []
    for frame in parents:
        chain = []
        current = frame
        for _ in range(_MAX_DEPTH + 2):
            chain.append(current)
            if current not in parents:
                break
            current = parents[current]
            if current == frame:
                errors.append(
                    f"Frame {frame} is in a loop. It's loop has elements:\n{' -> '.join(chain)}"
                )
                break
    return errors


def multiple_authority(heard: Heard) -> list[str]:
    errors: list[str] = []
    authority: dict[str, str] = {}
    for message, _, callerid in heard:
        for t in message.transforms:
            child = t.child_frame_id
            if child in authority and authority[child] != callerid:
                text = (
                    f"node [{callerid}] publishing transform [{child}] with parent "
                    f"[{t.header.frame_id}] already published by node [{authority[child]}]"
                )
                if text not in errors:
                    errors.append(text)
            authority[child] = callerid
    return errors


def not_normalized(heard: Heard) -> list[str]:
    errors = []
    for message, _, _ in heard:
        for t in message.transforms:
            q = t.transform.rotation
            length = math.sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w)
            if math.fabs(length - 1) > 1e-6:
                errors.append(
                    f"rotation from [{t.header.frame_id}] to [{t.child_frame_id}] is not unit "
                    f"length, {length}"
                )
    return errors


def rules(heard: Heard) -> list[tuple[str, Callable[[], object], str]]:
    """tf's warnings, then its errors, over what was heard."""
    return [
        ("warning", lambda: not heard, "No tf messages"),
        ("warning", lambda: rostime_delta(heard), "Received out-of-date/future transforms:"),
        (
            "warning",
            lambda: not_normalized(heard),
            "Received non-normalized rotation in transforms:",
        ),
        ("error", lambda: reparenting(heard), "TF re-parenting contention:"),
        ("error", lambda: cycle_detection(heard), "TF cycle detection::"),
        ("error", lambda: multiple_authority(heard), "TF multiple authority contention:"),
    ]


def check_tf(
    master_uri: str, published: list[str], findings: Findings, say: Callable[[str], None]
) -> None:
    """When ``/tf`` is among the ``published`` topics: listen a second, record tf's
    findings."""
    if "/tf" not in published:
        return
    from rosx.msg.codec.classes import get_message_class  # noqa: PLC0415 - message classes load on first use
    from rosx.names.anonymous import anonymous_node_name  # noqa: PLC0415 - name rules load only when used
    from rosx.node import Node  # noqa: PLC0415 - the node runtime loads with the first node

    say("running tf checks, this will take a second...")
    heard: Heard = []
    lock = threading.Lock()

    def handle(message: Any) -> None:
        callerid = (getattr(message, "_connection_header", None) or {}).get("callerid", "")
        with lock:
            heard.append((message, time.time(), callerid))

    node = Node(anonymous_node_name("roswtf"), master_uri=master_uri, environ={}).start()
    try:
        node.subscribe("/tf", get_message_class("tf/tfMessage"), handle)
        node.wait_for_shutdown(LISTEN)
    finally:
        node.shutdown("tf checks complete")
    say("... tf checks complete")
    with lock:
        findings.run(rules(list(heard)))


__all__ = ["check_tf", "rules"]
