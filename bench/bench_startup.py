"""Start-up: wall time of the ROS-named tools' common commands and of a short rospy script.

Each command runs as a new process, ROS 1's (Debian's) and rosx's alternately, against one
master: ROS 1's roscore, then rosx's, each on a free port with two rospy nodes of ten topics.
Medians of ``--runs`` runs, and the ratio rosx / ROS 1 (targets: 0.3 for a command, 0.4 for the
script). The script is ``init_node`` + a ``Publisher`` + its first ``publish`` + exit, run with
Debian's Python and rospy, and with ``rosx run-script``; then both through ``rosrun`` from a
package.

    python bench/bench_startup.py [--runs 11] [--master ros1|rosx|both] [--only SUBSTRING]

rosx's commands run from the ``rosx`` console script, without ``ROS_PACKAGE_PATH`` (rosx ships
the standard types; ROS 1's tools need the path to find theirs).
"""

from __future__ import annotations

import argparse
import contextlib
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
import xmlrpc.client
from collections.abc import Iterator
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from bench import interpreter
from tests.support.procs import free_port, port_open, running, wait_for
from tests.support.ros1 import ROS1_PYTHON, ros1_available, ros1_environ

COMMAND_TARGET = 0.3
SCRIPT_TARGET = 0.4

NODE = """
import rospy
from std_msgs.msg import String
rospy.init_node('bench', anonymous=True)
pubs = [rospy.Publisher('/bench/t%d' % i, String, queue_size=1) for i in range(10)]
rospy.spin()
"""

SCRIPT = """\
#!/usr/bin/env python3
import rospy
from geometry_msgs.msg import Twist

rospy.init_node("startup", anonymous=True)
publisher = rospy.Publisher("/turtle1/cmd_vel", Twist, queue_size=1)
twist = Twist()
twist.linear.x = 1.0
publisher.publish(twist)
"""

PACKAGE_XML = """\
<?xml version="1.0"?>
<package format="2">
  <name>startup_bench</name>
  <version>0.0.0</version>
  <description>start-up benchmark</description>
  <maintainer email="bench@example.com">bench</maintainer>
  <license>BSD</license>
  <buildtool_depend>catkin</buildtool_depend>
</package>
"""

#: Each tool's common commands (ROS 1's spelling; rosx takes the same words after ``rosx``).
COMMANDS: list[list[str]] = [
    ["rostopic", "list"],
    ["rostopic", "type", "/rosout"],
    ["rostopic", "info", "/rosout"],
    ["rosnode", "list"],
    ["rosnode", "info", "/rosout"],
    ["rosparam", "get", "/"],
    ["rosparam", "list"],
    ["rosservice", "list"],
    ["rosservice", "type", "/rosout/get_loggers"],
    ["rosmsg", "show", "geometry_msgs/Twist"],
    ["rossrv", "show", "std_srvs/Empty"],
    ["rosmsg", "md5", "turtlesim/Pose"],
    ["rospack", "find", "turtlesim"],
]


def timed(args: list[str], env: dict[str, str]) -> float:
    start = time.perf_counter()
    done = subprocess.run(args, env=env, capture_output=True, check=False)
    elapsed = time.perf_counter() - start
    if done.returncode != 0:
        raise SystemExit(f"{' '.join(args)} failed ({done.returncode}): {done.stderr.decode()}")
    return elapsed


def compare(
    ros1: list[str], rosx: list[str], ros1_env: dict[str, str], rosx_env: dict[str, str], runs: int
) -> tuple[float, float]:
    """Medians of ``runs`` alternating runs of both command lines, after one unmeasured each."""
    timed(ros1, ros1_env)
    timed(rosx, rosx_env)
    ros1_times, rosx_times = [], []
    for _ in range(runs):
        ros1_times.append(timed(ros1, ros1_env))
        rosx_times.append(timed(rosx, rosx_env))
    return statistics.median(ros1_times), statistics.median(rosx_times)


def registered(uri: str, topics: int) -> bool:
    """True once the master lists ``topics`` publishers of the nodes' topics and /rosout."""
    try:
        reply: Any = xmlrpc.client.ServerProxy(uri).getSystemState("/bench")
    except OSError:
        return False
    publishers: dict[str, list[str]] = dict(reply[2][0])
    bench = sum(len(nodes) for topic, nodes in publishers.items() if topic.startswith("/bench/"))
    return bench == topics and "/rosout_agg" in publishers


