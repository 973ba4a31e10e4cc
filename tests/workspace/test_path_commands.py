"""ROS 1's command names as programs on ``PATH`` after ``rosx shell-init``: found by ``timeout``,
``env``, ``xargs`` and scripts as ROS 1's are, written once per install in the user's cache
folder, and shell functions where that folder cannot be written."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from collections.abc import Callable, Sequence
from pathlib import Path

import pytest

from rosx.workspace.path_commands import MODE, command_folder, command_script, write_commands
from rosx.workspace.shell import shell_init
from tests.support.cli import clean_environ, rosx

INIT = f"{sys.executable} -m rosx_commands shell-init"
ROSX = f"{sys.executable} -m rosx_commands"


def test_the_folder_is_in_the_cache_folder_and_named_after_the_install(tmp_path: Path) -> None:
    home = {"HOME": str(tmp_path)}
    folder = command_folder(home, "/venv/bin/rosx")
    assert folder is not None and folder.parent == tmp_path / ".cache" / "rosx"
    assert folder.name.startswith("bin-") and len(folder.name) == len("bin-1a2b3c4d")
    assert command_folder(home, "/other/bin/rosx") != folder
    assert command_folder(home, "/venv/bin/rosx") == folder
    xdg = command_folder({**home, "XDG_CACHE_HOME": str(tmp_path / "xdg")}, "/venv/bin/rosx")
    assert xdg == tmp_path / "xdg" / "rosx" / folder.name
    # The XDG spec: a relative XDG_CACHE_HOME is ignored.
    assert command_folder({**home, "XDG_CACHE_HOME": "rel"}, "/venv/bin/rosx") == folder
    assert command_folder({"HOME": "relative"}, "/venv/bin/rosx") is None


def test_programs_are_written_once_and_only_the_given_names_stay(tmp_path: Path) -> None:
    folder = tmp_path / "bin-x"
    write_commands(folder, "/venv/bin/rosx", ["rostopic", "rosmsg-proto", "gone"])
    script = folder / "rostopic"
    assert script.read_text() == '#!/bin/sh\nexec /venv/bin/rosx rostopic "$@"\n'
    assert script.read_text() == command_script("/venv/bin/rosx", "rostopic")
    assert script.stat().st_mode & 0o7777 == MODE
    assert os.access(folder / "rosmsg-proto", os.X_OK)
    written = {p.name: (p.stat().st_ino, p.stat().st_mtime_ns) for p in folder.iterdir()}
    (folder / ".rostopic.123").write_text("another shell-init's file being written")

    write_commands(folder, "/venv/bin/rosx", ["rostopic", "rosmsg-proto"])
    assert {p.name for p in folder.iterdir()} == {"rostopic", "rosmsg-proto", ".rostopic.123"}
    for path in (script, folder / "rosmsg-proto"):
        assert (path.stat().st_ino, path.stat().st_mtime_ns) == written[path.name]

    script.write_text("#!/bin/sh\nexec /old/rosx rostopic\n")
    write_commands(folder, "/venv/bin/rosx", ["rostopic", "rosmsg-proto"])
    assert script.read_text() == command_script("/venv/bin/rosx", "rostopic")
    script.chmod(0o644)
    write_commands(folder, "/venv/bin/rosx", ["rostopic", "rosmsg-proto"])
    assert script.stat().st_mode & 0o7777 == MODE


def test_without_a_folder_the_names_are_functions_and_sh_gets_no_dashed_ones() -> None:
    names = ["rostopic", "rosmsg-proto"]
    assert "rostopic() {" in shell_init("rosx", "bash", names)
    assert "rosmsg-proto() {" in shell_init("rosx", "bash", names)
    assert "rostopic() {" in shell_init("rosx", "sh", names)
    assert "rosmsg-proto" not in shell_init("rosx", "sh", names)
    with_folder = shell_init("rosx", "sh", names, folder="/c/rosx/bin-1")
    assert "rostopic() {" not in with_folder and "rosmsg-proto() {" not in with_folder
    assert "_rosx_bin=/c/rosx/bin-1\n" in with_folder


def run_shell(
    shell: str, script: str, home: Path, prefix: Sequence[str] = (), **extra: str
) -> subprocess.CompletedProcess[str]:
    if shutil.which(shell) is None:
        pytest.skip(f"{shell} is not installed")
    env = clean_environ(HOME=str(home), **extra)
    env.pop("XDG_CACHE_HOME", None)
    return subprocess.run(
        [*prefix, shell, "-c", script],
        cwd=home,
        env=env,
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
    )


def cache_folder(home: Path) -> Path:
    (folder,) = (home / ".cache" / "rosx").glob("bin-*")
    return folder


#: Where the shell finds a program of a name (functions aside), as bash's ``type -P`` says.
WHERE = {"bash": "type -P", "zsh": "whence -p", "sh": "command -v"}
#: What a name is to the shell (a function, a file…), as bash's ``type -t`` says.
KIND = {"bash": "type -t", "zsh": "whence -w"}


@pytest.mark.parametrize("shell", ["bash", "zsh", "sh"])
def test_programs_run_the_ros_commands(tmp_path: Path, shell: str, master: str) -> None:
    script_file = tmp_path / "show.sh"
    script_file.write_text("#!/bin/bash\nrosmsg show std_msgs/Bool\n")
    script_file.chmod(0o755)
    script = (
        f'eval "$({INIT} {shell})"\n'
        f'eval "$({INIT} {shell})"\n'
        f"{WHERE[shell]} rostopic\n"
        f"{WHERE[shell]} rosmsg-proto\n"
        'echo "$PATH" | tr : "\\n" | grep -c /rosx/bin-\n'
        "timeout -s INT 20 rostopic list\n"
        "env rosmsg show geometry_msgs/Vector3\n"
        "echo std_msgs/Bool | xargs rosmsg show\n"
        f"{script_file}\n"
        "nohup rosversion -d 2>/dev/null\n"
    )
    done = run_shell(shell, script, tmp_path, ROS_MASTER_URI=master)
    folder = cache_folder(tmp_path)
    assert done.stdout.splitlines() == [
        f"{folder}/rostopic",
        f"{folder}/rosmsg-proto",
        "1",
        "/rosout",
        "/rosout_agg",
        "float64 x",
        "float64 y",
        "float64 z",
        "",
        "bool data",
        "",
        "bool data",
        "",
        "noetic",
    ], done.stderr
    assert done.stderr == ""


def test_a_second_shell_init_rewrites_nothing(tmp_path: Path) -> None:
    first = run_shell("bash", f'eval "$({INIT} bash)"', tmp_path)
    assert first.returncode == 0, first.stderr
    folder = cache_folder(tmp_path)
    written = {p.name: (p.stat().st_ino, p.stat().st_mtime_ns) for p in folder.iterdir()}
    assert "rostopic" in written and "roscore" in written and "rqt" in written
    again = run_shell("bash", f'eval "$({INIT} bash)"\ntype -P rostopic', tmp_path)
    assert again.stdout == f"{folder}/rostopic\n", again.stderr
    assert {p.name: (p.stat().st_ino, p.stat().st_mtime_ns) for p in folder.iterdir()} == written


@pytest.mark.parametrize("shell", ["bash", "zsh"])
def test_the_completion_still_names_the_commands(tmp_path: Path, shell: str) -> None:
    if shell == "bash":
        check, expected = "complete -p rostopic", "complete -o default -F _rosx_complete rostopic"
    else:
        check, expected = "print -r -- $_comps[rostopic]", "_rosx_complete"
    prelude = "autoload -Uz compinit && compinit -u\n" if shell == "zsh" else ""
    done = run_shell(shell, f'{prelude}eval "$({INIT} {shell})"\n{check}', tmp_path)
    assert done.stdout == f"{expected}\n", done.stderr


def _read_only(cache: Path) -> list[str]:
    """A folder without write permission; how to run a shell that it stops."""
    cache.mkdir(parents=True)
    cache.chmod(0o555)
    if not os.access(cache, os.W_OK):
        return []
    # root: in a user namespace of its own, root has no capability over the files of the
    # (unmapped) root outside, so the folder's mode applies to it.
    prefix = ["unshare", "-U"]
    if shutil.which("unshare") is not None:
        probe = subprocess.run(
            [*prefix, "test", "-w", str(cache)], capture_output=True, check=False
        )
        if probe.returncode == 1:
            return prefix
    cache.chmod(0o755)
    pytest.skip("this user writes to read-only folders, and unshare -U cannot stop that")


def _a_file_in_the_way(cache: Path) -> list[str]:
    cache.parent.mkdir(parents=True)
    cache.write_text("not a folder\n")
    return []


@pytest.mark.parametrize("shell", ["bash", "zsh"])
@pytest.mark.parametrize("block", [_read_only, _a_file_in_the_way], ids=["read-only", "file"])
def test_an_unwritable_cache_folder_falls_back_to_functions(
    tmp_path: Path, shell: str, block: Callable[[Path], list[str]]
) -> None:
    cache = tmp_path / ".cache" / "rosx"
    prefix = block(cache)
    try:
        script = (
            f'code="$({INIT} {shell})"; echo "status=$?"\n'
            'eval "$code"\n'
            f"{KIND[shell]} rostopic\n"
            "rosmsg show std_msgs/Bool\n"
            "rosmsg-proto msg std_msgs/Bool\n"
        )
        done = run_shell(shell, script, tmp_path, prefix)
    finally:
        if cache.is_dir():
            cache.chmod(0o755)
    first = "function" if shell == "bash" else "rostopic: function"
    assert done.stdout.splitlines() == [
        "status=0",
        first,
        "bool data",
        "",
        '"data: false"',
    ], done.stderr
    (note,) = done.stderr.splitlines()
    assert note.startswith(f"rosx shell-init: cannot write {cache}/bin-")
    assert note.endswith("ROS commands are shell functions in this shell")
    assert not (cache.is_dir() and any(cache.iterdir()))


def test_a_command_name_defined_by_an_older_shell_init_runs_the_program(tmp_path: Path) -> None:
    script = f'rostopic() {{ {ROSX} rostopic "$@"; }}\neval "$({INIT} bash)"\ntype -t rostopic\n'
    done = run_shell("bash", script, tmp_path)
    assert done.stdout == "file\n", done.stderr


def test_a_refused_write_leaves_functions_and_one_line_on_stderr(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    def refuse(folder: Path, rosx: str, names: object) -> None:
        raise PermissionError(13, "Permission denied", str(folder))

    monkeypatch.setattr("rosx.workspace.path_commands.write_commands", refuse)
    result = rosx("shell-init", "bash", environ=clean_environ(HOME=str(tmp_path)))
    assert result.status == 0
    assert 'rostopic() { _rosx rostopic "$@"; }' in result.out and "\n  *) PATH=" not in result.out
    (note,) = result.err.splitlines()
    assert note.startswith(f"rosx shell-init: cannot write {tmp_path}/.cache/rosx/bin-")
    assert "(Permission denied); ROS commands are shell functions in this shell" in note
