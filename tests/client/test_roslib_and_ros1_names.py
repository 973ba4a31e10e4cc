"""Old scripts' ``roslib`` (and ``rospkg``, ``genpy``), and rospy's names in what scripts print.

The real ``teleop_twist_keyboard.py`` (fetched, never copied here) starts with
``import roslib; roslib.load_manifest(...)``: it runs under ``rosx run-script`` and publishes
``geometry_msgs/Twist`` on ``/cmd_vel`` for its keys. Tracebacks and ``repr`` name rospy's and
genpy's modules (``rospy.exceptions.ROSInitException``), which is what students search for.
"""

from __future__ import annotations

import contextlib
import os
import pty
import select
import subprocess
import sys
import termios
from collections.abc import Callable
from pathlib import Path
from typing import Any

from rosx.msg.codec.classes import get_message_class
from rosx.node import Node
from tests.support.cli import clean_environ
from tests.support.fetched import fetched_file
from tests.support.procs import stop, wait_for

Twist = get_message_class("geometry_msgs/Twist")


def _vector(twist: Any) -> tuple[float, ...]:
    linear, angular = twist.linear, twist.angular
    return (linear.x, linear.y, linear.z, angular.x, angular.y, angular.z)


def test_teleop_twist_keyboard_publishes_twist_for_its_keys(
    tmp_path: Path, master: str, make_node: Callable[[str], Node]
) -> None:
    script = fetched_file("ros-teleop/teleop_twist_keyboard", "teleop_twist_keyboard.py", tmp_path)
    twists: list[Any] = []
    listener = make_node("/base")
    subscriber = listener.subscribe("/cmd_vel", Twist, twists.append)
    main_fd, terminal_fd = pty.openpty()
    # Its README's own parameters, which make it wait for each key rather than look every
    # half second (each look starts by discarding what was typed, so a key typed as one look
    # ends is lost, on a slow machine now and then) and send its twist again ten times a
    # second (a key read while it was still sending the last twist is otherwise sent only
    # with the next key).
    process = subprocess.Popen(
        [sys.executable, "-m", "rosx_commands", "run-script", str(script),
         "_key_timeout:=600", "_repeat_rate:=10.0"],
        stdin=terminal_fd, stdout=terminal_fd, stderr=terminal_fd,
        env=clean_environ(ROS_MASTER_URI=master), start_new_session=True,
    )  # fmt: skip
    seen = bytearray()

    def printed(text: bytes) -> Callable[[], bool]:
        def arrived() -> bool:
            if select.select([main_fd], [], [], 0.05)[0]:
                with contextlib.suppress(OSError):
                    seen.extend(os.read(main_fd, 4096))
            return text in seen

        return arrived

    def reading_keys() -> bool:
        # The script puts its terminal in raw mode (discarding what was typed) each time it
        # waits for a key, and back between keys: a key typed between two waits is lost. The
        # discarding comes first, so a key typed once the raw mode shows is read.
        return not termios.tcgetattr(terminal_fd)[3] & termios.ICANON

    def key(keys: bytes, twist: tuple[float, ...]) -> None:
        wait_for(reading_keys, what="the script waiting for a key")
        os.write(main_fd, keys)
        wait_for(lambda: twists and _vector(twists[-1]) == twist, what=f"{twist} for {keys!r}")

    try:
        # A loaded machine may take a while to start Python twice (rosx, then the script).
        help_shown = printed(b"currently:\tspeed 0.5\tturn 1.0")
        wait_for(help_shown, timeout=60, what="the script's key help")
        wait_for(lambda: subscriber.get_num_connections() == 1, what="its publisher")
        assert b"Reading from the keyboard  and Publishing to Twist!" in seen
        key(b"i", (0.5, 0.0, 0.0, 0.0, 0.0, 0.0))
        key(b"j", (0.0, 0.0, 0.0, 0.0, 0.0, 1.0))
        key(b"q", (0.0, 0.0, 0.0, 0.0, 0.0, 1.1))  # 10 % faster
        key(b"k", (0.0,) * 6)
        key(b"I", (0.55, 0.0, 0.0, 0.0, 0.0, 0.0))
        os.write(main_fd, b"\x03")
        assert process.wait(15) == 0
        # it stops the robot as it leaves
        wait_for(lambda: _vector(twists[-1]) == (0.0,) * 6, what="the stopping twist")
    except TimeoutError as error:
        raise AssertionError(f"the script printed {bytes(seen)!r}") from error
    finally:
        stop(process)
        os.close(main_fd)
        os.close(terminal_fd)


