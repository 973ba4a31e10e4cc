"""What comparisons take out of ROS 1's stderr (`tests.support.ros1.without_ros1_noise`): rospy's
shutdown race, exactly as Debian's ``rosservice call`` printed it after its answer, and no
other traceback."""

from __future__ import annotations

from tests.support.ros1 import ROSDEP_UNSET, without_ros1_noise

ANSWER = (
    "ERROR: Incompatible arguments to call service:\n"
    "No field name [x:1]\n"
    "Provided arguments are:\n"
    " * {'x:1': None} (type dict)\n"
    "\n"
    "Service arguments are: [x y theta name]\n"
)
ACCEPT_RACE = """\
Exception in thread Thread-4 (run):
Traceback (most recent call last):
  File "/usr/lib/python3.11/threading.py", line 1038, in _bootstrap_inner
    self.run()
  File "/usr/lib/python3.11/threading.py", line 975, in run
    self._target(*self._args, **self._kwargs)
  File "/usr/lib/python3/dist-packages/rospy/impl/tcpros_base.py", line 161, in run
    (client_sock, client_addr) = self.server_sock.accept()
                                 ^^^^^^^^^^^^^^^^^^^^^^^^^
  File "/usr/lib/python3.11/socket.py", line 294, in accept
    fd, addr = self._accept()
               ^^^^^^^^^^^^^^
OSError: [Errno 9] Bad file descriptor
"""


def test_rospys_accept_race_and_the_rosdep_line_are_taken_out() -> None:
    assert without_ros1_noise(ROSDEP_UNSET + ANSWER + ACCEPT_RACE) == ANSWER


def test_any_other_traceback_stays() -> None:
    other_error = ACCEPT_RACE.replace("[Errno 9] Bad file descriptor", "[Errno 22] Invalid")
    other_place = ACCEPT_RACE.replace("tcpros_base.py", "tcpros_service.py")
    handler = ACCEPT_RACE.replace("in run\n    (client_sock", "in run\n    handler(client_sock")
    for stderr in (other_error, other_place, handler):
        assert without_ros1_noise(ANSWER + stderr) == ANSWER + stderr
