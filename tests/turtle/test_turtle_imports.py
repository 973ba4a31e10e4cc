"""turtlesim's small programs start fast: numpy loads with the engine only, textual never."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest


def modules_after(code: str) -> set[str]:
    script = f"{code}\nimport sys, json\nprint(json.dumps(sorted(sys.modules)))"
    done = subprocess.run(
        [sys.executable, "-c", script], capture_output=True, text=True, check=True
    )
    return set(json.loads(done.stdout.splitlines()[-1]))


@pytest.mark.parametrize(
    "module",
    [
        "rosx_turtle.executables",
        "rosx_turtle.teleop",
        "rosx_turtle.tutorials.mimic",
        "rosx_turtle.tutorials.draw_square",
        "rosx_turtle.engine.constants",
    ],
)
def test_no_numpy_and_no_tui(module: str) -> None:
    loaded = modules_after(f"import {module}")
    assert not {m for m in loaded if m.split(".")[0] in ("numpy", "textual")}


def test_the_simulator_loads_numpy_but_no_tui() -> None:
    loaded = modules_after("from rosx_turtle.node import run_turtlesim, TurtlesimNode")
    assert "numpy" in loaded
    assert not {m for m in loaded if m.split(".")[0] == "textual"}
