"""The bridge's test helpers: a bridge on a free port, and node.js scripts run as clients."""

from __future__ import annotations

import json
import secrets
import subprocess
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from rosx.bridge.app import Bridge, BridgeOptions


@dataclass
class Running:
    """What a module's tests reach: the master, the bridge's port and its environment."""

    master: str
    port: int
    environ: dict[str, str]
    bridge: Bridge
    lines: list[str]

    @property
    def url(self) -> str:
        return f"ws://127.0.0.1:{self.port}"


def start_bridge(master: str, **options: object) -> tuple[Bridge, list[str]]:
    """A bridge on a free port of the loopback; its log lines collected."""
    environ = {"ROS_MASTER_URI": master, "ROS_IP": "127.0.0.1"}
    lines: list[str] = []
    # A name of its own: a second node of one name makes the master shut the first down.
    name = f"rosbridge_websocket_{secrets.token_hex(4)}"
    settings = BridgeOptions(port=0, master_uri=master, environ=environ, node_name=name)
    for key, value in options.items():
        setattr(settings, key, value)
    return Bridge(settings, log=lines.append).start(), lines


class NodeScript:
    """A node script's run; its JSON lines (``{"step", "value"}``) read as they come."""

    def __init__(self, folder: Path, *args: str) -> None:
        self.process = subprocess.Popen(
            ["node", *args], cwd=folder, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True
        )
        self.steps: dict[str, list[Any]] = {}

    def _read(self) -> bool:
        stdout = self.process.stdout
        assert stdout is not None
        line = stdout.readline()
        if not line:
            return False
        data = json.loads(line)
        assert data["step"] != "error", data["value"]
        self.steps.setdefault(data["step"], []).append(data["value"])
        return True

    def step(self, name: str) -> Any:
        """The first value of step ``name``, waiting for it (the script stops itself on a
        deadline; its error fails the test)."""
        while name not in self.steps:
            if not self._read():
                err = self.process.stderr.read() if self.process.stderr else ""
                raise AssertionError(f"node ended before {name!r}: {self.steps} {err[-2000:]}")
        return self.steps[name][0]

    def values(self, name: str) -> list[Any]:
        """Every value of step ``name``, once the script has ended."""
        while self._read():
            pass
        return self.steps.get(name, [])

    def finish(self) -> int:
        try:
            return self.process.wait(timeout=30)
        finally:
            if self.process.poll() is None:
                self.process.kill()
                self.process.wait()
            for stream in (self.process.stdout, self.process.stderr):
                if stream is not None:
                    stream.close()
