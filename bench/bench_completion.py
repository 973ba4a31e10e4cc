"""Tab completion: wall time of rosx's answer to a <TAB>, beside the ROS 1 commands rosbash's
completion runs for the same <TAB>.

rosbash completes ``roscd ros<TAB>`` with ``rospack list-names`` (and a stack listing),
``rostopic echo <TAB>`` with ``rostopic list``, ``rosnode info <TAB>`` with ``rosnode list``,
``rostopic pub /t geometry_msgs/Twist <TAB>`` with ``rosmsg-proto msg -s``; rosx answers each
with the one process its shell functions start (`rosx_commands.invocation.complete_command`:
Python without ``site``). Both against one master (rosx's roscore on a free port), on ROS 1's
interpreter, medians of ``--runs`` runs, ratio rosx / ROS 1. For ``rosmsg show pkg/Ty<TAB>``
rosbash runs ``rospack list``, ``rospack find`` and ``find``; only ``rospack find`` is timed, a
lower bound. `bench_package_index.py` times a <TAB> with a large package path.

    python bench/bench_completion.py [--runs 11]
"""

from __future__ import annotations

import argparse
import shlex
import shutil
import statistics
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from bench import interpreter
from rosx.workspace.environment import SHARE
from rosx_commands.invocation import complete_command
from tests.support.procs import free_port, port_open, running, wait_for
from tests.support.ros1 import ros1_available, ros1_environ

ROSX = [sys.executable, "-m", "rosx_commands"]

#: (what is completed, the words rosx's completion is given, the ROS 1 command rosbash runs)
CASES = [
    ("roscd ros<TAB>", ["1", "roscd", "ros"], ["/usr/bin/rospack", "list-names"]),
    ("rostopic echo <TAB>", ["2", "rostopic", "echo", ""], ["/usr/bin/rostopic", "list"]),
    ("rosnode info <TAB>", ["2", "rosnode", "info", ""], ["/usr/bin/rosnode", "list"]),
    (
        "rostopic pub /t geometry_msgs/Twist <TAB>",
        ["4", "rostopic", "pub", "/t", "geometry_msgs/Twist", ""],
        ["/usr/bin/rosmsg-proto", "msg", "-s", "geometry_msgs/Twist"],
    ),
    (
        "rosmsg show geometry_msgs/Tw<TAB>",
        ["2", "rosmsg", "show", "geometry_msgs/Tw"],
        ["/usr/bin/rospack", "find", "geometry_msgs"],
    ),
]


def timed(argv: list[str], env: dict[str, str]) -> float:
    start = time.perf_counter()
    subprocess.run(argv, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
    return time.perf_counter() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--runs", type=int, default=11)
    interpreter.add_option(parser)
    options = parser.parse_args()
    interpreter.run_on(options.python)
    runs = options.runs
    tab = shlex.split(complete_command())
    port = free_port()
    uri = f"http://127.0.0.1:{port}"
    env = ros1_environ(ROS_MASTER_URI=uri)
    # rosx as `rosx shell-init` sets it up: its own share/ on the package path (Debian's tools
    # need /usr/share, which rospack's cache makes cheap for them and a crawl expensive for rosx).
    ours_env = {**env, "ROS_PACKAGE_PATH": str(SHARE)}
    ros1 = ros1_available() and shutil.which("rospack", path="/usr/bin") is not None
    with running([*ROSX, "roscore", "-p", str(port)], env):
        wait_for(lambda: port_open(port), what="roscore")
        print(f"{'completion':45} {'rosx (s)':>9} {'ROS 1 (s)':>9} {'ratio':>6}")
        for what, ours, theirs in CASES:
            timed([*tab, *ours], ours_env)
            rosx_times = [timed([*tab, *ours], ours_env) for _ in range(runs)]
            rosx_median = statistics.median(rosx_times)
            if ros1:
                timed(theirs, env)
                ros1_median = statistics.median(timed(theirs, env) for _ in range(runs))
                print(
                    f"{what:45} {rosx_median:9.3f} {ros1_median:9.3f} "
                    f"{rosx_median / ros1_median:6.2f}"
                )
            else:
                print(f"{what:45} {rosx_median:9.3f} {'-':>9} {'-':>6}")


if __name__ == "__main__":
    main()
