"""The package index with a real ``ROS_PACKAGE_PATH``: rospack, rosmsg and a <TAB>, with ROS 1.

The path is a generated catkin workspace of ``--packages`` packages (each with a message
type, a script and a launch folder) in front of Debian's ``/usr/share``, where Debian's ROS 1
lives among the rest of the system's files: every crawl of the path walks all of it. Each
command runs as a new process, ROS 1's and rosx's alternately, after one unmeasured run of each
(so rospack's cache and rosx's exist); medians of ``--runs`` runs. ``ROS_HOME`` is a fresh
folder, where both keep their caches. Targets (DESIGN.md): ``rospack find``/``list`` ≤ 3 x C++
rospack's, ``rosmsg show`` ≤ 0.3 x ROS 1's, a <TAB> ≤ 30 ms.

The <TAB> is timed in bash as a user's shell runs it, ``roscd pkg_1<TAB>``: ROS 1's rosbash
completion (``_roscomplete_sub_dir``: ``rospack find``, ``rospack list-names`` and ``rosstack
list-names``, which trust rospack's cache with no time limit there) and rosx's (the function
``rosx shell-init`` defines), alternately in one bash, from the function's call to its return.

Then the cache's point: a package added to the workspace a moment ago, and one removed. rosx's
next command sees both (and pays a crawl once); rospack answers ``list`` from its cache, up to
60 s old (it crawls again for a ``find`` it cannot answer, and checks that a found folder is
still there).

    python bench/bench_package_index.py [--runs 11] [--packages 300]
"""

from __future__ import annotations

import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from bench import interpreter
from bench.interpreter import ROS1_PYTHON
from rosx.packages.cache import RACY_SECONDS
from tests.support.packages import package
from tests.support.ros1 import ros1_available, ros1_environ

#: What each package depends on (a rospy package's usual list).
DEPENDS = ("rospy", "std_msgs", "geometry_msgs")

#: How long ago the generated files were made (a real workspace is older than a moment).
AGE = 3600


def workspace(root: Path, count: int) -> Path:
    """``root/src`` with ``count`` packages, their times moved back by `AGE` seconds."""
    src = root / "src"
    for number in range(count):
        name = f"pkg_{number:03d}"
        made = package(src, name, *DEPENDS)
        for folder in ("msg", "scripts", "launch", "src"):
            (made / folder).mkdir()
        (made / "CMakeLists.txt").write_text(f"project({name})\n")
        (made / "msg" / f"Reading{number:03d}.msg").write_text("float64 value\n")
        (made / "scripts" / "node.py").write_text("import rospy\n")
    age(root)
    return src


def age(root: Path) -> None:
    """The files' times moved back by `AGE`; then a wait until their change times (which
    nothing sets back) are older than rosx's cache trusts (`RACY_SECONDS`, as git's index
    does not trust a time of a moment ago), as a real workspace's are."""
    then = time.time() - AGE
    for directory, _, files in os.walk(root):
        for name in files:
            os.utime(Path(directory, name), (then, then))
        os.utime(directory, (then, then))
    time.sleep(RACY_SECONDS + 0.5)


def timed(argv: list[str], env: dict[str, str]) -> float:
    start = time.perf_counter()
    done = subprocess.run(argv, env=env, capture_output=True, check=False)
    elapsed = time.perf_counter() - start
    if done.returncode != 0:
        raise SystemExit(f"{' '.join(argv)} failed ({done.returncode}): {done.stderr.decode()}")
    return elapsed


def medians(commands: list[tuple[list[str], dict[str, str]]], runs: int) -> list[float]:
    """Each command once unmeasured, then ``runs`` rounds of all, alternating; the medians."""
    for argv, env in commands:
        timed(argv, env)
    times: list[list[float]] = [[] for _ in commands]
    for _ in range(runs):
        for spent, (argv, env) in zip(times, commands, strict=True):
            spent.append(timed(argv, env))
    return [statistics.median(spent) for spent in times]


