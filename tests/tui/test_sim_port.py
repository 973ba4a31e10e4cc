"""Where ``rosx sim`` starts its master without ``--port``: on the port of ``ROS_MASTER_URI``
when that names this machine (as roslaunch starts its core), so that the other terminals,
which follow the variable, find it."""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from rosx.master.client import master_is_online
from rosx.workspace import path_commands
from rosx_commands.context import Environment
from rosx_commands.main import run_tool
from tests.support.procs import free_port


def test_sim_starts_its_master_where_ros_master_uri_points(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    uri = f"http://127.0.0.1:{free_port()}/"
    seen: list[bool] = []

    def running(environ: object) -> str | None:  # once the sim runs: look, then stop it
        seen.append(master_is_online(uri, "/sim_port_test", timeout=5.0))
        raise KeyboardInterrupt

    monkeypatch.setattr(path_commands, "hint_once", running)
    stdout, stderr = io.StringIO(), io.StringIO()
    environ = {"ROS_IP": "127.0.0.1", "HOME": str(tmp_path), "ROS_MASTER_URI": uri}
    status = run_tool(["sim", "--headless"], Environment(stdout, stderr, io.StringIO(), environ))
    assert (seen, status, stderr.getvalue()) == ([True], 0, "")
    assert not master_is_online(uri, "/sim_port_test", timeout=5.0)
