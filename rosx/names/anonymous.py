"""Anonymous names: unique names built from a base, in ROS 1's two forms.

* `anonymous_name` is rosgraph's ``anonymous_name``: ``base_<hostname>_<pid>_<random int>``,
  used for resources that must not collide across machines.
* `anonymous_node_name` is what ``rospy.init_node(name, anonymous=True)`` registers, and so what
  ``rosnode list`` shows for ROS 1's own tools: ``base_<pid>_<milliseconds since the epoch>``.
* `roscpp_anonymous_name` is what roscpp's ``ros::init_options::AnonymousName`` registers (its
  C++ tools: tf_echo, map_server…): ``base_<wall time in nanoseconds>``.

The host name, process id, random source and clock are parameters so that tests can fix them.
"""

from __future__ import annotations

import os
import random
import socket
import sys
import time

__all__ = ["anonymous_name", "anonymous_node_name", "roscpp_anonymous_name"]

# Host names may hold "-" (RFC 952) and addresses "." or ":", none of them legal in a ROS name.
_ILLEGAL_HOST_CHARS = str.maketrans({".": "_", "-": "_", ":": "_"})


def anonymous_name(
    base: str,
    *,
    hostname: str | None = None,
    pid: int | None = None,
    rng: random.Random | None = None,
) -> str:
    """A name unlikely to be used by any other process on any machine.

    ``.``, ``-`` and ``:`` anywhere in the result become ``_``.

    Args:
        base: The stem, e.g. ``rostopic``.
        hostname: This machine's name; defaults to `socket.gethostname`.
        pid: This process's id; defaults to `os.getpid`.
        rng: Source of the random suffix (an int in ``[0, sys.maxsize]``); defaults to the
            `random` module's shared generator.

    Returns:
        E.g. ``rostopic_my_host_4242_3907618530164535313``.
    """
    host = socket.gethostname() if hostname is None else hostname
    process = os.getpid() if pid is None else pid
    suffix = (random if rng is None else rng).randint(0, sys.maxsize)
    return f"{base}_{host}_{process}_{suffix}".translate(_ILLEGAL_HOST_CHARS)


def anonymous_node_name(base: str, *, pid: int | None = None, now: float | None = None) -> str:
    """The name rospy gives an anonymous node.

    Args:
        base: The node's base name, e.g. ``rostopic``.
        pid: This process's id; defaults to `os.getpid`.
        now: Seconds since the epoch; defaults to `time.time`.

    Returns:
        E.g. ``rostopic_4242_1700000000123``.
    """
    process = os.getpid() if pid is None else pid
    millis = int((time.time() if now is None else now) * 1000)
    return f"{base}_{process}_{millis}"


def roscpp_anonymous_name(base: str, *, now_ns: int | None = None) -> str:
    """``base_<wall time in nanoseconds>``, as roscpp's ``init_options::AnonymousName`` names a
    node; ``now_ns`` defaults to `time.time_ns`."""
    return f"{base}_{time.time_ns() if now_ns is None else now_ns}"