PROBE = """\
import roslib; roslib.load_manifest('anything')
import sys, traceback
import genpy, rospkg, rospy
import roslib.message, roslib.names, roslib.packages
from geometry_msgs.msg import Twist
from std_srvs.srv import Empty, EmptyRequest
print(repr(rospy.Time(1, 5)), repr(rospy.Duration(2)), repr(genpy.Time(3)))
print(type(rospy.Time(1)), rospy.Duration.__mro__[1])
print(Twist, type(Twist().linear), Empty, EmptyRequest)
print(rospy.ROSInitException, rospy.ServiceException, rospy.Publisher, rospy.ServiceProxy)
print(genpy.Message, genpy.SerializationError, rospy.topics.Subscriber, rospy.timer.Rate)
print(roslib.message.get_message_class('geometry_msgs/Twist') is Twist,
      roslib.message.get_message_class('no_such/Type'), roslib.message.get_service_class('std_srvs/Empty'))
print(roslib.names.package_resource_name('std_msgs/String'), roslib.names.ns_join('/a', 'b'))
print(roslib.packages.get_pkg_dir('rospy_tutorials') == rospkg.RosPack().get_path('rospy_tutorials'))
print([p.rpartition('/')[2] for p in roslib.packages.find_node('roscpp_tutorials', 'talker')])
print(roslib.message.strify_message(Twist().linear))
try:
    rospkg.RosPack().get_path('no_such_package')
except rospkg.ResourceNotFound as error:
    print(type(error).__module__, repr(str(error)))
try:
    roslib.packages.get_pkg_dir('no_such_package')
except roslib.packages.InvalidROSPkgException as error:
    print(error)
rospy.get_rostime()
"""

PRINTED = """\
rospy.Time[1000000005] rospy.Duration[2000000000] genpy.Time[3000000000]
<class 'rospy.rostime.Time'> <class 'genpy.rostime.Duration'>
<class 'geometry_msgs.msg._Twist.Twist'> <class 'geometry_msgs.msg._Vector3.Vector3'> \
<class 'std_srvs.srv._Empty.Empty'> <class 'std_srvs.srv._Empty.EmptyRequest'>
<class 'rospy.exceptions.ROSInitException'> <class 'rospy.service.ServiceException'> \
<class 'rospy.topics.Publisher'> <class 'rospy.impl.tcpros_service.ServiceProxy'>
<class 'genpy.message.Message'> <class 'genpy.message.SerializationError'> \
<class 'rospy.topics.Subscriber'> <class 'rospy.timer.Rate'>
True None <class 'std_srvs.srv._Empty.Empty'>
('std_msgs', 'String') /a/b
True
['talker']
x: 0.0
y: 0.0
z: 0.0
rospkg.common 'no_such_package\\nROS path [0]=/nowhere'
Cannot locate installation of package no_such_package: \
b"[rospack] Error: package 'no_such_package' not found". ROS_ROOT[None] ROS_PACKAGE_PATH[/nowhere]
"""


def test_old_scripts_find_roslib_and_print_rospys_names(tmp_path: Path) -> None:
    """What one script prints: the texts of Debian's rospy, genpy, roslib and rospkg for the
    same lines (``ROS path`` listed once: Debian's rospkg adds its own ``/usr/share``)."""
    script = tmp_path / "probe.py"
    script.write_text(PROBE)
    done = subprocess.run(
        [sys.executable, "-m", "rosx_commands", "run-script", str(script)],
        capture_output=True, text=True, timeout=60, check=False,
        env=clean_environ(ROS_PACKAGE_PATH="/nowhere"),
    )  # fmt: skip
    assert done.stdout == PRINTED
    assert done.returncode == 1
    assert done.stderr == (
        "Traceback (most recent call last):\n"
        f'  File "{script}", line {PROBE.splitlines().index("rospy.get_rostime()") + 1}, '
        "in <module>\n"
        "    rospy.get_rostime()\n"
        "rospy.exceptions.ROSInitException: time is not initialized. Have you called init_node()?\n"
    )
