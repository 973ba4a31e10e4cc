"""roslaunch's printing options, rosx against Debian's ``/usr/bin/roslaunch``, over a corpus.

The corpus (``tests/launch/corpus``) is a small catkin-style package tree (``pkgs/``) and launch
files as wide as ROS 1's own ``tools/roslaunch/test/xml`` covers: ``valid/`` files, whose
``--nodes``, ``--files``, ``--dump-params``, ``--ros-args``, ``--args NODE`` and
``--find-node NODE`` must print what roslaunch prints (anonymous ids and the order of
``--files``, a Python set in roslaunch, aside), and ``invalid/`` files, which both refuse.
The SUMMARY block is compared with roslaunch's own ``ROSLaunchConfig.summary()``.
"""

from __future__ import annotations

import re
import socket
import subprocess
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest

from tests.support.ros1 import OVERLAY, needs_ros1, ros1_environ, ros1_python

CORPUS = Path(__file__).resolve().parent.parent / "launch" / "corpus"
VALID = sorted(p.name for p in (CORPUS / "valid").glob("*.launch"))
INVALID = sorted(p.name for p in (CORPUS / "invalid").glob("*.launch"))
_HOST = re.escape(socket.gethostname().translate(str.maketrans(".-:", "___")))
_ANON = re.compile(rf"_{_HOST}_\d+_\d+")

pytestmark = needs_ros1


def environ(**extra: str) -> dict[str, str]:
    """The environment both roslaunches run in: the corpus packages first on the path."""
    return ros1_environ(
        ROS_PACKAGE_PATH=f"{CORPUS / 'pkgs'}:{OVERLAY}:/usr/share",
        CORPUS_VAR="corpus-value",
        **extra,
    )


def ros1(args: list[str], env: dict[str, str]) -> tuple[int, str, str]:
    done = subprocess.run(
        ["/usr/bin/roslaunch", *args],
        capture_output=True,
        text=True,
        env=env,
        cwd=CORPUS,
        timeout=120,
        check=False,
    )
    return done.returncode, done.stdout, done.stderr


def rosx(
    args: list[str], env: dict[str, str], monkeypatch: pytest.MonkeyPatch
) -> tuple[int, str, str]:
    """``rosx roslaunch ARGS…`` (through the printing helpers until the command exists)."""
    from rosx_commands.main import TOOLS

    monkeypatch.chdir(CORPUS)
    if "roslaunch" in TOOLS:
        from tests.support.cli import rosx as run

        result = run("roslaunch", *args, environ=env)
        return result.status, result.out, result.err
    from tests.support.launch_print import main

    return main(args, env)


def _comparable(args: list[str], out: str) -> str:
    if args[0] == "--files":
        out = "".join(sorted(out.splitlines(True)))
    return _ANON.sub("_ANON", out)


def same_outputs(commands: list[list[str]], monkeypatch: pytest.MonkeyPatch, **extra: str) -> None:
    """Each command line prints the same in both, with the same status (ROS 1's run 3 at once)."""
    env = environ(**extra)
    with ThreadPoolExecutor(max_workers=3) as pool:
        theirs = list(pool.map(lambda args: ros1(args, env), commands))
    for args, (status, out, err) in zip(commands, theirs, strict=True):
        mine, text, problem = rosx(args, env, monkeypatch)
        assert (mine, _comparable(args, text)) == (status, _comparable(args, out)), (
            args,
            err,
            problem,
        )


def same_output(args: list[str], monkeypatch: pytest.MonkeyPatch, **extra: str) -> None:
    same_outputs([args], monkeypatch, **extra)


