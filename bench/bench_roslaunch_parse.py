"""roslaunch's parsing, Debian's and rosx's, side by side in one run.

1. ``roslaunch --dump-params`` of a file with 1 000 parameters (10 groups of 100, half of them
   typed, a quarter from ``<rosparam>``), wall time of the whole command: Debian's
   ``/usr/bin/roslaunch`` against rosx's (``rosx roslaunch`` when the command exists, else the
   printing helpers behind it, ``tests/support/launch_print.py``, in a fresh Python).
2. The same file loaded in-process, start-up excluded: roslaunch's ``XmlLoader`` (Debian's
   Python) against `rosx.launch.load_launch` + `dump_params_text`, median of many loads.
3. Every ``valid/`` file of the test corpus (``tests/launch/corpus``) loaded in-process, as in 2.

Each case alternates ROS 1 and rosx and prints medians and the ratio rosx / ROS 1.

    python bench/bench_roslaunch_parse.py [--runs 7]
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from tests.support.ros1 import (  # noqa: E402 -- after the path is set
    OVERLAY,
    ROS1_PYTHON,
    ros1_available,
    ros1_environ,
)

CORPUS = ROOT / "tests" / "launch" / "corpus"

ROS1_LOADS = """
import json, statistics, sys, time
import roslaunch.config, roslaunch.xmlloader
files, rounds = json.loads(sys.argv[1]), int(sys.argv[2])
sys.argv = ["roslaunch"]
times = []
for _ in range(rounds):
    start = time.perf_counter()
    for name in files:
        config = roslaunch.config.ROSLaunchConfig()
        roslaunch.xmlloader.XmlLoader().load(name, config, verbose=False)
    times.append(time.perf_counter() - start)
print(json.dumps(statistics.median(times)))
"""


def params_file(directory: Path) -> Path:
    """A launch file of 1 000 parameters."""
    lines = ["<launch>"]
    for group in range(10):
        lines.append(f'  <group ns="group{group}">')
        for i in range(50):
            lines.append(f'    <param name="p{i}" value="{group * 100 + i}" />')
        for i in range(50, 75):
            lines.append(f'    <param name="p{i}" type="double" value="{i}.5" />')
        body = "\n".join(f"      q{i}: [{i}, text {i}]" for i in range(75, 100))
        lines.append(f'    <rosparam param="yaml">\n{body}\n    </rosparam>')
        lines.append("  </group>")
    lines.append("</launch>")
    path = directory / "params.launch"
    path.write_text("\n".join(lines) + "\n")
    return path


def rosx_command() -> list[str]:
    try:
        from rosx_commands.main import TOOLS
    except ImportError:
        TOOLS = {}  # noqa: N806
    if "roslaunch" in TOOLS:
        return [sys.executable, "-c", "from rosx_commands.main import run; run()", "roslaunch"]
    return [sys.executable, str(ROOT / "tests" / "support" / "launch_print.py")]


def timed(args: list[str], env: dict[str, str]) -> float:
    start = time.perf_counter()
    done = subprocess.run(args, capture_output=True, env=env, check=False)
    elapsed = time.perf_counter() - start
    if done.returncode != 0 or not done.stdout:
        raise SystemExit(f"{args} failed: {done.stderr.decode()[-500:]}")
    return elapsed


def rosx_loads(files: list[str], rounds: int, env: dict[str, str]) -> float:
    from rosx.launch import dump_params_text, load_launch
    from rosx.launch.run.command import run_command
    from rosx.packages.index import PackageIndex

    index = PackageIndex.from_environ(env)  # crawled once, as roslaunch's rospack is cached
    times = []
    for _ in range(rounds):
        start = time.perf_counter()
        for name in files:
            dump_params_text(load_launch([name], {}, env, index, with_core=False, run=run_command))
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def ros1_loads(files: list[str], rounds: int, env: dict[str, str]) -> float:
    done = subprocess.run(
        [ROS1_PYTHON, "-c", ROS1_LOADS, json.dumps(files), str(rounds)],
        capture_output=True,
        text=True,
        env=env,
        check=True,
    )
    return float(json.loads(done.stdout))


def row(label: str, ros1: float, rosx: float) -> None:
    print(f"{label:<44}{ros1 * 1000:>10.1f}{rosx * 1000:>10.1f}{rosx / ros1:>8.2f}")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=7)
    runs = parser.parse_args().runs
    if not ros1_available():
        print("ROS 1 is not installed: nothing to compare with")
        return 0
    env = ros1_environ(
        ROS_PACKAGE_PATH=f"{CORPUS / 'pkgs'}:{OVERLAY}:/usr/share", CORPUS_VAR="corpus-value"
    )
    os.chdir(CORPUS)
    with tempfile.TemporaryDirectory() as tmp:
        big = str(params_file(Path(tmp)))
        ros1_times: list[float] = []
        rosx_times: list[float] = []
        for _ in range(runs):
            ros1_times.append(timed(["/usr/bin/roslaunch", "--dump-params", big], env))
            rosx_times.append(timed([*rosx_command(), "--dump-params", big], env))
        print(f"{'case':<44}{'ROS 1 ms':>10}{'rosx ms':>10}{'ratio':>8}")
        row(
            "--dump-params, 1 000 params (command)",
            *map(statistics.median, (ros1_times, rosx_times)),
        )
        row(
            "load 1 000 params + dump (in-process)",
            ros1_loads([big], 20, env),
            rosx_loads([big], 20, env),
        )
        corpus = [str(p) for p in sorted((CORPUS / "valid").glob("*.launch"))]
        row(
            f"load the {len(corpus)} corpus files (in-process)",
            ros1_loads(corpus, 10, env),
            rosx_loads(corpus, 10, env),
        )
    print(
        f"(medians; {runs} command runs; python {sys.version.split()[0]}, {os.cpu_count()} cores)"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
