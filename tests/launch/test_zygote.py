"""The fork server for Python nodes: a node's stdout log, as roslaunch's child gets it."""

from __future__ import annotations

import os
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest

from rosx.launch.run.zygote import ZygoteClient, ZygoteError
from tests.support.procs import wait_for

pytestmark = pytest.mark.skipif(sys.platform == "win32", reason="the helper forks: POSIX only")


@pytest.fixture
def helper() -> Iterator[ZygoteClient]:
    client = ZygoteClient(dict(os.environ), on_exit=lambda: None)
    try:
        assert client.wait_ready(60), "the helper did not load"
        yield client
    finally:
        client.close()


def test_a_node_s_stdout_log_exists_once_it_has_a_pid(helper: ZygoteClient, tmp_path: Path) -> None:
    script = tmp_path / "hello.py"
    script.write_text("print('hello from', __import__('sys').argv[1:])\n")
    log = tmp_path / "hello-1-stdout.log"
    pid = helper.start(str(script), ["a"], dict(os.environ), str(tmp_path), str(log), append=False)
    assert log.exists()  # opened before the fork, as roslaunch opens it before starting
    wait_for(lambda: helper.exit_code(pid) is not None, what="the node's exit")
    assert helper.exit_code(pid) == 0
    assert log.read_text() == "hello from ['a']\n"


def test_a_respawned_node_appends_to_its_stdout_log(helper: ZygoteClient, tmp_path: Path) -> None:
    script = tmp_path / "once.py"
    script.write_text("print('run')\n")
    log = tmp_path / "once-1-stdout.log"
    for _ in range(2):
        pid = helper.start(str(script), [], dict(os.environ), str(tmp_path), str(log), append=True)
        wait_for(lambda: helper.exit_code(pid) == 0, what="the node's exit")  # noqa: B023
    assert log.read_text() == "run\nrun\n"


def test_a_stdout_log_that_cannot_be_opened_is_refused_before_the_fork(
    helper: ZygoteClient, tmp_path: Path
) -> None:
    script = tmp_path / "never.py"
    script.write_text("print('ran')\n")
    log = tmp_path / "missing-folder" / "never-1-stdout.log"
    with pytest.raises(ZygoteError, match="No such file or directory"):
        helper.start(str(script), [], dict(os.environ), str(tmp_path), str(log), append=False)
    assert helper.exits == {}  # nothing was forked
    # The helper goes on serving.
    good = tmp_path / "never-2-stdout.log"
    pid = helper.start(str(script), [], dict(os.environ), str(tmp_path), str(good), append=False)
    wait_for(lambda: helper.exit_code(pid) == 0, what="the node's exit")
    assert good.read_text() == "ran\n"


def test_a_helper_started_without_stdout_gives_its_nodes_their_logs(tmp_path: Path) -> None:
    """A launcher whose stdout is closed starts the helper so: the first log the helper opens
    takes file descriptor 1, and the node must still write to it."""
    script = tmp_path / "hello.py"
    script.write_text("print('hello')\n")
    log = tmp_path / "hello-1-stdout.log"
    launcher = (
        "import os, sys, time\n"
        "os.close(1)\n"
        "from rosx.launch.run.zygote import ZygoteClient\n"
        "client = ZygoteClient(dict(os.environ), on_exit=lambda: None)\n"
        "assert client.wait_ready(60)\n"
        f"pid = client.start({str(script)!r}, [], dict(os.environ), {str(tmp_path)!r},\n"
        f"                   {str(log)!r}, append=False)\n"
        "deadline = time.monotonic() + 60\n"
        "while client.exit_code(pid) is None and time.monotonic() < deadline:\n"
        "    time.sleep(0.05)\n"
        "client.close()\n"
        "sys.exit(client.exit_code(pid))\n"
    )
    done = subprocess.run([sys.executable, "-c", launcher], timeout=120, check=False)
    assert done.returncode == 0
    assert log.read_text() == "hello\n"


def test_a_launcher_stopped_while_the_helper_loads_leaves_no_traceback() -> None:
    """Ctrl-C before any node starts closes the socket while the helper still imports rospy:
    the helper must end quietly when it finds the launcher gone."""
    launcher = (
        "import os, sys\n"
        "from rosx.launch.run.zygote import ZygoteClient\n"
        "client = ZygoteClient(dict(os.environ), on_exit=lambda: None)\n"
        "client.close()\n"
        "sys.exit(client.process.returncode)\n"
    )
    done = subprocess.run(
        [sys.executable, "-c", launcher], capture_output=True, text=True, timeout=120, check=False
    )
    assert done.stderr == ""
    assert done.returncode == 0
