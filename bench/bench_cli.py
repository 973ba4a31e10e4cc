"""Wall time of `rostopic list` and `rosnode list`: ROS 1's tools and rosx's, on one master.

Starts ROS 1's roscore on a free port with a few rospy nodes, then runs each command N times
alternating ROS 1 and rosx, and prints medians and the ratio rosx / ROS 1 (target: <= 0.3).

    python bench/bench_cli.py [--runs 15]
"""

from __future__ import annotations

import argparse
import os
import shutil
import statistics
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from tests.support.procs import free_port, port_open, running, wait_for
from tests.support.ros1 import ROS1_PYTHON, ros1_available, ros1_environ

NODE = """
import rospy
from std_msgs.msg import String
rospy.init_node('bench', anonymous=True)
pubs = [rospy.Publisher('/bench/t%d' % i, String, queue_size=1) for i in range(10)]
rospy.spin()
"""


def timed(args: list[str], env: dict[str, str]) -> float:
    start = time.perf_counter()
    subprocess.run(args, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
    return time.perf_counter() - start


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=15)
    runs = parser.parse_args().runs
    if not ros1_available():
        print('ROS 1 reference not installed: eval "$(../shared/tools/ros1-reference)"')
        return 1
    rosx = shutil.which("rosx") or str(Path(sys.executable).parent / "rosx")
    port = free_port()
    env = ros1_environ(ROS_MASTER_URI=f"http://localhost:{port}")
    rosx_env = {k: v for k, v in env.items() if k != "ROS_PACKAGE_PATH"}
    with running(["/usr/bin/roscore", "-p", str(port)], env):
        wait_for(lambda: port_open(port), what="roscore")
        with running([ROS1_PYTHON, "-c", NODE], env), running([ROS1_PYTHON, "-c", NODE], env):
            time.sleep(3)
            print(f"{'command':<16}{'ROS 1 (s)':>12}{'rosx (s)':>12}{'ratio':>8}")
            for tool in ("rostopic", "rosnode"):
                ros1_times, rosx_times = [], []
                for _ in range(runs):
                    ros1_times.append(timed([f"/usr/bin/{tool}", "list"], env))
                    rosx_times.append(timed([rosx, tool, "list"], rosx_env))
                a, b = statistics.median(ros1_times), statistics.median(rosx_times)
                print(f"{tool + ' list':<16}{a:>12.3f}{b:>12.3f}{b / a:>8.2f}")
    print(f"(medians of {runs} runs; python {sys.version.split()[0]}, {os.cpu_count()} cores)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