@pytest.mark.parametrize("option", ["--nodes", "--files", "--dump-params", "--ros-args"])
@pytest.mark.parametrize("name", VALID)
def test_valid_files_print_as_roslaunch(
    name: str, option: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    same_output([option, f"valid/{name}"], monkeypatch)


def _node_names(name: str, monkeypatch: pytest.MonkeyPatch) -> list[str]:
    status, out, _ = rosx(["--nodes", f"valid/{name}"], environ(), monkeypatch)
    assert status == 0
    return out.split()


#: Files whose every node's command line is compared; of the others, the first node's.
_EVERY_NODE = {"nodes.launch", "remap.launch", "env.launch", "anon.launch"}
#: Files of turtlesim's nodes: rosx provides turtlesim's programs itself, where Debian's
#: roslaunch finds no executable (the reference has turtlesim's messages only), so their
#: command lines differ by design; only --find-node is compared.
_PROVIDED = {"turtlemimic.launch", "multisim.launch"}


@pytest.mark.parametrize("name", VALID)
def test_args_and_find_node_as_roslaunch(name: str, monkeypatch: pytest.MonkeyPatch) -> None:
    names = [n for n in _node_names(name, monkeypatch) if _ANON.search(n) is None]
    asked = names if name in _EVERY_NODE else names[:1] + names[-1:]
    if name in _PROVIDED:
        asked = []
    commands = [["--args", node, f"valid/{name}"] for node in dict.fromkeys(asked)]
    commands += [["--find-node", node, f"valid/{name}"] for node in names[:1]]
    commands += [[option, "no_such_node", f"valid/{name}"] for option in ("--args", "--find-node")]
    same_outputs(commands, monkeypatch)


@pytest.mark.parametrize(
    "args",
    [
        ["--nodes", "valid/args.launch", "valid/second.launch", "robot:=cli", "count:=9"],
        ["--dump-params", "valid/args.launch", "valid/second.launch", "robot:=cli", "count:=9"],
        ["--dump-params", "valid/args.launch", "use_sim:=false", "_private:=1", "count:=0"],
        ["--ros-args", "valid/args.launch", "valid/second.launch"],
        ["--nodes", "corpus_pkg", "main.launch"],
        ["--files", "corpus_pkg", "main.launch", "robot:=x"],
        ["--dump-params", "corpus_pkg", "main.launch", "robot:=x"],
        ["--args", "main_talker", "corpus_pkg", "main.launch"],
        ["--find-node", "main_talker", "corpus_pkg", "main.launch"],
        ["--ros-args", "corpus_pkg", "inc_args.launch"],
        ["--dump-params", "valid/namespace.launch", "__ns:=/other"],
        ["--nodes", "valid/namespace.launch", "__ns:=other"],
        ["--nodes", "corpus_pkg", "no_such.launch"],
        ["--nodes", "no_such.launch"],
        ["--nodes", "valid/args.launch", "valid/args.launch"],
        ["--nodes", "corpus_pkg", "inc_args.launch", "required_arg:=given"],
        ["--nodes", "corpus_pkg", "inc_args.launch", "fixed_inside:=changed", "required_arg:=1"],
    ],
    ids=" ".join,
)
def test_command_lines_as_roslaunch(args: list[str], monkeypatch: pytest.MonkeyPatch) -> None:
    same_output(args, monkeypatch)


@pytest.mark.parametrize("option", ["--nodes", "--dump-params", "--args node"])
def test_ros_namespace_as_roslaunch(option: str, monkeypatch: pytest.MonkeyPatch) -> None:
    same_output([*option.split(), "valid/namespace.launch"], monkeypatch, ROS_NAMESPACE="/robot")


@pytest.mark.parametrize("name", INVALID)
def test_invalid_files_refused_as_roslaunch(name: str, monkeypatch: pytest.MonkeyPatch) -> None:
    env = environ()
    status, out, _ = ros1(["--nodes", f"invalid/{name}"], env)
    mine, text, problem = rosx(["--nodes", f"invalid/{name}"], env, monkeypatch)
    assert (status, out) == (1, "")
    assert (mine, text) == (1, "")
    # One line, naming the file (and the line and tag where there is one); no traceback.
    assert "Traceback" not in problem
    assert len(problem.splitlines()) == 1
    assert re.match(r"^\S+\.launch(:\d+)?: ", problem), problem


# Machines are left unassigned (a launch of an undeclared machine fails later, in roslaunch
# too), so the summary is asked for with its MACHINES section, which is then cut out.
_SUMMARY = """
import json, sys
import roslaunch.config
config = roslaunch.config.load_config_default(
    [sys.argv[1]], None, verbose=False, assign_machines=False
)
head, rest = config.summary(local=False).split("\\n\\nMACHINES\\n")
print(json.dumps(head + "\\n\\nNODES\\n" + rest.split("\\n\\nNODES\\n", 1)[1]))
"""


@pytest.mark.parametrize("name", VALID)
def test_summary_as_roslaunch(name: str) -> None:
    from rosx.launch import load_launch, summary_text
    from rosx.launch.run.command import run_command
    from rosx.packages.index import PackageIndex

    path = str(CORPUS / "valid" / name)
    env = environ()
    script = f"import sys; sys.argv = ['roslaunch', {path!r}]\n" + _SUMMARY
    theirs = ros1_python(
        script, ROS_PACKAGE_PATH=env["ROS_PACKAGE_PATH"], CORPUS_VAR="corpus-value"
    )
    plan = load_launch([path], {}, env, PackageIndex.from_environ(env), run=run_command)
    mine = summary_text(plan)
    # roscore's /rosdistro and /rosversion come from `rosversion` in ROS 1, from rosx's core here.
    core = re.compile(r"^ \* /ros(distro|version): .*\n", re.M)
    assert _ANON.sub("_ANON", core.sub("", mine)) == _ANON.sub("_ANON", core.sub("", theirs + "\n"))
