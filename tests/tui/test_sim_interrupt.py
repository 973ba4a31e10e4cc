"""``rosx sim`` stops cleanly on Ctrl-C (``kill -INT``) whenever it comes once it has started,
even in the moment between starting its nodes and waiting for the signal (the one-time tip)."""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from rosx.master.client import master_is_online
from rosx.workspace import path_commands
from rosx_commands.context import Environment
from rosx_commands.main import run_tool
from tests.support.procs import free_port


def test_ctrl_c_while_the_tip_is_given_stops_the_sim_with_status_0(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    port = free_port()
    uri = f"http://127.0.0.1:{port}/"
    seen: list[bool] = []

    def interrupted(environ: object) -> str | None:
        seen.append(master_is_online(uri, "/sim_interrupt_test", timeout=5.0))
        raise KeyboardInterrupt

    monkeypatch.setattr(path_commands, "hint_once", interrupted)
    stderr = io.StringIO()
    env = Environment(
        io.StringIO(), stderr, io.StringIO(), {"ROS_IP": "127.0.0.1", "HOME": str(tmp_path)}
    )
    try:
        status = run_tool(["sim", "--headless", "--port", str(port)], env)
    except KeyboardInterrupt:
        pytest.fail("Ctrl-C escaped rosx sim: a traceback, killed by SIGINT")
    assert (seen, status, stderr.getvalue()) == ([True], 0, "")
    assert not master_is_online(uri, "/sim_interrupt_test", timeout=5.0)
