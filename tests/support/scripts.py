"""Running a ROS Python script with rosx's rospy, and reading the JSON it prints."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path
from typing import Any

from tests.support.cli import clean_environ


def script_command(script: Path, *args: str) -> list[str]:
    """How ``rosx rosrun`` runs a Python script: ``rosx run-script``, on this interpreter."""
    return [sys.executable, "-m", "rosx_commands", "run-script", str(script), *args]


def start_script(script: Path, **environ: str) -> subprocess.Popen[str]:
    """``script`` started as `script_command` runs it, its output piped as text."""
    return subprocess.Popen(
        script_command(script),
        env=clean_environ(**environ),
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )


def run_script(
    tmp_path: Path, source: str, *args: str, **environ: str
) -> subprocess.CompletedProcess[str]:
    script = tmp_path / "script.py"
    script.write_text(source)
    return subprocess.run(
        script_command(script, *args),
        env=clean_environ(**environ),
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=60,
        check=False,
    )


def json_of(done: subprocess.CompletedProcess[str]) -> Any:
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout.splitlines()[-1])
