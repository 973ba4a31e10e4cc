"""A core, a turtlesim and a bridge on free ports, shared by a test module."""

from __future__ import annotations

import hashlib
import os
import shutil
import subprocess
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest

from rosx_turtle.node.turtlesim import TurtlesimNode
from rosx_turtle.roscpp import NodeArgs
from tests.support.bridge import NodeScript, Running, start_bridge


@pytest.fixture(scope="module")
def running(master: str) -> Iterator[Running]:
    """turtlesim and a bridge (with rosapi) on the module's master."""
    environ = {"ROS_MASTER_URI": master, "ROS_IP": "127.0.0.1"}
    sim = TurtlesimNode(NodeArgs.parse([], "turtlesim"), environ=environ).start()
    bridge, lines = start_bridge(master)
    try:
        yield Running(master, bridge.port, environ, bridge, lines)
    finally:
        bridge.shutdown("test over")
        sim.shutdown("test over")


#: The npm packages the JavaScript clients need: roslib (roslibjs), Lichtblick's own rosbridge
#: client and message readers (its packages forget tslib), playwright-core for the browser
#: page, esbuild to bundle the page's script with roslib, and Foxglove's WebSocket client.
NPM_PACKAGES = (
    "roslib@2.1.0",
    "ws@8",
    "@lichtblick/roslibjs@1.0.0",
    "@lichtblick/rosmsg@1",
    "@lichtblick/rosmsg-serialization@1",
    "tslib@2",
    "playwright-core@1",
    "esbuild@0.25",
    "@foxglove/ws-protocol@0.8",
)
JS = Path(__file__).parent / "js"


def _npm_cache() -> Path:
    base = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
    key = hashlib.sha256(" ".join(NPM_PACKAGES).encode()).hexdigest()[:12]
    return Path(base) / "rosx-tests" / f"npm-{key}"


@pytest.fixture(scope="session")
def npm_dir() -> Path:
    """A folder with the npm packages installed and this folder's scripts beside them (the
    page bundled); skips when node, npm or the registry cannot be had. Installed once into
    the user's cache, so later runs only copy the scripts."""
    node, npm = shutil.which("node"), shutil.which("npm")
    if node is None or npm is None:
        pytest.skip("node and npm are not installed")
    folder = _npm_cache()
    marker = folder / "installed"
    if not marker.exists():
        folder.mkdir(parents=True, exist_ok=True)
        (folder / "package.json").write_text('{"private": true}\n')
        done = subprocess.run(
            [npm, "install", "--no-audit", "--no-fund", "--loglevel=error", *NPM_PACKAGES],
            cwd=folder, capture_output=True, text=True, timeout=300, check=False,
        )  # fmt: skip
        if done.returncode != 0:
            pytest.skip(f"npm install failed (registry unreachable?): {done.stderr.strip()[-200:]}")
        marker.write_text("\n".join(NPM_PACKAGES))
    for script in JS.iterdir():
        shutil.copy(script, folder / script.name)
    # a module for page.html; a classic script for file-page.html (a file's page may not load
    # modules)
    for form, out in (("esm", "page.js"), ("iife", "page-classic.js")):
        bundled = subprocess.run(
            [str(folder / "node_modules/.bin/esbuild"), "page.mjs", "--bundle", f"--format={form}",
             "--platform=browser", f"--outfile={out}", "--log-level=warning",
             "--alias:ws=./ws-browser.mjs"],
            cwd=folder, capture_output=True, text=True, timeout=120, check=False,
        )  # fmt: skip
        assert bundled.returncode == 0, bundled.stderr
    return folder


@pytest.fixture
def node_script(npm_dir: Path) -> Iterator[Callable[..., NodeScript]]:
    """Run node scripts in the npm folder; each is stopped after the test."""
    started: list[NodeScript] = []

    def run(*args: str) -> NodeScript:
        script = NodeScript(npm_dir, *args)
        started.append(script)
        return script

    yield run
    for script in started:
        script.finish()