@contextlib.contextmanager
def master(kind: str, rosx: str, env: dict[str, str]) -> Iterator[dict[str, str]]:
    """ROS 1's or rosx's roscore with two rospy nodes; the environment naming it."""
    port = free_port()
    env = {**env, "ROS_MASTER_URI": f"http://127.0.0.1:{port}"}
    core = (
        ["/usr/bin/roscore", "-p", str(port)]
        if kind == "ros1"
        else [rosx, "roscore", "-p", str(port)]
    )
    with running(core, env):
        wait_for(lambda: port_open(port), what=f"{kind} roscore")
        with running([ROS1_PYTHON, "-c", NODE], env), running([ROS1_PYTHON, "-c", NODE], env):
            wait_for(lambda: registered(env["ROS_MASTER_URI"], 20), timeout=60, what="the nodes")
            yield env


def row(what: str, where: str, ros1: float, rosx: float, target: float) -> None:
    ratio = rosx / ros1
    met = "yes" if ratio <= target else "no"
    print(
        f"| `{what}` | {where} | {ros1:.3f} | {rosx:.3f} | {ratio:.2f} | ≤ {target} | {met} |",
        flush=True,
    )


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=11)
    parser.add_argument("--master", choices=["ros1", "rosx", "both"], default="both")
    parser.add_argument("--only", default="", help="only the commands containing this text")
    interpreter.add_option(parser)
    options = parser.parse_args()
    if not ros1_available():
        print('ROS 1 reference not installed: eval "$(../shared/tools/ros1-reference)"')
        return 1
    interpreter.run_on(options.python)
    # The console script of the Python that runs this bench: the one `--python` chose.
    rosx = str(Path(sys.executable).parent / "rosx")
    if not Path(rosx).exists():
        rosx = shutil.which("rosx") or rosx
    kinds = ["ros1", "rosx"] if options.master == "both" else [options.master]
    # A script's "#!/usr/bin/env python3" is then Debian's Python, as on a ROS 1 machine.
    base = ros1_environ(PATH=f"{Path(ROS1_PYTHON).parent}{os.pathsep}{os.environ['PATH']}")
    # Both interpreters keep their compiled modules, as an installed rosx and Debian's ROS do.
    base.pop("PYTHONDONTWRITEBYTECODE", None)
    print("| command | master | ROS 1 (s) | rosx (s) | ratio | target | met |")
    print("|---|---|---|---|---|---|---|")
    for kind in kinds:
        with master(kind, rosx, base) as ros1_env:
            rosx_env = {k: v for k, v in ros1_env.items() if k != "ROS_PACKAGE_PATH"}
            for command in COMMANDS:
                what = " ".join(command)
                if options.only in what:
                    ros1_time, rosx_time = compare(
                        [f"/usr/bin/{command[0]}", *command[1:]],
                        [rosx, *command],
                        ros1_env,
                        rosx_env,
                        options.runs,
                    )
                    row(what, kind, ros1_time, rosx_time, COMMAND_TARGET)
            if "script" in options.only or not options.only:
                script(rosx, kind, ros1_env, rosx_env, options.runs)
    print(
        f"(medians of {options.runs} runs; python {sys.version.split()[0]}, {os.cpu_count()} cores)"
    )
    return 0


def script(
    rosx: str, kind: str, ros1_env: dict[str, str], rosx_env: dict[str, str], runs: int
) -> None:
    """The rospy script run directly, then through rosrun from a package."""
    with tempfile.TemporaryDirectory() as tmp:
        package = Path(tmp) / "startup_bench"
        (package / "scripts").mkdir(parents=True)
        (package / "package.xml").write_text(PACKAGE_XML)
        path = package / "scripts" / "talk_once.py"
        path.write_text(SCRIPT)
        path.chmod(0o755)
        ros1_time, rosx_time = compare(
            [ROS1_PYTHON, str(path)], [rosx, "run-script", str(path)], ros1_env, rosx_env, runs
        )
        row("init_node + publish + exit", kind, ros1_time, rosx_time, SCRIPT_TARGET)
        ros1_path = {**ros1_env, "ROS_PACKAGE_PATH": f"{tmp}:{ros1_env['ROS_PACKAGE_PATH']}"}
        rosx_path = {**rosx_env, "ROS_PACKAGE_PATH": tmp}
        ros1_time, rosx_time = compare(
            ["/usr/bin/rosrun", "startup_bench", "talk_once.py"],
            [rosx, "rosrun", "startup_bench", "talk_once.py"],
            ros1_path,
            rosx_path,
            runs,
        )
        row("rosrun (same script)", kind, ros1_time, rosx_time, SCRIPT_TARGET)


if __name__ == "__main__":
    sys.exit(main())
