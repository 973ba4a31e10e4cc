"""Every new terminal has ROS 1's command names, rosx's, in front of a system's ROS 1.

A workspace's ``devel/setup.bash`` (and ``setup.sh``, ``setup.zsh``, ``install/``) gives what
Noetic's gives, since it chains to ``/opt/ros/noetic/setup.bash``: the command names on
``PATH``, ``roscd``/``rosls``, completion and the ``ROS_*`` variables. ``rosx shell-init
--install`` adds the one line that makes every new terminal ready; ``rosx sim`` says so once.
The shells start as a new terminal does (`tests.support.terminal`), with Debian's ROS 1 in
``/usr/bin`` where it is installed.
"""

from __future__ import annotations

import os
import select
import shlex
import shutil
import signal
import subprocess
from pathlib import Path

import pytest

from rosx.workspace.environment import SHARE
from tests.support.procs import free_port, stop, wait_for
from tests.support.terminal import NewTerminal, debian_ros1_program

NAMES = ("roscore", "rosrun", "rostopic", "roslaunch", "catkin_make", "rosed")
#: Where each shell says it finds a program, functions aside.
WHERE = {"bash": "type -P", "zsh": "whence -p", "sh": "command -v"}


@pytest.fixture
def user(tmp_path: Path) -> NewTerminal:
    return NewTerminal(tmp_path / "home")


def _catkin_workspace(user: NewTerminal, *targets: str) -> Path:
    """``~/catkin_ws`` with the sheet's lab2 package, built by ``rosx catkin_make``."""
    workspace = user.home / "catkin_ws"
    (workspace / "src").mkdir(parents=True)
    built = user.run(
        "cd ~/catkin_ws/src && rosx catkin_create_pkg lab2 std_msgs rospy roscpp >/dev/null"
        f" && cd ~/catkin_ws && rosx catkin_make {' '.join(targets)} >/dev/null"
    )
    assert built.returncode == 0, built.stderr
    return workspace


@pytest.mark.parametrize(
    ("shell", "setup"),
    [("bash", "devel/setup.bash"), ("zsh", "devel/setup.zsh"), ("sh", "devel/setup.sh"),
     ("bash", "install/setup.bash")],
)  # fmt: skip
def test_a_workspaces_setup_file_gives_rosxs_command_names_first(
    user: NewTerminal, shell: str, setup: str
) -> None:
    workspace = _catkin_workspace(user, "install")
    space = workspace / setup.partition("/")[0]
    if debian_ros1_program("roscore") is not None:  # the case that matters: a system's ROS 1
        assert user.run(f"{WHERE['sh']} roscore").stdout == "/usr/bin/roscore\n"
    script = (
        f". ~/catkin_ws/{setup}\n"
        + "".join(f"{WHERE[shell]} {name}\n" for name in NAMES)
        + "echo $ROS_DISTRO $ROS_PACKAGE_PATH\n"
        "rosversion -d\n"
        "rospack find lab2\n"
        "roscd lab2 && pwd\n"
    )
    done = user.run(script, shell)
    packages = space / "share" if space.name == "install" else workspace / "src"
    assert done.stdout.splitlines() == [
        *(f"{space}/bin/{name}" for name in NAMES),
        f"noetic {packages}:{SHARE}",
        "noetic",
        f"{packages}/lab2",
        f"{packages}/lab2",
    ], done.stderr
    assert done.stderr == ""


def test_sourcing_twice_or_after_ros1s_setup_keeps_rosx_first(user: NewTerminal) -> None:
    workspace = _catkin_workspace(user)
    done = user.run(
        "PATH=/opt/ros/noetic/bin:$PATH\n"
        ". ~/catkin_ws/devel/setup.bash\n. ~/catkin_ws/devel/setup.bash\n"
        'echo "$PATH" | tr : "\\n" | grep -c "^$HOME/catkin_ws/devel/bin$"\n'
        'echo "$PATH" | cut -d: -f1\n'
        "type -t roscd rosls\ncomplete -p rosrun\n"
        "{ catkin make; } 2>&1 | tail -n 1\n"
    )
    assert done.stdout.splitlines() == [
        "1",
        f"{workspace}/devel/bin",
        "function",
        "function",
        "complete -o default -F _rosx_complete rosrun",
        "[rosx] Did you mean catkin_make? (catkin_make)",
    ], done.stderr