def row(what: str, ros1: float | None, rosx: float, target: str, met: bool) -> None:
    theirs = f"{ros1 * 1000:.1f}" if ros1 is not None else "-"
    ratio = f"{rosx / ros1:.2f}" if ros1 is not None else "-"
    load = os.getloadavg()[0]  # the machine's other work, as the row was measured
    print(
        f"| `{what}` | {theirs} | {rosx * 1000:.1f} | {ratio} | {target} | "
        f"{'yes' if met else 'no'} | {load:.1f} |",
        flush=True,
    )


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=11)
    parser.add_argument("--packages", type=int, default=300)
    interpreter.add_option(parser)
    options = parser.parse_args()
    if not ros1_available():
        print('ROS 1 reference not installed: eval "$(../shared/tools/ros1-reference)"')
        return 1
    interpreter.run_on(options.python)
    rosx = str(Path(sys.executable).parent / "rosx")
    if not Path(rosx).exists():
        rosx = shutil.which("rosx") or rosx
    with tempfile.TemporaryDirectory() as tmp:
        src = workspace(Path(tmp) / "catkin_ws", options.packages)
        home = Path(tmp) / "ros_home"
        env = ros1_environ(ROS_PACKAGE_PATH=f"{src}:/usr/share", ROS_HOME=str(home))
        env["PATH"] = f"{Path(ROS1_PYTHON).parent}{os.pathsep}{env['PATH']}"
        env.pop("PYTHONDONTWRITEBYTECODE", None)
        bare = {k: v for k, v in env.items() if k != "ROS_PACKAGE_PATH"}
        middle = f"pkg_{options.packages // 2:03d}"
        print(f"ROS_PACKAGE_PATH: {options.packages} packages, then /usr/share "
              f"({sum(1 for _ in Path('/usr/share').iterdir())} entries)")  # fmt: skip
        print("| command | ROS 1 (ms) | rosx (ms) | ratio | target | met | load |")
        print("|---|---|---|---|---|---|---|")
        for argv, target in (
            (["rospack", "find", "roscpp"], 3.0),
            (["rospack", "find", middle], 3.0),
            (["rospack", "list"], 3.0),
            (["rosmsg", "show", "geometry_msgs/Twist"], 0.3),
            (["rosmsg", "show", f"{middle}/Reading{options.packages // 2:03d}"], 0.3),
        ):
            ros1, mine = medians([([f"/usr/bin/{argv[0]}", *argv[1:]], env), ([rosx, *argv], env)],
                                 options.runs)  # fmt: skip
            row(" ".join(argv), ros1, mine, f"≤ {target} x", mine / ros1 <= target)
        ros1_tab, tab = tabs(env, options.runs)
        row("roscd pkg_1<TAB> (bash)", ros1_tab, tab, "≤ 30 ms", tab <= 0.030)
        (floor,) = medians([([rosx, "rospack", "find", "roscpp"], bare)], options.runs)
        row("rospack find roscpp, no ROS_PACKAGE_PATH (floor)", None, floor, "-", True)
        fresh(src, env, rosx)
    print(f"(medians of {options.runs} runs; python {sys.version.split()[0]}, "
          f"{os.cpu_count()} cores)")  # fmt: skip
    return 0


def tabs(env: dict[str, str], runs: int) -> tuple[float, float]:
    """``roscd pkg_1<TAB>`` in one bash: ROS 1's rosbash completion and rosx's, alternately
    after one unmeasured round; their medians."""
    from rosx.workspace.completion import completion
    from rosx_commands.invocation import complete_command

    script = (
        "source /usr/share/bash-completion/completions/rosbash\n"
        + completion("bash", complete=complete_command())
        + "tab() {\n"
        "  COMP_WORDS=(roscd pkg_1); COMP_CWORD=1\n"
        '  local t0=$EPOCHREALTIME; "$1"; local t1=$EPOCHREALTIME\n'
        '  echo "$1 $t0 $t1 ${#COMPREPLY[@]}"\n'
        "}\n"
        f"for i in $(seq {runs + 1}); do tab _roscomplete_sub_dir; tab _rosx_complete; done\n"
    )
    done = subprocess.run(
        ["bash", "-c", script], env={**env, "LC_ALL": "C"}, capture_output=True, text=True,
        check=True,
    )  # fmt: skip
    spent: dict[str, list[float]] = {"_roscomplete_sub_dir": [], "_rosx_complete": []}
    for line in done.stdout.splitlines():
        function, start, end, offered = line.split()
        if offered == "0":
            raise SystemExit(f"{function} offered nothing: {done.stderr}")
        spent[function].append(float(end) - float(start))
    ros1, mine = (statistics.median(times[1:]) for times in spent.values())
    return ros1, mine


def fresh(src: Path, env: dict[str, str], rosx: str) -> None:
    """A package made and one removed a moment ago: who sees it, and what the first rosx
    command after the change costs (a crawl)."""
    # Both caches fresh just before the change, as in a session that ran a command a moment ago.
    for argv in (["/usr/bin/rospack", "list-names"], [rosx, "rospack", "list-names"]):
        subprocess.run(argv, env=env, capture_output=True, check=True)
    package(src, "made_just_now", *DEPENDS)
    shutil.rmtree(src / "pkg_000")

    def answer(argv: list[str]) -> tuple[str, float]:
        start = time.perf_counter()
        done = subprocess.run(argv, env=env, capture_output=True, text=True, check=False)
        spent = time.perf_counter() - start
        text = done.stdout.strip() if done.returncode == 0 else done.stderr.strip()
        return text, spent

    ros1_list, _ = answer(["/usr/bin/rospack", "list-names"])
    rosx_list, crawl = answer([rosx, "rospack", "list-names"])
    ros1_find, _ = answer(["/usr/bin/rospack", "find", "pkg_000"])
    rosx_find, _ = answer([rosx, "rospack", "find", "pkg_000"])
    print("\nA package made and one removed a moment ago:")
    print(
        f"- made_just_now listed: rospack {'made_just_now' in ros1_list.split()}, "
        f"rosx {'made_just_now' in rosx_list.split()} ({crawl * 1000:.0f} ms: a crawl)"
    )
    print(f"- rospack find pkg_000 (removed): rospack {ros1_find!r}; rosx {rosx_find!r}")


if __name__ == "__main__":
    raise SystemExit(main())
