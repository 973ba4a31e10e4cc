"""textual loads only when there is a screen to draw: not for headless nodes, nor ``rosx sim``
without a terminal, nor any other command."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest


def _modules_after(code: str) -> set[str]:
    script = f"{code}\nimport sys, json\nprint(json.dumps(sorted(sys.modules)))"
    done = subprocess.run(
        [sys.executable, "-c", script], capture_output=True, text=True, check=True
    )
    return set(json.loads(done.stdout.splitlines()[-1]))


@pytest.mark.parametrize(
    "code",
    [
        "import rosx_turtle.sim, rosx_turtle.tui.pond_run, rosx_turtle.node.run",
        "import rosx_commands.sim",
        # A taken port: rosx sim refuses before any screen (and without a terminal draws none).
        "import io, socket\nfrom rosx_commands.context import Environment\n"
        "from rosx_commands.main import run_tool\n"
        "s = socket.socket(); s.bind(('127.0.0.1', 0)); s.listen()\n"
        "port = str(s.getsockname()[1])\n"
        "out, err = io.StringIO(), io.StringIO()\n"
        "status = run_tool(['sim', '--port', port], Environment(stdout=out, stderr=err, environ={}))\n"
        "assert status == 1 and 'already in use' in err.getvalue(), err.getvalue()",
    ],
)
def test_no_textual_without_a_screen(code: str) -> None:
    assert not {m for m in _modules_after(code) if m.split(".")[0] == "textual"}