@pytest.mark.parametrize("shell", ["bash", "zsh"])
def test_shell_init_install_makes_every_new_terminal_ready(user: NewTerminal, shell: str) -> None:
    before = user.run(f"{WHERE[shell]} rostopic || echo none", shell, interactive=True)
    assert before.stdout.strip() in ("none", debian_ros1_program("rostopic")), before.stdout
    installed = user.run(f"rosx shell-init --install {shell}", shell)
    startup = user.home / f".{shell}rc"
    line = startup.read_text().splitlines()[-1]
    assert installed.stdout.splitlines()[:2] == [
        f"rosx shell-init: added to {startup}:",
        f"  {line}",
    ]
    assert line.startswith('eval "$(') and f" shell-init {shell})" in line
    again = user.run(f"rosx shell-init --install {shell}", shell)
    assert again.stdout == f"rosx shell-init: {startup} already has the line; open a new terminal\n"
    assert startup.read_text().count("shell-init") == 1
    after = user.run(
        f"{WHERE[shell]} rostopic\nrosversion -d\ntype roscd | head -1\n"
        "roscd roscpp/cmake && pwd",  # beginner tutorial 2
        shell,
        interactive=True,
    )
    rostopic, distro, roscd, cmake = after.stdout.splitlines()
    assert rostopic.startswith(f"{user.home}/.cache/rosx/bin-") and rostopic.endswith("/rostopic")
    assert distro == "noetic"
    assert roscd.startswith("roscd is a") and "function" in roscd
    assert cmake == f"{SHARE}/roscpp/cmake"


def test_install_follows_shell_and_keeps_the_rest_of_the_file(user: NewTerminal) -> None:
    startup = user.home / ".zshrc"
    startup.write_text(
        "alias ll='ls -l'\neval \"$(/old/rosx shell-init zsh)\"  # rosx: ROS 1's command names in every terminal"
    )
    done = user.run("rosx shell-init --install", SHELL="/usr/bin/zsh")
    assert done.returncode == 0, done.stderr
    lines = startup.read_text().splitlines()
    assert lines[0] == "alias ll='ls -l'" and len(lines) == 2 and "/old/rosx" not in lines[1]
    refused = user.run("rosx shell-init --install fish")
    assert (refused.returncode, refused.stderr.splitlines()[-1]) == (
        2, "rosx shell-init: error: --install knows bash and zsh, not 'fish'"
    )  # fmt: skip


def _sim_hint(user: NewTerminal, **extra: str) -> str:
    """What ``rosx sim --headless`` writes on stderr before Ctrl-C, in a new terminal."""
    environ = {**user.environ, **extra}
    process = subprocess.Popen(
        ["rosx", "sim", "--headless", "--port", str(free_port())],
        env={**environ, "PATH": environ["PATH"]}, cwd=user.home, text=True,
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, start_new_session=True,
        executable=str(user.bin / "rosx"),
    )  # fmt: skip
    out = b""

    def serving() -> bool:
        nonlocal out
        assert process.stdout is not None
        if select.select([process.stdout], [], [], 0.1)[0]:
            out += os.read(process.stdout.fileno(), 4096)
        return b"ROS_MASTER_URI=" in out

    try:
        wait_for(serving, 60, "rosx sim's master")
        process.send_signal(signal.SIGINT)
        _, err = process.communicate(timeout=30)
    finally:
        stop(process)
    assert process.returncode == 0, err
    return err


def test_rosx_sim_says_once_how_to_get_the_names(user: NewTerminal) -> None:
    first = _sim_hint(user)
    assert first.splitlines()[0] == (
        "Tip: to type roscore, rostopic, rosrun… without `rosx` in front, in every new "
        "terminal, run once: rosx shell-init --install"
    )
    assert "shell-init" not in _sim_hint(user)  # once
    ready = NewTerminal(user.home.parent / "other")
    ready.run("rosx shell-init --install bash")
    names = ready.run('eval "$(rosx shell-init bash)"; echo "$PATH"').stdout.strip()
    assert "shell-init" not in _sim_hint(ready, PATH=names)  # the names are there already


def test_the_sheets_typos_in_a_new_terminal(user: NewTerminal) -> None:
    """In a terminal (a pty) set up by ``shell-init --install``: ROS 1's errors, then the
    command meant, or what rosx has instead of a package it lacks."""
    if shutil.which("script") is None:
        pytest.skip("util-linux's script is not installed")
    user.run("rosx shell-init --install bash")
    typed = [
        "rosrun turtlesim turtle teleop key",
        "rosrun gazebo_ros gzserver",
        "rosmsg show geometry msgs/Twist",
        "catkin make",
    ]
    terminal = f"bash -i -c {shlex.quote('; '.join(typed))}"  # a terminal's shell, on a pty
    done = user.run(f"script -qec {shlex.quote(terminal)} /dev/null")
    lines = [line.rstrip("\r") for line in done.stdout.splitlines()]
    for meant in (
        "[rosrun] Did you mean turtle_teleop_key? (rosrun turtlesim turtle_teleop_key)",
        "[rosx] gazebo_ros is not part of rosx; instead: "
        "rosx roslaunch turtlebot3_stage turtlebot3_world.launch",
        "[rosmsg] Did you mean geometry_msgs/Twist? (rosmsg show geometry_msgs/Twist)",
        "[rosx] Did you mean catkin_make? (catkin_make)",
    ):
        assert meant in lines, lines
    assert "[rospack] Error: package 'gazebo_ros' not found" in lines
