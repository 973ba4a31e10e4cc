"""``rosx rosclean``: ROS 1's texts, prompts and statuses, beside Debian's rosclean."""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from tests.support.cli import clean_environ, rosx

DEBIAN_ROSCLEAN = shutil.which("rosclean", path="/usr/bin")
needs_rosclean = pytest.mark.skipif(DEBIAN_ROSCLEAN is None, reason="Debian's rosclean is absent")


def _home(root: Path) -> dict[str, str]:
    """A ROS_HOME with two runs' log folders and a ``latest`` link."""
    ros_home = root / ".ros"
    for run, size in (("run-old", 3000), ("run-new", 5000)):
        folder = ros_home / "log" / run
        folder.mkdir(parents=True)
        (folder / "rosout.log").write_text("x" * size)
    os.utime(ros_home / "log" / "run-old", (1_000_000_000, 1_000_000_000))
    (ros_home / "log" / "latest").symlink_to(ros_home / "log" / "run-new")
    return clean_environ(ROS_HOME=str(ros_home), HOME=str(root))


def _debian(argv: list[str], env: dict[str, str], stdin: str = "") -> tuple[int, str, str]:
    assert DEBIAN_ROSCLEAN is not None
    done = subprocess.run(
        [DEBIAN_ROSCLEAN, *argv], input=stdin, capture_output=True, text=True, env=env,
        timeout=60, check=False,
    )  # fmt: skip
    return done.returncode, done.stdout, done.stderr


def test_check_prints_du_and_the_label(tmp_path: Path) -> None:
    env = _home(tmp_path)
    result = rosx("rosclean", "check", environ=env)
    assert (result.status, result.err) == (0, "")
    assert result.out.endswith(" ROS node logs\n") and result.out.count("\n") == 1


def test_check_without_log_folders_prints_nothing(tmp_path: Path) -> None:
    result = rosx("rosclean", "check", environ=clean_environ(ROS_HOME=str(tmp_path / "none")))
    assert (result.status, result.out, result.err) == (0, "", "")


def test_purge_asks_and_keeps_the_logs_on_no(tmp_path: Path) -> None:
    env = _home(tmp_path)
    result = rosx("rosclean", "purge", stdin="maybe\nn\n", environ=env)
    assert result.status == 0
    assert result.out == (
        "Purging ROS node logs.\nPLEASE BE CAREFUL TO VERIFY THE COMMAND BELOW!\n"
        f"Okay to perform:\n\nrm -rf {tmp_path}/.ros/log\n(y/n)?\n"
    )
    assert (tmp_path / ".ros" / "log" / "run-new").is_dir()


def test_purge_removes_the_log_folder_on_yes_and_with_y(tmp_path: Path) -> None:
    env = _home(tmp_path)
    assert rosx("rosclean", "purge", stdin="y\n", environ=env).status == 0
    assert not (tmp_path / ".ros" / "log").exists()
    env = _home(tmp_path / "again")
    result = rosx("rosclean", "purge", "-y", environ=env)
    assert (result.status, result.out) == (0, "Purging ROS node logs.\n")
    assert not (tmp_path / "again" / ".ros" / "log").exists()


def test_purge_to_a_size_below_the_threshold_removes_nothing(tmp_path: Path) -> None:
    env = _home(tmp_path)
    result = rosx("rosclean", "purge", "--size", "1", "-y", environ=env)
    assert result.out == (
        "Directory size of ROS node logs is 0 MB which is already below the requested "
        "threshold of 1 MB.\n"
    )
    assert (tmp_path / ".ros" / "log" / "run-old").is_dir()


@pytest.mark.parametrize("argv", [[], ["bogus"], ["purge", "--size", "x"]])
def test_usage_errors_are_argparses(tmp_path: Path, argv: list[str]) -> None:
    result = rosx("rosclean", *argv, environ=_home(tmp_path))
    assert (result.status, result.out) == (2, "")
    assert result.err.startswith("usage: rosclean ")
    assert "rosclean" in result.err.splitlines()[-1] and ": error: " in result.err


@needs_rosclean
@pytest.mark.parametrize(
    ("argv", "stdin"),
    [
        (["check"], ""),
        (["purge"], "n\n"),
        (["purge"], "y\n"),
        (["purge", "-y"], ""),
        (["purge", "--size", "1"], ""),
        (["-h"], ""),
        (["purge", "-h"], ""),
        (["bogus"], ""),
    ],
)
def test_same_as_debians_rosclean(tmp_path: Path, argv: list[str], stdin: str) -> None:
    ours_env = _home(tmp_path / "ours")
    theirs_env = _home(tmp_path / "theirs")
    ours = rosx("rosclean", *argv, stdin=stdin, environ=ours_env)
    status, out, err = _debian(argv, theirs_env, stdin)
    assert ours.status == status
    assert ours.out.replace("/ours/", "/theirs/") == out
    assert ours.err.splitlines()[-1:] == err.splitlines()[-1:]
    assert (tmp_path / "ours" / ".ros" / "log").exists() == (
        tmp_path / "theirs" / ".ros" / "log"
    ).exists()


def test_a_cores_run_folder_is_where_roscd_log_goes_and_what_rosclean_purges(
    tmp_path: Path,
) -> None:
    """ROS/Tutorials: roscore logs to ``~/.ros/log/<run_id>`` (``latest`` points there),
    ``roscd log`` goes there while it runs, ``rosclean check`` counts it, ``purge -y`` ends it."""
    from tests.support.procs import free_port, port_open, running, wait_for

    port = free_port()
    env = clean_environ(HOME=str(tmp_path), ROS_MASTER_URI=f"http://127.0.0.1:{port}/")
    core = [sys.executable, "-m", "rosx_commands", "roscore", "-p", str(port)]
    log = tmp_path / ".ros" / "log"
    with running(core, env):
        wait_for(lambda: port_open(port) and (log / "latest").is_symlink(), what="roscore")
        where = rosx("roscd", "--where", "log", environ=env)
        assert (where.status, where.err) == (0, "")
        run = Path(where.out.strip())
        assert run.parent == log and (log / "latest").resolve() == run.resolve()
        assert re.fullmatch(r"[0-9a-f-]{36}", run.name)
        check = rosx("rosclean", "check", environ=env)
        assert re.fullmatch(r"\S+ ROS node logs\n", check.out)
    assert rosx("rosclean", "purge", "-y", environ=env).out == "Purging ROS node logs.\n"
    assert not log.exists()
    after = rosx("roscd", "--where", "log", environ=env)
    assert (after.out, after.err) == (f"{log}\n", "No active roscore\n")
