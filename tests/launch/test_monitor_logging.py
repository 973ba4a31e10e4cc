"""A node whose stdout log cannot be opened still starts, as ROS 1's roslaunch starts it."""

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
