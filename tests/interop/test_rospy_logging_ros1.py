"""One script, two rospys: a handler the script adds to ``logging.getLogger('rosout')`` sees the
same records (logger, level, message, place) under Debian's rospy and under rosx's
(``rosx run-script``), and the console shows the same lines.

Skipped where ROS 1's rospy is absent.
"""

from __future__ import annotations

import re
import subprocess
from pathlib import Path

import pytest

from rosx.master.server import MasterThread
from tests.support.cli import clean_environ
from tests.support.ros1 import ROS1_PYTHON, ros1_python_imports
from tests.support.scripts import script_command

pytestmark = pytest.mark.skipif(
    not ros1_python_imports("rospy", "rosgraph"), reason="ROS 1's rospy is absent"
)

PROBE = r"""
import logging
import rospy
import rosgraph.roslogging
import rospy.impl.rosout

class Seen(logging.Handler):
    def emit(self, record):
        print("seen", record.name, record.levelno, record.levelname, repr(record.getMessage()),
              record.filename, record.funcName, bool(record.exc_info), flush=True)

rospy.init_node("probe")
logger = logging.getLogger("rosout")
print("handlers", len(logger.handlers),
      isinstance(logger.handlers[0], rosgraph.roslogging.RosStreamHandler),
      isinstance(logger.handlers[1], rospy.impl.rosout.RosOutHandler), flush=True)
logger.addHandler(Seen())

class Part:
    def work(self):
        rospy.loginfo("in a method %s %d", "x", 3)

Part().work()
rospy.logdebug("below the level")
rospy.logwarn("careful")
rospy.logerr("broken: %s", [1, 2])
rospy.logfatal("gone")
rospy.loginfo("from a part", logger_name="part")
for _ in range(3):
    rospy.loginfo_throttle(60, "throttled")
    rospy.logwarn_once("once")
    rospy.logerr_throttle_identical(60, "same")
try:
    1 / 0
except ZeroDivisionError:
    rospy.logerr("with a traceback", exc_info=True)
logger.setLevel(logging.DEBUG)
rospy.logdebug("now shown")
"""

STAMP = re.compile(r"\[\d+\.\d+\]")


def _run(command: list[str], home: Path) -> tuple[list[str], list[str], list[str]]:
    """The handler's records, the stdout lines and the stderr lines (stamps blanked)."""
    with MasterThread(port=0, host="127.0.0.1", advertised_host="127.0.0.1") as master:
        env = clean_environ(ROS_MASTER_URI=master.uri, ROS_HOME=str(home), PYTHONWARNINGS="ignore")
        done = subprocess.run(
            command, env=env, capture_output=True, text=True, timeout=120, check=False
        )
    assert done.returncode == 0, done.stderr
    out = STAMP.sub("[T]", done.stdout).splitlines()
    # The traceback's frames name the script as each Python was given it; its last line is kept.
    err = [line for line in STAMP.sub("[T]", done.stderr).splitlines() if line[:1] != " "]
    seen = [line for line in out if not line.startswith("[")]
    return seen, [line for line in out if line.startswith("[")], err


def test_a_handler_on_rosout_sees_the_same_records(tmp_path: Path) -> None:
    script = tmp_path / "probe.py"
    script.write_text(PROBE)
    theirs = _run([ROS1_PYTHON, str(script)], tmp_path)
    ours = _run(script_command(script), tmp_path)
    assert ours == theirs
    seen, out, err = ours
    assert seen[:3] == [
        "handlers 2 True True",
        "seen rosout 20 INFO 'in a method x 3' probe.py Part.work False",
        "seen rosout 30 WARNING 'careful' probe.py <module> False",
    ]
    assert "seen rosout.part 20 INFO 'from a part' probe.py <module> False" in seen
    assert "seen rosout 40 ERROR 'with a traceback' probe.py <module> True" in seen
    assert [line for line in seen if "throttled" in line or "once" in line] == [
        "seen rosout 20 INFO 'throttled' probe.py <module> False",
        "seen rosout 30 WARNING 'once' probe.py <module> False",
    ]
    assert out[-1] == "[DEBUG] [T]: now shown"
    assert err[:2] == ["[WARN] [T]: careful", "[ERROR] [T]: broken: [1, 2]"]
