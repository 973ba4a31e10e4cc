"""roslaunch: Debian's and rosx's, side by side in one run.

1. Start-up: a launch file of 5 rospy nodes (each ``init_node`` then ``spin``), no master
   running; the time from starting ``roslaunch`` to every node registered with the master it
   starts (polled every 5 ms), then the time from SIGINT to its exit. ROS 1's nodes run with
   Debian's rospy, rosx's with rosx's (the same scripts).
2. The same with a master already running (a ROS 1 roscore), so only the launcher and the
   nodes are timed.

(``--dump-params`` of 1 000 parameters is timed by ``bench_roslaunch_parse.py``.)

Each case alternates ROS 1 and rosx, ``--runs`` times (default 5), and prints medians and the
ratio rosx / ROS 1 (design target for start-up: <= 0.5). Both run from bytecode caches, as
installed software does (``PYTHONDONTWRITEBYTECODE`` is dropped; one round warms them).

    python bench/bench_roslaunch.py [--runs 5] [--nodes 5]
"""

from __future__ import annotations

import argparse
import os
import signal
import statistics
import subprocess
import sys
import tempfile
import time
from functools import partial
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from rosx.transport.client import XmlRpcClient
from tests.support.procs import free_port, port_open, running, stop, wait_for
from tests.support.ros1 import ros1_available, ros1_environ

NODE = """\
#!/usr/bin/python3
import rospy

rospy.init_node("bench_node")
rospy.spin()
"""


def make_package(root: Path, nodes: int) -> Path:
    package = root / "benchlaunch"
    (package / "scripts").mkdir(parents=True)
    (package / "launch").mkdir()
    (package / "package.xml").write_text(
        '<?xml version="1.0"?>\n<package format="2"><name>benchlaunch</name>'
        "<version>0.0.1</version><description>bench</description>"
        '<maintainer email="a@b.c">a</maintainer><license>BSD</license></package>\n'
    )
    script = package / "scripts" / "node.py"
    script.write_text(NODE)
    script.chmod(0o755)
    lines = [f'  <node name="n{i}" pkg="benchlaunch" type="node.py"/>' for i in range(nodes)]
    (package / "launch" / "nodes.launch").write_text(
        "<launch>\n" + "\n".join(lines) + "\n</launch>\n"
    )
    return package


def _freed(port: int) -> bool:
    return not port_open(port)


def registered(client: XmlRpcClient, uri: str) -> set[str]:
    try:
        code, _, state = client.call(uri, "getSystemState", "/bench", timeout=1.0)
    except Exception:
        return set()
    if code != 1:
        return set()
    return {n for group in state for _, names in group for n in names}


def one_launch(
    command: list[str], env: dict[str, str], uri: str, names: set[str]
) -> tuple[float, float]:
    """Seconds to every node registered; seconds from SIGINT to the launcher's exit."""
    client = XmlRpcClient(timeout=1.0)
    start = time.perf_counter()
    process = subprocess.Popen(
        command,
        env=env,
        stdin=subprocess.DEVNULL,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
        start_new_session=True,
    )
    try:
        while not names <= registered(client, uri):
            if process.poll() is not None:
                raise RuntimeError(f"{command[0]} ended early")
            if time.perf_counter() - start > 120:
                raise TimeoutError(f"{command} did not register {names}")
            time.sleep(0.005)
        up = time.perf_counter() - start
        time.sleep(0.5)  # let the nodes settle before Ctrl-C, as a user would
        stop_start = time.perf_counter()
        os.kill(process.pid, signal.SIGINT)
        process.wait(60)
        down = time.perf_counter() - stop_start
    finally:
        stop(process)
        client.close()
    return up, down


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--nodes", type=int, default=5)
    options = parser.parse_args()
    if not ros1_available():
        print('ROS 1 reference not installed: eval "$(../shared/tools/ros1-reference)"')
        return 1
    rosx = [sys.executable, "-m", "rosx_commands", "roslaunch"]
    ros1 = ["/usr/bin/roslaunch"]
    names = {f"/n{i}" for i in range(options.nodes)}
    with tempfile.TemporaryDirectory() as tmp:
        root = Path(tmp)
        make_package(root / "src", options.nodes)
        base = ros1_environ(ROS_HOME=str(root / "home"))
        # Installed software runs from bytecode caches (pip and Debian write them); timing the
        # compilation of every module at every start would measure something else.
        base.pop("PYTHONDONTWRITEBYTECODE", None)
        base["ROS_PACKAGE_PATH"] = f"{root / 'src'}:{base['ROS_PACKAGE_PATH']}"
        rows: list[tuple[str, list[float], list[float]]] = []

        # 1. no master: roslaunch starts the core (a first round, not counted, warms caches).
        up: dict[str, list[float]] = {"ros1": [], "rosx": []}
        down: dict[str, list[float]] = {"ros1": [], "rosx": []}
        for round_ in range(options.runs + 1):
            for kind, command in (("ros1", ros1), ("rosx", rosx)):
                port = free_port()
                uri = f"http://localhost:{port}"
                env = {**base, "ROS_MASTER_URI": uri}
                args = [*command, "benchlaunch", "nodes.launch"]
                a, b = one_launch(args, env, uri, {*names, "/rosout"})
                if round_:
                    up[kind].append(a)
                    down[kind].append(b)
                wait_for(partial(_freed, port), what="the port freed")
        rows.append((f"{options.nodes} nodes + core: to all registered", up["ros1"], up["rosx"]))
        rows.append(("  then Ctrl-C to exit", down["ros1"], down["rosx"]))

        # 2. a ROS 1 roscore already running.
        port = free_port()
        uri = f"http://localhost:{port}"
        env = {**base, "ROS_MASTER_URI": uri}
        up = {"ros1": [], "rosx": []}
        with running(["/usr/bin/roscore", "-p", str(port)], env):
            wait_for(lambda: "/rosout" in registered(XmlRpcClient(), uri), what="roscore")
            for _ in range(options.runs):
                for kind, command in (("ros1", ros1), ("rosx", rosx)):
                    args = [*command, "benchlaunch", "nodes.launch"]
                    up[kind].append(one_launch(args, env, uri, names)[0])
                    wait_for(lambda: not names & registered(XmlRpcClient(), uri), what="exit")
        rows.append((f"{options.nodes} nodes, master running", up["ros1"], up["rosx"]))

    print(f"{'case':<42}{'ROS 1 (s)':>11}{'rosx (s)':>10}{'ratio':>8}")
    for label, ros1_times, rosx_times in rows:
        a, b = statistics.median(ros1_times), statistics.median(rosx_times)
        print(f"{label:<42}{a:>11.3f}{b:>10.3f}{b / a:>8.2f}")
    print(
        f"(medians of {options.runs} runs; python {sys.version.split()[0]}, {os.cpu_count()} cores)"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
