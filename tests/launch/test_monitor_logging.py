"""How the monitor starts a node, as ROS 1's roslaunch does: one whose stdout log cannot be
opened still starts, and one that exits at once has started (its exit is reported after)."""

from __future__ import annotations

import io
import os
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest

from rosx.launch.run.console import LaunchConsole
from rosx.launch.run.monitor import LocalProcess, ProcessMonitor
from rosx.launch.run.zygote import ForkedProcess, ZygoteClient
from tests.support.procs import wait_for

Streams = tuple[io.StringIO, io.StringIO, ProcessMonitor]


@pytest.fixture
def monitor() -> Iterator[Streams]:
    out, err = io.StringIO(), io.StringIO()
    monitor = ProcessMonitor(LaunchConsole(out, err, color=False), sigint_timeout=5.0)
    try:
        yield out, err, monitor
    finally:
        monitor.stop_all()


def _ran(process: LocalProcess) -> bool:
    return not process.poll() and process.exit_code == 0


def test_the_node_starts_and_the_error_is_roslaunchs(monitor: Streams, tmp_path: Path) -> None:
    out, err, procs = monitor
    log_dir = tmp_path / "missing"
    marker = tmp_path / "ran"
    process = LocalProcess(
        "talker-1",
        [sys.executable, "-c", f"open({str(marker)!r}, 'w').write('yes'); print('dropped')"],
        dict(os.environ),
        tmp_path,
        log_dir=log_dir,
        log_output=True,
        is_node=False,
    )
    assert procs.start(process)
    assert err.getvalue() == (
        "[talker-1] ERROR: unable to configure logging "
        f"[[Errno 2] No such file or directory: '{log_dir / 'talker-1-stdout.log'}']\n"
    )
    assert out.getvalue() == f"process[talker-1]: started with pid [{process.pid}]\n"
    wait_for(lambda: _ran(process), what="the node's exit")
    assert marker.read_text() == "yes"
    assert not log_dir.exists()


def test_a_forked_node_does_the_same(monitor: Streams, tmp_path: Path) -> None:
    out, err, procs = monitor
    script = tmp_path / "node.py"
    marker = tmp_path / "ran"
    script.write_text(f"open({str(marker)!r}, 'w').write('yes')\nprint('dropped')\n")
    helper = ZygoteClient(dict(os.environ), on_exit=procs.wake)
    try:
        assert helper.wait_ready(60), "the helper did not load"
        process = ForkedProcess(
            "sim-2",
            [sys.executable, str(script)],
            dict(os.environ),
            tmp_path,
            log_dir=tmp_path / "missing",
            log_output=True,
            is_node=False,
            zygote=helper,
            script_index=1,
        )
        assert procs.start(process)
        assert err.getvalue().startswith("[sim-2] ERROR: unable to configure logging [[Errno 2]")
        assert out.getvalue() == f"process[sim-2]: started with pid [{process.pid}]\n"
        wait_for(lambda: _ran(process), what="the node's exit")
        assert marker.read_text() == "yes"
    finally:
        helper.close()


class _SlowToReturn(LocalProcess):
    """Returns from `start` only once the program has ended, as on a busy machine where a
    program that exits at once is done before the launcher looks at it."""

    def start(self) -> None:
        super().start()
        assert self.popen is not None
        self.popen.wait()


def test_a_required_node_that_exits_at_once_has_started(monitor: Streams, tmp_path: Path) -> None:
    out, err, procs = monitor
    process = _SlowToReturn(
        "q-2",
        ["sh", "-c", "exit 3"],
        dict(os.environ),
        tmp_path,
        log_dir=None,
        log_output=False,
        required=True,
        is_node=False,
    )
    assert procs.start(process)
    assert out.getvalue() == f"process[q-2]: started with pid [{process.pid}]\n"
    assert err.getvalue() == ""
    procs.spin()
    rule = "=" * 80
    assert err.getvalue() == (
        f"{rule}REQUIRED process [q-2] has died!\n"
        f"process has died [pid {process.pid}, exit code 3, cmd sh -c exit 3].\n"
        f"Initiating shutdown!\n{rule}\n"
    )
